#include <obbsat/oracle/pose_contact.hpp>

#include <obbsat/oracle/orientation.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace obbsat::oracle {

namespace {

constexpr double unit_roundoff = 0x1p-53;

// What a rounded slack's sign is when its error bound cannot decide it.
constexpr int undecided = 2;

// Step 1, in double: the four slacks and a bound on each one's error.
//
// With u = 2^-53 and the roundings of each step:
//   n = fl(c·c + s·s), p = fl(ca·cb + sa·sb), q = fl(ca·sb − sa·cb): two exact
//       products (24 + 24 significand bits, magnitudes within 2^-298 .. 2^256)
//       and one rounding, so each has its exact sign (a rounded sum of two
//       doubles is zero only when the exact sum is);
//   r = fl(fl(h0·n + h1·|p|) + h2·|q|) (or with p, q swapped): at most four
//       roundings per term, all terms >= 0: |r − exact| <= γ4·exact <= 4.0001u·r;
//   e = fl(fl(dx·ax) + fl(dy·ay)) with dx = fl(xb − xa), dy = fl(yb − ya): at
//       most three roundings per term, so with t = fl(|fl(dx·ax)| + |fl(dy·ay)|),
//       |e − exact| <= γ3·(|dx·ax| + |dy·ay|) <= 3.0001u·t;
//   fl(r − |e|) adds at most u·(r + |e|) <= u·(r + 1.0001·t).
// So |computed − exact| <= 5.001u·(r + t), below the bound 8u·fl(r + t) used
// (scaling by 8u is exact). Nothing underflows: every nonzero term is at least
// 2^-447, far above double's 2^-1022; nothing overflows: every term is at
// most 2^387.
//
// The same step checks the poses, at almost no cost: every input float is a
// factor of some term of some bound, and a product or sum with an infinity or
// a NaN is not finite (0·inf is NaN), so the bounds are all finite iff every
// input is; a rotation vector is (0, 0) iff its n is 0.
struct rounded_slacks {
    double value[4];
    double bound[4];
    bool valid_poses;
};

rounded_slacks rounded_slacks_of(const rect_pose& a, const rect_pose& b) {
    const double ca = a.rotation.x, sa = a.rotation.y, cb = b.rotation.x, sb = b.rotation.y;
    const double hxa = a.half_extents.x, hya = a.half_extents.y;
    const double hxb = b.half_extents.x, hyb = b.half_extents.y;
    const double na = ca * ca + sa * sa;
    const double nb = cb * cb + sb * sb;
    const double p = std::fabs(ca * cb + sa * sb);
    const double q = std::fabs(ca * sb - sa * cb);
    const double reach[4] = {(hxa * na + hxb * p) + hyb * q, (hya * na + hxb * q) + hyb * p,
                             (hxb * nb + hxa * p) + hya * q, (hyb * nb + hxa * q) + hya * p};
    const double dx = static_cast<double>(b.center.x) - a.center.x;
    const double dy = static_cast<double>(b.center.y) - a.center.y;
    // d·axis for the axes (ca, sa), (−sa, ca), (cb, sb), (−sb, cb).
    const double along_x[4] = {dx * ca, -(dx * sa), dx * cb, -(dx * sb)};
    const double along_y[4] = {dy * sa, dy * ca, dy * sb, dy * cb};
    rounded_slacks slacks{};
    for (int k = 0; k < 4; ++k) {
        const double e = along_x[k] + along_y[k];
        const double t = std::fabs(along_x[k]) + std::fabs(along_y[k]);
        slacks.value[k] = reach[k] - std::fabs(e);
        slacks.bound[k] = 8.0 * unit_roundoff * (reach[k] + t);
    }
    const double bound_sum = (slacks.bound[0] + slacks.bound[1]) + (slacks.bound[2] + slacks.bound[3]);
    const double least_half_extent = std::min(std::min(hxa, hya), std::min(hxb, hyb));
    slacks.valid_poses = std::isfinite(bound_sum) & (na * nb > 0.0) & (least_half_extent >= 0.0);
    return slacks;
}

int rounded_sign(double value, double bound) {
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

// Step 2, exact, for a slack step 1 could not decide: the same sum written
// with the stored floats.

// a1·b1 + a2·b2 for floats (n, p or q above); its double value has the exact sign.
struct product_pair {
    float a1;
    float b1;
    float a2;
    float b2;
};

double rounded(const product_pair& m) {
    return static_cast<double>(m.a1) * m.b1 + static_cast<double>(m.a2) * m.b2;
}

// One slack: h[0]·|m[0]| + h[1]·|m[1]| + h[2]·|m[2]| − |d·axis|, m[0] the
// squared length of the axis's own rotation vector, m[1] and m[2] how the
// other pose's axes lie on this one (p and q).
struct axis_slack {
    float h[3];
    product_pair m[3];
    point axis;
};

axis_slack axis_slack_of(const rect_pose& a, const rect_pose& b, int k) {
    const float ca = a.rotation.x, sa = a.rotation.y;
    const float cb = b.rotation.x, sb = b.rotation.y;
    const float hxa = a.half_extents.x, hya = a.half_extents.y;
    const float hxb = b.half_extents.x, hyb = b.half_extents.y;
    const product_pair p{ca, cb, sa, sb};   // u_a·u_b = v_a·v_b
    const product_pair q{ca, sb, -sa, cb};  // v_a·u_b = −(u_a·v_b)
    switch (k) {
        case 0: return axis_slack{{hxa, hxb, hyb}, {{ca, ca, sa, sa}, p, q}, {ca, sa}};
        case 1: return axis_slack{{hya, hxb, hyb}, {{ca, ca, sa, sa}, q, p}, {-sa, ca}};
        case 2: return axis_slack{{hxb, hxa, hya}, {{cb, cb, sb, sb}, p, q}, {cb, sb}};
        default: return axis_slack{{hyb, hxa, hya}, {{cb, cb, sb, sb}, q, p}, {-sb, cb}};
    }
}

// The terms of an exact sum, zeros left out.
struct exact_terms {
    double term[exact_sum_max_terms];
    int count = 0;

    void add(double v) {
        if (v != 0.0) {
            term[count++] = v;
        }
    }
    // x·y·z exactly, as two terms: x·y is exact in double, and fma gives the
    // rounding error of the second product exactly (a multiple of 2^-447, so
    // it never underflows).
    void add_product(float x, float y, float z) {
        const double xy = static_cast<double>(x) * y;
        const double rounded_product = xy * z;
        add(rounded_product);
        add(std::fma(xy, static_cast<double>(z), -rounded_product));
    }
};

// The exact sign of d·axis = xb·ax − xa·ax + yb·ay − ya·ay: when `filtered`,
// its double value first (the bound as in step 1, 4u·t > 3.0001u·t), the four
// exact products when that cannot decide.
int projection_sign(point axis, point ca, point cb, bool filtered) {
    if (filtered) {
        const double px = (static_cast<double>(cb.x) - ca.x) * axis.x;
        const double py = (static_cast<double>(cb.y) - ca.y) * axis.y;
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
// then the sign of a sum of at most 6 split products of three floats
// (12 terms) and 4 products of two.
int exact_slack_sign(const axis_slack& s, point ca, point cb, bool filtered) {
    exact_terms terms;
    for (int i = 0; i < 3; ++i) {
        const double m = rounded(s.m[i]);
        if (m == 0.0 || s.h[i] == 0.0f) {
            continue;
        }
        const float h = m > 0.0 ? s.h[i] : -s.h[i];
        terms.add_product(h, s.m[i].a1, s.m[i].b1);
        terms.add_product(h, s.m[i].a2, s.m[i].b2);
    }
    const int side = projection_sign(s.axis, ca, cb, filtered);
    if (side != 0) {
        // −|d·axis| = d·(−side·axis); negating a float is exact.
        const float ax = side > 0 ? -s.axis.x : s.axis.x;
        const float ay = side > 0 ? -s.axis.y : s.axis.y;
        terms.add(static_cast<double>(cb.x) * ax);
        terms.add(-(static_cast<double>(ca.x) * ax));
        terms.add(static_cast<double>(cb.y) * ay);
        terms.add(-(static_cast<double>(ca.y) * ay));
    }
    return sign_of_exact_sum(terms.term, terms.count);
}

bool has_area(const rect_pose& p) { return p.half_extents.x > 0.0f && p.half_extents.y > 0.0f; }

void check(const rect_pose& p, const char* which) {
    if (const char* defect = pose_defect(p)) {
        throw std::invalid_argument(std::string("obbsat::oracle::classify: pose ") + which + ": " + defect);
    }
}

// The class from the four slack signs, those still undecided found exactly.
contact classify_with(const rect_pose& a, const rect_pose& b, int signs[4], bool filtered) {
    bool all_positive = true;
    for (int k = 0; k < 4; ++k) {
        if (signs[k] == undecided) {
            signs[k] = exact_slack_sign(axis_slack_of(a, b, k), a.center, b.center, filtered);
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
    const rounded_slacks rounded = rounded_slacks_of(a, b);
    if (!rounded.valid_poses) {
        check(a, "a");
        check(b, "b");
    }
    int signs[4];
    bool all_positive = true;
    for (int k = 0; k < 4; ++k) {
        signs[k] = rounded_sign(rounded.value[k], rounded.bound[k]);
        if (signs[k] == -1) {
            return contact::separated;
        }
        all_positive = all_positive && signs[k] == 1;
    }
    if (all_positive) {
        return has_area(a) && has_area(b) ? contact::overlapping : contact::touching;
    }
    // Exact arithmetic only for the slacks step 1 left undecided.
    return classify_with(a, b, signs, true);
}

contact classify_exact(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    int signs[4] = {undecided, undecided, undecided, undecided};
    return classify_with(a, b, signs, false);
}

bool intersects(const rect_pose& a, const rect_pose& b) {
    return classify(a, b) != contact::separated;
}

std::array<int, 4> slack_signs(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    const rounded_slacks rounded = rounded_slacks_of(a, b);
    std::array<int, 4> signs{};
    for (int k = 0; k < 4; ++k) {
        const std::size_t i = static_cast<std::size_t>(k);
        signs[i] = rounded_sign(rounded.value[k], rounded.bound[k]);
        if (signs[i] == undecided) {
            signs[i] = exact_slack_sign(axis_slack_of(a, b, k), a.center, b.center, true);
        }
    }
    return signs;
}

std::array<axis_terms, 4> terms_of_axes(const rect_pose& a, const rect_pose& b) {
    check(a, "a");
    check(b, "b");
    const double dx = static_cast<double>(b.center.x) - a.center.x;
    const double dy = static_cast<double>(b.center.y) - a.center.y;
    std::array<axis_terms, 4> terms{};
    for (int k = 0; k < 4; ++k) {
        const axis_slack s = axis_slack_of(a, b, k);
        auto reach_term = [&](int i) { return s.h[i] * std::fabs(rounded(s.m[i])); };
        // Term 0 is the axis's own pose, terms 1 and 2 the other's (axis_slack_of).
        const double own = reach_term(0);
        const double other = reach_term(1) + reach_term(2);
        const bool on_a = k < 2;
        terms[static_cast<std::size_t>(k)] =
            axis_terms{dx * s.axis.x + dy * s.axis.y, on_a ? own : other, on_a ? other : own};
    }
    return terms;
}

}  // namespace obbsat::oracle
