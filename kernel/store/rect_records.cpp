#include "store/finite_check.hpp"
#include "support/huge_pages.hpp"

#include <obbsat/rect_records.hpp>

namespace obbsat {

namespace {

std::size_t alignment_for(std::size_t bytes) {
    return bytes >= detail::huge_page_threshold ? detail::huge_page_bytes : 64;
}

}  // namespace

void* allocate_record_memory(std::size_t bytes) {
    const std::size_t alignment = alignment_for(bytes);
    void* block = ::operator new(bytes, std::align_val_t{alignment});
    detail::advise_huge_pages(block, bytes);
    return block;
}

void release_record_memory(void* block, std::size_t bytes) noexcept {
    ::operator delete(block, std::align_val_t{alignment_for(bytes)});
}

rect_records::rect_records(const rect* rects, std::size_t count) {
    records_.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        push_back(rects[i]);
    }
}

rect_records::rect_records(const std::vector<rect>& rects) : rect_records(rects.data(), rects.size()) {}

rect_records::rect_records(const rect_soa& rects) {
    records_.reserve(rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        records_.push_back(rects[i]);
    }
}

rect_records rect_records::from_poses(const pose* poses, std::size_t count) {
    rect_records out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        out.push_back(corners_of(poses[i]));
    }
    return out;
}

rect_records rect_records::from_poses(const std::vector<pose>& poses) {
    return from_poses(poses.data(), poses.size());
}

void rect_records::push_back(const rect& r) {
    detail::require_finite(r, records_.size());
    records_.push_back(r);
}

void rect_records::set(std::size_t index, const rect& r) {
    detail::require_index(index, records_.size());
    detail::require_finite(r, index);
    records_[index] = r;
}

const rect& rect_records::at(std::size_t index) const {
    detail::require_index(index, records_.size());
    return records_[index];
}

}  // namespace obbsat
