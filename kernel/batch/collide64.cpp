// Pair lists and streams over the double stores, split over threads: the
// backend's double lanes (dispatch/double_kernel_table.hpp, one table for poses
// and one for corners), or the scalar references of scalar_ref/ (the *64
// files) on the scalar backend.
#include "dispatch/double_kernel_table.hpp"
#include "support/fetch_ahead.hpp"
#include "support/work_shares.hpp"

#include <obbsat/collide64.hpp>
#include <obbsat/error.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/certified64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace obbsat {

namespace {

// A pair costs tens of nanoseconds here (more on the exact slow path), so a
// part is worth a core from fewer pairs than in the SIMD batch.
constexpr std::size_t min_pairs_per_part = 2048;

const char* store_description(store_kind s) { return s == store_kind::poses ? "double poses" : "double corners"; }

void require_method_on_doubles(const collide_options& options, store_kind store) {
    if (!is_method(options.test)) {
        throw invalid_input("collide_options::test holds " + std::to_string(static_cast<unsigned>(options.test)) +
                            ", which names no method");
    }
    if (!runs_on_doubles(options.test, store)) {
        std::string offered;
        for (const method m : methods_on_doubles(store)) {
            offered += std::string(offered.empty() ? "" : ", ") + method_name(m);
        }
        throw invalid_input(std::string("method ") + method_name(options.test) + " does not run on " +
                            store_description(store) + " (they take " + offered + ")");
    }
}

void require_verdicts_apart(const std::uint8_t* verdicts, const pair_index* pairs, std::size_t count) {
    const auto v = reinterpret_cast<std::uintptr_t>(verdicts);
    const auto p = reinterpret_cast<std::uintptr_t>(pairs);
    if (count != 0 && v < p + count * sizeof(pair_index) && p < v + count) {
        throw invalid_input("verdicts and pairs share memory: the verdict buffer must not overlap pairs");
    }
}

void require_indices(std::size_t size, const pair_index* pairs, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        const bool a_bad = pairs[i].a >= size;
        if (a_bad || pairs[i].b >= size) {
            throw invalid_input("pair " + std::to_string(i) + ": index " + std::to_string(a_bad ? pairs[i].a : pairs[i].b) +
                                " is out of range (" + std::to_string(size) + " rectangles)");
        }
    }
}

/// The checks every entry point makes, in order, before anything is written;
/// returns the backend that will run.
backend require_call(std::size_t size, const pair_index* pairs, std::size_t count, std::uint8_t* verdicts,
                     const collide_options& options, store_kind store) {
    require_verdicts_apart(verdicts, pairs, count);
    require_method_on_doubles(options, store);
    const backend ran = resolve_backend(options.use);  // unsupported_backend for one this CPU cannot run
    require_indices(size, pairs, count);
    return ran;
}

/// The backend's entries for options.test on double poses but the plain pair list.
const detail::pose64_method_kernels& pose_kernels_of(const detail::double_kernel_table& table, method m) {
    switch (m) {
        case method::exact: return table.exact_kernels;
        case method::conservative: return table.conservative_kernels;
        default: return table.local_kernels;  // the callers admit nothing else
    }
}

/// Of a method's three pair-list lanes (fetching nothing ahead, into L1,
/// into L2), the one a store of `bytes` asks for, as the float stores choose
/// (support/fetch_ahead.hpp).
template <class Lanes>
Lanes fetching_as_store_asks(std::size_t bytes, Lanes in_cache, Lanes fetching, Lanes far) {
    if (bytes > detail::store_bytes_from_dram) {
        return far;
    }
    return bytes > detail::store_bytes_in_l2 ? fetching : in_cache;
}

/// The backend's pair-list lanes for options.test over `count` double pose records.
detail::pose64_indexed_fn pose_kernel_of(const detail::double_kernel_table& table, method m, std::size_t count) {
    const detail::pose64_method_kernels& lanes = pose_kernels_of(table, m);
    const detail::pose64_indexed_fn in_cache =
        m == method::exact ? table.exact : m == method::conservative ? table.conservative : table.local;
    return fetching_as_store_asks(count * sizeof(double) * pose_records64::record_doubles, in_cache,
                                  lanes.indexed_fetching, lanes.indexed_far);
}

/// The backend's pair-list lanes for options.test (exact or conservative) over `count` double-corner records.
detail::rect64_indexed_fn corner_kernel_of(const detail::corner64_kernel_table& table, method m, std::size_t count) {
    const bool exact = m == method::exact;
    const detail::corner64_method_kernels& lanes = exact ? table.exact_kernels : table.conservative_kernels;
    return fetching_as_store_asks(count * sizeof(rect64), exact ? table.exact : table.conservative,
                                  lanes.indexed_fetching, lanes.indexed_far);
}

void report_settled(const std::vector<std::size_t>& settled, const collide_options& options) {
    if (options.slow_path_pairs != nullptr) {
        std::size_t total = 0;
        for (const std::size_t s : settled) {
            total += s;
        }
        *options.slow_path_pairs = total;
    }
}

/// method exact on one pair: the certified path, else the oracle; `settled`
/// counts the pairs the oracle answered.
template <class Item>
bool exact_counted(const Item& a, const Item& b, std::size_t& settled) {
    const ref::certified_verdict fast = ref::certify(a, b);
    if (fast.separated || fast.intersecting) {
        return fast.intersecting;
    }
    ++settled;
    return oracle::intersects(a, b);
}

/// verdicts over [0, count) of `decide(a, b, settled)`, split over threads; the
/// slow-path count goes to options.slow_path_pairs.
template <class Store, class Decide>
void decide_pairs(const Store& store, const pair_index* pairs, std::size_t count, std::uint8_t* verdicts,
                  const collide_options& options, const Decide& decide) {
    const std::size_t parts = detail::parts_for(count, options.threads, min_pairs_per_part);
    std::vector<std::size_t> settled(parts, 0);
    detail::run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = detail::share_of(count, part, parts);
        for (std::size_t i = begin; i < end; ++i) {
            verdicts[i] = decide(store[pairs[i].a], store[pairs[i].b], settled[part]) ? 1 : 0;
        }
    });
    report_settled(settled, options);
}

/// verdicts over [0, count) by `run_part(begin, end)` (returning the pairs
/// its slow path settled), split over threads.
template <class RunPart>
void run_parts_of(std::size_t count, const collide_options& options, const RunPart& run_part) {
    const std::size_t parts = detail::parts_for(count, options.threads, min_pairs_per_part);
    std::vector<std::size_t> settled(parts, 0);
    detail::run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = detail::share_of(count, part, parts);
        settled[part] = run_part(begin, end);
    });
    report_settled(settled, options);
}

/// verdicts over [0, count) by a backend's lanes over the records of `store`, split over threads.
template <class Kernel, class Store>
void run_lanes(Kernel kernel, const Store& store, const pair_index* pairs, std::size_t count,
               std::uint8_t* verdicts, const collide_options& options) {
    run_parts_of(count, options, [&](std::size_t begin, std::size_t end) {
        return kernel(store.data(), pairs + begin, end - begin, verdicts + begin);
    });
}

/// A stream of a_size pairs a[i], b[i] on double poses: the checks of the float
/// streams, then `run_part(lanes, begin, n)` over the parts of the batch, with
/// the backend's stream lanes for options.test, or nullptr for the scalar
/// references; returns the backend that ran.
template <class RunPart>
backend stream_of(std::size_t a_size, std::size_t b_size, const collide_options& options, const RunPart& run_part) {
    if (a_size != b_size) {
        throw invalid_input("stream batches differ in length: " + std::to_string(a_size) + " poses in A, " +
                            std::to_string(b_size) + " in B");
    }
    require_method_on_doubles(options, store_kind::poses);
    const backend ran = resolve_backend(options.use);  // unsupported_backend for one this CPU cannot run
    const detail::double_kernel_table* table = detail::double_kernels_for(ran);
    const detail::pose64_method_kernels* lanes = table != nullptr ? &pose_kernels_of(*table, options.test) : nullptr;
    run_parts_of(a_size, options,
                 [&](std::size_t begin, std::size_t end) { return run_part(lanes, begin, end - begin); });
    return table != nullptr ? ran : backend::scalar;
}

/// The verdicts of collide_stream over two stores of one kind, as a vector.
template <class Store>
std::vector<std::uint8_t> stream_verdicts_of(const Store& a, const Store& b, const collide_options& options) {
    std::vector<std::uint8_t> verdicts(a.size());
    collide_stream(a, b, verdicts.data(), options);
    return verdicts;
}

}  // namespace

backend collide_pairs(const pose_records64& poses, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options) {
    const backend ran = require_call(poses.size(), pairs, count, verdicts, options, store_kind::poses);
    if (const detail::double_kernel_table* table = detail::double_kernels_for(ran)) {
        run_lanes(pose_kernel_of(*table, options.test, poses.size()), poses, pairs, count, verdicts, options);
        return ran;
    }
    using pose64 = rect_pose64;
    switch (options.test) {
        case method::exact:
            decide_pairs(poses, pairs, count, verdicts, options,
                         [](const pose64& a, const pose64& b, std::size_t& settled) { return exact_counted(a, b, settled); });
            break;
        case method::conservative:
            decide_pairs(poses, pairs, count, verdicts, options,
                         [](const pose64& a, const pose64& b, std::size_t&) { return ref::conservative(a, b); });
            break;
        default:  // local: require_call admitted nothing else
            decide_pairs(poses, pairs, count, verdicts, options,
                         [](const pose64& a, const pose64& b, std::size_t&) { return ref::local(a, b); });
            break;
    }
    return backend::scalar;
}

std::vector<std::uint8_t> collide_pairs(const pose_records64& poses, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    std::vector<std::uint8_t> verdicts(pairs.size());
    collide_pairs(poses, pairs.data(), pairs.size(), verdicts.data(), options);
    return verdicts;
}

backend collide_stream(const pose_records64& a, const pose_records64& b, std::uint8_t* verdicts,
                       const collide_options& options) {
    constexpr std::size_t stride = pose_records64::record_doubles;
    const double* ra = a.data();
    const double* rb = b.data();
    return stream_of(a.size(), b.size(), options,
                     [&](const detail::pose64_method_kernels* lanes, std::size_t begin, std::size_t n) {
                         const double* pa = ra + stride * begin;
                         const double* pb = rb + stride * begin;
                         return lanes != nullptr ? lanes->stream(pa, pb, n, verdicts + begin)
                                                 : detail::scalar_pose64_stream(options.test, pa, pb, n, verdicts + begin);
                     });
}

std::vector<std::uint8_t> collide_stream(const pose_records64& a, const pose_records64& b, const collide_options& options) {
    return stream_verdicts_of(a, b, options);
}

backend collide_stream(const pose_soa64& a, const pose_soa64& b, std::uint8_t* verdicts,
                       const collide_options& options) {
    const detail::pose_soa64_view va = detail::view_of(a);
    const detail::pose_soa64_view vb = detail::view_of(b);
    return stream_of(a.size(), b.size(), options,
                     [&](const detail::pose64_method_kernels* lanes, std::size_t begin, std::size_t n) {
                         const detail::pose_soa64_view pa = detail::shifted(va, begin);
                         const detail::pose_soa64_view pb = detail::shifted(vb, begin);
                         return lanes != nullptr ? lanes->stream_soa(pa, pb, n, verdicts + begin)
                                                 : detail::scalar_pose64_stream_soa(options.test, pa, pb, n, verdicts + begin);
                     });
}

std::vector<std::uint8_t> collide_stream(const pose_soa64& a, const pose_soa64& b, const collide_options& options) {
    return stream_verdicts_of(a, b, options);
}

backend collide_pairs(const rect_records64& rects, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options) {
    const backend ran = require_call(rects.size(), pairs, count, verdicts, options, store_kind::corners);
    if (const detail::corner64_kernel_table* table = detail::corner64_kernels_for(ran)) {
        run_lanes(corner_kernel_of(*table, options.test, rects.size()), rects, pairs, count, verdicts, options);
        return ran;
    }
    if (options.test == method::exact) {
        decide_pairs(rects, pairs, count, verdicts, options,
                     [](const rect64& a, const rect64& b, std::size_t& settled) { return exact_counted(a, b, settled); });
    } else {  // conservative: require_call admitted nothing else
        decide_pairs(rects, pairs, count, verdicts, options,
                     [](const rect64& a, const rect64& b, std::size_t&) { return ref::conservative(a, b); });
    }
    return backend::scalar;
}

std::vector<std::uint8_t> collide_pairs(const rect_records64& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options) {
    std::vector<std::uint8_t> verdicts(pairs.size());
    collide_pairs(rects, pairs.data(), pairs.size(), verdicts.data(), options);
    return verdicts;
}

}  // namespace obbsat
