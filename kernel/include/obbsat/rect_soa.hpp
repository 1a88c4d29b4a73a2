// rect_soa: N rectangles as eight float arrays, one per corner coordinate
// (ulx, uly, urx, ury, lrx, lry, llx, lly), each 64-byte aligned and padded to
// a multiple of 16 entries, so a vector of any backend loads one coordinate of
// consecutive rectangles at once.
//
// Invariant: every stored coordinate is finite. Non-finite input is rejected
// when it is stored, with an error that names the rectangle and coordinate, so
// no kernel ever sees a NaN or an infinity in its input.
#pragma once

#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace obbsat {

/// The eight coordinate arrays of a rect_soa, in storage order.
enum class coord : unsigned { ulx, uly, urx, ury, lrx, lry, llx, lly };

/// The number of coordinate arrays.
inline constexpr unsigned coord_count = 8;

/// The name of a coordinate, e.g. "ury".
const char* coord_name(coord c);

class rect_soa {
public:
    /// Byte alignment of every coordinate array.
    static constexpr std::size_t alignment = 64;
    /// Arrays are padded (with zeros) to a multiple of this many entries.
    static constexpr std::size_t padding = 16;

    rect_soa() = default;
    /// Copies `count` rectangles; throws invalid_input on a non-finite coordinate.
    rect_soa(const rect* rects, std::size_t count);
    /// Copies the rectangles of `rects`; throws invalid_input on a non-finite coordinate.
    explicit rect_soa(const std::vector<rect>& rects);

    /// Copies `count` rectangles from eight coordinate arrays in coord order
    /// (ulx, uly, urx, ury, lrx, lry, llx, lly); throws invalid_input on a non-finite value.
    static rect_soa from_coordinate_arrays(const float* const arrays[coord_count], std::size_t count);

    /// Builds the corners of each pose (see corners_of); throws on non-finite results.
    static rect_soa from_poses(const pose* poses, std::size_t count);
    /// Builds the corners of each pose (see corners_of); throws on non-finite results.
    static rect_soa from_poses(const std::vector<pose>& poses);

    rect_soa(const rect_soa& other);
    rect_soa& operator=(const rect_soa& other);
    /// Moving leaves `other` empty (size and capacity 0), as std::vector does.
    rect_soa(rect_soa&& other) noexcept;
    rect_soa& operator=(rect_soa&& other) noexcept;
    ~rect_soa() = default;

    /// The number of rectangles.
    std::size_t size() const { return size_; }
    /// True iff there are no rectangles.
    bool empty() const { return size_ == 0; }
    /// The allocated entries per array, a multiple of `padding`.
    std::size_t capacity() const { return capacity_; }

    /// Makes room for `count` rectangles without reallocating on push_back.
    void reserve(std::size_t count);
    /// Appends one rectangle; throws invalid_input on a non-finite coordinate.
    void push_back(const rect& r);
    /// Replaces rectangle `index`; throws invalid_input on a bad index or non-finite coordinate.
    void set(std::size_t index, const rect& r);
    /// Removes every rectangle, keeping the storage.
    void clear();

    /// Rectangle `index` (unchecked beyond an assertion-free bounds contract: index < size()).
    rect operator[](std::size_t index) const;
    /// Rectangle `index`; throws invalid_input when index >= size().
    rect at(std::size_t index) const;

    /// The array of one coordinate: size() values, then zero padding up to capacity().
    const float* data(coord c) const {
        return storage_.get() + static_cast<std::size_t>(c) * capacity_;
    }

private:
    struct aligned_free {
        void operator()(float* p) const;
    };

    float* mutable_data(coord c) {
        return storage_.get() + static_cast<std::size_t>(c) * capacity_;
    }
    void grow_to(std::size_t min_capacity);
    void store(std::size_t index, const rect& r);

    std::unique_ptr<float[], aligned_free> storage_;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
};

}  // namespace obbsat
