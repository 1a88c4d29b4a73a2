// The error bound of the certified fast path on double poses
// (obbsat/ref/pose_conservative64.hpp, derived in docs/exact.md section 7):
// every computed gap against the exact gap in GMP rationals, on the families of
// test_support/pose_cases64.hpp, must lie within
//   E = 12.01u·RX·T* + 2^-1072·(Ha + Hb + 1)
// and every finite margin must exceed E.
#include "test_support/pose_cases64.hpp"

#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using obbsat::rect_pose64;
using obbsat::test::pose_pair64;

constexpr double unit_roundoff = 0x1p-53;

mpq_class abs_of(const mpq_class& v) { return v < 0 ? mpq_class(-v) : v; }

// The exact gap |w*| − r* of axis k (A.x, A.y, B.x, B.y) and its E.
struct exact_axis {
    mpq_class gap;
    mpq_class error_bound;
    mpq_class scale;  // RX·T*, the unit the error is measured in
};

exact_axis exact_axis_of(const rect_pose64& a, const rect_pose64& b, int k) {
    const mpq_class ca(a.rotation.x), sa(a.rotation.y), cb(b.rotation.x), sb(b.rotation.y);
    const mpq_class hxa(a.half_extents.x), hya(a.half_extents.y), hxb(b.half_extents.x), hyb(b.half_extents.y);
    const mpq_class dx = mpq_class(b.center.x) - mpq_class(a.center.x);
    const mpq_class dy = mpq_class(b.center.y) - mpq_class(a.center.y);
    const mpq_class P = abs_of(ca * cb + sa * sb), Q = abs_of(ca * sb - sa * cb);
    const mpq_class na = ca * ca + sa * sa, nb = cb * cb + sb * sb;
    mpq_class w, r;
    switch (k) {
        case 0: w = dx * ca + dy * sa; r = hxa * na + hxb * P + hyb * Q; break;
        case 1: w = dy * ca - dx * sa; r = hya * na + hxb * Q + hyb * P; break;
        case 2: w = dx * cb + dy * sb; r = hxb * nb + hxa * P + hya * Q; break;
        default: w = dy * cb - dx * sb; r = hyb * nb + hxa * Q + hya * P; break;
    }
    const mpq_class Ra(std::fmax(std::fabs(a.rotation.x), std::fabs(a.rotation.y)));
    const mpq_class Rb(std::fmax(std::fabs(b.rotation.x), std::fabs(b.rotation.y)));
    const mpq_class RX = k < 2 ? Ra : Rb;
    const mpq_class T = abs_of(dx) + abs_of(dy) + Ra * (hxa + hya) + Rb * (hxb + hyb);
    const mpq_class E = mpq_class(12.01 * unit_roundoff) * RX * T + mpq_class(0x1p-1072) * (hxa + hya + hxb + hyb + 1);
    return exact_axis{abs_of(w) - r, E, RX * T};
}

// Checks every axis of `count` pairs; returns the largest error seen, in u·RX·T*.
double check_family(const char* name, std::uint64_t seed, int count, pose_pair64 (*make)(obbsat::seeded_random&)) {
    obbsat::seeded_random random(seed);
    double worst = 0.0;
    int finite_margins = 0;
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const pose_pair64 pair = make(random);
        const obbsat::ref::pose_axes64 axes = obbsat::ref::local_axes(pair.a, pair.b);
        const obbsat::ref::pose_margins64 margins = obbsat::ref::margins_of(pair.a, pair.b, axes);
        double gap[4];
        obbsat::ref::pose_gaps(axes, gap);
        for (int k = 0; k < 4; ++k) {
            const double margin = k < 2 ? margins.a : margins.b;
            if (!std::isfinite(margin)) {
                continue;  // out of range: nothing is claimed, the bound need not hold
            }
            ++finite_margins;
            const exact_axis e = exact_axis_of(pair.a, pair.b, k);
            const mpq_class error = abs_of(mpq_class(gap[k]) - e.gap);
            EXPECT_TRUE(error <= e.error_bound) << "error " << error.get_d() << " bound " << e.error_bound.get_d() << " " << name << " pair " << i << " axis " << k;
            EXPECT_TRUE(mpq_class(margin) > e.error_bound) << "margin " << margin << " " << name << " pair " << i << " axis " << k;
            if (e.scale > 0) {
                worst = std::fmax(worst, mpq_class(error / e.scale).get_d() / unit_roundoff);
            }
        }
    }
    std::printf("[ bound64  ] %-26s %6d pairs  %7d axes with a margin  worst error %.3f u·RX·T (bound 12.01)\n",
                name, count, finite_margins, worst);
    EXPECT_GT(finite_margins, count);
    return worst;
}

TEST(pose_certified64, error_within_the_bound_on_utm_random_pairs) {
    check_family("UTM random", 41, 20000, obbsat::test::utm_random_pair);
}

TEST(pose_certified64, error_within_the_bound_on_utm_contacts) {
    check_family("UTM contacts 500000.125", 42, 20000, obbsat::test::utm_contact_pair);
    check_family("UTM contacts 6e6", 43, 20000, obbsat::test::utm_northing_contact_pair);
}

TEST(pose_certified64, error_within_the_bound_far_out) {
    check_family("contacts 1e9..1e15", 44, 20000, obbsat::test::far_contact_pair);
    check_family("random 1e9..1e15", 45, 20000, obbsat::test::far_random_pair);
}

TEST(pose_certified64, error_within_the_bound_on_slivers_and_near_parallel_pairs) {
    check_family("slivers", 46, 20000, obbsat::test::sliver_pair);
    // Unit rotations rounded from cos and sin: every rotation product rounds.
    const double worst = check_family("near parallel", 47, 20000, obbsat::test::near_parallel_pair);
    EXPECT_GT(worst, 0.1);  // the errors are real, not all zero
}

TEST(pose_certified64, error_within_the_bound_with_rotation_lengths_far_from_unit) {
    check_family("scaled rotations", 48, 20000, obbsat::test::scaled_rotation_pair);
}

}  // namespace
