#include "dispatch/backend_registry.hpp"
#include "support/fetch_ahead.hpp"
#include "store/finite_check.hpp"
#include "methods/method_check.hpp"
#include "store/pose_record.hpp"
#include "support/executor_scope.hpp"
#include "support/work_shares.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace obbsat {

namespace {

// Below this many pairs per part, waking another core costs more than it
// saves (a wake-up is a few microseconds; a pair is a few nanoseconds).
constexpr std::size_t min_pairs_per_part = 8192;

// Below this many pairs, a unit taken as it comes costs more (its share of
// the counter and of the cache lines at its ends) than it could save.
constexpr std::size_t min_pairs_per_unit = 4096;

// Units start on multiples of this, so every unit but the last fills whole
// vectors of the widest backend.
constexpr std::size_t part_alignment = 64;

/// Runs body(begin, end) over [0, count) split into aligned units, a few per
/// thread, each taken by the next thread free (work_shares.hpp); body returns
/// how many pairs it settled exactly, and the sum is reported through
/// options.slow_path_pairs. With an executor the units run on it.
template <class Body>
void split_over_threads(std::size_t count, const collide_options& options, const Body& body) {
    const std::size_t parts = detail::parts_for(count, options.threads, min_pairs_per_part);
    std::size_t settled = 0;
    if (parts <= 1) {
        settled = body(std::size_t{0}, count);  // no vector of one: a small batch allocates nothing
    } else {
        const detail::executor_scope scope(options.executor);
        const std::size_t units = detail::units_for(count, parts, min_pairs_per_unit);
        std::vector<std::size_t> settled_per_unit(units, 0);
        detail::run_units(units, parts, [&](std::size_t unit) {
            const auto [begin, end] = detail::aligned_share_of(count, unit, units, part_alignment);
            if (begin < end) {
                settled_per_unit[unit] = body(begin, end);
            }
        });
        for (const std::size_t s : settled_per_unit) {
            settled += s;
        }
    }
    if (options.slow_path_pairs != nullptr) {
        *options.slow_path_pairs = settled;
    }
}

/// Throws invalid_input naming the first pair with an index >= rect_count.
/// One pass of the backend's lanes, split like a batch, finds the largest
/// index; only when it is out of range is the offender searched for.
void check_indices(backend ran, std::size_t rect_count, const pair_index* pairs, std::size_t count,
                   const collide_options& options) {
    const detail::largest_index_fn largest_index = detail::kernels_for(ran).largest_index;
    const std::size_t parts = detail::parts_for(count, options.threads, min_pairs_per_part);
    std::uint32_t largest = 0;
    if (parts <= 1) {
        largest = largest_index(pairs, count);
    } else {
        const detail::executor_scope scope(options.executor);
        std::vector<std::uint32_t> part_largest(parts, 0);
        detail::run_parts(parts, [&](std::size_t part) {
            const auto [begin, end] = detail::share_of(count, part, parts);
            part_largest[part] = largest_index(pairs + begin, end - begin);
        });
        largest = *std::max_element(part_largest.begin(), part_largest.end());
    }
    if (count == 0 || largest < rect_count) {
        return;
    }
    for (std::size_t i = 0; i < count; ++i) {
        const pair_index& p = pairs[i];
        const bool a_bad = p.a >= rect_count;
        if (a_bad || p.b >= rect_count) {
            throw invalid_input("pair " + std::to_string(i) + ": index " +
                                std::to_string(a_bad ? p.a : p.b) + " is out of range (" +
                                std::to_string(rect_count) + " rectangles)");
        }
    }
}

/// The entry points of options.test on corners on backend `ran`; throws
/// invalid_input when options.test names no method that runs on corners.
const detail::method_kernels& kernels_of(backend ran, const collide_options& options) {
    detail::require_method_on(options, store_kind::corners);
    return detail::kernels_for(ran).of(options.test);
}

/// Of the entries `near` (fetching nothing ahead), `fetching` (16 pairs ahead
/// into L1) and `far` (128 ahead into L2), the one for a pair list over a
/// store of `bytes` of records (fetch_ahead.hpp).
template <class Fn>
Fn entry_for_store(std::size_t bytes, Fn near, Fn fetching, Fn far) {
    if (bytes <= detail::store_bytes_in_l2) {
        return near;
    }
    return bytes > detail::store_bytes_from_dram ? far : fetching;
}

/// The entry for pair lists over `count` packed corner records, fetching
/// their records ahead as the store's size asks.
detail::indexed_records_fn records_kernel_of(backend ran, const collide_options& options, std::size_t count) {
    const detail::method_kernels& kernels = kernels_of(ran, options);
    return entry_for_store(count * sizeof(rect), kernels.indexed_records_near, kernels.indexed_records,
                           kernels.indexed_records_far);
}

/// The same on poses.
const detail::pose_method_kernels& pose_kernels_of(backend ran, const collide_options& options) {
    detail::require_method_on(options, store_kind::poses);
    return detail::kernels_for(ran).on_poses(options.test);
}

/// The entry for pair lists over `count` pose records, chosen as records_kernel_of chooses.
detail::pose_indexed_fn pose_records_kernel_of(backend ran, const collide_options& options, std::size_t count) {
    const detail::pose_method_kernels& kernels = pose_kernels_of(ran, options);
    return entry_for_store(count * sizeof(float) * pose_records::record_floats, kernels.indexed_near,
                           kernels.indexed, kernels.indexed_far);
}

/// True iff no coordinate of rects[begin, end) is a NaN or an infinity.
bool all_finite(const rect* rects, std::size_t begin, std::size_t end) {
    constexpr std::size_t floats_per_rect = sizeof(rect) / sizeof(float);
    static_assert(floats_per_rect == coord_count, "a rect is eight packed floats");
    return detail::all_finite(reinterpret_cast<const float*>(rects + begin), (end - begin) * floats_per_rect);
}

/// Throws invalid_input naming the first non-finite coordinate of rects[0, count).
/// The scan is split like a batch (a rectangle costs about as much to scan as
/// a pair to decide would to fetch); only on failure is the offender searched.
void require_all_finite(const rect* rects, std::size_t count, const collide_options& options) {
    const std::size_t parts = detail::parts_for(count, options.threads, min_pairs_per_part);
    bool finite = true;
    if (parts <= 1) {
        finite = all_finite(rects, 0, count);
    } else {
        const detail::executor_scope scope(options.executor);
        std::vector<unsigned char> part_finite(parts, 1);
        detail::run_parts(parts, [&](std::size_t part) {
            const auto [begin, end] = detail::share_of(count, part, parts);
            part_finite[part] = all_finite(rects, begin, end) ? 1 : 0;
        });
        finite = std::find(part_finite.begin(), part_finite.end(), 0) == part_finite.end();
    }
    if (!finite) {
        for (std::size_t i = 0; i < count; ++i) {
            detail::require_finite(rects[i], i);
        }
    }
}

/// Throws invalid_input when the caller's verdict buffer (`count` bytes) and
/// another of the caller's buffers (`bytes` long, named `what`) share memory:
/// verdicts written by one part would overwrite what another has yet to read.
void require_verdicts_apart(const std::uint8_t* verdicts, std::size_t count, const void* other,
                            std::size_t bytes, const char* what) {
    const auto v = reinterpret_cast<std::uintptr_t>(verdicts);
    const auto o = reinterpret_cast<std::uintptr_t>(other);
    if (count != 0 && bytes != 0 && v < o + bytes && o < v + count) {
        throw invalid_input(std::string("verdicts and ") + what + " share memory: the verdict buffer must not overlap " +
                            what);
    }
}

}  // namespace

backend collide_pairs(const rect_soa& rects, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options) {
    require_verdicts_apart(verdicts, count, pairs, count * sizeof(pair_index), "pairs");
    const backend ran = resolve_backend(options.use);
    check_indices(ran, rects.size(), pairs, count, options);
    const detail::indexed_fn kernel = kernels_of(ran, options).indexed;
    const detail::soa_view view = detail::view_of(rects);
    split_over_threads(count, options, [&](std::size_t begin, std::size_t end) {
        return kernel(view, pairs + begin, end - begin, verdicts + begin);
    });
    return ran;
}

backend collide_pairs(const rect_records& rects, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options) {
    require_verdicts_apart(verdicts, count, pairs, count * sizeof(pair_index), "pairs");
    const backend ran = resolve_backend(options.use);
    check_indices(ran, rects.size(), pairs, count, options);
    const detail::indexed_records_fn kernel = records_kernel_of(ran, options, rects.size());
    const rect* records = rects.data();
    split_over_threads(count, options, [&](std::size_t begin, std::size_t end) {
        return kernel(records, pairs + begin, end - begin, verdicts + begin);
    });
    return ran;
}

backend collide_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs,
                      std::size_t count, std::uint8_t* verdicts, const collide_options& options) {
    require_verdicts_apart(verdicts, count, pairs, count * sizeof(pair_index), "pairs");
    require_verdicts_apart(verdicts, count, rects, rect_count * sizeof(rect), "rects");
    const backend ran = resolve_backend(options.use);
    require_all_finite(rects, rect_count, options);
    check_indices(ran, rect_count, pairs, count, options);
    const detail::indexed_records_fn kernel = records_kernel_of(ran, options, rect_count);
    split_over_threads(count, options, [&](std::size_t begin, std::size_t end) {
        return kernel(rects, pairs + begin, end - begin, verdicts + begin);
    });
    return ran;
}

namespace {

/// Throws invalid_input unless the two stream batches are equally long.
void require_same_length(std::size_t a, std::size_t b, const char* what) {
    if (a != b) {
        throw invalid_input("stream batches differ in length: " + std::to_string(a) + " " + what + " in A, " +
                            std::to_string(b) + " in B");
    }
}

}  // namespace

template <class Store>
std::vector<std::uint8_t> stream_verdicts_of(const Store& a, const Store& b, const collide_options& options) {
    std::vector<std::uint8_t> verdicts(a.size());
    collide_stream(a, b, verdicts.data(), options);
    return verdicts;
}

template <class Store>
std::vector<std::uint8_t> verdicts_of(const Store& rects, const std::vector<pair_index>& pairs,
                                      const collide_options& options) {
    std::vector<std::uint8_t> verdicts(pairs.size());
    collide_pairs(rects, pairs.data(), pairs.size(), verdicts.data(), options);
    return verdicts;
}

template <class Store>
std::vector<pair_index> hits_of(const Store& rects, const std::vector<pair_index>& pairs,
                                const collide_options& options) {
    const std::vector<std::uint8_t> verdicts = verdicts_of(rects, pairs, options);
    std::vector<pair_index> hits;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (verdicts[i] != 0) {
            hits.push_back(pairs[i]);
        }
    }
    return hits;
}

std::vector<std::uint8_t> collide_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    return verdicts_of(rects, pairs, options);
}

std::vector<pair_index> colliding_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    return hits_of(rects, pairs, options);
}

std::vector<std::uint8_t> collide_pairs(const rect_soa& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    return verdicts_of(rects, pairs, options);
}

std::vector<pair_index> colliding_pairs(const rect_soa& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    return hits_of(rects, pairs, options);
}

backend collide_stream(const rect_soa& a, const rect_soa& b, std::uint8_t* verdicts,
                       const collide_options& options) {
    require_same_length(a.size(), b.size(), "rectangles");
    const backend ran = resolve_backend(options.use);
    const detail::stream_fn kernel = kernels_of(ran, options).stream;
    const detail::soa_view va = detail::view_of(a);
    const detail::soa_view vb = detail::view_of(b);
    split_over_threads(a.size(), options, [&](std::size_t begin, std::size_t end) {
        return kernel(detail::shifted(va, begin), detail::shifted(vb, begin), end - begin, verdicts + begin);
    });
    return ran;
}

std::vector<std::uint8_t> collide_stream(const rect_soa& a, const rect_soa& b,
                                         const collide_options& options) {
    return stream_verdicts_of(a, b, options);
}

backend collide_pairs(const pose_records& poses, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options) {
    require_verdicts_apart(verdicts, count, pairs, count * sizeof(pair_index), "pairs");
    const backend ran = resolve_backend(options.use);
    const detail::pose_indexed_fn kernel = pose_records_kernel_of(ran, options, poses.size());
    check_indices(ran, poses.size(), pairs, count, options);
    const float* records = poses.data();
    split_over_threads(count, options, [&](std::size_t begin, std::size_t end) {
        return kernel(records, pairs + begin, end - begin, verdicts + begin);
    });
    return ran;
}

backend collide_pairs(const rect_pose* poses, std::size_t pose_count, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options) {
    require_verdicts_apart(verdicts, count, pairs, count * sizeof(pair_index), "pairs");
    require_verdicts_apart(verdicts, count, poses, pose_count * sizeof(rect_pose), "poses");
    const backend ran = resolve_backend(options.use);
    const detail::pose_stream_fn kernel = pose_kernels_of(ran, options).stream;
    require_valid_poses(poses, pose_count);
    check_indices(ran, pose_count, pairs, count, options);
    split_over_threads(count, options, [&](std::size_t begin, std::size_t end) {
        // Each pair's two poses gathered into records (cx, cy, hx, hy, c, s,
        // 0, 0), a block small enough for L1 at a time: the same floats the
        // indexed kernel would transpose from a pose_records.
        constexpr std::size_t block = 256;
        constexpr std::size_t ahead = 16;
        constexpr std::size_t floats = pose_records::record_floats;
        alignas(64) float a[block * floats];
        alignas(64) float b[block * floats];
        static_assert(sizeof(rect_pose) == 6 * sizeof(float), "a rect_pose row is cx, cy, hx, hy, c, s");
        const auto put = [](float* record, const rect_pose* p) {
            detail::widen_pose_row(record, reinterpret_cast<const float*>(p));
        };
        std::size_t settled = 0;
        for (std::size_t first = begin; first < end; first += block) {
            const std::size_t n = std::min(block, end - first);
            for (std::size_t k = 0; k < n; ++k) {
                if (first + k + ahead < end) {
                    __builtin_prefetch(poses + pairs[first + k + ahead].a);
                    __builtin_prefetch(poses + pairs[first + k + ahead].b);
                }
                put(a + floats * k, poses + pairs[first + k].a);
                put(b + floats * k, poses + pairs[first + k].b);
            }
            settled += kernel(a, b, n, verdicts + first);
        }
        return settled;
    });
    return ran;
}

std::vector<std::uint8_t> collide_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    return verdicts_of(poses, pairs, options);
}

std::vector<pair_index> colliding_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    return hits_of(poses, pairs, options);
}

backend collide_stream(const pose_records& a, const pose_records& b, std::uint8_t* verdicts,
                       const collide_options& options) {
    require_same_length(a.size(), b.size(), "poses");
    const backend ran = resolve_backend(options.use);
    const detail::pose_stream_fn kernel = pose_kernels_of(ran, options).stream;
    const float* ra = a.data();
    const float* rb = b.data();
    constexpr std::size_t floats = pose_records::record_floats;
    split_over_threads(a.size(), options, [&](std::size_t begin, std::size_t end) {
        return kernel(ra + floats * begin, rb + floats * begin, end - begin, verdicts + begin);
    });
    return ran;
}

std::vector<std::uint8_t> collide_stream(const pose_records& a, const pose_records& b,
                                         const collide_options& options) {
    return stream_verdicts_of(a, b, options);
}

backend collide_stream(const pose_soa& a, const pose_soa& b, std::uint8_t* verdicts,
                       const collide_options& options) {
    require_same_length(a.size(), b.size(), "poses");
    const backend ran = resolve_backend(options.use);
    const detail::pose_stream_soa_fn kernel = pose_kernels_of(ran, options).stream_soa;
    const detail::pose_soa_view va = detail::view_of(a);
    const detail::pose_soa_view vb = detail::view_of(b);
    split_over_threads(a.size(), options, [&](std::size_t begin, std::size_t end) {
        return kernel(detail::shifted(va, begin), detail::shifted(vb, begin), end - begin, verdicts + begin);
    });
    return ran;
}

std::vector<std::uint8_t> collide_stream(const pose_soa& a, const pose_soa& b, const collide_options& options) {
    return stream_verdicts_of(a, b, options);
}

}  // namespace obbsat
