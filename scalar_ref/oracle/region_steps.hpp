// The steps of the exact corner oracle, written once over the point type
// (obbsat::point for float corners, obbsat::point64 for double corners) and
// the piece and region types holding it: the reading of four corners as a
// closed region (obbsat/oracle/quad_region.hpp) and the contact of two
// regions (obbsat/oracle/contact.hpp). Every decision is an exact
// orientation sign, found by the overload of `orientation` for the point type
// (both are declared before these templates), or an exact comparison of input
// coordinates.
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/orientation.hpp>
#include <obbsat/oracle/orientation64.hpp>
#include <obbsat/oracle/quad_region.hpp>

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace obbsat::oracle::steps {

template <class Point>
bool same_point(Point a, Point b) { return a.x == b.x && a.y == b.y; }

// Lexicographic order (x, then y): along any line it is the order of the points
// on that line, so collinear betweenness needs no arithmetic.
template <class Point>
bool lex_less(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// For collinear a, b, c: b lies on the closed segment a-c.
template <class Point>
bool between_on_line(Point a, Point b, Point c) {
    return !(lex_less(b, a) && lex_less(b, c)) && !(lex_less(a, b) && lex_less(c, b));
}

// The closed segments a0-a1 and b0-b1 share a point.
template <class Point>
bool segments_meet(Point a0, Point a1, Point b0, Point b1) {
    const int b0_side = orientation(a0, a1, b0);
    const int b1_side = orientation(a0, a1, b1);
    if (b0_side * b1_side > 0) {
        return false;
    }
    const int a0_side = orientation(b0, b1, a0);
    const int a1_side = orientation(b0, b1, a1);
    if (a0_side * a1_side > 0) {
        return false;
    }
    if (b0_side == 0 && b1_side == 0 && a0_side == 0 && a1_side == 0) {
        // All four on one line: the spans must overlap.
        const Point a_lo = lex_less(a1, a0) ? a1 : a0;
        const Point a_hi = lex_less(a1, a0) ? a0 : a1;
        const Point b_lo = lex_less(b1, b0) ? b1 : b0;
        const Point b_hi = lex_less(b1, b0) ? b0 : b1;
        return !lex_less(a_hi, b_lo) && !lex_less(b_hi, a_lo);
    }
    return true;
}

// Convex hull of the four corners by Andrew's monotone chain: counter-clockwise,
// duplicates and collinear corners dropped, 1 to 4 corners.
template <class Piece, class Point>
Piece hull_of(const Point corners[4]) {
    Point sorted[4] = {corners[0], corners[1], corners[2], corners[3]};
    std::sort(sorted, sorted + 4, lex_less<Point>);
    Point distinct[4];
    int n = 0;
    for (const Point& p : sorted) {
        if (n == 0 || !same_point(distinct[n - 1], p)) {
            distinct[n++] = p;
        }
    }
    Piece hull{};
    if (n <= 2) {
        hull.count = static_cast<std::uint8_t>(n);
        std::copy(distinct, distinct + n, hull.corners);
        return hull;
    }
    Point chain[8];
    int size = 0;
    for (int i = 0; i < n; ++i) {  // lower chain, left to right
        while (size >= 2 && orientation(chain[size - 2], chain[size - 1], distinct[i]) <= 0) {
            --size;
        }
        chain[size++] = distinct[i];
    }
    const int lower_size = size;
    for (int i = n - 2; i >= 0; --i) {  // upper chain, right to left
        while (size > lower_size && orientation(chain[size - 2], chain[size - 1], distinct[i]) <= 0) {
            --size;
        }
        chain[size++] = distinct[i];
    }
    --size;  // the last point closes the chain onto the first
    hull.count = static_cast<std::uint8_t>(size);
    std::copy(chain, chain + size, hull.corners);
    return hull;
}

template <class Piece, class Point>
Piece triangle_ccw(Point a, Point b, Point c, int orientation_sign) {
    return orientation_sign > 0 ? Piece{3, {a, b, c, Point{}}}
                                : Piece{3, {a, c, b, Point{}}};
}

template <class Region, class Piece>
Region single_piece(quad_form form, const Piece& piece) {
    Region region{};
    region.form = form;
    region.piece_count = 1;
    region.pieces[0] = piece;
    return region;
}

/// The region of the four corners c (UL, UR, LR, LL), as quad_region.hpp reads them.
template <class Region, class Point>
Region region_from_corners(const Point c[4]) {
    using piece_type = std::remove_extent_t<decltype(Region::pieces)>;
    int turn[4];
    int left_turns = 0;
    int right_turns = 0;
    for (int i = 0; i < 4; ++i) {
        turn[i] = orientation(c[(i + 3) % 4], c[i], c[(i + 1) % 4]);
        left_turns += turn[i] > 0;
        right_turns += turn[i] < 0;
    }
    // The common case: four strict turns the same way. Then the corners are
    // distinct and the outline is a convex polygon already.
    if (left_turns == 4) {
        return single_piece<Region>(quad_form::convex, piece_type{4, {c[0], c[1], c[2], c[3]}});
    }
    if (right_turns == 4) {
        return single_piece<Region>(quad_form::convex, piece_type{4, {c[3], c[2], c[1], c[0]}});
    }

    const piece_type hull = hull_of<piece_type>(c);
    if (hull.count == 1) {
        return single_piece<Region>(quad_form::point, hull);
    }
    if (hull.count == 2) {
        return single_piece<Region>(quad_form::segment, hull);
    }
    // A repeated neighbouring corner leaves a triangle outline: convex.
    for (int i = 0; i < 4; ++i) {
        if (same_point(c[i], c[(i + 1) % 4])) {
            return single_piece<Region>(quad_form::convex, hull);
        }
    }
    // A collinear corner that is not between its neighbours is a spike: the
    // outline runs back along itself.
    for (int i = 0; i < 4; ++i) {
        if (turn[i] == 0 && !between_on_line(c[(i + 3) % 4], c[i], c[(i + 1) % 4])) {
            return single_piece<Region>(quad_form::non_simple, hull);
        }
    }
    if (left_turns == 0 || right_turns == 0) {
        // Strict turns one way plus at most a straight corner: a convex outline.
        return single_piece<Region>(quad_form::convex, hull);
    }
    if (segments_meet(c[0], c[1], c[2], c[3]) || segments_meet(c[1], c[2], c[3], c[0])) {
        return single_piece<Region>(quad_form::non_simple, hull);
    }
    // A simple outline turning both ways has exactly one reflex corner (three
    // turns of the outline's own sense, one against it).
    const int sense = left_turns == 3 ? 1 : -1;
    if (left_turns + right_turns != 4 || (left_turns != 3 && right_turns != 3)) {
        // Unreachable for a simple quadrilateral; the hull is the safe reading.
        return single_piece<Region>(quad_form::non_simple, hull);
    }
    int reflex = 0;
    while (turn[reflex] == sense) {
        ++reflex;
    }
    const Point apex = c[reflex];
    const Point next = c[(reflex + 1) % 4];
    const Point opposite = c[(reflex + 2) % 4];
    const Point previous = c[(reflex + 3) % 4];
    Region region{};
    region.form = quad_form::concave;
    region.piece_count = 2;
    // Both triangles have the outline's sense: their orientations are the
    // turns at `next` and at `previous`.
    region.pieces[0] = triangle_ccw<piece_type>(apex, next, opposite, sense);
    region.pieces[1] = triangle_ccw<piece_type>(apex, opposite, previous, sense);
    return region;
}

// Two polygons (3-4 counter-clockwise corners each). The outer side of edge
// p[i] -> p[i+1] is its right side: orientation < 0.
template <class Piece>
contact polygon_polygon(const Piece& a, const Piece& b) {
    bool weakly_separated = false;
    for (int pass = 0; pass < 2; ++pass) {
        const Piece& edges = pass == 0 ? a : b;
        const Piece& other = pass == 0 ? b : a;
        for (int i = 0; i < edges.count; ++i) {
            const auto from = edges.corners[i];
            const auto to = edges.corners[(i + 1) % edges.count];
            bool all_strictly_outside = true;
            bool all_outside_or_on = true;
            for (int j = 0; j < other.count && (all_strictly_outside || all_outside_or_on); ++j) {
                const int side = orientation(from, to, other.corners[j]);
                all_strictly_outside = all_strictly_outside && side < 0;
                all_outside_or_on = all_outside_or_on && side <= 0;
            }
            if (all_strictly_outside) {
                return contact::separated;
            }
            weakly_separated = weakly_separated || all_outside_or_on;
        }
    }
    return weakly_separated ? contact::touching : contact::overlapping;
}

// A polygon and the segment s0-s1 (s0 != s1): the segment has no interior.
template <class Piece, class Point>
contact polygon_segment(const Piece& a, Point s0, Point s1) {
    for (int i = 0; i < a.count; ++i) {
        const auto from = a.corners[i];
        const auto to = a.corners[(i + 1) % a.count];
        if (orientation(from, to, s0) < 0 && orientation(from, to, s1) < 0) {
            return contact::separated;
        }
    }
    // The segment's own line: all polygon corners strictly on one side.
    bool all_left = true;
    bool all_right = true;
    for (int j = 0; j < a.count; ++j) {
        const int side = orientation(s0, s1, a.corners[j]);
        all_left = all_left && side > 0;
        all_right = all_right && side < 0;
    }
    return (all_left || all_right) ? contact::separated : contact::touching;
}

template <class Piece, class Point>
contact polygon_point(const Piece& a, Point p) {
    for (int i = 0; i < a.count; ++i) {
        if (orientation(a.corners[i], a.corners[(i + 1) % a.count], p) < 0) {
            return contact::separated;
        }
    }
    return contact::touching;
}

template <class Point>
contact segment_segment(Point s0, Point s1, Point t0, Point t1) {
    const int t0_side = orientation(s0, s1, t0);
    const int t1_side = orientation(s0, s1, t1);
    if (t0_side * t1_side > 0) {
        return contact::separated;
    }
    const int s0_side = orientation(t0, t1, s0);
    const int s1_side = orientation(t0, t1, s1);
    if (s0_side * s1_side > 0) {
        return contact::separated;
    }
    if (t0_side == 0 && t1_side == 0) {
        // Both on one line: lexicographic order is the order along it.
        const Point s_lo = lex_less(s1, s0) ? s1 : s0;
        const Point s_hi = lex_less(s1, s0) ? s0 : s1;
        const Point t_lo = lex_less(t1, t0) ? t1 : t0;
        const Point t_hi = lex_less(t1, t0) ? t0 : t1;
        return (lex_less(s_hi, t_lo) || lex_less(t_hi, s_lo)) ? contact::separated
                                                              : contact::touching;
    }
    return contact::touching;
}

template <class Point>
contact segment_point(Point s0, Point s1, Point p) {
    if (orientation(s0, s1, p) != 0) {
        return contact::separated;
    }
    const bool before_both = lex_less(p, s0) && lex_less(p, s1);
    const bool after_both = lex_less(s0, p) && lex_less(s1, p);
    return (before_both || after_both) ? contact::separated : contact::touching;
}

template <class Point>
contact point_point(Point p, Point q) {
    return (p.x == q.x && p.y == q.y) ? contact::touching : contact::separated;
}

/// How two closed convex pieces relate (contact.hpp).
template <class Piece>
contact classify_pieces(const Piece& a, const Piece& b) {
    // Every test below is symmetric, so let `big` have at least as many corners.
    const Piece& big = a.count >= b.count ? a : b;
    const Piece& small = a.count >= b.count ? b : a;
    if (small.count >= 3) {
        return polygon_polygon(big, small);
    }
    if (big.count >= 3) {
        return small.count == 2 ? polygon_segment(big, small.corners[0], small.corners[1])
                                : polygon_point(big, small.corners[0]);
    }
    if (big.count == 2) {
        return small.count == 2
                   ? segment_segment(big.corners[0], big.corners[1], small.corners[0], small.corners[1])
                   : segment_point(big.corners[0], big.corners[1], small.corners[0]);
    }
    return point_point(big.corners[0], small.corners[0]);
}

/// How two regions relate: the most any two of their pieces share.
template <class Region>
contact classify_regions(const Region& a, const Region& b) {
    contact most = contact::separated;
    for (int i = 0; i < a.piece_count; ++i) {
        for (int j = 0; j < b.piece_count; ++j) {
            const contact c = classify_pieces(a.pieces[i], b.pieces[j]);
            if (c == contact::overlapping) {
                return c;
            }
            if (c == contact::touching) {
                most = c;
            }
        }
    }
    return most;
}

}  // namespace obbsat::oracle::steps
