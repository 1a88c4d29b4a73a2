#include <obbsat/oracle/quad_region.hpp>

#include <obbsat/oracle/orientation.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace obbsat::oracle {

namespace {

bool same_point(point a, point b) { return a.x == b.x && a.y == b.y; }

// Lexicographic order (x, then y): along any line it is the order of the points
// on that line, so collinear betweenness needs no arithmetic.
bool lex_less(point a, point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// For collinear a, b, c: b lies on the closed segment a-c.
bool between_on_line(point a, point b, point c) {
    return !(lex_less(b, a) && lex_less(b, c)) && !(lex_less(a, b) && lex_less(c, b));
}

// The closed segments a0-a1 and b0-b1 share a point.
bool segments_meet(point a0, point a1, point b0, point b1) {
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
        const point a_lo = lex_less(a1, a0) ? a1 : a0;
        const point a_hi = lex_less(a1, a0) ? a0 : a1;
        const point b_lo = lex_less(b1, b0) ? b1 : b0;
        const point b_hi = lex_less(b1, b0) ? b0 : b1;
        return !lex_less(a_hi, b_lo) && !lex_less(b_hi, a_lo);
    }
    return true;
}

// Convex hull of the four corners by Andrew's monotone chain: counter-clockwise,
// duplicates and collinear corners dropped, 1 to 4 corners.
convex_piece hull_of(const point corners[4]) {
    point sorted[4] = {corners[0], corners[1], corners[2], corners[3]};
    std::sort(sorted, sorted + 4, lex_less);
    point distinct[4];
    int n = 0;
    for (const point& p : sorted) {
        if (n == 0 || !same_point(distinct[n - 1], p)) {
            distinct[n++] = p;
        }
    }
    convex_piece hull{};
    if (n <= 2) {
        hull.count = static_cast<std::uint8_t>(n);
        std::copy(distinct, distinct + n, hull.corners);
        return hull;
    }
    point chain[8];
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

convex_piece triangle_ccw(point a, point b, point c, int orientation_sign) {
    return orientation_sign > 0 ? convex_piece{3, {a, b, c, point{}}}
                                : convex_piece{3, {a, c, b, point{}}};
}

quad_region single_piece(quad_form form, const convex_piece& piece) {
    quad_region region{};
    region.form = form;
    region.piece_count = 1;
    region.pieces[0] = piece;
    return region;
}

void require_finite(const rect& r) {
    const float values[8] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
    for (const float v : values) {
        if (!std::isfinite(v)) {
            throw std::invalid_argument("obbsat::oracle: a rect corner coordinate is not finite");
        }
    }
}

}  // namespace

quad_region region_of(const rect& r) {
    require_finite(r);
    const point c[4] = {r.ul, r.ur, r.lr, r.ll};
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
        return single_piece(quad_form::convex, convex_piece{4, {c[0], c[1], c[2], c[3]}});
    }
    if (right_turns == 4) {
        return single_piece(quad_form::convex, convex_piece{4, {c[3], c[2], c[1], c[0]}});
    }

    const convex_piece hull = hull_of(c);
    if (hull.count == 1) {
        return single_piece(quad_form::point, hull);
    }
    if (hull.count == 2) {
        return single_piece(quad_form::segment, hull);
    }
    // A repeated neighbouring corner leaves a triangle outline: convex.
    for (int i = 0; i < 4; ++i) {
        if (same_point(c[i], c[(i + 1) % 4])) {
            return single_piece(quad_form::convex, hull);
        }
    }
    // A collinear corner that is not between its neighbours is a spike: the
    // outline runs back along itself.
    for (int i = 0; i < 4; ++i) {
        if (turn[i] == 0 && !between_on_line(c[(i + 3) % 4], c[i], c[(i + 1) % 4])) {
            return single_piece(quad_form::non_simple, hull);
        }
    }
    if (left_turns == 0 || right_turns == 0) {
        // Strict turns one way plus at most a straight corner: a convex outline.
        return single_piece(quad_form::convex, hull);
    }
    if (segments_meet(c[0], c[1], c[2], c[3]) || segments_meet(c[1], c[2], c[3], c[0])) {
        return single_piece(quad_form::non_simple, hull);
    }
    // A simple outline turning both ways has exactly one reflex corner (three
    // turns of the outline's own sense, one against it).
    const int sense = left_turns == 3 ? 1 : -1;
    if (left_turns + right_turns != 4 || (left_turns != 3 && right_turns != 3)) {
        // Unreachable for a simple quadrilateral; the hull is the safe reading.
        return single_piece(quad_form::non_simple, hull);
    }
    int reflex = 0;
    while (turn[reflex] == sense) {
        ++reflex;
    }
    const point apex = c[reflex];
    const point next = c[(reflex + 1) % 4];
    const point opposite = c[(reflex + 2) % 4];
    const point previous = c[(reflex + 3) % 4];
    quad_region region{};
    region.form = quad_form::concave;
    region.piece_count = 2;
    // Both triangles have the outline's sense: their orientations are the
    // turns at `next` and at `previous`.
    region.pieces[0] = triangle_ccw(apex, next, opposite, sense);
    region.pieces[1] = triangle_ccw(apex, opposite, previous, sense);
    return region;
}

const char* quad_form_name(quad_form form) {
    switch (form) {
        case quad_form::point: return "point";
        case quad_form::segment: return "segment";
        case quad_form::convex: return "convex";
        case quad_form::concave: return "concave";
        case quad_form::non_simple: return "non_simple";
    }
    return "unknown";
}

}  // namespace obbsat::oracle
