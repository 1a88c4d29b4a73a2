// The error bound of the certified separating-edge test on double corners
// (obbsat/ref/certified64.hpp): every turn and orientation the fast path
// evaluates (a turn against its own quad's area), computed in double as its contract states, against the exact
// value in GMP rationals, must lie within 6.001u·area (u = 2^-53) of it, while
// the test decides at 16u·area. Pairs: the corners of the double families.
#include "test_support/pose_cases64.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using obbsat::point64;
using obbsat::rect64;
using obbsat::test::corner_pair;
using obbsat::test::rect_pair64;

constexpr double unit_roundoff = 0x1p-53;

// (e.x·(r.y − p.y)) − (e.y·(r.x − p.x)) in double, as step 6 computes it, and exactly.
double rounded_orientation(point64 p, point64 e, point64 r) { return (e.x * (r.y - p.y)) - (e.y * (r.x - p.x)); }

mpq_class exact_orientation(point64 p, point64 q, point64 r) {
    const mpq_class px(p.x), py(p.y), qx(q.x), qy(q.y), rx(r.x), ry(r.y);
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
}

double area_of(const rect64& a, const rect64& b) {
    double xmin = a.ul.x, xmax = a.ul.x, ymin = a.ul.y, ymax = a.ul.y;
    for (const point64 p : {a.ur, a.lr, a.ll, b.ul, b.ur, b.lr, b.ll}) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
    }
    return (xmax - xmin) * (ymax - ymin);
}

// The largest error seen over every orientation of edges of one quad against
// corners of the other, in u·area.
double check_family(const char* name, std::uint64_t seed, int count, rect_pair64 (*make)(obbsat::seeded_random&)) {
    obbsat::seeded_random random(seed);
    double worst = 0.0;
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const rect_pair64 pair = make(random);
        const double area = area_of(pair.a, pair.b);
        if (!(area >= 0x1p-900 && area <= 0x1p1000)) {
            continue;
        }
        for (int pass = 0; pass < 2; ++pass) {
            const rect64& q = pass == 0 ? pair.a : pair.b;
            const rect64& other = pass == 0 ? pair.b : pair.a;
            const point64 corner[4] = {q.ul, q.ur, q.lr, q.ll};
            for (int k = 0; k < 4; ++k) {
                const point64 from = corner[k];
                const point64 to = corner[(k + 1) % 4];
                const point64 edge{to.x - from.x, to.y - from.y};
                for (const point64 r : {other.ul, other.ur, other.lr, other.ll}) {
                    const mpq_class error = abs(mpq_class(rounded_orientation(from, edge, r)) -
                                                exact_orientation(from, to, r));
                    const double in_units = mpq_class(error / mpq_class(area)).get_d() / unit_roundoff;
                    worst = std::max(worst, in_units);
                    EXPECT_LE(in_units, 6.001) << name << " pair " << i;
                }
                // Step 5's turn at corner k+1, against the quad's own extent.
                const point64 after = corner[(k + 2) % 4];
                const point64 next{after.x - to.x, after.y - to.y};
                const double turn = (edge.x * next.y) - (edge.y * next.x);
                const double own_area = area_of(q, q);
                if (own_area >= 0x1p-900) {
                    const mpq_class error = abs(mpq_class(turn) - exact_orientation(from, to, after));
                    EXPECT_LE(mpq_class(error / mpq_class(own_area)).get_d() / unit_roundoff, 6.001)
                        << name << " pair " << i << " turn " << k;
                }
            }
        }
    }
    std::printf("[ bound64  ] %-26s %6d pairs  worst error %.3f u·area (bound 6.001, decided at 16)\n", name,
                count, worst);
    return worst;
}

TEST(certified64, orientation_error_within_the_bound) {
    check_family("UTM random", 71, 5000, corner_pair<obbsat::test::utm_random_pair>);
    check_family("UTM contacts", 72, 5000, corner_pair<obbsat::test::utm_contact_pair>);
    check_family("random 1e9..1e15", 73, 5000, corner_pair<obbsat::test::far_random_pair>);
    check_family("slivers", 74, 5000, corner_pair<obbsat::test::sliver_pair>);
    const double worst = check_family("near parallel", 75, 5000, corner_pair<obbsat::test::near_parallel_pair>);
    EXPECT_GT(worst, 0.01);  // real rounding is measured, not only exact zeros
    check_family("corners moved by ulps", 76, 5000, obbsat::test::nudged_corner_pair);
    check_family("scaled rotations", 77, 5000, corner_pair<obbsat::test::scaled_rotation_pair>);
}

}  // namespace
