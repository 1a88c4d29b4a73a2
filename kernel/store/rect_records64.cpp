#include "store/finite_check.hpp"

#include <obbsat/error.hpp>
#include <obbsat/rect_records64.hpp>
#include <obbsat/rect_soa.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace obbsat {

namespace {

std::string shown(double value) {
    std::ostringstream out;
    out.precision(17);
    out << value;
    return out.str();
}

}  // namespace

void require_finite(const rect64& r, std::size_t index) {
    const double values[coord_count] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
    for (unsigned c = 0; c < coord_count; ++c) {
        if (!std::isfinite(values[c])) {
            throw invalid_input("rectangle " + std::to_string(index) + ": coordinate " + coord_name(coord(c)) +
                                " is " + shown(values[c]) + ", not a finite number");
        }
    }
}

rect_records64::rect_records64(const rect64* rects, std::size_t count) {
    // Checked before anything is copied: a bad batch leaves nothing half-stored.
    for (std::size_t i = 0; i < count; ++i) {
        require_finite(rects[i], i);
    }
    records_.assign(rects, rects + count);
}

rect_records64::rect_records64(const std::vector<rect64>& rects) : rect_records64(rects.data(), rects.size()) {}

void rect_records64::push_back(const rect64& r) {
    require_finite(r, records_.size());
    records_.push_back(r);
}

void rect_records64::set(std::size_t index, const rect64& r) {
    detail::require_index(index, records_.size());
    require_finite(r, index);
    records_[index] = r;
}

const rect64& rect_records64::at(std::size_t index) const {
    detail::require_index(index, records_.size());
    return records_[index];
}

}  // namespace obbsat
