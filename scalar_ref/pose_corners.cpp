#include <obbsat/ref/pose_corners.hpp>

namespace obbsat::ref {

rect corners_of(const rect_pose& p) {
    const float ux = p.half_extents.x * p.rotation.x;
    const float uy = p.half_extents.x * p.rotation.y;
    const float wx = p.half_extents.y * p.rotation.y;  // v = (-wx, vy)
    const float vy = p.half_extents.y * p.rotation.x;
    const float left_x = p.center.x - ux;
    const float left_y = p.center.y - uy;
    const float right_x = p.center.x + ux;
    const float right_y = p.center.y + uy;
    return rect{point{left_x - wx, left_y + vy}, point{right_x - wx, right_y + vy},
                point{right_x + wx, right_y - vy}, point{left_x + wx, left_y - vy}};
}

}  // namespace obbsat::ref
