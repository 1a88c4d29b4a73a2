#include <obbsat/oracle/orientation.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace obbsat::oracle {

namespace {

// Error bound of the determinant evaluated in double as
//   (qx - px) * (ry - py) - (qy - py) * (rx - px):
//   |computed - exact| <= (3 + 16 eps) eps (|left| + |right|),  eps = 2^-53,
// (Shewchuk 1997, bound A of orient2d) under round-to-nearest and provided no
// operation underflows or overflows. With float inputs neither can happen:
// a nonzero difference of two floats is a multiple of 2^-149, a product of
// two such differences at least 2^-298 and at most 2^258, all far inside
// double's normal range; a final subtraction that lands below it is exact.
constexpr double filter_bound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;

// s + e == a + b exactly, with s the rounded sum (Knuth's branch-free two-sum).
void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double b_part = s - a;
    const double a_part = s - b_part;
    e = (a - a_part) + (b - b_part);
}

}  // namespace

// The terms are accumulated into a nonoverlapping expansion (components of
// increasing magnitude, zeros dropped); such an expansion has the sign of its
// largest component. Each term adds at most one component, so `count` terms
// fit in `count` places.
int sign_of_exact_sum(const double* terms, int count) {
    if (count < 0 || count > exact_sum_max_terms) {
        throw std::invalid_argument("sign_of_exact_sum: " + std::to_string(count) +
                                    " terms (at most " + std::to_string(exact_sum_max_terms) + ")");
    }
    double expansion[exact_sum_max_terms];
    int length = 0;
    for (int t = 0; t < count; ++t) {
        double carry = terms[t];
        int kept = 0;
        for (int i = 0; i < length; ++i) {
            double sum = 0.0;
            double error = 0.0;
            two_sum(carry, expansion[i], sum, error);
            if (error != 0.0) {
                expansion[kept++] = error;
            }
            carry = sum;
        }
        if (carry != 0.0) {
            expansion[kept++] = carry;
        }
        length = kept;
    }
    if (length == 0) {
        return 0;
    }
    return expansion[length - 1] > 0.0 ? 1 : -1;
}

int orientation_exact(point p, point q, point r) {
    // (qx - px)(ry - py) - (qy - py)(rx - px) expands (the px*py terms cancel)
    // to six products of two floats. Each is exact in double: 24 + 24
    // significand bits, and magnitudes between 2^-298 and 2^256.
    const double px = p.x, py = p.y, qx = q.x, qy = q.y, rx = r.x, ry = r.y;
    const double terms[6] = {qx * ry, -(qx * py), -(px * ry), -(qy * rx), qy * px, py * rx};
    return sign_of_exact_sum(terms, 6);
}

int orientation(point p, point q, point r) {
    const double left = (static_cast<double>(q.x) - p.x) * (static_cast<double>(r.y) - p.y);
    const double right = (static_cast<double>(q.y) - p.y) * (static_cast<double>(r.x) - p.x);
    const double determinant = left - right;
    const double magnitude = std::fabs(left) + std::fabs(right);
    if (magnitude == 0.0) {
        // Both products are exactly zero: a zero rounded difference means equal inputs.
        return 0;
    }
    const double bound = filter_bound * magnitude;
    if (determinant > bound) {
        return 1;
    }
    if (determinant < -bound) {
        return -1;
    }
    return orientation_exact(p, q, r);
}

}  // namespace obbsat::oracle
