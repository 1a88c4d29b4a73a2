#include "draw/svg_double_axes.hpp"

#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/local64.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace obbsat::svg {

namespace {

constexpr std::array<const char*, 4> pose_axis_labels = {"A.x", "A.y", "B.x", "B.y"};
constexpr std::array<const char*, 4> pose_axis_definitions = {"A's (c, s)", "A's (-s, c)", "B's (c, s)",
                                                              "B's (-s, c)"};

int first_separating(const std::vector<axis_view>& axes) {
    for (std::size_t k = 0; k < axes.size(); ++k) {
        if (!axes[k].overlap) {
            return static_cast<int>(k);
        }
    }
    return -1;
}

rect_pose64 without_extents(rect_pose64 p) {
    p.half_extents = point64{0.0, 0.0};
    return p;
}

// The four pose axes with local's double offsets and reaches as their bars,
// A's projection around 0 (its centre) and B's around the offset.
std::vector<axis_view> pose_axes(const rect_pose64& a, const rect_pose64& b, const ref::pose_axes64& both) {
    const ref::pose_axes64 a_alone = ref::local_axes(a, without_extents(b));
    const ref::pose_axes64 b_alone = ref::local_axes(without_extents(a), b);
    std::vector<axis_view> axes;
    for (std::size_t k = 0; k < 4; ++k) {
        const point64 rotation = k < 2 ? a.rotation : b.rotation;
        axis_view view;
        view.label = pose_axis_labels[k];
        view.definition = pose_axis_definitions[k];
        view.axis_x = k % 2 == 0 ? rotation.x : -rotation.y;
        view.axis_y = k % 2 == 0 ? rotation.y : rotation.x;
        view.a_min = -a_alone.reach[k];
        view.a_max = a_alone.reach[k];
        view.b_min = both.offset[k] - b_alone.reach[k];
        view.b_max = both.offset[k] + b_alone.reach[k];
        axes.push_back(view);
    }
    return axes;
}

}  // namespace

method_view view_of_pose64_method(method m, const rect_pose64& a, const rect_pose64& b, bool collides) {
    const ref::pose_axes64 both = ref::local_axes(a, b);
    method_view view;
    view.axes = pose_axes(a, b, both);
    if (m == method::local) {
        view.arithmetic = "double";
        for (std::size_t k = 0; k < 4; ++k) {
            view.axes[k].overlap = ref::shows_overlap(both, static_cast<int>(k));
        }
        view.separating = first_separating(view.axes);
        if ((view.separating < 0) != collides) {
            throw std::logic_error("the replayed steps of method local on doubles disagree with the library's verdict");
        }
        return view;
    }
    if (m != method::conservative && m != method::exact) {
        throw std::invalid_argument(std::string("method ") + method_name(m) + " does not run on double poses");
    }
    view.arithmetic = m == method::exact ? "exact signs (double oracle)"
                                         : "judged by exact signs; the method proves a double margin";
    const std::array<int, 4> signs = oracle::slack_signs(a, b);
    for (std::size_t k = 0; k < 4; ++k) {
        view.axes[k].overlap = signs[k] >= 0;
    }
    const int separating = first_separating(view.axes);
    if (collides) {
        if (separating >= 0) {
            const std::string& label = view.axes[static_cast<std::size_t>(separating)].label;
            if (m == method::exact) {
                throw std::logic_error("axis " + label +
                                       " separates the double poses exactly, yet method exact says they collide");
            }
            view.note = "axis " + label + " separates exactly, but by less than the method's margin";
        }
        return view;
    }
    if (separating < 0) {
        throw std::logic_error(std::string("method ") + method_name(m) +
                               " says apart, yet no axis separates the double poses exactly");
    }
    view.separating = separating;
    return view;
}

method_view view_of_rect64_method(method m, const rect64& a, const rect64& b, bool collides, world_point origin) {
    if (m != method::conservative && m != method::exact) {
        throw std::invalid_argument(std::string("method ") + method_name(m) + " does not run on double corners");
    }
    const auto relative = [&](const rect64& r) {
        return std::array<point64, 4>{point64{r.ul.x - origin.x, r.ul.y - origin.y},
                                      point64{r.ur.x - origin.x, r.ur.y - origin.y},
                                      point64{r.lr.x - origin.x, r.lr.y - origin.y},
                                      point64{r.ll.x - origin.x, r.ll.y - origin.y}};
    };
    const std::array<point64, 4> ca = relative(a);
    const std::array<point64, 4> cb = relative(b);
    const auto extent = [](const std::array<point64, 4>& corners, double x, double y, double& lo, double& hi) {
        lo = HUGE_VAL;
        hi = -HUGE_VAL;
        for (const point64& p : corners) {
            const double s = p.x * x + p.y * y;
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
    };
    method_view view;
    view.arithmetic = "double, from the corners as drawn; the verdict is the library's";
    const std::array<const char*, 4> labels = {"1", "2", "3", "4"};
    const std::array<const char*, 4> definitions = {"A.UR-A.UL", "A.LR-A.UR", "B.UR-B.UL", "B.LR-B.UR"};
    for (std::size_t k = 0; k < 4; ++k) {
        const std::array<point64, 4>& quad = k < 2 ? ca : cb;
        const point64 from = k % 2 == 0 ? quad[0] : quad[1];
        const point64 to = k % 2 == 0 ? quad[1] : quad[2];
        axis_view axis;
        axis.label = labels[k];
        axis.definition = definitions[k];
        axis.axis_x = to.x - from.x;
        axis.axis_y = to.y - from.y;
        extent(ca, axis.axis_x, axis.axis_y, axis.a_min, axis.a_max);
        extent(cb, axis.axis_x, axis.axis_y, axis.b_min, axis.b_max);
        const bool degenerate = axis.axis_x == 0.0 && axis.axis_y == 0.0;
        axis.overlap = degenerate || !(axis.a_max < axis.b_min || axis.b_max < axis.a_min);
        view.axes.push_back(axis);
    }
    const int separating = first_separating(view.axes);
    if (collides && separating >= 0) {
        view.note = "axis " + view.axes[static_cast<std::size_t>(separating)].label +
                    " shows a gap in double, below what the method decides on (its margin, or rounding)";
    } else if (!collides && separating < 0) {
        view.note = "no edge axis shows the gap in double; the double oracle finds the pair apart";
    } else if (!collides) {
        view.separating = separating;
    }
    return view;
}

}  // namespace obbsat::svg
