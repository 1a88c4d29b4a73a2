// The caller's executor (obbsat/executor.hpp) for the duration of one call
// into the library: every step of the call that runs work units (run_units in
// work_shares.hpp) hands them to it instead of the thread pool, including
// steps several layers down that never see collide_options. Internal to the
// library.
#pragma once

#include <obbsat/executor.hpp>

namespace obbsat::detail {

/// Sets the executor for work started on this thread until it goes out of
/// scope (nullptr: the thread pool), then puts back the one it replaced.
class executor_scope {
public:
    explicit executor_scope(const executor* given);
    ~executor_scope();
    executor_scope(const executor_scope&) = delete;
    executor_scope& operator=(const executor_scope&) = delete;

    /// The executor in scope on this thread, or nullptr.
    static const executor* current();

private:
    const executor* replaced_;
};

}  // namespace obbsat::detail
