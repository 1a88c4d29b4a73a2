#include "draw/svg_pair_axes.hpp"

#include <obbsat/oracle/orientation.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>

#include <array>
#include <stdexcept>

namespace obbsat::svg {

namespace {

constexpr std::array<const char*, 4> article_axis_names = {"A.UR-A.UL", "A.UR-A.LR", "B.UL-B.LL",
                                                           "B.UL-B.UR"};
constexpr std::array<const char*, 4> corner_names = {"UL", "UR", "LR", "LL"};

std::array<point, 4> corners_of(const rect& r) { return {r.ul, r.ur, r.lr, r.ll}; }

// The article's axes as (from, to) corner pairs: axis = to - from.
std::array<std::array<point, 2>, 4> article_axis_ends(const rect& a, const rect& b) {
    return {{{a.ul, a.ur}, {a.lr, a.ur}, {b.ll, b.ul}, {b.ur, b.ul}}};
}

axis_view article_axis(int k) {
    axis_view view;
    view.label = std::to_string(k + 1);
    view.definition = article_axis_names[static_cast<std::size_t>(k)];
    return view;
}

int first_separating(const std::vector<axis_view>& axes) {
    for (std::size_t k = 0; k < axes.size(); ++k) {
        if (!axes[k].overlap) {
            return static_cast<int>(k);
        }
    }
    return -1;
}

// A float or double method replayed on its four axes: each rect's extent by
// the method's own projection, each axis's verdict by its own overlap test.
// `origin` is where the method measures scalars from.
template <class Axis, class Project, class Overlap>
method_view replayed_view(const char* arithmetic, const Axis (&axes)[4], point origin, const rect& a,
                          const rect& b, Project project, Overlap overlap) {
    method_view view;
    view.arithmetic = arithmetic;
    for (int k = 0; k < 4; ++k) {
        const auto extent_a = project(a, axes[k]);
        const auto extent_b = project(b, axes[k]);
        axis_view v = article_axis(k);
        v.axis_x = axes[k].x;
        v.axis_y = axes[k].y;
        v.origin_x = origin.x;
        v.origin_y = origin.y;
        v.a_min = extent_a.min;
        v.a_max = extent_a.max;
        v.b_min = extent_b.min;
        v.b_max = extent_b.max;
        v.overlap = overlap(extent_a, extent_b);
        view.axes.push_back(v);
    }
    view.separating = first_separating(view.axes);
    return view;
}

// sat4 and sat4_centered, through the reference's own steps; the centered
// method measures from A.UL after moving every corner there in float.
method_view float_method_view(const rect& a, const rect& b, bool centered) {
    const point origin = centered ? a.ul : point{0.0f, 0.0f};
    const rect moved_a = centered ? ref::moved_to_origin(a, origin) : a;
    const rect moved_b = centered ? ref::moved_to_origin(b, origin) : b;
    point axes[4];
    ref::sat4_axes(moved_a, moved_b, axes);
    return replayed_view("float", axes, origin, moved_a, moved_b, ref::project_rect, ref::extents_overlap);
}

// sat4_double, through the reference's own steps in double.
method_view double_method_view(const rect& a, const rect& b) {
    ref::double_axis axes[4];
    ref::sat4_double_axes(a, b, axes);
    return replayed_view("double", axes, point{0.0f, 0.0f}, a, b, ref::sat4_double_projection,
                         ref::double_extents_overlap);
}

// The sign of (u_to - u_from) . (v_to - v_from), exact for all finite floats:
// expanded, it is eight products of two floats, each exact in double (24 + 24
// significand bits, magnitudes between 2^-298 and 2^256).
int exact_dot_sign(point u_from, point u_to, point v_from, point v_to) {
    const double ux0 = u_from.x, uy0 = u_from.y, ux1 = u_to.x, uy1 = u_to.y;
    const double vx0 = v_from.x, vy0 = v_from.y, vx1 = v_to.x, vy1 = v_to.y;
    const double terms[8] = {ux1 * vx1, -(ux1 * vx0), -(ux0 * vx1), ux0 * vx0,
                             uy1 * vy1, -(uy1 * vy0), -(uy0 * vy1), uy0 * vy0};
    return oracle::sign_of_exact_sum(terms, 8);
}

// True iff, on the axis to - from, every corner of one rect lies strictly
// before every corner of the other: the axis separates them exactly.
bool separates_exactly(const rect& a, const rect& b, point from, point to) {
    int before = 0;
    int after = 0;
    for (const point pa : corners_of(a)) {
        for (const point pb : corners_of(b)) {
            const int sign = exact_dot_sign(pa, pb, from, to);
            before += sign > 0 ? 1 : 0;
            after += sign < 0 ? 1 : 0;
        }
    }
    return before == 16 || after == 16;
}

// An axis judged by exact signs, with extents in double (measured from A.UL
// so that they stay precise far from the world origin) for drawing.
axis_view exact_axis(const rect& a, const rect& b, point from, point to, axis_view v) {
    v.axis_x = static_cast<double>(to.x) - static_cast<double>(from.x);
    v.axis_y = static_cast<double>(to.y) - static_cast<double>(from.y);
    v.origin_x = a.ul.x;
    v.origin_y = a.ul.y;
    const auto extent_of = [&](const rect& r, double& lo, double& hi) {
        bool first = true;
        for (const point p : corners_of(r)) {
            const double s = (static_cast<double>(p.x) - v.origin_x) * v.axis_x +
                             (static_cast<double>(p.y) - v.origin_y) * v.axis_y;
            lo = first || s < lo ? s : lo;
            hi = first || s > hi ? s : hi;
            first = false;
        }
    };
    extent_of(a, v.a_min, v.a_max);
    extent_of(b, v.b_min, v.b_max);
    v.overlap = !separates_exactly(a, b, from, to);
    return v;
}

// The first edge of A, then of B, whose normal separates the pair exactly.
bool find_separating_edge_normal(const rect& a, const rect& b, axis_view& found) {
    const std::array<const rect*, 2> quads = {&a, &b};
    for (std::size_t q = 0; q < 2; ++q) {
        const std::array<point, 4> c = corners_of(*quads[q]);
        for (std::size_t k = 0; k < 4; ++k) {
            const point p = c[k];
            const point r = c[(k + 1) % 4];
            // The normal (p.y - r.y, r.x - p.x) written as to - from of two
            // float points, so that its signs stay exact.
            const point to{p.y, r.x};
            const point from{r.y, p.x};
            axis_view v;
            v.label = "n";
            const std::string quad_name = q == 0 ? "A." : "B.";
            v.definition = "normal of " + quad_name + corner_names[k] + "-" + quad_name +
                           corner_names[(k + 1) % 4];
            v = exact_axis(a, b, from, to, v);
            if (!v.overlap) {
                found = v;
                return true;
            }
        }
    }
    return false;
}

method_view exact_method_view(method m, const rect& a, const rect& b, bool collides) {
    method_view view;
    view.arithmetic = m == method::exact ? "exact signs"
                                         : "judged by exact signs; the method proves a float margin";
    const auto ends = article_axis_ends(a, b);
    for (int k = 0; k < 4; ++k) {
        const auto& [from, to] = ends[static_cast<std::size_t>(k)];
        view.axes.push_back(exact_axis(a, b, from, to, article_axis(k)));
    }
    const int article_separating = first_separating(view.axes);
    if (collides) {
        if (article_separating >= 0) {
            if (m == method::exact) {
                throw std::logic_error("axis " + view.axes[static_cast<std::size_t>(article_separating)].label +
                                       " separates the pair exactly, yet method exact says they collide");
            }
            view.note = "axis " + view.axes[static_cast<std::size_t>(article_separating)].label +
                        " separates exactly, but by less than the method's margin";
        }
        return view;
    }
    if (article_separating >= 0) {
        view.separating = article_separating;
        return view;
    }
    if (m == method::conservative) {
        throw std::logic_error("method conservative says apart, yet no article axis separates the pair exactly");
    }
    axis_view normal;
    if (find_separating_edge_normal(a, b, normal)) {
        view.axes.push_back(normal);
        view.separating = static_cast<int>(view.axes.size()) - 1;
        view.note = "no article axis separates; an edge normal does";
        return view;
    }
    view.note = "separated, but no axis or edge normal separates (a concave or degenerate quad)";
    return view;
}

}  // namespace

method_view view_of_method(method m, const rect& a, const rect& b, bool collides) {
    method_view view;
    switch (m) {
        case method::sat4: view = float_method_view(a, b, false); break;
        case method::sat4_centered: view = float_method_view(a, b, true); break;
        case method::sat4_double: view = double_method_view(a, b); break;
        case method::conservative:
        case method::exact: return exact_method_view(m, a, b, collides);
        case method::local:  // refused for corners before any drawing (cli_args)
            throw std::logic_error("method local does not run on corners");
    }
    if ((view.separating < 0) != collides) {
        throw std::logic_error(std::string("the replayed steps of method ") + method_name(m) +
                               " disagree with the library's verdict");
    }
    return view;
}

}  // namespace obbsat::svg
