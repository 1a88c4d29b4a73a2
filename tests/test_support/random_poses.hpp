// Random pose pairs for the tests of the methods on poses, from seeded
// integer arithmetic and IEEE-exact float operations only (no sin or cos), so
// the same seed gives the same poses on every machine and the golden digests
// can use them. Each pair is drawn from one of several kinds, chosen so that
// both verdicts are frequent and the float methods meet their hard cases:
// near pairs, pairs placed on contact along an axis (then nudged by a few
// ulps), exact integer contacts with rotation vectors such as (3, 4), pairs
// far from the origin, rotation vectors far from unit length, zero half
// extents, slivers, near-parallel pairs, tiny and huge scales.
#pragma once

#include <obbsat/pose_records.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace obbsat::test_support {

/// Poses a[i] and b[i] form pair i.
struct pose_pairs {
    std::vector<rect_pose> a;
    std::vector<rect_pose> b;
};

namespace random_poses_detail {

/// A unit-length rotation vector (within rounding): a random direction, normalised in float.
inline point unit_rotation(seeded_random& random) {
    for (;;) {
        const float x = random.uniform(-1.0f, 1.0f);
        const float y = random.uniform(-1.0f, 1.0f);
        const float n = std::sqrt(x * x + y * y);
        if (n > 0.1f && n <= 1.0f) {
            return point{x / n, y / n};
        }
    }
}

/// A rotation vector with integer components of an exact length: (3, 4), (5, 12), (8, 15) and their turns.
inline point integer_rotation(seeded_random& random) {
    static const point triples[] = {{3, 4}, {4, 3}, {5, 12}, {12, 5}, {8, 15}, {1, 0}, {0, 1}, {7, 24}};
    point r = triples[random.below(8)];
    switch (random.below(4)) {
        case 0: return r;
        case 1: return point{-r.y, r.x};
        case 2: return point{-r.x, -r.y};
        default: return point{r.y, -r.x};
    }
}

inline float ulps_away(float value, int ulps) {
    for (; ulps > 0; --ulps) value = std::nextafter(value, INFINITY);
    for (; ulps < 0; ++ulps) value = std::nextafter(value, -INFINITY);
    return value;
}

/// The reach of pose p along the direction (ux, uy), in double.
inline double reach_along(const rect_pose& p, double ux, double uy) {
    const double c = p.rotation.x, s = p.rotation.y;
    return p.half_extents.x * std::fabs(c * ux + s * uy) + p.half_extents.y * std::fabs(-s * ux + c * uy);
}

/// Moves b's center so that, along a's own x axis (or y axis), the two just touch, then nudges it by a few ulps.
inline void place_on_contact(seeded_random& random, const rect_pose& a, rect_pose& b) {
    const double c = a.rotation.x, s = a.rotation.y;
    const double n = std::sqrt(c * c + s * s);
    double ux = c / n, uy = s / n;
    if (random.below(2) == 1) {
        const double t = ux;
        ux = -uy;
        uy = t;
    }
    const double side = random.below(2) == 0 ? 1.0 : -1.0;
    const double distance = reach_along(a, ux, uy) + reach_along(b, ux, uy);
    const double slide = (random.uniform(-1.0f, 1.0f)) * 0.5 * distance;
    const double dx = side * distance * ux - slide * uy;
    const double dy = side * distance * uy + slide * ux;
    const int nudge = static_cast<int>(random.below(9)) - 4;
    b.center = point{ulps_away(static_cast<float>(a.center.x + dx), nudge),
                     ulps_away(static_cast<float>(a.center.y + dy), static_cast<int>(random.below(9)) - 4)};
}

inline float log_uniform(seeded_random& random, int lo_exponent, int hi_exponent) {
    const int e = lo_exponent + static_cast<int>(random.below(static_cast<std::uint64_t>(hi_exponent - lo_exponent + 1)));
    return std::ldexp(random.uniform(1.0f, 2.0f), e);
}

inline rect_pose random_pose(seeded_random& random, point center, float size) {
    return rect_pose{center, {size * random.uniform(0.05f, 1.0f), size * random.uniform(0.05f, 1.0f)},
                     unit_rotation(random)};
}

}  // namespace random_poses_detail

/// How many kinds random_pose_pair draws from.
inline constexpr unsigned pose_pair_kinds = 10;

/// One random pair of kind `kind` (< pose_pair_kinds).
inline void random_pose_pair(seeded_random& random, unsigned kind, rect_pose& a, rect_pose& b) {
    using namespace random_poses_detail;
    const point origin{random.uniform(-1000.0f, 1000.0f), random.uniform(-1000.0f, 1000.0f)};
    const float size_a = log_uniform(random, -3, 4);
    const float size_b = log_uniform(random, -3, 4);
    a = random_pose(random, origin, size_a);
    b = random_pose(random, origin, size_b);
    switch (kind) {
        case 0: {  // near each other
            const float spread = 1.5f * (size_a + size_b);
            b.center = point{origin.x + random.uniform(-spread, spread), origin.y + random.uniform(-spread, spread)};
            break;
        }
        case 1:  // on contact along one of a's axes, nudged by up to 4 ulps
            place_on_contact(random, a, b);
            break;
        case 2: {  // exact contact: integer centers, extents and rotation vectors
            a = rect_pose{{static_cast<float>(random.below(41)) - 20.0f, static_cast<float>(random.below(41)) - 20.0f},
                          {static_cast<float>(random.below(6)), static_cast<float>(random.below(6))},
                          integer_rotation(random)};
            b = rect_pose{{static_cast<float>(random.below(41)) - 20.0f, static_cast<float>(random.below(41)) - 20.0f},
                          {static_cast<float>(random.below(6)), static_cast<float>(random.below(6))},
                          integer_rotation(random)};
            if (random.below(2) == 0) {
                b.rotation = a.rotation;  // parallel frames: edge-to-edge contacts
            }
            break;
        }
        case 3: {  // far from the origin, on contact
            const float far = log_uniform(random, 13, 24);
            a.center = point{a.center.x + far, a.center.y - far * random.uniform(0.0f, 1.0f)};
            place_on_contact(random, a, b);
            break;
        }
        case 4: {  // rotation vectors far from unit length (the boxes scale with them)
            const float scale_a = log_uniform(random, -30, 30);
            const float scale_b = log_uniform(random, -30, 30);
            a.rotation = point{a.rotation.x * scale_a, a.rotation.y * scale_a};
            b.rotation = point{b.rotation.x * scale_b, b.rotation.y * scale_b};
            a.half_extents = point{a.half_extents.x / scale_a, a.half_extents.y / scale_a};
            b.half_extents = point{b.half_extents.x / scale_b, b.half_extents.y / scale_b};
            place_on_contact(random, a, b);
            break;
        }
        case 5: {  // zero half extents: segments and points
            if (random.below(2) == 0) a.half_extents.x = 0.0f;
            if (random.below(2) == 0) a.half_extents.y = 0.0f;
            if (random.below(2) == 0) b.half_extents.x = 0.0f;
            if (random.below(2) == 0) b.half_extents.y = 0.0f;
            place_on_contact(random, a, b);
            break;
        }
        case 6: {  // slivers
            a.half_extents.y = a.half_extents.x * log_uniform(random, -24, -10);
            b.half_extents.x = b.half_extents.y * log_uniform(random, -24, -10);
            place_on_contact(random, a, b);
            break;
        }
        case 7: {  // near-parallel: b's rotation a few ulps off a's
            b.rotation = point{ulps_away(a.rotation.x, static_cast<int>(random.below(9)) - 4),
                               ulps_away(a.rotation.y, static_cast<int>(random.below(9)) - 4)};
            place_on_contact(random, a, b);
            break;
        }
        case 8: {  // tiny scale
            const float tiny = log_uniform(random, -60, -40);
            for (rect_pose* p : {&a, &b}) {
                p->center = point{p->center.x * tiny, p->center.y * tiny};
                p->half_extents = point{p->half_extents.x * tiny, p->half_extents.y * tiny};
            }
            place_on_contact(random, a, b);
            break;
        }
        default: {  // huge scale
            const float huge = log_uniform(random, 40, 60);
            for (rect_pose* p : {&a, &b}) {
                p->center = point{p->center.x * huge, p->center.y * huge};
                p->half_extents = point{p->half_extents.x * huge, p->half_extents.y * huge};
            }
            place_on_contact(random, a, b);
            break;
        }
    }
}

/// `count` random pairs cycling through every kind.
inline pose_pairs random_pose_pairs(seeded_random& random, std::size_t count) {
    pose_pairs out;
    out.a.resize(count);
    out.b.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        random_pose_pair(random, static_cast<unsigned>(i % pose_pair_kinds), out.a[i], out.b[i]);
    }
    return out;
}

}  // namespace obbsat::test_support
