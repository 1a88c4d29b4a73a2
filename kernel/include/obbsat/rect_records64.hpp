// rect_records64: N rectangles by their four double corners (obbsat/rect64.hpp),
// one 64-byte record each (ulx, uly, urx, ury, lrx, lry, llx, lly), 64-byte
// aligned: one rectangle per cache line.
//
// The corner store for coordinates float32 would round (see
// obbsat/pose_records64.hpp). Every double is kept exactly as given.
//
// Invariant: every stored coordinate is finite (checked when stored, with an
// error naming the rectangle and the coordinate).
#pragma once

#include <obbsat/rect64.hpp>
#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <vector>

namespace obbsat {

class rect_records64 {
public:
    rect_records64() = default;
    /// Copies `count` rectangles; throws invalid_input naming the first non-finite coordinate.
    rect_records64(const rect64* rects, std::size_t count);
    /// Copies the rectangles of `rects`; throws invalid_input naming the first non-finite coordinate.
    explicit rect_records64(const std::vector<rect64>& rects);

    /// The number of rectangles.
    std::size_t size() const { return records_.size(); }
    /// True iff there are no rectangles.
    bool empty() const { return records_.empty(); }
    /// Makes room for `count` rectangles.
    void reserve(std::size_t count) { records_.reserve(count); }
    /// Appends one rectangle; throws invalid_input on a non-finite coordinate.
    void push_back(const rect64& r);
    /// Replaces rectangle `index`; throws invalid_input on a bad index or a non-finite coordinate.
    void set(std::size_t index, const rect64& r);
    /// Removes every rectangle.
    void clear() { records_.clear(); }

    /// Rectangle `index`, unchecked: index < size().
    const rect64& operator[](std::size_t index) const { return records_[index]; }
    /// Rectangle `index`; throws invalid_input when index >= size().
    const rect64& at(std::size_t index) const;
    /// The records, size() of them, the first on a 64-byte boundary.
    const rect64* data() const { return records_.data(); }

private:
    static_assert(sizeof(rect64) == 64, "a double corner record is one cache line");
    std::vector<rect64, cache_line_allocator<rect64>> records_;
};

/// Throws invalid_input naming rectangle `index` and the first non-finite
/// coordinate of `r`, e.g. "rectangle 3: coordinate urx is nan, not a finite number".
void require_finite(const rect64& r, std::size_t index);

}  // namespace obbsat
