#include "store/finite_check.hpp"

#include <obbsat/error.hpp>
#include <obbsat/rect_soa.hpp>

#include <cmath>
#include <cstring>
#include <new>
#include <string>

namespace obbsat {

namespace {

constexpr const char* coord_names[coord_count] = {"ulx", "uly", "urx", "ury",
                                                  "lrx", "lry", "llx", "lly"};

void flatten(const rect& r, float out[coord_count]) {
    const point corners[4] = {r.ul, r.ur, r.lr, r.ll};
    for (unsigned k = 0; k < 4; ++k) {
        out[2 * k] = corners[k].x;
        out[2 * k + 1] = corners[k].y;
    }
}

std::size_t round_up(std::size_t n, std::size_t multiple) {
    return (n + multiple - 1) / multiple * multiple;
}

}  // namespace

const char* coord_name(coord c) { return coord_names[static_cast<unsigned>(c)]; }

void rect_soa::aligned_free::operator()(float* p) const {
    ::operator delete[](p, std::align_val_t{alignment});
}

rect_soa::rect_soa(const rect* rects, std::size_t count) {
    reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        push_back(rects[i]);
    }
}

rect_soa::rect_soa(const std::vector<rect>& rects) : rect_soa(rects.data(), rects.size()) {}

rect_soa rect_soa::from_coordinate_arrays(const float* const arrays[coord_count], std::size_t count) {
    rect_soa out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        out.push_back(rect{{arrays[0][i], arrays[1][i]},
                           {arrays[2][i], arrays[3][i]},
                           {arrays[4][i], arrays[5][i]},
                           {arrays[6][i], arrays[7][i]}});
    }
    return out;
}

rect_soa rect_soa::from_poses(const pose* poses, std::size_t count) {
    rect_soa out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        out.push_back(corners_of(poses[i]));
    }
    return out;
}

rect_soa rect_soa::from_poses(const std::vector<pose>& poses) {
    return from_poses(poses.data(), poses.size());
}

rect_soa::rect_soa(const rect_soa& other) {
    reserve(other.size_);
    for (unsigned c = 0; c < coord_count; ++c) {
        if (other.size_ != 0) {
            std::memcpy(mutable_data(coord(c)), other.data(coord(c)), other.size_ * sizeof(float));
        }
    }
    size_ = other.size_;
}

rect_soa& rect_soa::operator=(const rect_soa& other) {
    if (this != &other) {
        rect_soa copy(other);
        *this = std::move(copy);
    }
    return *this;
}

rect_soa::rect_soa(rect_soa&& other) noexcept
    : storage_(std::move(other.storage_)), size_(other.size_), capacity_(other.capacity_) {
    other.size_ = 0;
    other.capacity_ = 0;
}

rect_soa& rect_soa::operator=(rect_soa&& other) noexcept {
    storage_ = std::move(other.storage_);
    size_ = other.size_;
    capacity_ = other.capacity_;
    other.size_ = 0;
    other.capacity_ = 0;
    return *this;
}

void rect_soa::reserve(std::size_t count) {
    if (count > capacity_) {
        grow_to(count);
    }
}

void rect_soa::grow_to(std::size_t min_capacity) {
    const std::size_t capacity = round_up(min_capacity, padding);
    const std::size_t total = capacity * coord_count;
    float* raw = static_cast<float*>(
        ::operator new[](total * sizeof(float), std::align_val_t{alignment}));
    std::unique_ptr<float[], aligned_free> fresh(raw);
    std::memset(raw, 0, total * sizeof(float));
    for (unsigned c = 0; c < coord_count; ++c) {
        if (size_ != 0) {
            std::memcpy(raw + c * capacity, data(coord(c)), size_ * sizeof(float));
        }
    }
    storage_ = std::move(fresh);
    capacity_ = capacity;
}

void rect_soa::push_back(const rect& r) {
    if (size_ == capacity_) {
        grow_to(capacity_ < padding ? padding : capacity_ * 2);
    }
    store(size_, r);
    ++size_;
}

void rect_soa::set(std::size_t index, const rect& r) {
    detail::require_index(index, size_);
    store(index, r);
}

void rect_soa::store(std::size_t index, const rect& r) {
    detail::require_finite(r, index);
    float values[coord_count];
    flatten(r, values);
    for (unsigned c = 0; c < coord_count; ++c) {
        mutable_data(coord(c))[index] = values[c];
    }
}

void rect_soa::clear() {
    for (unsigned c = 0; c < coord_count && storage_; ++c) {
        std::memset(mutable_data(coord(c)), 0, size_ * sizeof(float));
    }
    size_ = 0;
}

rect rect_soa::operator[](std::size_t i) const {
    auto at_coord = [&](coord c) { return data(c)[i]; };
    return rect{{at_coord(coord::ulx), at_coord(coord::uly)},
                {at_coord(coord::urx), at_coord(coord::ury)},
                {at_coord(coord::lrx), at_coord(coord::lry)},
                {at_coord(coord::llx), at_coord(coord::lly)}};
}

rect rect_soa::at(std::size_t index) const {
    detail::require_index(index, size_);
    return (*this)[index];
}

}  // namespace obbsat
