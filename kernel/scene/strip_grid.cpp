#include "scene/strip_grid.hpp"

#include "support/bit_width.hpp"

#include <algorithm>
#include <cmath>

namespace obbsat::detail {

namespace {

constexpr unsigned max_strip_bits = 20;

}  // namespace

strip_grid grid_for(const bounds_extent& extent, std::size_t boxes, double strip_factor) {
    strip_grid grid;
    const double width = extent.x_high - extent.x_low;
    const double height = extent.y_high - extent.y_low;
    grid.x_low = extent.x_low - width / 16;
    grid.x_high = extent.x_high + width / 16;
    grid.y_low = extent.y_low - height / 16;
    grid.y_high = extent.y_high + height / 16;
    grid.height_basis = extent.mean_height;

    const double span = grid.y_high - grid.y_low;
    const double most = static_cast<double>(std::min<std::size_t>(std::size_t{1} << max_strip_bits,
                                                                  std::max<std::size_t>(1, boxes)));
    double strip_height = strip_factor * extent.mean_height;
    if (!(strip_height > 0) || !(span / strip_height < most)) {
        strip_height = span / most;
    }
    double strips = span > 0 && strip_height > 0 ? std::floor(span / strip_height) + 1 : 1;
    strips = std::min(std::max(strips, 1.0), most);
    grid.strips = static_cast<std::uint32_t>(strips);
    grid.y_scale = span > 0 ? static_cast<double>(grid.strips) / span : 1;
    grid.strip_bits = bits_for(grid.strips - 1);
    // Enough x resolution for the sweep (a scene's width in 2^15 steps is far
    // finer than its rectangles), few enough bits that a key sorts in three
    // passes of eight bits.
    grid.q_bits = std::min(16u, std::max(8u, 24u - std::min(24u, grid.strip_bits)));
    grid.q_max = (std::uint32_t{1} << grid.q_bits) - 1;
    const double x_span = grid.x_high - grid.x_low;
    grid.x_scale = x_span > 0 ? static_cast<double>(grid.q_max) / x_span : 0;
    return grid;
}

bool grid_still_fits(const strip_grid& grid, const bounds_extent& extent) {
    return extent.x_low >= grid.x_low && extent.x_high <= grid.x_high && extent.y_low >= grid.y_low &&
           extent.y_high <= grid.y_high && extent.mean_height <= 1.5 * grid.height_basis &&
           extent.mean_height * 1.5 >= grid.height_basis;
}

}  // namespace obbsat::detail
