// The pose oracle on hand-worked cases: exact contacts with integer rotation
// vectors (a rotation (3, 4) has length 5, so a half extent 1 reaches 5),
// corner and edge contacts, one float step either side of them, segments and
// points, rotation vectors far from unit length, slacks far below double
// precision, centers far from the origin, and invalid poses. Then its invariances, and agreement with the quad oracle
// on poses whose corners are exact in float.
#include <obbsat/oracle/pose_contact.hpp>

#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

using obbsat::point;
using obbsat::rect;
using obbsat::rect_pose;
using obbsat::oracle::classify;
using obbsat::oracle::classify_exact;
using obbsat::oracle::contact;
using obbsat::oracle::intersects;

constexpr contact S = contact::separated;
constexpr contact T = contact::touching;
constexpr contact O = contact::overlapping;

rect_pose pose(float cx, float cy, float hx, float hy, float c, float s) {
    return rect_pose{{cx, cy}, {hx, hy}, {c, s}};
}

float up(float v) { return std::nextafter(v, INFINITY); }
float down(float v) { return std::nextafter(v, -INFINITY); }

std::string show(const rect_pose& p) {
    char text[200];
    std::snprintf(text, sizeof text, "{c %a,%a h %a,%a r %a,%a}", static_cast<double>(p.center.x),
                  static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                  static_cast<double>(p.half_extents.y), static_cast<double>(p.rotation.x),
                  static_cast<double>(p.rotation.y));
    return text;
}

// Both orders and both paths, so every case also checks symmetry and that the
// double filter never changes an answer.
void expect_contact(const rect_pose& a, const rect_pose& b, contact want) {
    EXPECT_EQ(classify(a, b), want) << show(a) << " " << show(b);
    EXPECT_EQ(classify(b, a), want) << show(a) << " " << show(b);
    EXPECT_EQ(classify_exact(a, b), want) << show(a) << " " << show(b);
    EXPECT_EQ(classify_exact(b, a), want) << show(a) << " " << show(b);
    EXPECT_EQ(intersects(a, b), want != S) << show(a) << " " << show(b);
}

TEST(pose_contact, identical_poses) {
    expect_contact(pose(0, 0, 1, 2, 3, 4), pose(0, 0, 1, 2, 3, 4), O);
    expect_contact(pose(0.1f, -7, 0.3f, 1e-3f, 0.6f, -0.8f), pose(0.1f, -7, 0.3f, 1e-3f, 0.6f, -0.8f), O);
    expect_contact(pose(1, 2, 3, 0, 3, 4), pose(1, 2, 3, 0, 3, 4), T);  // a segment
    expect_contact(pose(1, 2, 0, 0, 3, 4), pose(1, 2, 0, 0, 3, 4), T);  // a point
}

TEST(pose_contact, edge_to_edge_with_a_rotation_of_length_five) {
    // A: u = (3, 4), v = (-4, 3), half widths 5 and 5. B, turned the same way,
    // sits 10 along u: the edges meet. Sliding B along v keeps them in contact.
    const rect_pose a = pose(0, 0, 1, 1, 3, 4);
    expect_contact(a, pose(6, 8, 1, 1, 3, 4), T);
    expect_contact(a, pose(2, 11, 1, 1, 3, 4), T);              // slid by v
    expect_contact(a, pose(10, 5, 1, 1, 3, 4), T);              // slid by -v
    expect_contact(a, pose(-2, 14, 1, 1, 3, 4), T);             // slid by 2v: corner on corner
    expect_contact(a, pose(-6, 17, 1, 1, 3, 4), S);             // slid by 3v
    expect_contact(a, pose(up(6), 8, 1, 1, 3, 4), S);           // one float step apart
    expect_contact(a, pose(6, up(8), 1, 1, 3, 4), S);
    expect_contact(a, pose(down(6), 8, 1, 1, 3, 4), O);         // one float step into it
    expect_contact(a, pose(6, 8, down(1.0f), 1, 3, 4), S);      // B one step shorter
    expect_contact(a, pose(6, 8, up(1.0f), 1, 3, 4), O);        // B one step longer
    expect_contact(a, pose(6, 8, 1, 1, up(3.0f), 4), O);        // B's u one step longer
}

TEST(pose_contact, axis_rotations_and_a_quarter_turn) {
    // (0, 1): u points up, so hx spans y. A covers x in [-2, 2], y in [-1, 1].
    const rect_pose a = pose(0, 0, 1, 2, 0, 1);
    expect_contact(a, pose(5, 0, 3, 1, 1, 0), T);   // x in [2, 8]
    expect_contact(a, pose(5, 0, 3, 1, -1, 0), T);  // the same set, u reversed
    expect_contact(a, pose(5, 2, 3, 1, 1, 0), T);   // corner on corner (2, 1)
    expect_contact(a, pose(5, up(2.0f), 3, 1, 1, 0), S);
    expect_contact(a, pose(up(5.0f), 0, 3, 1, 1, 0), S);
    expect_contact(a, pose(down(5.0f), 0, 3, 1, 1, 0), O);
    // (-4, 3) is (3, 4) turned a quarter: B's u is A's v. B sits 10 along A's v.
    const rect_pose b = pose(0, 0, 1, 1, 3, 4);
    expect_contact(b, pose(-8, 6, 1, 1, -4, 3), T);
    expect_contact(b, pose(-8, up(6.0f), 1, 1, -4, 3), S);
    expect_contact(b, pose(-8, down(6.0f), 1, 1, -4, 3), O);
    expect_contact(b, pose(-8, 6, 1, 1, -4, up(3.0f)), O);
}

TEST(pose_contact, corner_to_corner) {
    // Turned the same way: A's corner u + v = (-1, 7) is B's corner -u - v.
    const rect_pose a = pose(0, 0, 1, 1, 3, 4);
    expect_contact(a, pose(-2, 14, 1, 1, 3, 4), T);
    expect_contact(a, pose(-2, up(14.0f), 1, 1, 3, 4), S);
    expect_contact(a, pose(down(-2.0f), 14, 1, 1, 3, 4), S);
    expect_contact(a, pose(-2, down(14.0f), 1, 1, 3, 4), O);
    // A diamond (rotation (1, 1), half diagonal 2) resting its bottom corner on
    // the corner (1, 1) of the square [-1, 1]^2, its edges leaving upwards.
    const rect_pose square = pose(0, 0, 1, 1, 1, 0);
    expect_contact(square, pose(1, 3, 1, 1, 1, 1), T);
    expect_contact(square, pose(1, up(3.0f), 1, 1, 1, 1), S);
    expect_contact(square, pose(1, down(3.0f), 1, 1, 1, 1), O);
    expect_contact(square, pose(0, 3, 1, 1, 1, 1), T);   // bottom corner on the edge y = 1
    expect_contact(square, pose(3, 1, 1, 1, 1, 1), T);   // left corner on the corner (1, 1)
}

TEST(pose_contact, points) {
    const rect_pose square = pose(0, 0, 1, 1, 3, 4);  // corners (-1, 7), (7, 1), (1, -7), (-7, -1)
    expect_contact(pose(7, 1, 0, 0, 1, 0), square, T);          // on a corner
    expect_contact(pose(3, 4, 0, 0, 1, 0), square, T);          // on an edge: u·5/5
    expect_contact(pose(up(3.0f), 4, 0, 0, 1, 0), square, S);
    expect_contact(pose(down(3.0f), 4, 0, 0, -7, 2), square, T);  // inside; its rotation is irrelevant
    expect_contact(pose(0, 0, 0, 0, 1, 0), square, T);          // the center: still only touching
    expect_contact(pose(8, 1, 0, 0, 1, 0), square, S);
    expect_contact(pose(1, 1, 0, 0, 1, 0), pose(1, 1, 0, 0, 0, -2), T);
    expect_contact(pose(1, 1, 0, 0, 1, 0), pose(1, up(1.0f), 0, 0, 1, 0), S);
}

TEST(pose_contact, segments) {
    const rect_pose square = pose(0, 0, 1, 1, 1, 0);  // [-1, 1]^2
    // From the corner (1, 1) outwards along (3, 4): touches at the corner.
    expect_contact(pose(4, 5, 1, 0, 3, 4), square, T);
    expect_contact(pose(up(4.0f), 5, 1, 0, 3, 4), square, S);
    expect_contact(pose(0, 0, 1, 0, 3, 4), square, T);          // through it: no interior
    expect_contact(pose(0, 0, 0, 1, 3, 4), square, T);          // the same along v
    expect_contact(pose(0, 0, 0.1f, 0, 3, 4), square, T);       // wholly inside
    expect_contact(pose(0, 3, 2, 0, 1, 0), square, S);          // parallel, above
    expect_contact(pose(0, 1, 2, 0, 1, 0), square, T);          // along the top edge
    expect_contact(pose(0, 1, -0.0f, 2, 0, 1), square, T);      // the same along v = (-1, 0), hx = -0
    // Segment against segment, all along (3, 4) or crossing it.
    const rect_pose s = pose(0, 0, 1, 0, 3, 4);  // from (-3, -4) to (3, 4)
    expect_contact(s, pose(0, 0, 1, 0, -4, 3), T);               // crossing at the middle
    expect_contact(s, pose(6, 8, 1, 0, 3, 4), T);                // end to end
    expect_contact(s, pose(6, up(8.0f), 1, 0, 3, 4), S);         // parallel, one step off the line
    expect_contact(s, pose(up(6.0f), 8, 1, 0, 3, 4), S);
    expect_contact(s, pose(3, 4, 1, 0, 3, 4), T);                // collinear, overlapping half
    expect_contact(s, pose(7, 1, 0, 5, 3, 4), T);                // crossing at the end (3, 4), along v
    expect_contact(s, pose(up(7.0f), 1, 0, 5, 3, 4), S);
    // Points on a segment.
    expect_contact(s, pose(1.5f, 2, 0, 0, 1, 0), T);
    expect_contact(s, pose(1.5f, up(2.0f), 0, 0, 1, 0), S);
    expect_contact(s, pose(-3, -4, 0, 0, 1, 0), T);
    expect_contact(s, pose(-6, -8, 0, 0, 1, 0), S);              // on the line, past the end
}

TEST(pose_contact, rotation_vectors_far_from_unit_length) {
    // The same sets as (3, 4) with half extents 1, the rotation scaled by 2^-66
    // (about 1e-20) or 2^50 (about 1e15) and the half extents by the inverse.
    const float small = 0x1p-66f, large = 0x1p50f;
    const rect_pose a_small = pose(0, 0, 0x1p66f, 0x1p66f, 3 * small, 4 * small);
    const rect_pose a_large = pose(0, 0, 0x1p-50f, 0x1p-50f, 3 * large, 4 * large);
    for (const rect_pose& a : {a_small, a_large}) {
        expect_contact(a, pose(6, 8, 1, 1, 3, 4), T);
        expect_contact(a, pose(6, 8, 0x1p-50f, 0x1p-50f, 3 * large, 4 * large), T);
        expect_contact(a, pose(-2, 14, 0x1p66f, 0x1p66f, 3 * small, 4 * small), T);
        expect_contact(a, pose(up(6.0f), 8, 1, 1, 3, 4), S);
        expect_contact(a, pose(down(6.0f), 8, 0x1p66f, 0x1p66f, 3 * small, 4 * small), O);
        expect_contact(a, pose(3, 4, 0, 0, 1, 0), T);
        expect_contact(a, pose(up(3.0f), 4, 0, 0, 1, 0), S);
    }
    // A tiny rotation with a unit half extent is a tiny box: 1e-20 wide.
    const rect_pose tiny = pose(0, 0, 1, 1, 1e-20f, 0);
    expect_contact(tiny, pose(1e-20f, 0, 0, 0, 1, 0), T);
    expect_contact(tiny, pose(up(1e-20f), 0, 0, 0, 1, 0), S);
    expect_contact(tiny, pose(2e-20f, 0, 1, 1, 1e-20f, 0), T);
    expect_contact(tiny, pose(down(2e-20f), 0, 1, 1, 1e-20f, 0), O);
}

TEST(pose_contact, slacks_below_double_precision) {
    // Rotation (1, t), t = 2^-30: squared length 1 + 2^-60, which rounds to 1
    // in double. B, turned as A, sits 2 along x: the slack along A's u is
    // 2·(1 + t²) − 2 = 2^-59, overlapping where double sees edges touching.
    const float t = 0x1p-30f;
    const rect_pose a = pose(0, 0, 1, 1, 1, t);
    expect_contact(a, pose(2, 2 * t, 1, 1, 1, t), T);        // 2u: edge on edge
    expect_contact(a, pose(2, 0, 1, 1, 1, t), O);            // slack 2^-59
    expect_contact(a, pose(2, up(2 * t), 1, 1, 1, t), S);    // slack -2^-82
    expect_contact(a, pose(2, down(2 * t), 1, 1, 1, t), O);
    expect_contact(a, pose(1, t, 0, 0, 1, 0), T);            // a point on that edge
    expect_contact(a, pose(1, up(t), 0, 0, 1, 0), S);        // slack -2^-83
    // A segment from the origin along (1, 4), its center 2^65 away: in double
    // the small box's center is lost in the differences (float steps there
    // are 2^42), so double arithmetic finds no separating axis.
    const float x = 0x1p65f;
    const rect_pose ray = pose(x, 4 * x, x, 0, 1, 4);        // from (0, 0) to (2x, 8x)
    expect_contact(ray, pose(0.5f, -0.25f, 0.25f, 0.25f, 1, 0), S);
    expect_contact(ray, pose(0.25f, -0.25f, 0.25f, 0.25f, 1, 0), T);  // corner on the end
    expect_contact(ray, pose(0, 0, 0.25f, 0.25f, 1, 0), T);           // the end inside a box
    expect_contact(ray, pose(-0.25f, 0, 0.25f, 0.25f, 0, 1), T);
    expect_contact(ray, pose(-0.25f - 0x1p-20f, 0, 0.25f, 0.25f, 0, 1), S);
    // A segment along (4, 3) centered about 2^-42 from the origin, and a point
    // 623·(4, 3) away: it misses the segment's line by less than the rounding
    // of the centers' difference in double (2^-41), so even the sign of that
    // difference along the axis (-3, 4) must be found exactly.
    const rect_pose along = pose(0x1.c0ff08p-42f, 0x1.6a928cp-42f, 1246, 0, 4, 3);
    expect_contact(along, pose(2492, 1869, 0, 0, 1, 0), S);
    expect_contact(pose(0, 0, 1246, 0, 4, 3), pose(2492, 1869, 0, 0, 1, 0), T);
    expect_contact(pose(0x1p-42f, 0x1.5555p-42f, 1246, 0, 4, 3), pose(2492, 1869, 0, 0, 1, 0), S);
}

TEST(pose_contact, far_from_the_origin) {
    // Floats are 1 apart near 1e7 and 2 apart near 3e7: these centers are exact.
    const float x = 1e7f, y = 3e7f;
    const rect_pose a = pose(x, y, 1, 1, 3, 4);
    expect_contact(a, pose(x + 6, y + 8, 1, 1, 3, 4), T);       // edge to edge
    expect_contact(a, pose(x - 2, y + 14, 1, 1, 3, 4), T);      // corner to corner
    expect_contact(a, pose(x + 7, y + 8, 1, 1, 3, 4), S);       // one float step apart
    expect_contact(a, pose(x + 5, y + 8, 1, 1, 3, 4), O);
    expect_contact(a, pose(x + 6, y + 10, 1, 1, 3, 4), S);
    expect_contact(a, pose(x + 6, y + 6, 1, 1, 3, 4), O);
    expect_contact(a, pose(x - 8, y + 6, 1, 1, -4, 3), T);      // a quarter turn, along A's v
    expect_contact(a, pose(x + 3, y + 4, 0, 0, 1, 0), T);       // a point on an edge
    expect_contact(a, pose(x + 4, y + 4, 0, 0, 1, 0), S);
    // Against a box near the origin: the centers' difference is not a float.
    expect_contact(pose(0, 0, 1, 1, 1, 0), pose(x, 0.5f, x - 1, 1, 1, 0), T);
    expect_contact(pose(1e-30f, 0, 1, 1, 1, 0), pose(x, 0.5f, x - 1, 1, 1, 0), O);
    expect_contact(pose(-1e-30f, 0, 1, 1, 1, 0), pose(x, 0.5f, x - 1, 1, 1, 0), S);
    expect_contact(pose(1e-30f, 0, 0, 0, 1, 0), pose(x, 0.5f, x - 1, 1, 1, 0), S);  // a point
    expect_contact(pose(1, 1e-30f, 0, 0, 1, 0), pose(x, 0.5f, x - 1, 1, 1, 0), T);
}

TEST(pose_contact, a_zero_half_extent_may_be_negative_zero) {
    expect_contact(pose(0, 0, -0.0f, 1, 1, 0), pose(0, 0, 1, 1, 1, 0), T);
    expect_contact(pose(0, 0, -0.0f, -0.0f, 1, 0), pose(0, 0, 1, 1, 1, 0), T);
}

TEST(pose_contact, invalid_poses_are_rejected) {
    const rect_pose good = pose(0, 0, 1, 1, 1, 0);
    const rect_pose bad[] = {
        pose(NAN, 0, 1, 1, 1, 0),      pose(0, INFINITY, 1, 1, 1, 0),  pose(0, 0, INFINITY, 1, 1, 0),
        pose(0, 0, 1, 1, NAN, 0),      pose(0, 0, 1, 1, 1, -INFINITY), pose(0, 0, -1, 1, 1, 0),
        pose(0, 0, 1, -1e-45f, 1, 0),  pose(0, 0, 1, 1, 0, 0),         pose(0, 0, 1, 1, -0.0f, -0.0f),
        pose(INFINITY, 0, 0, 0, 0, 1), pose(0, 0, NAN, 0, 1, 0),       pose(0, 0, 0, INFINITY, 0, 1),
        pose(0, 0, 0, 0, INFINITY, 0), pose(0, 0, -INFINITY, 0, 1, 0), pose(NAN, NAN, 0, 0, 0, 0),
    };
    // Zero half extents and a rotation component 0 in the partners, so that
    // a product of 0 and an infinity (NaN) must be seen too.
    const rect_pose partners[] = {good, pose(0, 0, 0, 0, 0, 1)};
    for (const rect_pose& partner : partners) {
        EXPECT_EQ(obbsat::oracle::pose_defect(partner), nullptr);
    }
    for (const rect_pose& p : bad) {
        EXPECT_NE(obbsat::oracle::pose_defect(p), nullptr) << show(p);
        for (const rect_pose& partner : partners) {
            EXPECT_THROW(classify(p, partner), std::invalid_argument) << show(p);
            EXPECT_THROW(classify(partner, p), std::invalid_argument) << show(p);
            EXPECT_THROW(classify_exact(partner, p), std::invalid_argument) << show(p);
            EXPECT_THROW(intersects(p, partner), std::invalid_argument) << show(p);
        }
    }
    try {
        classify(good, pose(0, 0, 1, -2, 1, 0));
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("pose b: a half extent is negative"), std::string::npos)
            << error.what();
    }
}

// A pose with small integer rotation, half extents and center, so that its
// corners are exact in float; half extents zero now and then.
rect_pose lattice_pose(obbsat::seeded_random& random) {
    auto integer = [&](int lo, int hi) {
        const auto span = static_cast<std::uint64_t>(hi - lo + 1);
        return static_cast<float>(lo + static_cast<int>(random.below(span)));
    };
    rect_pose p{{integer(-6, 6), integer(-6, 6)}, {integer(0, 2), integer(0, 2)}, {0, 0}};
    while (p.rotation.x == 0 && p.rotation.y == 0) {
        p.rotation = point{integer(-3, 3), integer(-3, 3)};
    }
    return p;
}

rect corners_of(const rect_pose& p) {
    const float ux = p.half_extents.x * p.rotation.x, uy = p.half_extents.x * p.rotation.y;
    const float vx = -p.half_extents.y * p.rotation.y, vy = p.half_extents.y * p.rotation.x;
    const point c = p.center;
    return rect{{c.x - ux + vx, c.y - uy + vy},
                {c.x + ux + vx, c.y + uy + vy},
                {c.x + ux - vx, c.y + uy - vy},
                {c.x - ux - vx, c.y - uy - vy}};
}

rect_pose scaled(const rect_pose& p, int exponent, int rotation_exponent) {
    auto s = [](float v, int e) { return std::ldexp(v, e); };
    return rect_pose{{s(p.center.x, exponent), s(p.center.y, exponent)},
                     {s(p.half_extents.x, exponent - rotation_exponent),
                      s(p.half_extents.y, exponent - rotation_exponent)},
                     {s(p.rotation.x, rotation_exponent), s(p.rotation.y, rotation_exponent)}};
}

TEST(pose_contact, agrees_with_the_quad_oracle_on_exact_corners) {
    // On this lattice the corners (within +-6 + 2*3 + 2*3) are exact in float,
    // so the quad oracle sees exactly the same sets, by another argument.
    obbsat::seeded_random random(31);
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 100000; ++i) {
        const rect_pose a = lattice_pose(random);
        const rect_pose b = lattice_pose(random);
        const contact want = classify(corners_of(a), corners_of(b));
        ASSERT_EQ(classify(a, b), want) << show(a) << " " << show(b);
        ASSERT_EQ(classify_exact(a, b), want) << show(a) << " " << show(b);
        ++counts[static_cast<int>(want)];
    }
    for (const int count : counts) {
        EXPECT_GT(count, 10000);
    }
}

TEST(pose_contact, invariant_under_swap_and_power_of_two_scaling) {
    // Scaling every length by 2^e keeps the answer; so does scaling the
    // rotation vectors by 2^k and the half extents by 2^-k, for any e and k
    // that keep the floats exact (here: down to subnormals, up to 2^121).
    obbsat::seeded_random random(32);
    for (int i = 0; i < 20000; ++i) {
        const rect_pose a = lattice_pose(random);
        const rect_pose b = lattice_pose(random);
        const contact c = classify(a, b);
        ASSERT_EQ(classify(b, a), c);
        for (const int exponent : {-120, -40, 0, 60, 100}) {
            for (const int rotation_exponent : {-20, 0, 7}) {
                const int ka = rotation_exponent, kb = -rotation_exponent / 2;
                ASSERT_EQ(classify(scaled(a, exponent, ka), scaled(b, exponent, kb)), c)
                    << show(a) << " " << show(b) << " " << exponent << " " << rotation_exponent;
            }
        }
    }
}

TEST(pose_contact, slack_signs_and_terms_of_each_axis_by_hand) {
    // A: u = (3, 4), v = (-4, 3), half extents 1 and 2; B axis-aligned, half
    // extents 2 and 1, at d = (6, 8). na = 25, nb = 1, p = 3, q = -4.
    const rect_pose a = pose(0, 0, 1, 2, 3, 4);
    const rect_pose b = pose(6, 8, 2, 1, 1, 0);
    const auto terms = obbsat::oracle::terms_of_axes(a, b);
    const double want[4][3] = {{50, 25, 10}, {0, 50, 11}, {6, 11, 2}, {8, 10, 1}};
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(terms[k].offset, want[k][0]) << k;
        EXPECT_EQ(terms[k].reach_a, want[k][1]) << k;
        EXPECT_EQ(terms[k].reach_b, want[k][2]) << k;
    }
    EXPECT_EQ(obbsat::oracle::slack_signs(a, b), (std::array<int, 4>{-1, 1, 1, 1}));
    // Edge to edge along A's u (see above): zero slack there and on B's u.
    const rect_pose c = pose(0, 0, 1, 1, 3, 4);
    EXPECT_EQ(obbsat::oracle::slack_signs(c, pose(6, 8, 1, 1, 3, 4)), (std::array<int, 4>{0, 1, 0, 1}));
    EXPECT_EQ(obbsat::oracle::slack_signs(c, pose(up(6), 8, 1, 1, 3, 4)), (std::array<int, 4>{-1, 1, -1, 1}));
    EXPECT_THROW(obbsat::oracle::slack_signs(c, pose(0, 0, 1, 1, 0, 0)), std::invalid_argument);
    EXPECT_THROW(obbsat::oracle::terms_of_axes(pose(0, 0, -1, 1, 1, 0), c), std::invalid_argument);
}

TEST(pose_contact, slack_signs_agree_with_the_class_and_with_the_terms) {
    // On the lattice every term is a small integer, exact in double: the sign
    // of reach_a + reach_b - |offset| is the slack's sign.
    obbsat::seeded_random random(34);
    for (int i = 0; i < 50000; ++i) {
        const rect_pose a = lattice_pose(random);
        const rect_pose b = lattice_pose(random);
        const std::array<int, 4> signs = obbsat::oracle::slack_signs(a, b);
        const auto terms = obbsat::oracle::terms_of_axes(a, b);
        bool some_negative = false, all_positive = true;
        for (std::size_t k = 0; k < 4; ++k) {
            const double slack = terms[k].reach_a + terms[k].reach_b - std::fabs(terms[k].offset);
            ASSERT_EQ(signs[k], (slack > 0) - (slack < 0)) << show(a) << " " << show(b) << " axis " << k;
            some_negative = some_negative || signs[k] < 0;
            all_positive = all_positive && signs[k] > 0;
        }
        const bool areas = a.half_extents.x > 0 && a.half_extents.y > 0 && b.half_extents.x > 0 &&
                           b.half_extents.y > 0;
        const contact want = some_negative ? S : all_positive && areas ? O : T;
        ASSERT_EQ(classify(a, b), want) << show(a) << " " << show(b);
    }
}

TEST(pose_contact, pair_list_matches_one_classify_per_pair) {
    obbsat::seeded_random random(33);
    std::vector<rect_pose> poses(500);
    for (rect_pose& p : poses) {
        p = lattice_pose(random);
    }
    std::vector<obbsat::pair_index> pairs(20000);
    for (obbsat::pair_index& p : pairs) {
        p = obbsat::pair_index{static_cast<std::uint32_t>(random.below(poses.size())),
                               static_cast<std::uint32_t>(random.below(poses.size()))};
    }
    std::vector<contact> expected(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        expected[i] = classify(poses[pairs[i].a], poses[pairs[i].b]);
    }
    for (const unsigned threads : {1u, 2u, 3u, 0u}) {
        EXPECT_EQ(obbsat::oracle::classify_pairs(poses, pairs, threads), expected) << threads;
    }
}

TEST(pose_contact, pair_list_names_an_invalid_pose_and_writes_nothing) {
    std::vector<rect_pose> poses(10, pose(0, 0, 1, 1, 1, 0));
    poses[6].rotation = point{0, 0};
    const std::vector<obbsat::pair_index> pairs(100, obbsat::pair_index{0, 1});
    const contact not_written = static_cast<contact>(0xab);
    std::vector<contact> out(pairs.size(), not_written);
    try {
        obbsat::oracle::classify_pairs(poses.data(), poses.size(), pairs.data(), pairs.size(), out.data());
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("pose 6"), std::string::npos) << error.what();
    }
    std::vector<obbsat::pair_index> beyond(5000, obbsat::pair_index{1, 2});
    beyond[4321] = obbsat::pair_index{10, 0};
    poses[6].rotation = point{1, 0};
    out.assign(beyond.size(), not_written);
    EXPECT_THROW(obbsat::oracle::classify_pairs(poses.data(), poses.size(), beyond.data(), beyond.size(),
                                                out.data(), 2),
                 std::out_of_range);
    for (const contact c : out) {
        ASSERT_EQ(c, not_written);
    }
}

}  // namespace
