// A persistent pool of worker threads, so that splitting a batch over cores
// costs a wake-up, not a thread start.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace obbsat::detail {

class thread_pool {
public:
    /// The process-wide pool; workers start on first use and live until exit.
    static thread_pool& shared();

    /// Runs task(0) .. task(parts - 1) and returns when all have finished. The
    /// calling thread runs part 0. If another batch holds the pool, the parts
    /// run one after another on the calling thread. `task` must not throw.
    void run(std::size_t parts, const std::function<void(std::size_t)>& task);

    ~thread_pool();

private:
    thread_pool() = default;
    void grow_to(std::size_t workers);
    void worker_loop(std::size_t part);

    std::mutex batch_owner_;  // held by the one batch using the workers
    std::mutex state_;
    std::condition_variable wake_;
    std::condition_variable finished_;
    std::vector<std::thread> workers_;
    const std::function<void(std::size_t)>* task_ = nullptr;
    std::size_t parts_ = 0;
    std::size_t unfinished_ = 0;
    std::uint64_t generation_ = 0;
    bool stopping_ = false;
};

}  // namespace obbsat::detail
