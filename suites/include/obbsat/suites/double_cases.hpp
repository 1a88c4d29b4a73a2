// Seeded makes of double pose pairs, shared by the double pose oracle's
// cross-check, the double methods' tests and `obbsat gen --precision double`
// and `obbsat accuracy --precision double` (tools/accuracy/double_families): building footprints at UTM-like coordinates
// (1e5 to 1e7 metres) near contact by a millimetre or 1 to 4 ulps, exact
// contacts from decimal coordinates such as 500000.125, poses far out (1e9 to
// 1e15), slivers, near-parallel pairs, and rotation vectors far from unit
// length. Exact contacts come from dyadic values whose products and sums are
// exact in double, so that a pair meant to touch does touch. Header only:
// the tests include it without linking obbsat_suites. The unit rotations
// come from std::cos and std::sin, so unlike the float suites the bytes may
// differ between C libraries; the dyadic contact makes do not.
#pragma once

#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose64.hpp>
#include <obbsat/scene.hpp>

#include <cmath>
#include <cstdint>

namespace obbsat::suites {

struct pose_pair64 {
    rect_pose64 a;
    rect_pose64 b;
};

/// A double uniform in [lo, hi), from 53 random bits.
inline double uniform64(seeded_random& random, double lo, double hi) {
    const double unit = static_cast<double>(random.next() >> 11) * 0x1p-53;
    return lo + (hi - lo) * unit;
}

inline int integer_in(seeded_random& random, int lo, int hi) {
    return lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

/// `v` moved by `steps` doubles (up when positive).
inline double nudged64(double v, int steps) {
    for (; steps > 0; --steps) v = std::nextafter(v, INFINITY);
    for (; steps < 0; ++steps) v = std::nextafter(v, -INFINITY);
    return v;
}

/// A unit rotation (cos t, sin t) rounded to double.
inline point64 unit_rotation64(seeded_random& random) {
    const double t = uniform64(random, -3.2, 3.2);
    return point64{std::cos(t), std::sin(t)};
}

/// A rotation vector of quarter integers from -2 to 2 (not (0, 0)): products with
/// dyadic lengths stay exact, so contacts built from it are exact.
inline point64 dyadic_rotation64(seeded_random& random) {
    point64 r{0, 0};
    while (r.x == 0 && r.y == 0) {
        r = point64{0.25 * integer_in(random, -8, 8), 0.25 * integer_in(random, -8, 8)};
    }
    return r;
}

/// A half extent in [lo, hi) rounded to eighths, zero one time in eight.
inline double dyadic_half_extent(seeded_random& random, double lo, double hi) {
    return random.below(8) == 0 ? 0.0 : std::round(uniform64(random, lo, hi) * 8.0) / 8.0;
}

/// A + a·u + b·v for the pose's u = (c, s), v = (−s, c), in double.
inline point64 pose_point(const rect_pose64& p, double a, double b) {
    const double c = p.rotation.x, s = p.rotation.y;
    return point64{p.center.x + a * c - b * s, p.center.y + a * s + b * c};
}

/// How the last pair of a make was moved off its exact contact.
enum class nudge { none, ulps, millimetre };

/// Moves b's center by 1 to 4 ulps (half the time) or a millimetre (a quarter) in x or y.
inline void nudge_center(seeded_random& random, rect_pose64& b) {
    const unsigned kind = static_cast<unsigned>(random.below(4));
    double& coordinate = random.below(2) == 0 ? b.center.x : b.center.y;
    const int direction = random.below(2) == 0 ? -1 : 1;
    if (kind < 2) {
        coordinate = nudged64(coordinate, direction * integer_in(random, 1, 4));
    } else if (kind == 2) {
        coordinate += direction * 0.001;
    }
}

/// Building-sized poses (half extents 0 to 60 m, unit rotations) at a UTM-like
/// center in [lo, hi), B within reach of A: a mix of separated and overlapping pairs.
inline pose_pair64 random_pair_at(seeded_random& random, double lo, double hi) {
    const point64 ca{uniform64(random, lo, hi), uniform64(random, lo, hi)};
    const point64 cb{ca.x + uniform64(random, -100.0, 100.0), ca.y + uniform64(random, -100.0, 100.0)};
    auto extent = [&] { return random.below(16) == 0 ? 0.0 : uniform64(random, 0.0, 60.0); };
    return pose_pair64{rect_pose64{ca, {extent(), extent()}, unit_rotation64(random)},
                       rect_pose64{cb, {extent(), extent()}, unit_rotation64(random)}};
}

/// random_pair_at for UTM-like coordinates, 1e5 to 1e7 metres.
inline pose_pair64 utm_random_pair(seeded_random& random) { return random_pair_at(random, 1e5, 1e7); }

/// A dyadic pose at a decimal-like center (an eighth of a metre, around `base`)
/// and B with one corner exactly on A's outline (an edge point or a corner), B
/// turned as A, a quarter turn from it, or freely (dyadic): edges on edges, corners
/// on edges. Then B's center is nudged (see nudge_center) three times in four.
inline pose_pair64 contact_pair_at(seeded_random& random, double base) {
    const double scale = base >= 1e9 ? 64.0 : 1.0;  // keep the dyadic grid representable far out
    const point64 ca{base + 0.125 * integer_in(random, 0, 8000) * scale,
                     base + 0.125 * integer_in(random, 0, 8000) * scale};
    rect_pose64 a{ca, {dyadic_half_extent(random, 1, 40) * scale, dyadic_half_extent(random, 1, 40) * scale},
                  dyadic_rotation64(random)};
    const unsigned turn = static_cast<unsigned>(random.below(3));
    const point64 rb = turn == 0 ? a.rotation
                       : turn == 1 ? point64{-a.rotation.y, a.rotation.x}
                                   : dyadic_rotation64(random);
    // A point on A's outline: a side (±hxa or ±hya) and a dyadic position along it.
    const double along = 0.125 * integer_in(random, -8, 8);
    const int side = integer_in(random, 0, 3);
    const double hxa = a.half_extents.x, hya = a.half_extents.y;
    const point64 x = side == 0   ? pose_point(a, hxa, along * hya)
                      : side == 1 ? pose_point(a, -hxa, along * hya)
                      : side == 2 ? pose_point(a, along * hxa, hya)
                                  : pose_point(a, along * hxa, -hya);
    rect_pose64 b{{0, 0}, {dyadic_half_extent(random, 1, 40) * scale, dyadic_half_extent(random, 1, 40) * scale},
                  rb};
    // B's corner (−sx·hxb, −sy·hyb) at x: its center at x + sx·hxb·ub + sy·hyb·vb.
    const double sx = random.below(2) == 0 ? 1.0 : -1.0;
    const double sy = random.below(2) == 0 ? 1.0 : -1.0;
    b.center = x;
    b.center = pose_point(b, sx * b.half_extents.x, sy * b.half_extents.y);
    if (random.below(4) != 0) {
        nudge_center(random, b);
    }
    return pose_pair64{a, b};
}

/// Exact and nudged contacts around 500000.125 (UTM eastings).
inline pose_pair64 utm_contact_pair(seeded_random& random) { return contact_pair_at(random, 500000.125); }

/// Exact and nudged contacts around 6e6 (UTM northings).
inline pose_pair64 utm_northing_contact_pair(seeded_random& random) { return contact_pair_at(random, 6e6); }

/// Contacts far out, 1e9 to 1e15.
inline pose_pair64 far_contact_pair(seeded_random& random) {
    return contact_pair_at(random, std::ldexp(1.0, integer_in(random, 30, 49)));
}

/// Random pairs far out, 1e9 to 1e15, sizes as random_pair_at.
inline pose_pair64 far_random_pair(seeded_random& random) {
    const double base = std::ldexp(1.0, integer_in(random, 30, 49));
    return random_pair_at(random, base, 2.0 * base);
}

/// A sliver (one half extent 0 or below a micrometre, the other up to 100 m) and
/// a pose beside it, at UTM-like coordinates: the sliver's long side meets or
/// nearly meets the other's outline.
inline pose_pair64 sliver_pair(seeded_random& random) {
    pose_pair64 pair = utm_contact_pair(random);
    double& thin = random.below(2) == 0 ? pair.a.half_extents.x : pair.a.half_extents.y;
    thin = random.below(2) == 0 ? 0.0 : uniform64(random, 0.0, 1e-6);
    return pair;
}

/// Near-parallel pairs: B turned from A by 1e-15 to 1e-6 radians, edge to edge at
/// UTM-like coordinates, its center a millimetre or a few ulps off the contact.
inline pose_pair64 near_parallel_pair(seeded_random& random) {
    const double t = uniform64(random, -3.2, 3.2);
    const double tilt = std::ldexp(uniform64(random, -1.0, 1.0), -integer_in(random, 20, 50));
    const rect_pose64 a{{uniform64(random, 1e5, 1e7), uniform64(random, 1e5, 1e7)},
                        {uniform64(random, 1, 50), uniform64(random, 1, 50)},
                        {std::cos(t), std::sin(t)}};
    rect_pose64 b{{0, 0}, {uniform64(random, 1, 50), uniform64(random, 1, 50)}, {std::cos(t + tilt), std::sin(t + tilt)}};
    // Side by side along A's v axis, B's center over A's top edge plus B's half height.
    const double along = uniform64(random, -1.0, 1.0) * a.half_extents.x;
    const point64 top = pose_point(a, along, a.half_extents.y + b.half_extents.y);
    b.center = top;
    nudge_center(random, b);
    return pose_pair64{a, b};
}

/// Contacts near the origin with each rotation scaled by 2^k and its half extents
/// by 2^-k (k from -200 to 200): the same sets with rotation lengths from 1e-60 to 1e60.
inline pose_pair64 scaled_rotation_pair(seeded_random& random) {
    pose_pair64 pair = contact_pair_at(random, 0.0);
    for (rect_pose64* p : {&pair.a, &pair.b}) {
        const int k = integer_in(random, -200, 200);
        p->rotation = point64{std::ldexp(p->rotation.x, k), std::ldexp(p->rotation.y, k)};
        p->half_extents = point64{std::ldexp(p->half_extents.x, -k), std::ldexp(p->half_extents.y, -k)};
    }
    return pair;
}

/// The corners UL, UR, LR, LL of a pose, each coordinate rounded to double
/// (exact for the dyadic makes above).
inline rect64 corners64(const rect_pose64& p) {
    const double hx = p.half_extents.x, hy = p.half_extents.y;
    return rect64{pose_point(p, -hx, hy), pose_point(p, hx, hy), pose_point(p, hx, -hy), pose_point(p, -hx, -hy)};
}

struct rect_pair64 {
    rect64 a;
    rect64 b;
};

/// The corners of a pose pair of `make`.
template <pose_pair64 (*make)(seeded_random&)>
rect_pair64 corner_pair(seeded_random& random) {
    const pose_pair64 pair = make(random);
    return rect_pair64{corners64(pair.a), corners64(pair.b)};
}

/// Corners of a contact or sliver pair with every coordinate of one quad moved by
/// up to 3 ulps either way: thin quads turn concave or cross themselves.
inline rect_pair64 nudged_corner_pair(seeded_random& random) {
    rect_pair64 pair = random.below(2) == 0 ? corner_pair<sliver_pair>(random) : corner_pair<utm_contact_pair>(random);
    rect64& moved = random.below(2) == 0 ? pair.a : pair.b;
    for (point64* p : {&moved.ul, &moved.ur, &moved.lr, &moved.ll}) {
        p->x = nudged64(p->x, integer_in(random, -3, 3));
        p->y = nudged64(p->y, integer_in(random, -3, 3));
    }
    return pair;
}

}  // namespace obbsat::suites
