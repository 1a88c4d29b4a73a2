#include <obbsat/oracle/pose_contact64.hpp>

#include <obbsat/oracle/product_sum.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace obbsat::oracle {

namespace {

// The terms of one exact sum, zero factors left out.
struct terms_of_sum {
    product_term term[product_sum_max_terms];
    int count = 0;

    void add(double x, double y, double z = 1.0) {
        if (x != 0.0 && y != 0.0 && z != 0.0) {
            term[count++] = product_term{{x, y, z}};
        }
    }
    int sign() const { return sign_of_product_sum(term, count); }
};

// a1·b1 + a2·b2: a rotation product (n, p or q).
struct product_pair {
    double a1;
    double b1;
    double a2;
    double b2;
};

int sign_of(const product_pair& m) {
    terms_of_sum sum;
    sum.add(m.a1, m.b1);
    sum.add(m.a2, m.b2);
    return sum.sign();
}

// One slack: h[0]·|m[0]| + h[1]·|m[1]| + h[2]·|m[2]| − |d·axis|, m[0] the
// squared length of the axis's own rotation, m[1] and m[2] how the other
// pose's axes lie on this one (p and q).
struct axis_slack {
    double h[3];
    product_pair m[3];
    point64 axis;
};

axis_slack axis_slack_of(const rect_pose64& a, const rect_pose64& b, int k) {
    const double ca = a.rotation.x, sa = a.rotation.y;
    const double cb = b.rotation.x, sb = b.rotation.y;
    const double hxa = a.half_extents.x, hya = a.half_extents.y;
    const double hxb = b.half_extents.x, hyb = b.half_extents.y;
    const product_pair p{ca, cb, sa, sb};   // u_a·u_b = v_a·v_b
    const product_pair q{ca, sb, -sa, cb};  // v_a·u_b = −(u_a·v_b)
    switch (k) {
        case 0: return axis_slack{{hxa, hxb, hyb}, {{ca, ca, sa, sa}, p, q}, {ca, sa}};
        case 1: return axis_slack{{hya, hxb, hyb}, {{ca, ca, sa, sa}, q, p}, {-sa, ca}};
        case 2: return axis_slack{{hxb, hxa, hya}, {{cb, cb, sb, sb}, p, q}, {cb, sb}};
        default: return axis_slack{{hyb, hxa, hya}, {{cb, cb, sb, sb}, q, p}, {-sb, cb}};
    }
}

// d·axis = xb·ax − xa·ax + yb·ay − ya·ay, added to `sum` times `scale` (±1).
void add_projection(terms_of_sum& sum, point64 axis, point64 ca, point64 cb, double scale) {
    sum.add(scale * cb.x, axis.x);
    sum.add(-scale * ca.x, axis.x);
    sum.add(scale * cb.y, axis.y);
    sum.add(-scale * ca.y, axis.y);
}

// The slack's exact sign: each |m| and |d·axis| opened with its exact sign
// (negating a double is exact), then one exact sum of at most ten products.
int slack_sign(const axis_slack& s, point64 ca, point64 cb) {
    terms_of_sum slack;
    for (int i = 0; i < 3; ++i) {
        const int m_sign = sign_of(s.m[i]);
        if (m_sign == 0 || s.h[i] == 0.0) {
            continue;
        }
        const double h = m_sign > 0 ? s.h[i] : -s.h[i];
        slack.add(h, s.m[i].a1, s.m[i].b1);
        slack.add(h, s.m[i].a2, s.m[i].b2);
    }
    terms_of_sum projection;
    add_projection(projection, s.axis, ca, cb, 1.0);
    const int side = projection.sign();
    if (side != 0) {
        add_projection(slack, s.axis, ca, cb, side > 0 ? -1.0 : 1.0);
    }
    return slack.sign();
}

bool has_area(const rect_pose64& p) { return p.half_extents.x > 0.0 && p.half_extents.y > 0.0; }

void check(const rect_pose64& p, const char* which) {
    if (const char* defect = pose_defect(p)) {
        throw std::invalid_argument(std::string("obbsat::oracle::classify: pose ") + which + ": " + defect);
    }
}

}  // namespace

const char* pose_defect(const rect_pose64& p) {
    const double values[6] = {p.center.x,       p.center.y,   p.half_extents.x,
                              p.half_extents.y, p.rotation.x, p.rotation.y};
    for (const double v : values) {
        if (!std::isfinite(v)) {
            return "a value is not finite";
        }
    }
    if (p.half_extents.x < 0.0 || p.half_extents.y < 0.0) {
        return "a half extent is negative";
    }
    if (p.rotation.x == 0.0 && p.rotation.y == 0.0) {
        return "the rotation vector is (0, 0)";
    }
    return nullptr;
}

std::array<int, 4> slack_signs(const rect_pose64& a, const rect_pose64& b) {
    check(a, "a");
    check(b, "b");
    std::array<int, 4> signs{};
    for (int k = 0; k < 4; ++k) {
        signs[static_cast<std::size_t>(k)] = slack_sign(axis_slack_of(a, b, k), a.center, b.center);
    }
    return signs;
}

contact classify(const rect_pose64& a, const rect_pose64& b) {
    check(a, "a");
    check(b, "b");
    bool all_positive = true;
    for (int k = 0; k < 4; ++k) {
        const int sign = slack_sign(axis_slack_of(a, b, k), a.center, b.center);
        if (sign < 0) {
            return contact::separated;
        }
        all_positive = all_positive && sign > 0;
    }
    return all_positive && has_area(a) && has_area(b) ? contact::overlapping : contact::touching;
}

bool intersects(const rect_pose64& a, const rect_pose64& b) { return classify(a, b) != contact::separated; }

}  // namespace obbsat::oracle
