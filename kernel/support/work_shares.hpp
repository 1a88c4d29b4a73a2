// Shares of work over the thread pool (thread_pool.hpp): how many parts a
// job of n items is worth, which items part k of them takes, and running the
// parts. Each caller passes its own smallest part, the number of items below
// which waking another core costs more than it saves. Internal to the library.
#pragma once

#include "support/thread_pool.hpp"

#include <algorithm>
#include <cstddef>
#include <thread>
#include <utility>

namespace obbsat::detail {

/// Parts for `items` items: `threads` of them (0: one per hardware thread),
/// but no more than one per `min_per_part` items, and at least one.
inline std::size_t parts_for(std::size_t items, unsigned threads, std::size_t min_per_part) {
    std::size_t wanted = threads;
    if (wanted == 0) {
        wanted = std::max(1u, std::thread::hardware_concurrency());
    }
    return std::max<std::size_t>(1, std::min(wanted, items / min_per_part));
}

/// [begin, end) of part `part` of `parts` over n items: n * part / parts to
/// n * (part + 1) / parts, so the parts differ by at most one item.
inline std::pair<std::size_t, std::size_t> share_of(std::size_t n, std::size_t part, std::size_t parts) {
    return {n * part / parts, n * (part + 1) / parts};
}

/// The same with every boundary but n rounded down to a multiple of
/// `alignment` (a power of two): with 64, the parts write disjoint words of a
/// bit set; with a vector's width, every part but the last fills whole vectors.
inline std::pair<std::size_t, std::size_t> aligned_share_of(std::size_t n, std::size_t part, std::size_t parts,
                                                            std::size_t alignment) {
    const auto boundary = [&](std::size_t k) { return k == parts ? n : (n * k / parts) & ~(alignment - 1); };
    return {boundary(part), boundary(part + 1)};
}

/// Runs task(0) .. task(parts - 1): on the calling thread alone when there is
/// one part, else on the shared pool (see thread_pool::run; `task` must not throw).
template <class Task>
void run_parts(std::size_t parts, const Task& task) {
    if (parts <= 1) {
        task(std::size_t{0});
        return;
    }
    thread_pool::shared().run(parts, [&](std::size_t part) { task(part); });
}

}  // namespace obbsat::detail
