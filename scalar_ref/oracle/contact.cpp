#include <obbsat/oracle/contact.hpp>

#include <obbsat/oracle/orientation.hpp>

namespace obbsat::oracle {

namespace {

bool lex_less(point a, point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// Two polygons (3-4 counter-clockwise corners each). The outer side of edge
// p[i] -> p[i+1] is its right side: orientation < 0.
contact polygon_polygon(const convex_piece& a, const convex_piece& b) {
    bool weakly_separated = false;
    for (int pass = 0; pass < 2; ++pass) {
        const convex_piece& edges = pass == 0 ? a : b;
        const convex_piece& other = pass == 0 ? b : a;
        for (int i = 0; i < edges.count; ++i) {
            const point from = edges.corners[i];
            const point to = edges.corners[(i + 1) % edges.count];
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
contact polygon_segment(const convex_piece& a, point s0, point s1) {
    for (int i = 0; i < a.count; ++i) {
        const point from = a.corners[i];
        const point to = a.corners[(i + 1) % a.count];
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

contact polygon_point(const convex_piece& a, point p) {
    for (int i = 0; i < a.count; ++i) {
        if (orientation(a.corners[i], a.corners[(i + 1) % a.count], p) < 0) {
            return contact::separated;
        }
    }
    return contact::touching;
}

contact segment_segment(point s0, point s1, point t0, point t1) {
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
        const point s_lo = lex_less(s1, s0) ? s1 : s0;
        const point s_hi = lex_less(s1, s0) ? s0 : s1;
        const point t_lo = lex_less(t1, t0) ? t1 : t0;
        const point t_hi = lex_less(t1, t0) ? t0 : t1;
        return (lex_less(s_hi, t_lo) || lex_less(t_hi, s_lo)) ? contact::separated
                                                              : contact::touching;
    }
    return contact::touching;
}

contact segment_point(point s0, point s1, point p) {
    if (orientation(s0, s1, p) != 0) {
        return contact::separated;
    }
    const bool before_both = lex_less(p, s0) && lex_less(p, s1);
    const bool after_both = lex_less(s0, p) && lex_less(s1, p);
    return (before_both || after_both) ? contact::separated : contact::touching;
}

contact point_point(point p, point q) {
    return (p.x == q.x && p.y == q.y) ? contact::touching : contact::separated;
}

}  // namespace

char contact_letter(contact c) {
    switch (c) {
        case contact::separated: return 'S';
        case contact::touching: return 'T';
        case contact::overlapping: return 'O';
    }
    return '?';
}

contact classify(const convex_piece& a, const convex_piece& b) {
    // Every test below is symmetric, so let `big` have at least as many corners.
    const convex_piece& big = a.count >= b.count ? a : b;
    const convex_piece& small = a.count >= b.count ? b : a;
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

contact classify(const quad_region& a, const quad_region& b) {
    contact most = contact::separated;
    for (int i = 0; i < a.piece_count; ++i) {
        for (int j = 0; j < b.piece_count; ++j) {
            const contact c = classify(a.pieces[i], b.pieces[j]);
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

contact classify(const rect& a, const rect& b) {
    return classify(region_of(a), region_of(b));
}

bool intersects(const rect& a, const rect& b) {
    return classify(a, b) != contact::separated;
}

}  // namespace obbsat::oracle
