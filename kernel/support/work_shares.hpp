// Shares of work over threads: how many parts a job of n items is worth,
// which items part k of them takes, and running them. Each caller passes its
// own smallest part, the number of items below which waking another core
// costs more than it saves. Internal to the library.
//
// Work units taken as they come: a step whose work splits finely cuts it into
// a few units per thread (units_for), and each thread takes the next unit
// from a shared counter until none is left (run_units), so a thread on a busy
// core takes fewer units instead of making the others wait for its share.
// What a unit produces is kept per unit and combined in unit order, never per
// thread, so that no answer depends on which thread took which unit. The
// units run on the thread pool (thread_pool.hpp), or on the caller's executor
// when one is in scope (executor_scope.hpp). Steps too small to pay for more
// units than threads keep one unit per thread (run_parts).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
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

/// Units a thread's work is cut into where units are taken as they come:
/// enough that a thread slowed by other work on its core hands most of its
/// share to the others, few enough that each unit's setup stays negligible.
/// A step ends when its last unit does, so the others wait up to a unit for
/// it: at eight a thread the sweep of 1M boxes left the caller waiting 1.1 to
/// 1.5 ms at its end (timed on a loaded machine), about 4% of a query on two
/// threads; sixteen halve the unit, and so the expected wait.
constexpr std::size_t units_per_thread = 16;

/// Units for `items` items over `threads` threads (parts_for's count):
/// units_per_thread per thread, but none smaller than `min_per_unit` items,
/// and never fewer than `threads` (each then one share, as run_parts takes
/// them); one for one thread, where more would cost without saving.
inline std::size_t units_for(std::size_t items, std::size_t threads, std::size_t min_per_unit) {
    if (threads <= 1) {
        return 1;
    }
    return std::max(threads, std::min(threads * units_per_thread, items / min_per_unit));
}

/// Runs task(0) .. task(units - 1), each once, on at most `threads` threads
/// at a time that take the next unit as they come free: the thread pool's,
/// or the units go to the executor in scope (executor_scope.hpp), which may
/// run them anywhere. Returns when all have ended. An exception thrown by a
/// unit is thrown again here once the units running have ended (the one of
/// the lowest unit if several throw); units not yet started are then skipped.
/// Throws invalid_input when an executor did not run every unit exactly once.
void run_unit_list(std::size_t units, std::size_t threads, const std::function<void(std::size_t)>& task);

template <class Task>
void run_units(std::size_t units, std::size_t threads, const Task& task) {
    if (units <= 1) {
        if (units == 1) {
            task(std::size_t{0});
        }
        return;
    }
    run_unit_list(units, threads, [&](std::size_t unit) { task(unit); });
}

/// Runs task(0) .. task(parts - 1), one part a thread: run_units with as many
/// units as threads.
template <class Task>
void run_parts(std::size_t parts, const Task& task) {
    run_units(std::max<std::size_t>(parts, 1), parts, task);
}

}  // namespace obbsat::detail
