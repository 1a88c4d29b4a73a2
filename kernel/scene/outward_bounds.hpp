// The float bounds of double rows rounded outward (obbsat/ref/bounds64.hpp),
// bit for bit the reference's, a run of rows at a time. The reference takes
// one row through four conversions, each with a branch on which side of the
// double its nearest float fell (about half the bounds of a scene at random):
// on a million rows that is most of a double scene query's bounds pass.
// Here the double bounds of a run are staged first (stage 1 of the contract,
// the same arithmetic in the same order), and each of the four is then
// rounded outward in a plain loop over the run, the step to the next float
// computed on the bits and kept or not by a select: loops the compiler
// turns into vector code at the baseline ISA. Internal to the library.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace obbsat::detail {

/// The double bounds of up to `size` rows (stage 1 of obbsat/ref/bounds64.hpp).
struct double_bounds_run {
    static constexpr std::size_t size = 256;
    alignas(64) double lo_x[size];
    alignas(64) double lo_y[size];
    alignas(64) double hi_x[size];
    alignas(64) double hi_y[size];
};

/// Stage 1 for `count` <= double_bounds_run::size pose rows (cx, cy, hx, hy, c, s),
/// `stride` doubles apart: ref::bounds_of(rect_pose64) before its rounding.
inline void stage_pose_bounds(const double* rows, std::size_t stride, std::size_t count, double_bounds_run& out) {
    for (std::size_t r = 0; r < count; ++r) {
        const double* v = rows + stride * r;
        const double ac = std::fabs(v[4]);
        const double as = std::fabs(v[5]);
        const double ex = (ac * v[2]) + (as * v[3]);
        const double ey = (as * v[2]) + (ac * v[3]);
        const double mx = ((std::fabs(v[0]) + ex) * 0x1p-50) + 0x1p-1060;
        const double my = ((std::fabs(v[1]) + ey) * 0x1p-50) + 0x1p-1060;
        out.lo_x[r] = (v[0] - ex) - mx;
        out.lo_y[r] = (v[1] - ey) - my;
        out.hi_x[r] = (v[0] + ex) + mx;
        out.hi_y[r] = (v[1] + ey) + my;
    }
}

/// Stage 1 for `count` <= double_bounds_run::size corner rows (UL, UR, LR, LL),
/// `stride` doubles apart: the least and greatest corner, as ref::bounds_of(rect64).
inline void stage_corner_bounds(const double* rows, std::size_t stride, std::size_t count, double_bounds_run& out) {
    for (std::size_t r = 0; r < count; ++r) {
        const double* v = rows + stride * r;
        out.lo_x[r] = std::min(std::min(v[0], v[2]), std::min(v[4], v[6]));
        out.lo_y[r] = std::min(std::min(v[1], v[3]), std::min(v[5], v[7]));
        out.hi_x[r] = std::max(std::max(v[0], v[2]), std::max(v[4], v[6]));
        out.hi_y[r] = std::max(std::max(v[1], v[3]), std::max(v[5], v[7]));
    }
}

/// Stage 2 for `count` doubles (not NaN): ref::float_at_least of each (Up)
/// or ref::float_at_most, the same floats.
template <bool Up>
void round_outward(const double* in, std::size_t count, float* out) {
    for (std::size_t r = 0; r < count; ++r) {
        const double d = in[r];
        const float f = static_cast<float>(d);
        const double back = static_cast<double>(f);
        const bool wrong_side = Up ? back < d : back > d;
        std::int32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        // The next float away from zero is one more in the magnitude's bits,
        // the next towards zero one less; from a zero of either sign the step
        // is the least subnormal of the direction's sign.
        const bool away = (bits >= 0) == Up;
        const std::int32_t from_zero = Up ? 1 : static_cast<std::int32_t>(0x80000001u - 0x100000000u);
        const std::int32_t stepped = (bits & 0x7fffffff) == 0 ? from_zero : (away ? bits + 1 : bits - 1);
        const std::int32_t kept = wrong_side ? stepped : bits;
        float rounded;
        std::memcpy(&rounded, &kept, sizeof rounded);
        out[r] = rounded;
    }
}

/// Stage 2 of a run's `count` double bounds, into four arrays of floats.
inline void round_bounds_outward(const double_bounds_run& in, std::size_t count, float* lo_x, float* lo_y,
                                 float* hi_x, float* hi_y) {
    round_outward<false>(in.lo_x, count, lo_x);
    round_outward<false>(in.lo_y, count, lo_y);
    round_outward<true>(in.hi_x, count, hi_x);
    round_outward<true>(in.hi_y, count, hi_y);
}

}  // namespace obbsat::detail
