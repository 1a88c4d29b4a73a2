// An engine's own job system running obbsat's parallel work, in place of the
// library's thread pool (the shape of Box2D v3's enqueueTask / finishTask).
//
// A call given an executor (collide_options::executor) starts no thread of
// its own: each parallel step of the call is cut into work units, handed to
// `enqueue` as one task over the items [0, count), and waited for with
// `finish`. `collide_options::threads` then says how many units a step is cut
// into (about the number of the engine's workers; 0: one per hardware thread),
// not how many threads run them. The answer never depends on the executor:
// which thread runs which range, in which order, or at once.
#pragma once

#include <cstddef>

namespace obbsat {

/// The work obbsat hands to an executor: runs items [begin, end) of the task
/// whose context is `task_context`. It never throws: an error inside an item
/// is kept and thrown again on the thread that called obbsat, after `finish`.
using executor_task = void (*)(std::size_t begin, std::size_t end, void* task_context);

/// A job system that runs obbsat's work units. Both functions are called
/// only from the thread that called obbsat, one task at a time.
struct executor {
    /// Runs task(begin, end, task_context) over ranges that together cover
    /// [0, count) exactly once, each range at least `min_range` items long
    /// where count allows, possibly in parallel and on any threads, and
    /// returns a handle for `finish`. It may also run them all before it
    /// returns and return nullptr, and `finish` is then not called. A range
    /// outside [0, count), or items left out or run twice, make the obbsat
    /// call throw invalid_input after `finish`.
    void* (*enqueue)(executor_task task, std::size_t count, std::size_t min_range, void* task_context,
                     void* user_context) = nullptr;
    /// Returns once every range of the task behind `handle` has returned.
    void (*finish)(void* handle, void* user_context) = nullptr;
    /// Passed to both functions as is.
    void* user_context = nullptr;
};

}  // namespace obbsat
