// The one-shot scene queries' working memory kept between calls (spare_search.hpp).
#include "scene/spare_search.hpp"

#include <memory>
#include <new>
#include <mutex>
#include <utility>

namespace obbsat::detail {

namespace {

std::mutex& spare_mutex() {
    static std::mutex m;
    return m;
}

/// The memory left by the last query, in a query that runs nothing; nullptr when none is left.
std::unique_ptr<pair_search>& spare() {
    static std::unique_ptr<pair_search> kept;
    return kept;
}

}  // namespace

spare_search::spare_search(const collide_options& options) : search_(options) {
    search_.keep_working_memory_up_to(spare_search_limit);
    std::unique_ptr<pair_search> taken;
    {
        const std::lock_guard<std::mutex> lock(spare_mutex());
        taken = std::move(spare());
    }
    if (taken) {
        search_.swap_working_memory(*taken);
    }
    // `taken` now holds this query's empty buffers, and goes.
}

spare_search::~spare_search() {
    if (search_.working_bytes() > spare_search_limit) {
        return;
    }
    try {
        // Made outside the lock; dropped at the end if another query left its memory first.
        auto left = std::make_unique<pair_search>(search_.options());
        left->swap_working_memory(search_);
        const std::lock_guard<std::mutex> lock(spare_mutex());
        if (!spare()) {
            spare() = std::move(left);
        }
    } catch (const std::bad_alloc&) {
        // No room for the holder: the memory goes with the query, as it would without a spare.
    }
}

std::size_t spare_search_bytes() {
    const std::lock_guard<std::mutex> lock(spare_mutex());
    return spare() ? spare()->working_bytes() : 0;
}

void release_spare_search() {
    std::unique_ptr<pair_search> released;
    {
        const std::lock_guard<std::mutex> lock(spare_mutex());
        released = std::move(spare());
    }
}

}  // namespace obbsat::detail
