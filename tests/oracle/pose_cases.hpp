// Seeded makes of pose pairs for the pose oracle's cross-check and timing:
// exact contacts on a small lattice, near contacts rounded to float, far from
// the origin, with rotation vectors far from unit length or with components
// of two very different scales, and points nearly on a segment's line. Every
// make has poses with a zero half extent.
#pragma once

#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <cmath>
#include <cstdint>

namespace obbsat::test {

struct pose_pair {
    rect_pose a;
    rect_pose b;
};

inline float nudged(float v, int steps) {
    for (; steps > 0; --steps) v = std::nextafter(v, INFINITY);
    for (; steps < 0; ++steps) v = std::nextafter(v, -INFINITY);
    return v;
}

inline int random_integer(seeded_random& random, int lo, int hi) {
    return lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

/// A half extent: zero one time in eight, else uniform in [0, top).
inline float random_half_extent(seeded_random& random, float top) {
    return random.below(8) == 0 ? 0.0f : random.uniform(0.0f, top);
}

/// A rotation vector of integers from -4 to 4, not (0, 0).
inline point integer_rotation(seeded_random& random) {
    point r{0, 0};
    while (r.x == 0 && r.y == 0) {
        r = point{static_cast<float>(random_integer(random, -4, 4)),
                  static_cast<float>(random_integer(random, -4, 4))};
    }
    return r;
}

/// Integer rotation, center and half extents on the half-integer lattice, so that
/// contacts between two such poses are frequent and exact.
inline rect_pose lattice_pose(seeded_random& random) {
    auto half_integer = [&](int lo, int hi) { return 0.5f * static_cast<float>(random_integer(random, lo, hi)); };
    const point center{half_integer(-12, 12), half_integer(-12, 12)};
    const point half_extents{half_integer(0, 4), half_integer(0, 4)};
    return rect_pose{center, half_extents, integer_rotation(random)};
}

/// A rotation vector of one of four kinds: small integers, a float unit vector
/// (cos t, sin t), the same scaled by 2^k (k from -66 to 50), or two random floats.
inline point random_rotation(seeded_random& random) {
    const float angle = random.uniform(-3.2f, 3.2f);
    switch (random.below(4)) {
        case 0: return integer_rotation(random);
        case 1: return point{std::cos(angle), std::sin(angle)};
        case 2: {
            const int k = random_integer(random, -66, 50);
            return point{std::ldexp(std::cos(angle), k), std::ldexp(std::sin(angle), k)};
        }
        default: {
            point r{0, 0};
            while (r.x == 0 && r.y == 0) {
                r = point{random.uniform(-3.0f, 3.0f), random.uniform(-3.0f, 3.0f)};
            }
            return r;
        }
    }
}

/// Half extents for a rotation vector r such that the true half widths are below `size`.
inline point random_half_extents(seeded_random& random, point r, float size) {
    const float length = std::sqrt(r.x * r.x + r.y * r.y);
    return point{random_half_extent(random, size) / length, random_half_extent(random, size) / length};
}

/// A pose of random rotation whose true half widths are below `size`.
inline rect_pose random_pose(seeded_random& random, point center, float size) {
    const point r = random_rotation(random);
    return rect_pose{center, random_half_extents(random, r, size), r};
}

/// The true corners of a pose, rounded to double, in the order UL, UR, LR, LL.
inline void rounded_corners(const rect_pose& p, double x[4], double y[4]) {
    const double ux = static_cast<double>(p.half_extents.x) * p.rotation.x;
    const double uy = static_cast<double>(p.half_extents.x) * p.rotation.y;
    const double vx = -static_cast<double>(p.half_extents.y) * p.rotation.y;
    const double vy = static_cast<double>(p.half_extents.y) * p.rotation.x;
    const double su[4] = {-1, 1, 1, -1}, sv[4] = {1, 1, -1, -1};
    for (int i = 0; i < 4; ++i) {
        x[i] = p.center.x + su[i] * ux + sv[i] * vx;
        y[i] = p.center.y + su[i] * uy + sv[i] * vy;
    }
}

/// B placed so that one of its corners lies on A's outline (a corner of A or a point
/// of an edge), in double; then rounded to float, and its center moved by up to two
/// float steps half of the time. B is turned as A, a quarter turn from it, or freely,
/// so that edges lie on edges too.
inline rect_pose near_contact(seeded_random& random, const rect_pose& a, float size) {
    rect_pose b = random_pose(random, point{0, 0}, size);
    switch (random.below(4)) {
        case 0: b.rotation = a.rotation; break;
        case 1: b.rotation = point{-a.rotation.y, a.rotation.x}; break;
        default: break;
    }
    if (b.rotation.x != a.rotation.x || b.rotation.y != a.rotation.y) {
        b.half_extents = random_half_extents(random, b.rotation, size);
    }
    double ax[4], ay[4], bx[4], by[4];
    rounded_corners(a, ax, ay);
    rounded_corners(b, bx, by);  // B centered at the origin
    const std::size_t edge = random.below(4), corner = random.below(4);
    const double t = random.below(3) == 0 ? 0.0 : static_cast<double>(random.uniform(0.0f, 1.0f));
    const double target_x = ax[edge] + t * (ax[(edge + 1) % 4] - ax[edge]);
    const double target_y = ay[edge] + t * (ay[(edge + 1) % 4] - ay[edge]);
    b.center = point{static_cast<float>(target_x - bx[corner]), static_cast<float>(target_y - by[corner])};
    if (random.below(2) == 0) {
        b.center.x = nudged(b.center.x, random_integer(random, -2, 2));
        b.center.y = nudged(b.center.y, random_integer(random, -2, 2));
    }
    return b;
}

/// Two lattice poses: exact contacts are frequent.
inline pose_pair lattice_pair(seeded_random& random) {
    const rect_pose a = lattice_pose(random);
    return pose_pair{a, lattice_pose(random)};
}

/// Lattice pairs with lengths times 4 (even integers) and centers moved by (1e7, 3e7):
/// floats there are 1 and 2 apart, so the centers stay exact and so do the contacts.
inline pose_pair lattice_pair_far(seeded_random& random) {
    pose_pair p = lattice_pair(random);
    for (rect_pose* q : {&p.a, &p.b}) {
        q->center = point{4 * q->center.x + 1e7f, 4 * q->center.y + 3e7f};
        q->half_extents = point{4 * q->half_extents.x, 4 * q->half_extents.y};
    }
    return p;
}

/// Lattice pairs with each rotation vector scaled by 2^k and its half extents by
/// 2^-k: the same sets, with k from -66 (rotation lengths near 1e-20) to 50 (1e15).
inline pose_pair lattice_pair_scaled_rotations(seeded_random& random) {
    pose_pair p = lattice_pair(random);
    for (rect_pose* q : {&p.a, &p.b}) {
        const int k = random_integer(random, -66, 50);
        q->rotation = point{std::ldexp(q->rotation.x, k), std::ldexp(q->rotation.y, k)};
        q->half_extents = point{std::ldexp(q->half_extents.x, -k), std::ldexp(q->half_extents.y, -k)};
    }
    return p;
}

/// Lattice pairs with rotations (a, b·2^-k) or (a·2^-k, b), k from 27 to 60: each
/// slack is a lattice part plus parts of order 2^-k and 2^-2k. When the lattice part
/// cancels, as at a lattice contact, the rest decides, and 2^-2k is below what double
/// resolves. B is turned as A, or a quarter turn from it, three times in four: edges
/// then lie along edges and the parts of order 2^-k cancel too.
inline pose_pair lattice_pair_two_scale_rotations(seeded_random& random) {
    pose_pair p = lattice_pair(random);
    for (rect_pose* q : {&p.a, &p.b}) {
        const float small = std::ldexp(1.0f, -random_integer(random, 27, 60));
        const float large = static_cast<float>(random_integer(random, 1, 4) * (random.below(2) == 0 ? 1 : -1));
        const float other = static_cast<float>(random_integer(random, -4, 4)) * small;
        q->rotation = random.below(2) == 0 ? point{large, other} : point{other, large};
    }
    switch (random.below(4)) {
        case 0:
        case 1: p.b.rotation = p.a.rotation; break;
        case 2: p.b.rotation = point{-p.a.rotation.y, p.a.rotation.x}; break;
        default: break;
    }
    return p;
}

/// A random pose of size 2^-20 to 2^20 and a pose with a corner on its outline.
inline pose_pair corner_on_outline(seeded_random& random) {
    const float size = std::ldexp(1.0f, random_integer(random, -20, 20));
    const point center{random.uniform(-4, 4) * size, random.uniform(-4, 4) * size};
    const rect_pose a = random_pose(random, center, size);
    return pose_pair{a, near_contact(random, a, size)};
}

/// corner_on_outline for sizes 1 to 100 at 1e7 to 3e7, where the float grid is 1 or 2.
inline pose_pair corner_on_outline_far(seeded_random& random) {
    const float size = random.uniform(1, 100);
    const point center{random.uniform(1e7f, 3e7f), -random.uniform(1e7f, 3e7f)};
    const rect_pose a = random_pose(random, center, size);
    return pose_pair{a, near_contact(random, a, size)};
}

/// A segment (or a box 2^-60 wide) through or near the origin along an integer
/// rotation (c, s), centered at zero or within 2^-30 of it, and a point k·(c, s) up
/// to 1024 along it, or a float step off: whether the point is on the segment's line
/// turns on far less than the rounding of the centers' difference in double.
inline pose_pair point_along_a_segment(seeded_random& random) {
    const point r = integer_rotation(random);
    const float k = static_cast<float>(random_integer(random, 1, 1024));
    auto tiny = [&] {
        return random.below(4) == 0 ? 0.0f : std::ldexp(random.uniform(-1, 1), -random_integer(random, 30, 70));
    };
    const point center{tiny(), tiny()};
    const float width = random.below(3) == 0 ? 0x1p-60f : 0.0f;
    const rect_pose segment{center, {k * random.uniform(0.5f, 1.5f), width}, r};
    rect_pose dot{{k * r.x, k * r.y}, {0, 0}, {1, 0}};
    if (random.below(4) == 0) {
        dot.center.x = nudged(dot.center.x, random_integer(random, -1, 1));
    }
    return pose_pair{segment, dot};
}

/// Any two poses centered in a square of side 16, half widths below 4.
inline pose_pair random_pair(seeded_random& random) {
    auto center = [&] { return point{random.uniform(-8, 8), random.uniform(-8, 8)}; };
    const rect_pose a = random_pose(random, center(), 4);
    return pose_pair{a, random_pose(random, center(), 4)};
}

struct pose_make {
    const char* name;
    pose_pair (*make)(seeded_random&);
};

/// Every make, by name.
inline constexpr pose_make pose_makes[] = {
    {"lattice", lattice_pair},
    {"lattice_far", lattice_pair_far},
    {"lattice_scaled_turns", lattice_pair_scaled_rotations},
    {"lattice_two_scale_turns", lattice_pair_two_scale_rotations},
    {"corner_on_outline", corner_on_outline},
    {"corner_on_outline_far", corner_on_outline_far},
    {"point_along_a_segment", point_along_a_segment},
    {"random", random_pair},
};

}  // namespace obbsat::test
