#include <obbsat/oracle/contact64.hpp>

#include "region_steps.hpp"

#include <cmath>
#include <stdexcept>

namespace obbsat::oracle {

namespace {

void require_finite(const rect64& r) {
    const double values[8] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
    for (const double v : values) {
        if (!std::isfinite(v)) {
            throw std::invalid_argument("obbsat::oracle: a rect64 corner coordinate is not finite");
        }
    }
}

}  // namespace

quad_region64 region_of(const rect64& r) {
    require_finite(r);
    const point64 c[4] = {r.ul, r.ur, r.lr, r.ll};
    return steps::region_from_corners<quad_region64>(c);
}

contact classify(const rect64& a, const rect64& b) { return steps::classify_regions(region_of(a), region_of(b)); }

bool intersects(const rect64& a, const rect64& b) { return classify(a, b) != contact::separated; }

}  // namespace obbsat::oracle
