// The oracle on hand-worked cases, one or more per class and per kind of set
// (segment, point, rectangle, reflex quad, bow-tie), then its invariances:
// swapping the pair, relabelling corners, and scaling by powers of two (exact
// in float) never change the answer.
#include <obbsat/oracle/contact.hpp>

#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using obbsat::point;
using obbsat::rect;
using obbsat::oracle::classify;
using obbsat::oracle::contact;
using obbsat::oracle::intersects;

rect box(float x0, float y0, float x1, float y1) { return rect{{x0, y1}, {x1, y1}, {x1, y0}, {x0, y0}}; }
rect segment(point a, point b) { return rect{a, b, b, a}; }
rect dot(point p) { return rect{p, p, p, p}; }

constexpr contact S = contact::separated;
constexpr contact T = contact::touching;
constexpr contact O = contact::overlapping;

// Checks both orders, so every case also checks symmetry.
void expect_contact(const rect& a, const rect& b, contact want) {
    EXPECT_EQ(classify(a, b), want);
    EXPECT_EQ(classify(b, a), want);
    EXPECT_EQ(intersects(a, b), want != S);
}

TEST(contact, letters) {
    EXPECT_EQ(obbsat::oracle::contact_letter(S), 'S');
    EXPECT_EQ(obbsat::oracle::contact_letter(T), 'T');
    EXPECT_EQ(obbsat::oracle::contact_letter(O), 'O');
}

TEST(contact, segments) {
    expect_contact(segment({0, 0}, {2, 2}), segment({0, 2}, {2, 0}), T);    // crossing
    expect_contact(segment({0, 0}, {2, 2}), segment({2, 2}, {3, 0}), T);    // shared endpoint
    expect_contact(segment({0, 0}, {2, 2}), segment({1, 1}, {5, 0}), T);    // endpoint on the other
    expect_contact(segment({0, 0}, {2, 2}), segment({1, 1}, {3, 3}), T);    // collinear, overlapping
    expect_contact(segment({0, 0}, {2, 2}), segment({2, 2}, {3, 3}), T);    // collinear, end to end
    expect_contact(segment({0, 0}, {2, 2}), segment({3, 3}, {4, 4}), S);    // collinear, apart
    expect_contact(segment({0, 0}, {2, 0}), segment({0, 1}, {2, 1}), S);    // parallel
    expect_contact(segment({0, 0}, {2, 2}), segment({2, 0}, {1.5f, 1}), S); // would cross if longer
    expect_contact(segment({0, 0}, {0, 4}), segment({0, 1}, {0, 2}), T);    // vertical, nested
}

TEST(contact, points) {
    const rect square = box(0, 0, 2, 2);
    expect_contact(dot({1, 0}), square, T);        // on an edge
    expect_contact(dot({2, 2}), square, T);        // on a corner
    expect_contact(dot({1, 1}), square, T);        // inside: a point has no interior
    expect_contact(dot({3, 1}), square, S);        // outside
    expect_contact(dot({2, 2.5f}), square, S);     // beyond a corner
    expect_contact(dot({1, 1}), dot({1, 1}), T);
    expect_contact(dot({1, 1}), dot({1, std::nextafter(1.0f, 2.0f)}), S);
    expect_contact(dot({1, 1}), segment({0, 0}, {2, 2}), T);
    expect_contact(dot({1, std::nextafter(1.0f, 2.0f)}), segment({0, 0}, {2, 2}), S);
    expect_contact(dot({3, 3}), segment({0, 0}, {2, 2}), S);  // on the line, past the end
}

TEST(contact, segments_against_rectangles) {
    const rect square = box(0, 0, 2, 2);
    expect_contact(segment({-1, 1}, {3, 1}), square, T);   // through the middle
    expect_contact(segment({0, -1}, {0, 3}), square, T);   // along an edge line
    expect_contact(segment({-1, 3}, {3, -1}), square, T);  // along the square's diagonal
    expect_contact(segment({-1, 1}, {1, 3}), square, T);   // through corner (0, 2) only
    expect_contact(segment({-2, 2}, {0, 4}), square, S);
    expect_contact(segment({3, 0}, {3, 2}), square, S);
    expect_contact(segment({0.5f, 0.5f}, {1.5f, 1.5f}), square, T);  // wholly inside
}

TEST(contact, rectangles) {
    const rect a = box(0, 0, 2, 2);
    expect_contact(a, box(2, 0, 4, 2), T);              // edge on edge
    expect_contact(a, box(2, 1, 4, 3), T);              // edge on part of an edge
    expect_contact(a, box(2, 2, 4, 4), T);              // corner on corner
    expect_contact(a, rect{{1, 2}, {2, 3}, {1, 4}, {0, 3}}, T);  // corner on edge (a diamond)
    expect_contact(a, rect{{1, 1.5f}, {2, 2.5f}, {1, 3.5f}, {0, 2.5f}}, O);
    expect_contact(a, box(-1, 0.5f, 3, 1.5f), O);       // a cross
    expect_contact(a, box(0.5f, 0.5f, 1.5f, 1.5f), O);  // nested
    expect_contact(a, box(0, 0, 1, 1), O);              // nested, sharing two edges
    expect_contact(a, a, O);                            // identical
    expect_contact(a, rect{a.lr, a.ll, a.ul, a.ur}, O); // identical, relabelled
    expect_contact(a, box(std::nextafter(2.0f, 3.0f), 0, 4, 2), S);  // one float step apart
    expect_contact(a, box(std::nextafter(2.0f, 1.0f), 0, 4, 2), O);  // one float step into it
}

TEST(contact, a_reflex_quad_keeps_its_notch_empty) {
    // Arrowhead with the reflex corner (2, 1); the notch below it is outside.
    const rect dart{{0, 0}, {2, 1}, {4, 0}, {2, 4}};
    expect_contact(dart, dot({2, 0.5f}), S);                          // in the notch
    expect_contact(dart, dot({2, 1}), T);                             // the reflex corner
    expect_contact(dart, dot({2, 2}), T);                             // inside
    expect_contact(dart, box(1.75f, -1, 2.25f, 0.5f), S);             // fits into the notch
    expect_contact(dart, box(1.75f, -1, 2.25f, 1.5f), O);             // reaches the body
    expect_contact(dart, rect{{1, 0.5f}, {3, 0.5f}, {3, -1}, {1, -1}}, T);  // touches both notch edges
    expect_contact(dart, segment({2, 1}, {2, 3}), T);                 // along the diagonal
}

TEST(contact, a_bow_tie_covers_its_hull) {
    const rect bow_tie{{0, 0}, {4, 4}, {4, 0}, {0, 4}};
    // The hull is the square [0, 4]^2. Near the middle of its top edge lies
    // no point of either lobe of the crossed outline, yet the hull overlaps.
    expect_contact(bow_tie, box(1.5f, 3.5f, 2.5f, 5), O);
    expect_contact(bow_tie, box(4, 1, 5, 3), T);
    expect_contact(bow_tie, box(4.5f, 1, 5, 3), S);
}

TEST(contact, non_finite_input_is_rejected) {
    EXPECT_THROW(classify(box(0, 0, 1, 1), box(0, 0, NAN, 1)), std::invalid_argument);
}

rect relabel(const rect& r, int shift, bool reverse) {
    const point c[4] = {r.ul, r.ur, r.lr, r.ll};
    point o[4];
    for (int i = 0; i < 4; ++i) {
        o[i] = c[reverse ? (shift + 4 - i) % 4 : (shift + i) % 4];
    }
    return rect{o[0], o[1], o[2], o[3]};
}

rect scale(const rect& r, int exponent) {
    auto s = [&](point p) { return point{std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)}; };
    return rect{s(r.ul), s(r.ur), s(r.lr), s(r.ll)};
}

TEST(contact, invariant_under_swap_relabelling_and_power_of_two_scaling) {
    // Half-integer lattice corners in [-1.5, 1.5]: every form and every kind of
    // contact occurs, reflex and bow-tie quads included.
    obbsat::seeded_random random(77);
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 20000; ++i) {
        float v[16];
        for (float& x : v) {
            x = 0.5f * static_cast<float>(static_cast<int>(random.below(7)) - 3);
        }
        const rect a{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
        const rect b{{v[8], v[9]}, {v[10], v[11]}, {v[12], v[13]}, {v[14], v[15]}};
        const contact c = classify(a, b);
        ++counts[static_cast<int>(c)];
        ASSERT_EQ(classify(b, a), c);
        const int shift = static_cast<int>(random.below(4));
        const bool reverse = random.below(2) == 1;
        ASSERT_EQ(classify(relabel(a, shift, reverse), b), c);
        ASSERT_EQ(classify(a, relabel(b, shift, !reverse)), c);
        // 2^-140 pushes the lattice deep into the subnormals, 2^120 near the top.
        for (const int exponent : {-140, -60, 30, 120}) {
            ASSERT_EQ(classify(scale(a, exponent), scale(b, exponent)), c) << exponent;
        }
    }
    EXPECT_GT(counts[0], 1000);
    EXPECT_GT(counts[1], 1000);
    EXPECT_GT(counts[2], 1000);
}

}  // namespace
