#include <obbsat/oracle/orientation64.hpp>

#include <obbsat/oracle/product_sum.hpp>

#include <cmath>

namespace obbsat::oracle {

namespace {

constexpr double filter_bound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;

// Below this magnitude an underflowed product could matter: go exact.
constexpr double least_filtered_magnitude = 0x1p-900;

}  // namespace

int orientation_exact(point64 p, point64 q, point64 r) {
    // (qx − px)(ry − py) − (qy − py)(rx − px), expanded: the px·py terms cancel.
    const product_term terms[6] = {{{q.x, r.y, 1.0}},  {{-q.x, p.y, 1.0}}, {{-p.x, r.y, 1.0}},
                                   {{-q.y, r.x, 1.0}}, {{q.y, p.x, 1.0}},  {{p.y, r.x, 1.0}}};
    return sign_of_product_sum(terms, 6);
}

int orientation(point64 p, point64 q, point64 r) {
    const double left = (q.x - p.x) * (r.y - p.y);
    const double right = (q.y - p.y) * (r.x - p.x);
    const double determinant = left - right;
    const double magnitude = std::fabs(left) + std::fabs(right);
    // NaN (from an overflow) fails both comparisons and goes exact.
    if (magnitude >= least_filtered_magnitude && magnitude <= 0x1.fffffffffffffp1023) {
        const double bound = filter_bound * magnitude;
        if (determinant > bound) {
            return 1;
        }
        if (determinant < -bound) {
            return -1;
        }
    }
    return orientation_exact(p, q, r);
}

}  // namespace obbsat::oracle
