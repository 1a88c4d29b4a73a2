// A borrowed view of rectangles in structure-of-arrays form: what a kernel reads.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstddef>

namespace obbsat::detail {

struct soa_view {
    const float* coords[coord_count];  // ulx, uly, urx, ury, lrx, lry, llx, lly
    std::size_t size;

    /// The rectangle at `i`, assembled from the eight arrays.
    rect at(std::size_t i) const {
        return rect{{coords[0][i], coords[1][i]},
                    {coords[2][i], coords[3][i]},
                    {coords[4][i], coords[5][i]},
                    {coords[6][i], coords[7][i]}};
    }

    /// The same arrays starting `offset` rectangles later.
    soa_view shifted(std::size_t offset) const {
        soa_view out = *this;
        for (auto& c : out.coords) {
            c += offset;
        }
        out.size = size - offset;
        return out;
    }
};

inline soa_view view_of(const rect_soa& rects) {
    soa_view v{};
    for (unsigned c = 0; c < coord_count; ++c) {
        v.coords[c] = rects.data(coord(c));
    }
    v.size = rects.size();
    return v;
}

}  // namespace obbsat::detail
