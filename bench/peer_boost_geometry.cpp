// Boost.Geometry as a peer: a general polygon library's intersects() on the
// same candidate pairs. Each rectangle becomes an open clockwise ring of its
// four corners in double (the float corners convert exactly). intersects()
// counts touching boundaries as intersecting, like sat4.
//
// Agreement can fall just short of 1 with reference_only > 0: a few
// near-touching pairs lie apart by less than one float ulp of their
// coordinates; Boost, deciding the quadrilaterals in double, sees the gap,
// while sat4 rounds its projections to float as its definition says and
// finds them touching.
#include "bench_registry.hpp"
#include "peer_harness.hpp"

#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/algorithms/intersects.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>

#include <map>
#include <vector>

namespace obbsat_bench {

namespace {

using bg_point = boost::geometry::model::d2::point_xy<double>;
using bg_ring = boost::geometry::model::ring<bg_point, /*ClockWise=*/true, /*Closed=*/false>;

bg_point to_bg(const obbsat::point& p) {
    return bg_point(static_cast<double>(p.x), static_cast<double>(p.y));
}

const std::vector<bg_ring>& boost_rings(workload& w) {
    static std::map<const workload*, std::vector<bg_ring>> cache;
    std::vector<bg_ring>& rings = cache[&w];
    if (rings.empty()) {
        rings.resize(w.rects().size());
        for (std::size_t i = 0; i < rings.size(); ++i) {
            const obbsat::rect r = w.rects()[i];
            rings[i] = bg_ring{to_bg(r.ul), to_bg(r.ur), to_bg(r.lr), to_bg(r.ll)};
            // The scene's corners wind clockwise, but the library's contract
            // accepts either winding; correct() makes the ring what the type says.
            boost::geometry::correct(rings[i]);
        }
    }
    return rings;
}

}  // namespace

void register_boost_geometry_peers() {
    register_peer("boost_geometry_intersects", [](workload& w) {
        const std::vector<bg_ring>* rings = &boost_rings(w);
        return [rings](std::uint32_t a, std::uint32_t b) {
            return boost::geometry::intersects((*rings)[a], (*rings)[b]);
        };
    });
}

}  // namespace obbsat_bench
