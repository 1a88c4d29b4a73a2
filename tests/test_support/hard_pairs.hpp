// Pairs of rectangles where a kernel that deviates from the reference's
// operation order would show it: exact contact on integer corners, contact
// moved by a few ulps, near-parallel edges, slivers, segments and points,
// large offsets, overflowing products and subnormal coordinates.
//
// Built from a fixed seed with basic IEEE arithmetic, std::nextafter and
// std::ldexp only (no sin, cos, pow), so the list is the same, bit for bit,
// on every machine: the golden digest in test_backends covers it. Every random
// draw is its own statement (or inside a braced list, which C++ evaluates left
// to right): the order of function arguments is unspecified.
#pragma once

#include "rect_shapes.hpp"

#include <obbsat/rect.hpp>
#include <obbsat/scene.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace obbsat::test_support {

struct labelled_pair {
    rect a;
    rect b;
    const char* family;
};

namespace hard_pairs_detail {

/// `value` moved `steps` floats toward +inf (steps > 0) or -inf (steps < 0).
inline float nudged(float value, int steps) {
    const float toward = steps > 0 ? HUGE_VALF : -HUGE_VALF;
    for (int k = 0; k < (steps > 0 ? steps : -steps); ++k) {
        value = std::nextafter(value, toward);
    }
    return value;
}

inline rect nudged(const rect& r, int x_steps, int y_steps) {
    auto move = [&](point p) { return point{nudged(p.x, x_steps), nudged(p.y, y_steps)}; };
    return rect{move(r.ul), move(r.ur), move(r.lr), move(r.ll)};
}

/// A float in [1, 2) times 2^exponent: a random magnitude without pow.
inline double magnitude(seeded_random& random, int min_exponent, int max_exponent) {
    const auto span = static_cast<std::uint64_t>(max_exponent - min_exponent + 1);
    const int exponent = min_exponent + static_cast<int>(random.below(span));
    return std::ldexp(static_cast<double>(random.uniform(1.0f, 2.0f)), exponent);
}

inline double signed_unit(seeded_random& random) {
    return static_cast<double>(random.uniform(-1.0f, 1.0f));
}

/// Collects pairs, each also in swapped order and with B walked the other way.
class pair_list {
public:
    explicit pair_list(std::vector<labelled_pair>& out) : out_(out) {}

    void add(const rect& a, const rect& b, const char* family) {
        out_.push_back({a, b, family});
        out_.push_back({b, a, family});
        out_.push_back({a, reversed_winding(b), family});
        out_.push_back({relabelled(b), a, family});
    }

private:
    std::vector<labelled_pair>& out_;
};

/// A rectangle touching another, and a lattice vector that moves it out of contact.
struct contact {
    rect b;
    point outward;
};

/// Rectangles touching a = integer_rect(origin, ea, eb, k) exactly: along an
/// edge, on part of an edge, corner to corner, or by one corner on an edge.
inline std::vector<contact> integer_contacts(point origin, int ea, int eb, int k) {
    const point u{static_cast<float>(ea), static_cast<float>(eb)};
    const point w{static_cast<float>(-eb), static_cast<float>(ea)};
    const point v = scaled(w, static_cast<float>(k));
    const point low_right = plus(origin, u);
    // Lattice steps with a positive share of u (resp. w): (+-1, 0) or (0, +-1).
    const point along_u =
        ea != 0 ? point{ea > 0 ? 1.0f : -1.0f, 0.0f} : point{0.0f, eb > 0 ? 1.0f : -1.0f};
    const point along_w =
        eb != 0 ? point{eb > 0 ? -1.0f : 1.0f, 0.0f} : point{0.0f, ea > 0 ? 1.0f : -1.0f};
    // -(u + w) has a negative share of both u and w.
    const point away_from_both = scaled(plus(u, w), -1.0f);
    // Both edges of a corner-on B point away from A along u, so B meets A in its corner only.
    const point outward_left = plus(u, w);
    const point outward_right = minus(u, w);
    std::vector<contact> out;
    out.push_back({from_edges(low_right, u, v), along_u});           // edge on edge
    out.push_back({from_edges(plus(origin, v), u, v), along_w});     // on the top edge
    out.push_back({from_edges(plus(low_right, v), u, v), along_u});  // corner on corner
    out.push_back({from_edges(minus(origin, plus(u, v)), u, v), away_from_both});  // corner below
    for (int j = 0; j <= k; ++j) {
        const point on_edge = plus(low_right, scaled(w, static_cast<float>(j)));
        // Part of an edge, then one corner on the edge.
        out.push_back({from_edges(on_edge, u, w), along_u});
        out.push_back({from_edges(on_edge, outward_left, outward_right), along_u});
    }
    return out;
}

inline void add_integer_contacts(pair_list& list) {
    const point origins[] = {{0, 0}, {7, -3}};
    for (const point origin : origins) {
        for (int ea = -3; ea <= 3; ++ea) {
            for (int eb = -3; eb <= 3; ++eb) {
                if (ea == 0 && eb == 0) {
                    continue;
                }
                for (int k = 1; k <= 3; ++k) {
                    const rect a = integer_rect(origin, ea, eb, k);
                    for (const contact& c : integer_contacts(origin, ea, eb, k)) {
                        list.add(a, c.b, "integer_touching");
                        list.add(a, translated(c.b, c.outward), "integer_one_step_apart");
                        list.add(a, translated(c.b, scaled(c.outward, -1.0f)),
                                 "integer_one_step_in");
                    }
                }
            }
        }
    }
    // Identical and nested rectangles.
    for (int ea = -3; ea <= 3; ++ea) {
        for (int eb = 1; eb <= 3; ++eb) {
            const rect outer = integer_rect({-1, -2}, 4 * ea, 4 * eb, 2);
            const rect inner =
                integer_rect({static_cast<float>(ea - eb), static_cast<float>(eb + ea)}, ea, eb, 2);
            list.add(outer, outer, "integer_identical");
            list.add(outer, inner, "integer_nested");
        }
    }
}

/// Contacts moved 1 to 4 ulps per coordinate, apart or together, in 8 directions,
/// at the origin (where zero moves to a subnormal) and around 1e6 (ulp 1/16 or 1/8).
inline void add_ulp_moves(pair_list& list) {
    const point origins[] = {{0, 0}, {1048576, -1000000}};
    for (const point origin : origins) {
        for (int ea = -2; ea <= 2; ++ea) {
            for (int eb = -2; eb <= 2; ++eb) {
                if (ea == 0 && eb == 0) {
                    continue;
                }
                const int k = 2;
                const rect a = integer_rect(origin, ea, eb, k);
                for (const contact& c : integer_contacts(origin, ea, eb, k)) {
                    const rect& b = c.b;
                    for (int steps = 1; steps <= 4; ++steps) {
                        for (int dx = -1; dx <= 1; ++dx) {
                            for (int dy = -1; dy <= 1; ++dy) {
                                if (dx != 0 || dy != 0) {
                                    list.add(a, nudged(b, dx * steps, dy * steps), "ulp_moves");
                                }
                            }
                        }
                    }
                }
            }
        }
    }
}

/// Long rectangles whose facing edges are within 1e-6 rad of parallel and
/// within a few ulps of touching.
inline void add_near_parallel(pair_list& list, seeded_random& random, int count) {
    for (int i = 0; i < count; ++i) {
        const double length = magnitude(random, 0, 10);
        const double height = length * magnitude(random, -10, -1);
        // A half-angle tangent t turns by 2t (to within t^3): |angle| <= 1e-6.
        const turn turn_a = turn_from_half_tangent(0.5e-6 * signed_unit(random));
        const turn turn_b = turn_from_half_tangent(0.5e-6 * signed_unit(random));
        const double cx = (i % 3 == 0) ? magnitude(random, 10, 20) : 0.0;
        const double cy = (i % 5 == 0) ? -magnitude(random, 10, 20) : 0.0;
        const double other_height = height * static_cast<double>(random.uniform(0.5f, 2.0f));
        // Gap between the facing edges: exact contact, or a few ulps of the coordinates.
        const double ulp = std::ldexp(1.0, std::ilogb(std::fabs(cy) + height + other_height) - 23);
        const double gap = static_cast<double>(static_cast<int>(random.below(9)) - 4) * ulp;
        const double slide = length * signed_unit(random);
        const double other_length = length * static_cast<double>(random.uniform(0.5f, 2.0f));
        const rect a = turned_rect(cx, cy, length, height, turn_a.c, turn_a.s);
        const rect b = turned_rect(cx + slide, cy + height + other_height + gap, other_length,
                                   other_height, turn_b.c, turn_b.s);
        list.add(a, b, "near_parallel");
        // The same pair on its side, so the facing edges are near-vertical.
        auto on_side = [](const rect& r) {
            auto flip = [](point p) { return point{-p.y, p.x}; };
            return rect{flip(r.ul), flip(r.ur), flip(r.lr), flip(r.ll)};
        };
        list.add(on_side(a), on_side(b), "near_parallel");
    }
}

/// Rectangles a million times longer than wide, crossing, stacked or side by side.
inline void add_slivers(pair_list& list, seeded_random& random, int count) {
    for (int i = 0; i < count; ++i) {
        const double length = magnitude(random, -4, 12);
        const double width = length * 1.0e-6;
        const turn turn_a = turn_from_half_tangent(signed_unit(random));
        const turn turn_b = (i % 2 == 0) ? turn_a : turn_from_half_tangent(signed_unit(random));
        const double cx = length * signed_unit(random);
        const double cy = length * signed_unit(random);
        const rect a = turned_rect(0.0, 0.0, length, width, turn_a.c, turn_a.s);
        list.add(a, turned_rect(cx, cy, length, width, turn_b.c, turn_b.s), "slivers");
        // Stacked parallel slivers, a few widths apart or overlapping.
        const double offset = width * static_cast<double>(static_cast<int>(random.below(7)) - 1);
        list.add(
            a,
            turned_rect(-turn_a.s * offset, turn_a.c * offset, length, width, turn_a.c, turn_a.s),
            "slivers");
        // A sliver against an ordinary rectangle.
        list.add(a, turned_rect(cx, cy, length * 0.1, length * 0.05, turn_b.c, turn_b.s),
                 "slivers");
    }
}

/// Zero-width rectangles (segments) and zero-size ones (points), on a small
/// lattice so that they often touch exactly, and at random float positions.
inline void add_segments_and_points(pair_list& list, seeded_random& random, int count) {
    auto lattice = [&]() {
        return point{static_cast<float>(static_cast<int>(random.below(9)) - 4),
                     static_cast<float>(static_cast<int>(random.below(9)) - 4)};
    };
    auto anywhere = [&]() {
        return point{random.uniform(-4.0f, 4.0f), random.uniform(-4.0f, 4.0f)};
    };
    for (int i = 0; i < count; ++i) {
        const bool on_lattice = i % 2 == 0;
        auto spot = [&]() { return on_lattice ? lattice() : anywhere(); };
        const point box_origin = lattice();
        const int ea = static_cast<int>(random.below(4)) + 1;
        const int eb = static_cast<int>(random.below(7)) - 3;
        const rect box = integer_rect(box_origin, ea, eb, 1);
        const point spots[5] = {spot(), spot(), spot(), spot(), spot()};
        const rect segment = segment_rect(spots[0], spots[1]);
        const rect dot = point_rect(spots[2]);
        list.add(box, segment, "segments_points");
        list.add(box, dot, "segments_points");
        list.add(segment, segment_rect(spots[3], spots[4]), "segments_points");
        list.add(segment, dot, "segments_points");
        list.add(dot, point_rect(spots[3]), "segments_points");
        list.add(dot, dot, "segments_points");
        // A segment lying along an edge of the box, and a point on its corner.
        list.add(box, segment_rect(box.ul, box.ur), "segments_points");
        list.add(box, point_rect(box.lr), "segments_points");
    }
}

/// Ordinary and touching pairs far from the origin, where the coordinates'
/// ulp is 1/16 (1e6) or 1 (1e7) and the products lose most of their bits.
inline void add_offsets(pair_list& list, seeded_random& random, int count) {
    const double offsets[] = {1.0e6, 1.0e7};
    const char* families[] = {"offset_1e6", "offset_1e7"};
    for (unsigned f = 0; f < 2; ++f) {
        const double base = offsets[f];
        for (int i = 0; i < count; ++i) {
            const double cx = base * (1.0 + 0.5 * signed_unit(random));
            const double cy = base * signed_unit(random);
            const turn turn_a = turn_from_half_tangent(signed_unit(random));
            const turn turn_b = turn_from_half_tangent(signed_unit(random));
            const double ha = static_cast<double>(random.uniform(0.5f, 5.0f));
            const double hb = static_cast<double>(random.uniform(0.5f, 5.0f));
            const double dx = 8.0 * signed_unit(random);
            const double dy = 8.0 * signed_unit(random);
            const rect a = turned_rect(cx, cy, ha, hb, turn_a.c, turn_a.s);
            const rect b = turned_rect(cx + dx, cy + dy, hb, ha, turn_b.c, turn_b.s);
            list.add(a, b, families[f]);
            // Integer contacts moved there: still exact corners below 2^24.
            const int ea = static_cast<int>(random.below(5)) - 2;
            const int eb = static_cast<int>(random.below(4)) + 1;
            const point origin{static_cast<float>(std::floor(cx)),
                               static_cast<float>(std::floor(cy))};
            const auto contacts = integer_contacts(origin, ea, eb, 2);
            const rect touching = contacts[random.below(contacts.size())].b;
            list.add(integer_rect(origin, ea, eb, 2), touching, families[f]);
        }
    }
}

/// Coordinates near 1e30 (products overflow to inf, inf - inf gives NaN) and
/// near the float limit (the axis subtraction itself overflows).
inline void add_huge(pair_list& list, seeded_random& random, int count) {
    for (int i = 0; i < count; ++i) {
        // Integer contacts times 2^100 (about 1.3e30): exact corners, infinite products.
        const int ea = static_cast<int>(random.below(7)) - 3;
        const int eb = static_cast<int>(random.below(3)) + 1;
        const point origin{static_cast<float>(static_cast<int>(random.below(5)) - 2), 0.0f};
        const float big = std::ldexp(1.0f, 100);
        const auto contacts = integer_contacts(origin, ea, eb, 2);
        const rect a = scaled(integer_rect(origin, ea, eb, 2), big);
        const rect touching = contacts[random.below(contacts.size())].b;
        list.add(a, scaled(touching, big), "huge");

        // Arbitrary quadrilaterals with coordinates of magnitude 1e29 .. 1e31.
        auto huge_value = [&]() {
            const double sign_and_fraction = signed_unit(random);
            return static_cast<float>(sign_and_fraction * magnitude(random, 96, 103));
        };
        auto huge_quad = [&]() {
            return rect{{huge_value(), huge_value()},
                        {huge_value(), huge_value()},
                        {huge_value(), huge_value()},
                        {huge_value(), huge_value()}};
        };
        const rect quad_a = huge_quad();
        const rect quad_b = huge_quad();
        list.add(quad_a, quad_b, "huge");

        // A rectangle spanning nearly the whole float range: its axes are infinite.
        const float limit = std::ldexp(random.uniform(1.0f, 1.99f), 127);
        const rect spanning = axis_aligned(-limit, -limit * 0.5f, limit, limit * 0.5f);
        list.add(spanning, quad_a, "huge");
        // Huge against ordinary: the ordinary axes are finite, the products not.
        list.add(a, axis_aligned(-1, -1, 1, 1), "huge");
        list.add(spanning, integer_rect(origin, ea, eb, 1), "huge");
    }
}

/// Subnormal coordinates: integer contacts scaled into the subnormal range
/// (exact, but every product underflows to zero), and subnormal rectangles
/// against ordinary ones near the origin, whose products are subnormal and
/// would read as zero under flush-to-zero.
inline void add_subnormal(pair_list& list, seeded_random& random, int count) {
    const int exponents[] = {-149, -145, -140, -133, -127};
    for (int i = 0; i < count; ++i) {
        const int ea = static_cast<int>(random.below(7)) - 3;
        const int eb = static_cast<int>(random.below(3)) + 1;
        const point origin{static_cast<float>(static_cast<int>(random.below(5)) - 2),
                           static_cast<float>(static_cast<int>(random.below(5)) - 2)};
        const float tiny = std::ldexp(1.0f, exponents[random.below(5)]);
        const auto contacts = integer_contacts(origin, ea, eb, 2);
        const rect a = integer_rect(origin, ea, eb, 2);
        const contact& touching = contacts[random.below(contacts.size())];
        const rect& b = touching.b;
        list.add(scaled(a, tiny), scaled(b, tiny), "subnormal");
        list.add(scaled(a, tiny), scaled(translated(b, touching.outward), tiny), "subnormal");
        // Ordinary A with a corner at the origin against subnormal B near it.
        const rect ordinary = integer_rect({0, 0}, ea, eb, 2);
        list.add(ordinary, scaled(b, tiny), "subnormal");
        list.add(scaled(ordinary, tiny), a, "subnormal");
    }
}

/// Quadrilaterals that are not rectangles: random corners, often concave or
/// self-intersecting; the method answers for them as given.
inline void add_random_quads(pair_list& list, seeded_random& random, int count) {
    for (int i = 0; i < count; ++i) {
        const double scale = magnitude(random, -6, 8);
        auto corner = [&](double cx, double cy) {
            const double dx = scale * signed_unit(random);
            const double dy = scale * signed_unit(random);
            return point{static_cast<float>(cx + dx), static_cast<float>(cy + dy)};
        };
        auto quad = [&](double cx, double cy) {
            return rect{corner(cx, cy), corner(cx, cy), corner(cx, cy), corner(cx, cy)};
        };
        const double cx = scale * signed_unit(random);
        const double cy = scale * signed_unit(random);
        const rect a = quad(0, 0);
        const rect b = quad(cx, cy);
        list.add(a, b, "random_quads");
    }
}

}  // namespace hard_pairs_detail

/// Every hard pair, in a fixed order; `per_family` scales the random families.
inline std::vector<labelled_pair> hard_pairs(int per_family = 4000) {
    using namespace hard_pairs_detail;
    std::vector<labelled_pair> out;
    pair_list list(out);
    seeded_random random(0x0bb5a7);
    add_integer_contacts(list);
    add_ulp_moves(list);
    add_near_parallel(list, random, per_family);
    add_slivers(list, random, per_family);
    add_segments_and_points(list, random, per_family);
    add_offsets(list, random, per_family);
    add_huge(list, random, per_family);
    add_subnormal(list, random, per_family);
    add_random_quads(list, random, per_family);
    return out;
}

}  // namespace obbsat::test_support
