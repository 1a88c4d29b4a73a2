#include <obbsat/oracle/quad_region.hpp>

#include "region_steps.hpp"

#include <cmath>
#include <stdexcept>

namespace obbsat::oracle {

namespace {

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
    return steps::region_from_corners<quad_region>(c);
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
