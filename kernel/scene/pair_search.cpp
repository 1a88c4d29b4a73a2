// The scene query's driver (pair_search.hpp): what a query is, and its steps taken in turn.
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "methods/method_check.hpp"
#include "scene/search_common.hpp"
#include "support/work_shares.hpp"

#include <obbsat/error.hpp>

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

namespace obbsat::detail {

pair_search::pair_search(const collide_options& options) : options_(options) {}

template <class F>
void pair_search::each_buffer(pair_search& other, const F& f) {
    f(key_by_id_, other.key_by_id_);
    f(keys_, other.keys_);
    f(order_, other.order_);
    f(changed_strip_, other.changed_strip_);
    for (auto [mine, others] : {std::pair{&stay_keys_, &other.stay_keys_}, {&stay_ids_, &other.stay_ids_},
                                {&moved_keys_, &other.moved_keys_}, {&moved_ids_, &other.moved_ids_},
                                {&q_lo_, &other.q_lo_}, {&q_hi_, &other.q_hi_}, {&strip_hi_, &other.strip_hi_},
                                {&visit_keys_, &other.visit_keys_}, {&visit_ids_, &other.visit_ids_},
                                {&far_keys_, &other.far_keys_}, {&far_ids_, &other.far_ids_},
                                {&near_keys_, &other.near_keys_}, {&near_ids_, &other.near_ids_}}) {
        f(*mine, *others);
    }
    f(packed_, other.packed_);
    f(spare_, other.spare_);
    f(records_, other.records_);
    f(records64_, other.records64_);
    f(double_bounds_, other.double_bounds_);
    for (auto [mine, others] : {std::pair{&in_lo_x_, &other.in_lo_x_}, {&in_lo_y_, &other.in_lo_y_},
                                {&in_hi_x_, &other.in_hi_x_}, {&in_hi_y_, &other.in_hi_y_}}) {
        f(*mine, *others);
    }
    f(side_, other.side_);
    f(filters_, other.filters_);
    f(own_begin_, other.own_begin_);
    f(visit_begin_, other.visit_begin_);
}

void pair_search::swap_working_memory(pair_search& other) {
    each_buffer(other, [](auto& mine, auto& others) { mine.swap(others); });
    // Each query sets every field of a unit it sweeps (sweep) and clears
    // what the unit found; its blocks of pairs and strip arrays stay.
    parts_.swap(other.parts_);
    pass_memory_.swap(other.pass_memory_);
    sort_scratch_.swap(other.sort_scratch_);
    sort_buckets_.swap(other.sort_buckets_);
}

std::size_t pair_search::working_bytes() {
    std::size_t bytes = 0;
    const auto add = [&bytes](const auto& v) { bytes += v.capacity() * sizeof(v[0]); };
    each_buffer(*this, [&add](const auto& mine, const auto&) { add(mine); });
    for (const part& p : parts_) {
        for (const auto* v : {&p.q_lo, &p.q_hi, &p.starts, &p.store, &p.lo_x, &p.lo_y, &p.hi_x, &p.hi_y}) {
            add(*v);
        }
        add(p.id);
        add(p.candidates);
        add(p.verdicts);
        bytes += p.found.bytes();
    }
    for (const strip_pass_memory& memory : pass_memory_) {
        for (const strip_visitors* each : {&memory.visitors[0], &memory.visitors[1], &memory.merged}) {
            const strip_visitors& visitors = *each;
            for (const auto* v : {&visitors.q_lo, &visitors.q_hi, &visitors.id}) {
                add(*v);
            }
            for (const auto* v :
                 {&visitors.store, &visitors.lo_x, &visitors.lo_y, &visitors.hi_x, &visitors.hi_y}) {
                add(*v);
            }
        }
        add(memory.far_visits);
        for (const auto* v : {&memory.own_at, &memory.visitor_at, &memory.own_q, &memory.climbing}) {
            add(*v);
        }
    }
    for (const pair_sort_scratch<pair_index>& s : sort_scratch_) {
        add(s.spare);
        add(s.counts);
    }
    bytes += sort_buckets_.bytes();
    return bytes;
}

void pair_search::free_working_memory() {
    // The units' pairs stay: they are the answer still to be sorted.
    pair_search empty(options_);
    each_buffer(empty, [](auto& mine, auto& others) { mine.swap(others); });
}

void pair_search::set_query(const query_input& input) {
    if (!input.doubles) {
        detail::require_method_on(options_, input.kind);  // a double query's is checked by bound_doubles
    }
    doubles_ = input.doubles;
    double_kind_ = input.double_kind;
    ran_ = resolve_backend(options_.use);
    stats_ = find_pairs_stats{};
    kind_ = input.kind;
    self_ = input.b == nullptr;
    a_count_ = input.a_count;
    n_ = input.a_count + (self_ ? 0 : input.b_count);
    if (n_ > std::numeric_limits<std::uint32_t>::max()) {
        throw invalid_input("a scene query takes at most 4294967295 rectangles, not " + std::to_string(n_));
    }
    stats_.boxes = n_;
    stats_.bounds_seconds = double_bounds_seconds_;
    filtered_ = input.filtered();
}

void pair_search::run(const query_input& input, const pair_chunk_sink& emit) {
    set_query(input);
    used_parts_ = 0;
    // The order built below is this query's rows, slot for row.
    kept_.by_id = false;
    kept_.empty_slots = 0;
    kept_.remap_pending = false;
    slots_ = n_;
    for (part& p : parts_) {
        p.found.clear();
    }
    if (n_ < 2 || (!self_ && (input.a_count == 0 || input.b_count == 0))) {
        // Nothing to compare, and no bounds pass to check the rows: they are
        // checked here, so that what a larger query refuses this one does too.
        require_valid_rows(input);
        return;
    }
    const std::size_t parts = parts_for(n_, options_.threads, min_boxes_per_part);
    used_parts_ = parts;
    auto start = clock_type::now();
    // Keys on a grid about to be replaced (grid_too_wide) would serve no repair.
    bool repair = same_scene_as_last() && !grid_too_wide();
    const bool time_order = repair && kept_.paused;
    if (time_order) {
        // A paused pair_finder (kept_pairs::paused) sees rows move far or
        // change places, where a repair of the order may cost more than a
        // sort: it takes the one it last timed cheaper, timing the other
        // every order_retime_period calls.
        ++kept_.paused_orders;
        if (kept_.repair_seconds == 0) {
            repair = true;
        } else if (kept_.sort_seconds == 0) {
            repair = false;
        } else {
            const bool cheaper = kept_.repair_seconds <= kept_.sort_seconds;
            repair = kept_.paused_orders % order_retime_period == 0 ? !cheaper : cheaper;
        }
    }
    measure_extent(input, parts, repair);
    order_boxes(input, parts);
    if (one_shot_ && double_records_only()) {
        // The float rows of `input` are read no more (copy_double_records
        // reads the double rows): their memory goes before the records' comes.
        decltype(double_bounds_)().swap(double_bounds_);
    }
    const double bounds_and_order = seconds_since(start);
    stats_.bounds_seconds += bounds_and_order;
    if (time_order) {
        (repair ? kept_.repair_seconds : kept_.sort_seconds) = std::max(bounds_and_order, 1e-9);
    }
    start = clock_type::now();
    if (sweeps_strip_by_strip(parts)) {
        // The copy and the visits are timed with the sweep they are part of.
        copy_and_sweep(input, parts, emit ? &emit : nullptr);
        stats_.sweep_seconds = seconds_since(start);
    } else {
        copy_records(input, parts);
        collect_visits(parts);
        stats_.order_seconds = seconds_since(start);
        start = clock_type::now();
        sweep(parts, emit ? &emit : nullptr);
        stats_.sweep_seconds = seconds_since(start);
    }
    if (options_.slow_path_pairs != nullptr) {
        *options_.slow_path_pairs = stats_.slow_path_pairs;
    }
    // The next query widens by this one's typical extent; this one's widening
    // used the last one's throughout.
    kept_.typical_extent = kept_.measured_typical_extent;
}

}  // namespace obbsat::detail
