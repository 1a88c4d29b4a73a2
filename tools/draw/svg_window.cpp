#include "draw/svg_window.hpp"

#include <algorithm>
#include <utility>

namespace obbsat::svg {

namespace {

// Pixels of room around the window, so that the cut ends of lines stay
// hidden under the clip path's edge.
constexpr double cut_slack = 4;

struct cut_box {
    double lo_x, hi_x, lo_y, hi_y;
};

cut_box box_of(const window& w) {
    return {w.left - cut_slack, w.left + w.size + cut_slack, w.top - cut_slack, w.top + w.size + cut_slack};
}

// The exact ends of a cut lie in the box, the computed ones need not: a
// position far outside the window (an inset magnifies by up to about 1e46,
// so positions reach 1e85) carries a rounding error that dwarfs the window,
// and so does a point interpolated from it. Put back into the box, such a
// point is nearer its exact place, and never beyond the picture.
svg_point into_box(const cut_box& b, svg_point p) {
    return {std::clamp(p.x, b.lo_x, b.hi_x), std::clamp(p.y, b.lo_y, b.hi_y)};
}

}  // namespace

// Liang-Barsky.
bool cut_segment(const window& w, svg_point& p, svg_point& q) {
    const cut_box box = box_of(w);
    const double lo_x = box.lo_x, hi_x = box.hi_x;
    const double lo_y = box.lo_y, hi_y = box.hi_y;
    const double dx = q.x - p.x, dy = q.y - p.y;
    double t0 = 0.0, t1 = 1.0;
    const double steps[4] = {-dx, dx, -dy, dy};
    const double room[4] = {p.x - lo_x, hi_x - p.x, p.y - lo_y, hi_y - p.y};
    for (int i = 0; i < 4; ++i) {
        if (steps[i] == 0.0) {
            if (room[i] < 0.0) {
                return false;
            }
            continue;
        }
        const double t = room[i] / steps[i];
        if (steps[i] < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
    }
    if (t0 > t1) {
        return false;
    }
    const svg_point from{p.x + t0 * dx, p.y + t0 * dy};
    const svg_point to{p.x + t1 * dx, p.y + t1 * dy};
    p = into_box(box, from);
    q = into_box(box, to);
    return true;
}

// Sutherland-Hodgman, one side of the box at a time.
std::vector<svg_point> cut_polygon(const window& w, std::vector<svg_point> polygon) {
    const cut_box box = box_of(w);
    const double bounds[4] = {box.lo_x, box.hi_x, box.lo_y, box.hi_y};
    for (int side = 0; side < 4; ++side) {
        const auto inside = [&](svg_point p) {
            switch (side) {
                case 0: return p.x >= bounds[0];
                case 1: return p.x <= bounds[1];
                case 2: return p.y >= bounds[2];
                default: return p.y <= bounds[3];
            }
        };
        const auto crossing = [&](svg_point p, svg_point q) {
            const bool vertical_side = side < 2;
            const double edge = bounds[side];
            const double t = vertical_side ? (edge - p.x) / (q.x - p.x) : (edge - p.y) / (q.y - p.y);
            return svg_point{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
        };
        std::vector<svg_point> kept;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const svg_point p = polygon[i];
            const svg_point q = polygon[(i + 1) % polygon.size()];
            if (inside(p)) {
                kept.push_back(p);
                if (!inside(q)) {
                    kept.push_back(crossing(p, q));
                }
            } else if (inside(q)) {
                kept.push_back(crossing(p, q));
            }
        }
        polygon = std::move(kept);
        if (polygon.empty()) {
            break;
        }
    }
    for (svg_point& p : polygon) {
        p = into_box(box, p);
    }
    return polygon;
}

}  // namespace obbsat::svg
