#include "thread_pool.hpp"

namespace obbsat::detail {

thread_pool& thread_pool::shared() {
    static thread_pool pool;
    return pool;
}

thread_pool::~thread_pool() {
    {
        std::lock_guard<std::mutex> lock(state_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) {
        w.join();
    }
}

void thread_pool::grow_to(std::size_t workers) {
    while (workers_.size() < workers) {
        const std::size_t part = workers_.size() + 1;  // part 0 is the caller's
        workers_.emplace_back([this, part] { worker_loop(part); });
    }
}

void thread_pool::worker_loop(std::size_t part) {
    std::uint64_t seen = 0;
    for (;;) {
        const std::function<void(std::size_t)>* task = nullptr;
        {
            std::unique_lock<std::mutex> lock(state_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) {
                return;
            }
            seen = generation_;
            if (part >= parts_) {
                continue;
            }
            task = task_;
        }
        (*task)(part);
        {
            std::lock_guard<std::mutex> lock(state_);
            if (--unfinished_ == 0) {
                finished_.notify_one();
            }
        }
    }
}

void thread_pool::run(std::size_t parts, const std::function<void(std::size_t)>& task) {
    std::unique_lock<std::mutex> owner(batch_owner_, std::try_to_lock);
    if (parts <= 1 || !owner.owns_lock()) {
        for (std::size_t p = 0; p < parts; ++p) {
            task(p);
        }
        return;
    }
    {
        std::lock_guard<std::mutex> lock(state_);
        grow_to(parts - 1);
        task_ = &task;
        parts_ = parts;
        unfinished_ = parts - 1;
        ++generation_;
    }
    wake_.notify_all();
    task(0);
    std::unique_lock<std::mutex> lock(state_);
    finished_.wait(lock, [&] { return unfinished_ == 0; });
    task_ = nullptr;
    parts_ = 0;
}

}  // namespace obbsat::detail
