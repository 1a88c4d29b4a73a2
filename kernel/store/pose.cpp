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

pose pose_of(const rect& r) {
    const double cx = (static_cast<double>(r.ul.x) + r.ur.x + r.lr.x + r.ll.x) / 4.0;
    const double cy = (static_cast<double>(r.ul.y) + r.ur.y + r.lr.y + r.ll.y) / 4.0;
    const double wx = static_cast<double>(r.ur.x) - r.ul.x;
    const double wy = static_cast<double>(r.ur.y) - r.ul.y;
    const double hx = static_cast<double>(r.ur.x) - r.lr.x;
    const double hy = static_cast<double>(r.ur.y) - r.lr.y;
    return pose{point{static_cast<float>(cx), static_cast<float>(cy)},
                point{static_cast<float>(std::hypot(wx, wy) / 2.0), static_cast<float>(std::hypot(hx, hy) / 2.0)},
                static_cast<float>(std::atan2(wy, wx))};
}

}  // namespace obbsat

namespace obbsat {

rect_pose rect_pose_of(const pose& p) {
    const double angle = p.angle;
    return rect_pose{p.center, p.half_extents,
                     point{static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))}};
}

rect_pose rect_pose_of(const rect& r) {
    const double cx = (static_cast<double>(r.ul.x) + r.ur.x + r.lr.x + r.ll.x) / 4.0;
    const double cy = (static_cast<double>(r.ul.y) + r.ur.y + r.lr.y + r.ll.y) / 4.0;
    const double wx = static_cast<double>(r.ur.x) - r.ul.x;
    const double wy = static_cast<double>(r.ur.y) - r.ul.y;
    const double tx = static_cast<double>(r.ur.x) - r.lr.x;
    const double ty = static_cast<double>(r.ur.y) - r.lr.y;
    const double width = std::hypot(wx, wy);
    const double height = std::hypot(tx, ty);
    double c = 1.0;
    double s = 0.0;
    if (width > 0.0) {
        c = wx / width;
        s = wy / width;
    } else if (height > 0.0) {
        c = ty / height;
        s = -tx / height;
    }
    return rect_pose{point{static_cast<float>(cx), static_cast<float>(cy)},
                     point{static_cast<float>(width / 2.0), static_cast<float>(height / 2.0)},
                     point{static_cast<float>(c), static_cast<float>(s)}};
}

}  // namespace obbsat
