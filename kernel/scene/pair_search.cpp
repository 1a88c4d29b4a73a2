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

namespace obbsat::detail {

pair_search::pair_search(const collide_options& options) : options_(options) {}

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
    copy_records(input, parts);
    collect_visits(parts);
    stats_.order_seconds = seconds_since(start);
    start = clock_type::now();
    sweep(parts, emit ? &emit : nullptr);
    stats_.sweep_seconds = seconds_since(start);
    if (options_.slow_path_pairs != nullptr) {
        *options_.slow_path_pairs = stats_.slow_path_pairs;
    }
    // The next query widens by this one's typical extent; this one's widening
    // used the last one's throughout.
    kept_.typical_extent = kept_.measured_typical_extent;
}

}  // namespace obbsat::detail
