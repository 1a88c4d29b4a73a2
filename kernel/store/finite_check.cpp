#include "store/finite_check.hpp"

#include <obbsat/error.hpp>
#include <obbsat/rect_soa.hpp>

#include <cmath>
#include <string>

namespace obbsat::detail {

void require_finite(const rect& r, std::size_t index) {
    const float values[coord_count] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y,
                                       r.lr.x, r.lr.y, r.ll.x, r.ll.y};
    for (unsigned c = 0; c < coord_count; ++c) {
        if (!std::isfinite(values[c])) {
            throw invalid_input("rectangle " + std::to_string(index) + ": coordinate " +
                                coord_name(coord(c)) + " is not finite");
        }
    }
}

void require_index(std::size_t index, std::size_t size) {
    if (index >= size) {
        throw invalid_input("rectangle " + std::to_string(index) + " is out of range (size " +
                            std::to_string(size) + ")");
    }
}

}  // namespace obbsat::detail
