// rect_records: N rectangles as packed 32-byte records (one obbsat::rect each:
// ulx, uly, urx, ury, lrx, lry, llx, lly), 64-byte aligned, so that fetching a
// rectangle at random touches one cache line, not eight.
//
// This is the store for indexed queries (a pair list over a scene): the
// kernels load each lane's record whole and transpose the records into
// structure-of-arrays lanes in registers. rect_soa suits streaming batches.
//
// Invariant: every stored coordinate is finite (checked when stored, with an
// error naming the rectangle and the coordinate).
#pragma once

#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstddef>
#include <new>
#include <vector>

namespace obbsat {

/// Memory for rectangle records: 64-byte aligned; a large block is aligned to
/// 2 MiB and asks the OS for transparent huge pages, since random access to a
/// scene of millions of rectangles otherwise misses the TLB on nearly every pair.
void* allocate_record_memory(std::size_t bytes);
/// Releases a block of allocate_record_memory of the same size.
void release_record_memory(void* block, std::size_t bytes) noexcept;

/// A std::allocator for record storage (see allocate_record_memory).
template <class T>
struct cache_line_allocator {
    using value_type = T;

    cache_line_allocator() = default;
    template <class U>
    cache_line_allocator(const cache_line_allocator<U>&) noexcept {}

    T* allocate(std::size_t n) { return static_cast<T*>(allocate_record_memory(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { release_record_memory(p, n * sizeof(T)); }

    template <class U>
    bool operator==(const cache_line_allocator<U>&) const noexcept { return true; }
    template <class U>
    bool operator!=(const cache_line_allocator<U>&) const noexcept { return false; }
};

class rect_records {
public:
    rect_records() = default;
    /// Copies `count` rectangles; throws invalid_input on a non-finite coordinate.
    rect_records(const rect* rects, std::size_t count);
    /// Copies the rectangles of `rects`; throws invalid_input on a non-finite coordinate.
    explicit rect_records(const std::vector<rect>& rects);
    /// Copies the rectangles of a structure-of-arrays store (already finite).
    explicit rect_records(const rect_soa& rects);

    /// Builds the corners of each pose (see corners_of); throws on non-finite results.
    static rect_records from_poses(const pose* poses, std::size_t count);
    /// Builds the corners of each pose (see corners_of); throws on non-finite results.
    static rect_records from_poses(const std::vector<pose>& poses);

    /// The number of rectangles.
    std::size_t size() const { return records_.size(); }
    /// True iff there are no rectangles.
    bool empty() const { return records_.empty(); }
    /// Makes room for `count` rectangles.
    void reserve(std::size_t count) { records_.reserve(count); }
    /// Appends one rectangle; throws invalid_input on a non-finite coordinate.
    void push_back(const rect& r);
    /// Replaces rectangle `index`; throws invalid_input on a bad index or non-finite coordinate.
    void set(std::size_t index, const rect& r);
    /// Removes every rectangle.
    void clear() { records_.clear(); }

    /// Rectangle `index`, unchecked: index < size().
    const rect& operator[](std::size_t index) const { return records_[index]; }
    /// Rectangle `index`; throws invalid_input when index >= size().
    const rect& at(std::size_t index) const;
    /// The records, size() of them, the first on a 64-byte boundary.
    const rect* data() const { return records_.data(); }

private:
    std::vector<rect, cache_line_allocator<rect>> records_;
};

}  // namespace obbsat
