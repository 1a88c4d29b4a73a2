#include <obbsat/oracle/pose_contact.hpp>

#include <obbsat/oracle/orientation.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace obbsat::oracle {

namespace {

constexpr double unit_roundoff = 0x1p-53;

// What rounded_slack_sign returns when the double evaluation cannot decide.
constexpr int undecided = 2;

// a1·b1 + a2·b2 for floats: both products are exact in double (24 + 24
// significand bits, magnitudes within 2^-298 .. 2^256), so the double value
// has one rounding, and a rounded sum of two doubles is zero only when the
// exact sum is: its sign is exact.
struct product_pair {
    float a1;
    float b1;
    float a2;
    float b2;
};

double rounded(const product_pair& m) {
    return static_cast<double>(m.a1) * m.b1 + static_cast<double>(m.a2) * m.b2;
}

// One axis of the test: slack = h[0]·|m[0]| + h[1]·|m[1]| + h[2]·|m[2]| − |d·axis|,
// m[0] the squared length of the axis's own rotation vector (never negative),
// m[1], m[2] the other pose's extents seen on this axis (p or q).
struct axis_slack {
    float h[3];
    product_pair m[3];
    point axis;
};

struct four_axes {
    axis_slack axes[4];
};

four_axes axes_of(const rect_pose& a, const rect_pose& b) {
    const float ca = a.rotation.x, sa = a.rotation.y;
    const float cb = b.rotation.x, sb = b.rotation.y;
    const float hxa = a.half_extents.x, hya = a.half_extents.y;
    const float hxb = b.half_extents.x, hyb = b.half_extents.y;
    const product_pair na{ca, ca, sa, sa};
    const product_pair nb{cb, cb, sb, sb};
    const product_pair p{ca, cb, sa, sb};   // u_a·u_b = v_a·v_b
    const product_pair q{ca, sb, -sa, cb};  // v_a·u_b = −(u_a·v_b)
    return four_axes{{
        {{hxa, hxb, hyb}, {na, p, q}, {ca, sa}},
        {{hya, hxb, hyb}, {na, q, p}, {-sa, ca}},
        {{hxb, hxa, hya}, {nb, p, q}, {cb, sb}},
        {{hyb, hxa, hya}, {nb, q, p}, {-sb, cb}},
    }};
}

// Term i of an axis's reach, h[i]·|m[i]|, in double.
double reach_term(const axis_slack& s, int i) { return s.h[i] * std::fabs(rounded(s.m[i])); }

// d·axis in double.
double rounded_offset(const axis_slack& s, double dx, double dy) { return dx * s.axis.x + dy * s.axis.y; }

// The slack in double, from dx = fl(xb − xa) and dy = fl(yb − ya):
//   r = fl(fl(h0·|m0| + h1·|m1|) + h2·|m2|), four roundings per term at most,
//       all terms >= 0: |r − exact| <= γ4·exact <= 4.0001u·r;
//   e = fl(fl(dx·ax) + fl(dy·ay)), three roundings per term:
//       |e − exact| <= γ3·(|dx·ax| + |dy·ay|) <= 3.0001u·t, t = fl(|fl(dx·ax)| + |fl(dy·ay)|);
//   fl(r − |e|) adds at most u·(r + |e|) <= u·(r + 1.0001·t).
// So |computed − exact| <= 5.001u·(r + t), below the bound 8u·fl(r + t) used
// (u = 2^-53; scaling by 8u is exact). Nothing underflows: nonzero terms are
// at least 2^-447, far above double's 2^-1022.
int rounded_slack_sign(const axis_slack& s, double dx, double dy) {
    const double r = (reach_term(s, 0) + reach_term(s, 1)) + reach_term(s, 2);
    const double e = rounded_offset(s, dx, dy);
    const double t = std::fabs(dx * s.axis.x) + std::fabs(dy * s.axis.y);
    const double value = r - std::fabs(e);
    const double bound = 8.0 * unit_roundoff * (r + t);
    if (value > bound) {
        return 1;
    }
    if (value < -bound) {
        return -1;
    }
    // A zero bound means every term is exactly zero (r and t are rounded sums
    // of terms that are never negative, and dx is zero only when xb == xa).
    return bound == 0.0 ? 0 : undecided;
}

// x·y·z exactly, as out[0] + out[1]: x·y is exact in double, and fma gives the
// rounding error of the second product exactly (a multiple of 2^-447, so it
// never underflows).
void split_product(float x, float y, float z, double* out) {
    const double xy = static_cast<double>(x) * y;
    out[0] = xy * z;
    out[1] = std::fma(xy, static_cast<double>(z), -out[0]);
}

// The exact sign of d·axis = xb·ax − xa·ax + yb·ay − ya·ay: when `filtered`,
// its double value first (the bound as in rounded_slack_sign, 4u·t > 3.0001u·t),
// the four exact products when that cannot decide.
int projection_sign(point axis, point ca, point cb, double dx, double dy, bool filtered) {
    if (filtered) {
        const double px = dx * axis.x;
        const double py = dy * axis.y;
        const double e = px + py;
        const double bound = 4.0 * unit_roundoff * (std::fabs(px) + std::fabs(py));
        if (e > bound) {
            return 1;
        }
        if (e < -bound) {
            return -1;
        }
    }
    const double terms[4] = {static_cast<double>(cb.x) * axis.x, -(static_cast<double>(ca.x) * axis.x),
                             static_cast<double>(cb.y) * axis.y, -(static_cast<double>(ca.y) * axis.y)};
    return sign_of_exact_sum(terms, 4);
}

// The slack's exact sign: every |m| and |d·axis| opened with its exact sign,
// then the sign of the sum of at most 6 split products of three floats
// (12 terms) and 4 products of two.
int exact_slack_sign(const axis_slack& s, point ca, point cb, double dx, double dy, bool filtered) {
    double terms[exact_sum_max_terms];
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        const double m = rounded(s.m[i]);
        if (m == 0.0 || s.h[i] == 0.0f) {
            continue;
        }
        const float h = m > 0.0 ? s.h[i] : -s.h[i];
        split_product(h, s.m[i].a1, s.m[i].b1, terms + count);
        split_product(h, s.m[i].a2, s.m[i].b2, terms + count + 2);
        count += 4;
    }
    const int side = projection_sign(s.axis, ca, cb, dx, dy, filtered);
    if (side != 0) {
        // −|d·axis| = d·(−side·axis); negating a float is exact.
        const float ax = side > 0 ? -s.axis.x : s.axis.x;
        const float ay = side > 0 ? -s.axis.y : s.axis.y;
        terms[count++] = static_cast<double>(cb.x) * ax;
        terms[count++] = -(static_cast<double>(ca.x) * ax);
        terms[count++] = static_cast<double>(cb.y) * ay;
        terms[count++] = -(static_cast<double>(ca.y) * ay);
    }
    return sign_of_exact_sum(terms, count);
}

bool has_area(const rect_pose& p) { return p.half_extents.x > 0.0f && p.half_extents.y > 0.0f; }

void check(const rect_pose& p, const char* which) {
    if (const char* defect = pose_defect(p)) {
        throw std::invalid_argument(std::string("obbsat::oracle::classify: pose ") + which + ": " + defect);
    }
}

double center_dx(const rect_pose& a, const rect_pose& b) {
    return static_cast<double>(b.center.x) - a.center.x;
}

double center_dy(const rect_pose& a, const rect_pose& b) {
    return static_cast<double>(b.center.y) - a.center.y;
}

// The class from the four slack signs: when `filtered`, each first by its
// double evaluation, and exactly only where that could not decide.
contact classify_valid(const rect_pose& a, const rect_pose& b, bool filtered) {
    const four_axes f = axes_of(a, b);
    const double dx = center_dx(a, b);
    const double dy = center_dy(a, b);
    int signs[4];
    for (int k = 0; k < 4; ++k) {
        signs[k] = filtered ? rounded_slack_sign(f.axes[k], dx, dy) : undecided;
        if (signs[k] == -1) {
            return contact::separated;
        }
    }
    bool all_positive = true;
    for (int k = 0; k < 4; ++k) {
        if (signs[k] == undecided) {
            signs[k] = exact_slack_sign(f.axes[k], a.center, b.center, dx, dy, filtered);
            if (signs[k] < 0) {
                return contact::separated;
            }
        }
        all_positive = all_positive && signs[k] > 0;
    }
    return all_positive && has_area(a) && has_area(b) ? contact::overlapping : contact::touching;
}

}  // namespace

const char* pose_defect(const rect_pose& p) {
    const float values[6] = {p.center.x,       p.center.y,       p.half_extents.x,
                             p.half_extents.y, p.rotation.x,     p.rotation.y};
    for (const float v : values) {
        if (!std::isfinite(v)) {
            return "a value is not finite";
        }
    }
    if (p.half_extents.x < 0.0f || p.half_extents.y < 0.0f) {
        return "a half extent is negative";
    }
    if (p.rotation.x == 0.0f && p.rotation.y == 0.0f) {
        return "the rotation vector is (0, 0)";
    }
    return nullptr;
}

contact classify(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    return classify_valid(a, b, true);
}

contact classify_exact(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    return classify_valid(a, b, false);
}

bool intersects(const rect_pose& a, const rect_pose& b) {
    return classify(a, b) != contact::separated;
}

std::array<int, 4> slack_signs(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    const four_axes f = axes_of(a, b);
    const double dx = center_dx(a, b);
    const double dy = center_dy(a, b);
    std::array<int, 4> signs{};
    for (std::size_t k = 0; k < 4; ++k) {
        signs[k] = rounded_slack_sign(f.axes[k], dx, dy);
        if (signs[k] == undecided) {
            signs[k] = exact_slack_sign(f.axes[k], a.center, b.center, dx, dy, true);
        }
    }
    return signs;
}

std::array<axis_terms, 4> terms_of_axes(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    const four_axes f = axes_of(a, b);
    const double dx = center_dx(a, b);
    const double dy = center_dy(a, b);
    std::array<axis_terms, 4> terms{};
    for (std::size_t k = 0; k < 4; ++k) {
        const axis_slack& s = f.axes[k];
        // Term 0 is the axis's own pose, terms 1 and 2 the other's (axes_of).
        const double own = reach_term(s, 0);
        const double other = reach_term(s, 1) + reach_term(s, 2);
        const bool on_a = k < 2;
        terms[k] = axis_terms{rounded_offset(s, dx, dy), on_a ? own : other, on_a ? other : own};
    }
    return terms;
}

}  // namespace obbsat::oracle
