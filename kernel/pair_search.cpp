#include "pair_search.hpp"

#include "backend_registry.hpp"
#include "method_check.hpp"
#include "pair_sort.hpp"
#include "radix_sort.hpp"
#include "thread_pool.hpp"

#include <obbsat/error.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/bounds.hpp>

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>
#include <thread>

namespace obbsat::detail {

namespace {

/// Strips are this many mean bounds heights tall (measured: see docs/performance.md).
constexpr double strip_factor = 2.0;

/// Candidates handed to the method's kernel at once.
constexpr std::size_t candidate_block = 2048;

/// Found pairs handed to a streaming sink at once.
constexpr std::size_t emit_block = 4096;

/// Below this many rectangles per part, a second core costs more than it saves.
constexpr std::size_t min_boxes_per_part = 16384;

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point start) {
    return std::chrono::duration<double>(clock_type::now() - start).count();
}

std::size_t parts_for(std::size_t boxes, unsigned threads) {
    std::size_t wanted = threads;
    if (wanted == 0) {
        wanted = std::max(1u, std::thread::hardware_concurrency());
    }
    return std::max<std::size_t>(1, std::min(wanted, boxes / min_boxes_per_part));
}

/// Runs task(part) for every part, on the shared pool when there are several.
template <class Task>
void run_parts(std::size_t parts, const Task& task) {
    if (parts <= 1) {
        task(std::size_t{0});
        return;
    }
    thread_pool::shared().run(parts, [&](std::size_t share) { task(share); });
}

/// [begin, end) of part `part` of `parts` over n items.
std::pair<std::size_t, std::size_t> share_of(std::size_t n, std::size_t part, std::size_t parts) {
    return {n * part / parts, n * (part + 1) / parts};
}

const float* record_at(const query_input& input, std::size_t id) {
    return id < input.a_count ? input.a + 8 * id : input.b + 8 * (id - input.a_count);
}

ref::box_bounds bounds_of_record(store_kind kind, const float* v) {
    if (kind == store_kind::poses) {
        return ref::bounds_of(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}});
    }
    return ref::bounds_of(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
}

double clamp_finite(float x) {
    return static_cast<double>(std::min(std::max(x, -FLT_MAX), FLT_MAX));
}

}  // namespace

pair_search::pair_search(const collide_options& options) : options_(options) {}

void pair_search::compute_bounds(const query_input& input, std::size_t parts) {
    lo_x_.resize(n_);
    lo_y_.resize(n_);
    hi_x_.resize(n_);
    hi_y_.resize(n_);
    struct partial {
        double x_low = std::numeric_limits<double>::infinity();
        double x_high = -std::numeric_limits<double>::infinity();
        double y_low = std::numeric_limits<double>::infinity();
        double y_high = -std::numeric_limits<double>::infinity();
        double height_sum = 0;
    };
    std::vector<partial> partials(parts);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        partial& p = partials[share];
        float x_low = FLT_MAX, x_high = -FLT_MAX, y_low = FLT_MAX, y_high = -FLT_MAX;
        double height_sum = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const ref::box_bounds b = bounds_of_record(kind_, record_at(input, i));
            lo_x_[i] = b.lo_x;
            lo_y_[i] = b.lo_y;
            hi_x_[i] = b.hi_x;
            hi_y_[i] = b.hi_y;
            x_low = std::min(x_low, b.lo_x);
            x_high = std::max(x_high, b.hi_x);
            y_low = std::min(y_low, b.lo_y);
            y_high = std::max(y_high, b.hi_y);
            height_sum += clamp_finite(b.hi_y) - clamp_finite(b.lo_y);
        }
        p.x_low = clamp_finite(x_low);
        p.x_high = clamp_finite(x_high);
        p.y_low = clamp_finite(y_low);
        p.y_high = clamp_finite(y_high);
        p.height_sum = height_sum;
    });
    partial all;
    for (const partial& p : partials) {
        all.x_low = std::min(all.x_low, p.x_low);
        all.x_high = std::max(all.x_high, p.x_high);
        all.y_low = std::min(all.y_low, p.y_low);
        all.y_high = std::max(all.y_high, p.y_high);
        all.height_sum += p.height_sum;
    }
    extent_ = bounds_extent{all.x_low, all.x_high, all.y_low, all.y_high,
                            all.height_sum / static_cast<double>(n_)};
}

void pair_search::order_boxes(std::size_t parts) {
    const bool same_scene = have_order_ && ordered_n_ == n_ && ordered_a_count_ == a_count_ &&
                            ordered_kind_ == kind_ && ordered_self_ == self_;
    const bool keep_grid = same_scene && grid_still_fits(grid_, extent_);
    if (!keep_grid) {
        grid_ = grid_for(extent_, n_, strip_factor);
    }
    key_by_id_.resize(n_);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        for (std::size_t i = begin; i < end; ++i) {
            key_by_id_[i] = grid_.key_of(lo_x_[i], lo_y_[i]);
        }
    });
    keys_.resize(n_);
    order_.resize(n_);
    stats_.reused_order = false;
    if (keep_grid) {
        // The last order, with this query's keys: nearly sorted when the
        // rectangles moved a little.
        for (std::size_t k = 0; k < n_; ++k) {
            keys_[k] = key_by_id_[order_[k]];
        }
        stats_.reused_order = repair_sort(keys_.data(), order_.data(), n_, 4 * n_);
    }
    if (!stats_.reused_order) {
        for (std::size_t i = 0; i < n_; ++i) {
            keys_[i] = key_by_id_[i];
            order_[i] = static_cast<std::uint32_t>(i);
        }
        radix_sort(keys_.data(), order_.data(), n_, grid_.key_bits(), spare_keys_, spare_values_);
    }
    have_order_ = true;
    ordered_n_ = n_;
    ordered_a_count_ = a_count_;
    ordered_kind_ = kind_;
    ordered_self_ = self_;
}

void pair_search::copy_records(const query_input& input, std::size_t parts) {
    records_.resize(n_);
    in_lo_x_.resize(n_);
    in_lo_y_.resize(n_);
    in_hi_x_.resize(n_);
    in_hi_y_.resize(n_);
    q_lo_.resize(n_);
    q_hi_.resize(n_);
    strip_hi_.resize(n_);
    side_.resize(n_);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        constexpr std::size_t ahead = 16;
        for (std::size_t k = begin; k < end; ++k) {
            if (k + ahead < end) {
                __builtin_prefetch(record_at(input, order_[k + ahead]));
            }
            const std::uint32_t id = order_[k];
            std::memcpy(records_[k].v, record_at(input, id), sizeof(record));
            // The same function on the same floats: the bounds of step 1.
            const ref::box_bounds b = bounds_of_record(kind_, records_[k].v);
            in_lo_x_[k] = b.lo_x;
            in_lo_y_[k] = b.lo_y;
            in_hi_x_[k] = b.hi_x;
            in_hi_y_[k] = b.hi_y;
            q_lo_[k] = grid_.q_of(b.lo_x);
            q_hi_[k] = grid_.q_of(b.hi_x);
            strip_hi_[k] = grid_.strip_of(b.hi_y);
            side_[k] = id >= a_count_ && !self_ ? 1 : 0;
        }
    });
}

void pair_search::collect_visits() {
    const std::uint32_t strips = grid_.strips;
    const unsigned q_bits = grid_.q_bits;
    own_begin_.assign(strips + 1, 0);
    std::size_t visits = 0;
    for (std::size_t k = 0; k < n_; ++k) {
        const std::uint32_t low = keys_[k] >> q_bits;
        ++own_begin_[low + 1];
        visits += strip_hi_[k] - low;
    }
    for (std::uint32_t s = 0; s < strips; ++s) {
        own_begin_[s + 1] += own_begin_[s];
    }
    visit_keys_.resize(visits);
    visit_ids_.resize(visits);
    std::size_t v = 0;
    for (std::size_t k = 0; k < n_; ++k) {
        const std::uint32_t low = keys_[k] >> q_bits;
        for (std::uint32_t s = low + 1; s <= strip_hi_[k]; ++s) {
            visit_keys_[v] = (s << q_bits) | q_lo_[k];
            visit_ids_[v] = static_cast<std::uint32_t>(k);
            ++v;
        }
    }
    radix_sort(visit_keys_.data(), visit_ids_.data(), visits, grid_.key_bits(), spare_keys_, spare_values_);
    visit_begin_.assign(strips + 1, 0);
    for (std::size_t i = 0; i < visits; ++i) {
        ++visit_begin_[(visit_keys_[i] >> q_bits) + 1];
    }
    for (std::uint32_t s = 0; s < strips; ++s) {
        visit_begin_[s + 1] += visit_begin_[s];
    }
    stats_.strips = strips;
    stats_.visits = visits;
}

void pair_search::flush_candidates(part& p) const {
    const std::size_t count = p.candidate_count;
    if (count == 0) {
        return;
    }
    const kernel_table& table = kernels_for(ran_);
    if (kind_ == store_kind::poses) {
        p.slow_path += table.on_poses(options_.test)
                           .indexed(records_.data()->v, p.candidates.data(), count, p.verdicts.data());
    } else {
        p.slow_path += table.of(options_.test)
                           .indexed_records(reinterpret_cast<const rect*>(records_.data()), p.candidates.data(),
                                            count, p.verdicts.data());
    }
    p.tested += count;
    for (std::size_t i = 0; i < count; ++i) {
        if (p.verdicts[i] == 0) {
            continue;
        }
        std::uint32_t a = order_[p.candidates[i].a];
        std::uint32_t b = order_[p.candidates[i].b];
        if (self_) {
            if (a > b) {
                std::swap(a, b);
            }
        } else {
            if (a >= a_count_) {
                std::swap(a, b);
            }
            b -= static_cast<std::uint32_t>(a_count_);
        }
        p.found.push_back(pair_index{a, b});
    }
    p.candidate_count = 0;
}

void pair_search::sweep_strip(std::uint32_t strip, part& p) const {
    // Merge the rectangles starting in this strip with its visitors, by
    // quantized lo_x (a rectangle before a visitor on equal keys).
    const std::size_t own_begin = own_begin_[strip];
    const std::size_t own_end = own_begin_[strip + 1];
    const std::size_t visit_begin = visit_begin_[strip];
    const std::size_t visit_end = visit_begin_[strip + 1];
    const std::size_t m = (own_end - own_begin) + (visit_end - visit_begin);
    if (m < 2) {
        return;
    }
    if (p.q_lo.size() < m) {
        for (auto* v : {&p.q_lo, &p.q_hi, &p.id}) {
            v->resize(m);
        }
        for (auto* v : {&p.lo_x, &p.lo_y, &p.hi_x, &p.hi_y}) {
            v->resize(m);
        }
        p.own.resize(m);
        p.side.resize(m);
    }
    std::size_t o = own_begin;
    std::size_t v = visit_begin;
    for (std::size_t e = 0; e < m; ++e) {
        const bool take_own = v == visit_end || (o < own_end && q_lo_[o] <= (visit_keys_[v] & grid_.q_max));
        const std::size_t k = take_own ? o++ : visit_ids_[v++];
        p.q_lo[e] = q_lo_[k];
        p.q_hi[e] = q_hi_[k];
        p.id[e] = static_cast<std::uint32_t>(k);
        p.lo_x[e] = in_lo_x_[k];
        p.lo_y[e] = in_lo_y_[k];
        p.hi_x[e] = in_hi_x_[k];
        p.hi_y[e] = in_hi_y_[k];
        p.own[e] = take_own ? 1 : 0;
        p.side[e] = side_[k];
    }
    // Sweep: each entry against the later entries that may overlap it in x.
    pair_index* candidates = p.candidates.data();
    std::size_t count = p.candidate_count;
    const bool cross = !self_;
    for (std::size_t e = 0; e + 1 < m; ++e) {
        const std::uint32_t q_hi = p.q_hi[e];
        const float lo_x = p.lo_x[e];
        const float hi_x = p.hi_x[e];
        const float lo_y = p.lo_y[e];
        const float hi_y = p.hi_y[e];
        const std::uint8_t own = p.own[e];
        const std::uint8_t side = p.side[e];
        const std::uint32_t id = p.id[e];
        for (std::size_t f = e + 1; f < m && p.q_lo[f] <= q_hi; ++f) {
            const bool hit = (p.lo_x[f] <= hi_x) & (p.hi_x[f] >= lo_x) & (p.lo_y[f] <= hi_y) &
                             (p.hi_y[f] >= lo_y) & ((own | p.own[f]) != 0) & (!cross | (side != p.side[f]));
            candidates[count] = pair_index{id, p.id[f]};
            count += hit ? 1 : 0;
            if (count == candidate_block) {
                p.candidate_count = count;
                flush_candidates(p);
                count = 0;
            }
        }
    }
    p.candidate_count = count;
}

void pair_search::sweep(const query_input& input, std::size_t parts, const pair_chunk_sink* emit) {
    (void)input;
    // Strips split so that each part has about the same number of entries.
    const std::uint32_t strips = grid_.strips;
    const std::size_t entries = n_ + stats_.visits;
    if (parts_.size() < parts) {
        parts_.resize(parts);
    }
    std::uint32_t s = 0;
    for (std::size_t i = 0; i < parts; ++i) {
        part& p = parts_[i];
        p.first_strip = s;
        const std::size_t target = entries * (i + 1) / parts;
        while (s < strips && (i + 1 == parts || own_begin_[s] + visit_begin_[s] < target)) {
            ++s;
        }
        p.end_strip = s;
        if (p.candidates.size() < candidate_block) {
            p.candidates.resize(candidate_block);
            p.verdicts.resize(candidate_block);
        }
        p.candidate_count = 0;
        p.found.clear();
        p.tested = 0;
        p.slow_path = 0;
    }
    std::mutex emit_mutex;
    std::vector<std::exception_ptr> failures(parts);
    std::atomic<bool> failed{false};
    run_parts(parts, [&](std::size_t index) {
        part& p = parts_[index];
        try {
            const auto hand_over = [&](bool all) {
                if (emit != nullptr && (all || p.found.size() >= emit_block) && !p.found.empty()) {
                    const std::lock_guard<std::mutex> lock(emit_mutex);
                    if (!failed.load()) {
                        (*emit)(p.found.data(), p.found.size());
                    }
                    p.found.clear();
                }
            };
            for (std::uint32_t strip = p.first_strip; strip < p.end_strip && !failed.load(); ++strip) {
                sweep_strip(strip, p);
                hand_over(false);
            }
            flush_candidates(p);
            hand_over(true);
        } catch (...) {
            failures[index] = std::current_exception();
            failed.store(true);
        }
    });
    for (const std::exception_ptr& failure : failures) {
        if (failure) {
            std::rethrow_exception(failure);
        }
    }
    for (std::size_t i = 0; i < parts; ++i) {
        stats_.candidates += parts_[i].tested;
        stats_.slow_path_pairs += parts_[i].slow_path;
    }
}

void pair_search::run(const query_input& input, const pair_chunk_sink& emit) {
    detail::require_method_on(options_, input.kind);
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
    for (part& p : parts_) {
        p.found.clear();
    }
    if (n_ < 2 || (!self_ && (input.a_count == 0 || input.b_count == 0))) {
        return;
    }
    const std::size_t parts = parts_for(n_, options_.threads);
    auto start = clock_type::now();
    compute_bounds(input, parts);
    stats_.bounds_seconds = seconds_since(start);
    start = clock_type::now();
    order_boxes(parts);
    copy_records(input, parts);
    collect_visits();
    stats_.order_seconds = seconds_since(start);
    start = clock_type::now();
    sweep(input, parts, emit ? &emit : nullptr);
    stats_.sweep_seconds = seconds_since(start);
    if (options_.slow_path_pairs != nullptr) {
        *options_.slow_path_pairs = stats_.slow_path_pairs;
    }
}

const std::vector<pair_index>& pair_search::collect(const query_input& input) {
    pairs_.clear();
    run(input, pair_chunk_sink{});
    const auto start = clock_type::now();
    std::size_t total = 0;
    for (const part& p : parts_) {
        total += p.found.size();
    }
    if (n_ >= 2) {
        pairs_.reserve(total);
        for (part& p : parts_) {
            pairs_.insert(pairs_.end(), p.found.begin(), p.found.end());
            p.found.clear();
        }
        sort_pairs(pairs_, self_ ? n_ : a_count_, spare_pairs_, counts_);
    }
    stats_.pairs = pairs_.size();
    stats_.output_seconds = seconds_since(start);
    return pairs_;
}

}  // namespace obbsat::detail
