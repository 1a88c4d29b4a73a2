// The methods on double corners (rect_records64), one pair per lane of
// doubles (2 per SSE2 vector, 4 per AVX2, 8 per AVX-512), doing the double
// operations of their scalar references in the same order, so that verdicts
// are bit for bit theirs:
//   exact         the certified fast path of obbsat/ref/certified64.hpp (the
//                 steps of certified_lanes.hpp in double); the lanes it leaves
//                 undecided are settled by the exact oracle of
//                 obbsat/oracle/contact64.hpp, as obbsat/ref/exact64.hpp says;
//   conservative  obbsat/ref/conservative64.hpp: the steps of
//                 conservative_lanes.hpp in double, its fused projections and
//                 margin computed by fused_multiply_add (one rounding each).
// And the records as the record driver (record_batch.hpp) reads them: each
// lane's record read whole and transposed in registers (record64_transpose.hpp).
#pragma once

#include "lanes/batch_kernel.hpp"
#include "lanes/record_batch.hpp"
#include "lanes/certified_lanes.hpp"
#include "lanes/conservative_lanes.hpp"
#include "lanes/lanes.hpp"
#include "lanes/record64_transpose.hpp"

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// One double-corner rectangle per lane.
template <class Arch>
using quad64_lanes = quad<xsimd::batch<double, Arch>>;

/// Method exact on double corners: proven lanes from the certified path in
/// double, the rest from the double oracle.
///
/// The steps are certified_steps::certify's, ordered to hold fewer vectors at
/// once (a vector holds half the pairs of a float one, so the per-vector cost
/// is what the double path pays twice): the edges of b are made after those
/// of a are scanned. And when an edge of a already separates every lane, the
/// edges of b are not scanned: a lane once separating stays so and is then
/// never intersecting, so their scan could change no verdict.
template <class Arch>
struct corner_exact64_lanes {
    static constexpr bool has_slow_path = true;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad64_lanes<Arch>& a, const quad64_lanes<Arch>& b) {
        using steps = certified_steps<Arch, double>;
        using batch = typename steps::batch;
        using mask = typename steps::mask;
        using limits = typename steps::limits;
        const typename steps::extent xa = steps::extent_of(a);
        const typename steps::extent xb = steps::extent_of(b);
        const batch area_a = xa.area();
        const batch area_b = xb.area();
        const batch area = steps::joined(xa, xb).area();
        const batch min_area(limits::min_area);
        const batch factor(limits::bound_factor);
        const mask in_range =
            (area >= min_area) & (area <= batch(limits::max_area)) & (area_a >= min_area) & (area_b >= min_area);
        const batch bound = area * factor;

        mask separating(false), all_blocked(true);
        const typename steps::quad_edges ea = steps::edges_of(a, area_a * factor);
        steps::scan_edges(a, ea, b, bound, separating, all_blocked);
        const typename steps::quad_edges eb = steps::edges_of(b, area_b * factor);
        if (!xsimd::all(separating)) {
            steps::scan_edges(b, eb, a, bound, separating, all_blocked);
        }
        const mask decidable = in_range & ea.convex & eb.convex;
        const mask intersecting = decidable & ~separating & all_blocked;
        return lane_verdicts{lane_bits(intersecting), lane_bits(~((decidable & separating) | intersecting))};
    }

    static bool decide_exactly(const rect64& a, const rect64& b) { return oracle::intersects(a, b); }
};

/// Method conservative on double corners: conservative_lanes in double, the
/// steps of conservative64.hpp.
template <class Arch>
struct corner_conservative64_lanes : conservative_steps<Arch, double> {};

/// Double-corner rectangles in their 64-byte records, as record_batch.hpp
/// reads them (whole records transposed in registers, record64_transpose.hpp).
template <class Arch>
struct corner64_records_of {
    using value = rect64;
    static constexpr std::size_t width = record64_transpose<Arch>::width;

    static const rect64* record(const rect64* records, std::size_t index) { return records + index; }

    /// Every load reads whole cache lines, so whether they are cached changes nothing.
    template <bool InCache, class Index>
    static OBBSAT_LANE_INLINE quad64_lanes<Arch> load(const rect64* records, const Index& index) {
        return record64_transpose<Arch>::load([&](std::size_t lane) { return records + index(lane); });
    }

    static rect64 at(const rect64* records, std::size_t index) { return records[index]; }
};

}  // namespace
}  // namespace obbsat::detail
