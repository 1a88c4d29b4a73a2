#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>

namespace obbsat::ref {

rect moved_to_origin(const rect& r, point origin) {
    auto moved = [&](point p) { return point{p.x - origin.x, p.y - origin.y}; };
    return rect{moved(r.ul), moved(r.ur), moved(r.lr), moved(r.ll)};
}

bool sat4_centered(const rect& a, const rect& b) {
    const point origin = a.ul;
    return sat4(moved_to_origin(a, origin), moved_to_origin(b, origin));
}

}  // namespace obbsat::ref
