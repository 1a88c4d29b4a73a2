// A borrowed view of rectangles in structure-of-arrays form: what a kernel reads.
// Plain data, with its helpers of internal linkage: the per-ISA kernels read
// it too (kernel/lanes/README.md).
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstddef>

namespace obbsat::detail {

struct soa_view {
    const float* coords[coord_count];  // ulx, uly, urx, ury, lrx, lry, llx, lly
    std::size_t size;
};

namespace {

/// The rectangle at `i` of `v`, assembled from the eight arrays.
inline rect rect_at(const soa_view& v, std::size_t i) {
    return rect{{v.coords[0][i], v.coords[1][i]},
                {v.coords[2][i], v.coords[3][i]},
                {v.coords[4][i], v.coords[5][i]},
                {v.coords[6][i], v.coords[7][i]}};
}

/// The arrays of `v` starting `offset` rectangles later.
inline soa_view shifted(const soa_view& v, std::size_t offset) {
    soa_view out = v;
    for (auto& c : out.coords) {
        c += offset;
    }
    out.size = v.size - offset;
    return out;
}

inline soa_view view_of(const rect_soa& rects) {
    soa_view v{};
    for (unsigned c = 0; c < coord_count; ++c) {
        v.coords[c] = rects.data(coord(c));
    }
    v.size = rects.size();
    return v;
}

}  // namespace
}  // namespace obbsat::detail
