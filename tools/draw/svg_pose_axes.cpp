#include "draw/svg_pose_axes.hpp"

#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/ref/local.hpp>

#include <array>
#include <stdexcept>
#include <string>

namespace obbsat::svg {

namespace {

// In the order of ref::local_axes and oracle::slack_signs.
constexpr std::array<const char*, 4> axis_labels = {"A.x", "A.y", "B.x", "B.y"};
constexpr std::array<const char*, 4> axis_definitions = {"A's (c, s)", "A's (-s, c)", "B's (c, s)",
                                                         "B's (-s, c)"};

// Axis k without its extents: the rotation vector of its pose, or that
// vector turned a quarter, with scalars measured from A's centre.
axis_view pose_axis(const rect_pose& a, const rect_pose& b, std::size_t k) {
    const point rotation = k < 2 ? a.rotation : b.rotation;
    axis_view view;
    view.label = axis_labels[k];
    view.definition = axis_definitions[k];
    view.axis_x = k % 2 == 0 ? static_cast<double>(rotation.x) : -static_cast<double>(rotation.y);
    view.axis_y = k % 2 == 0 ? static_cast<double>(rotation.y) : static_cast<double>(rotation.x);
    view.origin_x = 0.0;
    view.origin_y = 0.0;
    return view;
}

// Both projections on an axis: A's at 0, B's at the centre offset.
void set_extents(axis_view& view, double offset, double reach_a, double reach_b) {
    view.a_min = -reach_a;
    view.a_max = reach_a;
    view.b_min = offset - reach_b;
    view.b_max = offset + reach_b;
}

int first_separating(const std::vector<axis_view>& axes) {
    for (std::size_t k = 0; k < axes.size(); ++k) {
        if (!axes[k].overlap) {
            return static_cast<int>(k);
        }
    }
    return -1;
}

rect_pose without_extents(rect_pose p) {
    p.half_extents = point{0.0f, 0.0f};
    return p;
}

// Method local, through its reference's steps.
method_view local_view(const rect_pose& a, const rect_pose& b) {
    const ref::pose_axes both = ref::local_axes(a, b);
    const ref::pose_axes a_alone = ref::local_axes(a, without_extents(b));
    const ref::pose_axes b_alone = ref::local_axes(without_extents(a), b);
    method_view view;
    view.arithmetic = "float";
    for (std::size_t k = 0; k < 4; ++k) {
        axis_view axis = pose_axis(a, b, k);
        set_extents(axis, both.offset[k], a_alone.reach[k], b_alone.reach[k]);
        axis.overlap = ref::shows_overlap(both, static_cast<int>(k));
        view.axes.push_back(axis);
    }
    view.separating = first_separating(view.axes);
    return view;
}

// Methods conservative and exact: every axis judged by its exact slack sign.
method_view certified_view(method m, const rect_pose& a, const rect_pose& b, bool collides) {
    const std::array<int, 4> signs = oracle::slack_signs(a, b);
    const std::array<oracle::axis_terms, 4> terms = oracle::terms_of_axes(a, b);
    method_view view;
    view.arithmetic = m == method::exact ? "exact signs" : "judged by exact signs; the method proves a float margin";
    for (std::size_t k = 0; k < 4; ++k) {
        axis_view axis = pose_axis(a, b, k);
        set_extents(axis, terms[k].offset, terms[k].reach_a, terms[k].reach_b);
        axis.overlap = signs[k] >= 0;
        view.axes.push_back(axis);
    }
    const int separating = first_separating(view.axes);
    if (collides) {
        if (separating >= 0) {
            const std::string& label = view.axes[static_cast<std::size_t>(separating)].label;
            if (m == method::exact) {
                throw std::logic_error("axis " + label + " separates the poses exactly, yet method exact says they collide");
            }
            view.note = "axis " + label + " separates exactly, but by less than the method's margin";
        }
        return view;
    }
    if (separating < 0) {
        // The four axes are complete for two rectangles: some slack is negative.
        throw std::logic_error(std::string("method ") + method_name(m) +
                               " says apart, yet no axis separates the poses exactly");
    }
    view.separating = separating;
    return view;
}

}  // namespace

method_view view_of_pose_method(method m, const rect_pose& a, const rect_pose& b, bool collides) {
    if (m == method::conservative || m == method::exact) {
        return certified_view(m, a, b, collides);
    }
    if (m != method::local) {
        throw std::invalid_argument(std::string("method ") + method_name(m) + " does not run on poses");
    }
    const method_view view = local_view(a, b);
    if ((view.separating < 0) != collides) {
        throw std::logic_error("the replayed steps of method local disagree with the library's verdict");
    }
    return view;
}

}  // namespace obbsat::svg
