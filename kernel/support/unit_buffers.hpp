// Buffers the units of a step borrow while they run, kept by the caller
// between steps. A unit taken by whichever thread comes free (work_shares.hpp)
// may need working memory of its own, such as the two small buffers a bucket
// of a sort on several threads is sorted in: allocated in each unit, that is
// a hundred or more blocks of about 100 KiB for every sort of a million keys
// on two threads, each from the allocator of the thread that took the unit,
// and fresh pages whenever the allocator gave them back to the OS between
// two queries. Here a unit takes the first buffer of the set no other unit
// holds, grows it if it is too short, and gives it back when it ends. The set
// holds a buffer per unit that ran at the same time as others (the step's
// threads), each as long as the longest unit it served needed: bounded by
// what the largest step needed, released with the set. A unit that finds
// every buffer held (an executor running more units at once than the step
// has threads) works in memory of its own, as without the set.
// Internal to the library.
#pragma once

#include "support/scratch_vector.hpp"

#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

namespace obbsat::detail {

template <class T>
class unit_buffers {
    struct slot {
        std::atomic<bool> held{false};
        scratch_vector<T> items;
    };

public:
    /// A buffer of at least `count` elements, this unit's until the lease ends; its contents are unwritten.
    class lease {
    public:
        lease(unit_buffers* from, std::size_t count) {
            if (from != nullptr) {
                for (const std::unique_ptr<slot>& each : from->slots_) {
                    if (!each->held.load(std::memory_order_relaxed) &&
                        !each->held.exchange(true, std::memory_order_acquire)) {
                        slot_ = each.get();
                        break;
                    }
                }
            }
            scratch_vector<T>& items = slot_ != nullptr ? slot_->items : own_;
            if (items.size() < count) {
                items.resize(count);
            }
            data_ = items.data();
        }
        ~lease() {
            if (slot_ != nullptr) {
                slot_->held.store(false, std::memory_order_release);
            }
        }
        lease(const lease&) = delete;
        lease& operator=(const lease&) = delete;

        T* data() const { return data_; }

    private:
        slot* slot_ = nullptr;
        scratch_vector<T> own_;  ///< when every buffer of the set is held
        T* data_ = nullptr;
    };

    /// Room for `units` units at once (the threads of the step about to
    /// run); call it before the step, never while its units run.
    void reserve_units(std::size_t units) {
        while (slots_.size() < units) {
            slots_.push_back(std::make_unique<slot>());
        }
    }

    /// Bytes the buffers hold.
    std::size_t bytes() const {
        std::size_t sum = 0;
        for (const std::unique_ptr<slot>& each : slots_) {
            sum += each->items.capacity() * sizeof(T);
        }
        return sum;
    }

    /// Buffers in the set.
    std::size_t buffers() const { return slots_.size(); }

    void swap(unit_buffers& other) noexcept { slots_.swap(other.slots_); }

private:
    std::vector<std::unique_ptr<slot>> slots_;  ///< each on its own: a held flag never moves
};

}  // namespace obbsat::detail
