// The layout of a scene query's sweep: the scene cut into horizontal strips,
// and x positions quantized to integers that sort like the floats they come
// from. Both maps are monotone (x <= y implies q(x) <= q(y)), which is all
// the sweep's correctness needs; the layout only decides how fast it runs.
// Internal to the library.
#pragma once

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

struct strip_grid {
    double x_low = 0;       ///< the x that quantizes to 0
    double x_high = 0;      ///< the x where the quantized scale reaches q_max (rounding may put it at q_max - 1)
    double x_scale = 0;     ///< q_max / (x_high - x_low), or 0
    double y_low = 0;       ///< the bottom of strip 0
    double y_high = 0;      ///< the top of the last strip
    double y_scale = 1;     ///< 1 / strip height
    double height_basis = 0;  ///< the mean bounds height the strips were cut for
    std::uint32_t strips = 1;
    unsigned strip_bits = 0;
    unsigned q_bits = 24;
    std::uint32_t q_max = (1u << 24) - 1;

    /// x quantized: floor((x - x_low) * x_scale), clamped to [0, q_max].
    std::uint32_t q_of(float x) const { return clamped_floor((static_cast<double>(x) - x_low) * x_scale, q_max); }

    /// The strip holding y: floor((y - y_low) * y_scale), clamped to [0, strips - 1].
    std::uint32_t strip_of(float y) const {
        return clamped_floor((static_cast<double>(y) - y_low) * y_scale, strips - 1);
    }

    /// floor(t) clamped to [0, top], 0 for a NaN; top < 2^31. Written as
    /// selects (max then min, which a NaN leaves at 0) and a conversion to
    /// int32, so that a loop over many boxes (store_sweep_bounds) takes no branch.
    static std::uint32_t clamped_floor(double t, std::uint32_t top) {
        const double above = 0.0 < t ? t : 0.0;
        const double inside = static_cast<double>(top) < above ? static_cast<double>(top) : above;
        return static_cast<std::uint32_t>(static_cast<std::int32_t>(inside));
    }

    /// The sort key of a rectangle: its lowest strip, then its quantized lo_x.
    std::uint32_t key_of(float lo_x, float lo_y) const {
        return (strip_of(lo_y) << q_bits) | q_of(lo_x);
    }

    /// Bits a key can use.
    unsigned key_bits() const { return strip_bits + q_bits; }
};

/// The extent and mean height of a set of bounds, clamped to finite values.
struct bounds_extent {
    double x_low, x_high, y_low, y_high;
    double mean_height;
};

/// Strips `strip_factor` mean heights tall (at most 2^20 of them, at most one
/// per rectangle), with a margin of a sixteenth of the extent on every side so
/// that a scene moving a little keeps its layout.
strip_grid grid_for(const bounds_extent& extent, std::size_t boxes, double strip_factor);

/// True iff `extent` lies inside the grid's range and its mean height is
/// within a factor 1.5 of the one the strips were cut for.
bool grid_still_fits(const strip_grid& grid, const bounds_extent& extent);

}  // namespace obbsat::detail
