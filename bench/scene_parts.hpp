// How the grid and R-tree peers use a second core: as an application
// without a thread pool would, the boxes (or grid rows) are cut into one
// contiguous part per thread, each part's broadphase and narrowphase run on
// its own std::thread started for the query, and the parts' pairs are joined
// at the end. Starting a thread costs some tens of microseconds, small beside
// a query over 10^4 boxes or more.
#pragma once

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace obbsat_bench {

/// [begin, end) of part `part` of `parts` over `count` items, in order.
struct part_range {
    std::size_t begin;
    std::size_t end;
};

inline part_range part_of(std::size_t count, unsigned parts, unsigned part) {
    return {count * part / parts, count * (part + 1u) / parts};
}

/// Calls run(part) for every part < parts: part 0 on the calling thread, the
/// others each on a thread of its own; rethrows the first part's exception.
template <class Run>
void run_parts(unsigned parts, const Run& run) {
    std::vector<std::exception_ptr> failed(parts);
    const auto guarded = [&run, &failed](unsigned part) {
        try {
            run(part);
        } catch (...) {
            failed[part] = std::current_exception();
        }
    };
    std::vector<std::thread> helpers;
    for (unsigned part = 1; part < parts; ++part) {
        helpers.emplace_back(guarded, part);
    }
    guarded(0u);
    for (std::thread& t : helpers) {
        t.join();
    }
    for (const std::exception_ptr& e : failed) {
        if (e) {
            std::rethrow_exception(e);
        }
    }
}

}  // namespace obbsat_bench
