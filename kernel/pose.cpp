#include <obbsat/pose.hpp>

#include <cmath>

namespace obbsat {

rect corners_of(const pose& p) {
    const double c = std::cos(static_cast<double>(p.angle));
    const double s = std::sin(static_cast<double>(p.angle));
    const double cx = p.center.x;
    const double cy = p.center.y;
    const double hx = p.half_extents.x;
    const double hy = p.half_extents.y;
    auto corner = [&](double lx, double ly) {
        return point{static_cast<float>(cx + (c * lx - s * ly)),
                     static_cast<float>(cy + (s * lx + c * ly))};
    };
    return rect{corner(-hx, hy), corner(hx, hy), corner(hx, -hy), corner(-hx, -hy)};
}

}  // namespace obbsat
