#include "draw/svg_pair_panel.hpp"

#include "draw/svg_contact_overlay.hpp"
#include "draw/svg_double_axes.hpp"

#include "draw/svg_pair_axes.hpp"
#include "draw/svg_pair_contact.hpp"
#include "draw/svg_pose_axes.hpp"
#include "draw/svg_window.hpp"

#include <obbsat/oracle/quad_region.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace obbsat::svg {

namespace {

// Layout of a panel, in pixels from its top-left corner.
constexpr double margin = 10;
constexpr double main_left = margin;
constexpr double main_top = 50;
constexpr double main_size = 360;
constexpr double main_padding = 26;  // room for corner and axis labels
constexpr double side_left = main_left + main_size + margin;
// The inset leaves room below it for the longest legend (13 lines).
constexpr double inset_size = 200;
constexpr double caption_top = main_top + main_size + 16;
constexpr double line_height = 11.5;

constexpr std::array<const char*, 4> corner_names = {"UL", "UR", "LR", "LL"};

std::array<point, 4> corners_of(const rect& r) { return {r.ul, r.ur, r.lr, r.ll}; }

// A quad as a panel draws it: its corners in order around it, in the panel's
// world coordinates, and whether they carry the names UL UR LR LL (a pose's
// corners carry none; its centre is marked instead).
struct outline {
    std::array<world_point, 4> corners;
    bool named_corners;
};

outline outline_of(const rect& r) {
    outline o{{}, true};
    const std::array<point, 4> corners = corners_of(r);
    for (std::size_t i = 0; i < 4; ++i) {
        o.corners[i] = world_point{corners[i].x, corners[i].y};
    }
    return o;
}

// The corners of pose `p` (a rect_pose or a rect_pose64) in double, measured
// from `origin`, in the order of ref::corners_of (UL, UR, LR, LL): the centre
// difference first (exact for nearby values), then the rotated half extents;
// for float poses each product of two floats is exact, so each corner is two
// roundings from the pose's own, whatever the pose's scale.
template <class Pose>
outline outline_of_pose(const Pose& p, world_point origin) {
    const double cx = static_cast<double>(p.center.x) - origin.x;
    const double cy = static_cast<double>(p.center.y) - origin.y;
    const double hx = p.half_extents.x, hy = p.half_extents.y;
    const double ux = hx * p.rotation.x, uy = hx * p.rotation.y;
    const double vx = -(hy * p.rotation.y), vy = hy * p.rotation.x;
    return outline{{{{(cx - ux) + vx, (cy - uy) + vy},
                     {(cx + ux) + vx, (cy + uy) + vy},
                     {(cx + ux) - vx, (cy + uy) - vy},
                     {(cx - ux) - vx, (cy - uy) - vy}}},
                   false};
}

// The corners of double quad `r` measured from `origin`, named UL UR LR LL.
outline outline_of(const rect64& r, world_point origin) {
    outline o{{}, true};
    const std::array<point64, 4> corners = {r.ul, r.ur, r.lr, r.ll};
    for (std::size_t i = 0; i < 4; ++i) {
        o.corners[i] = world_point{corners[i].x - origin.x, corners[i].y - origin.y};
    }
    return o;
}

// Everything a panel draws, whatever kind of pair it shows.
struct panel_content {
    std::uint64_t pair_number;
    std::string members;  // who A and B are, e.g. "A = rect 3, B = rect 4"
    method test;
    bool collides;
    oracle::contact exact;
    outline a;
    outline b;
    method_view axes;
    contact_view contact;
    std::optional<contact_overlay> library_contact;  // the library's normal and points, when it has points
    std::vector<std::string> remarks;  // about the shapes, for the legend
    std::string caption_a;
    std::string caption_b;
};

const char* contact_name(oracle::contact c) {
    switch (c) {
        case oracle::contact::separated: return "separated";
        case oracle::contact::touching: return "touching";
        case oracle::contact::overlapping: return "overlapping";
    }
    return "unknown";
}

// How the exact oracle reads a quad (see quad_region.hpp), for a sentence.
const char* quad_form_article(oracle::quad_form form) {
    switch (form) {
        case oracle::quad_form::point: return "a point";
        case oracle::quad_form::segment: return "a segment";
        case oracle::quad_form::convex: return "convex";
        case oracle::quad_form::concave: return "concave (a corner pushed in)";
        case oracle::quad_form::non_simple: return "self-crossing (its hull is used)";
    }
    return "unknown";
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string hex_float(float value) { return format("%a", static_cast<double>(value)); }

std::string hex_rect(const rect& r) {
    std::string out;
    for (const point p : corners_of(r)) {
        out += (out.empty() ? "" : ",") + hex_float(p.x) + "," + hex_float(p.y);
    }
    return out;
}

std::string points_text(const std::vector<svg_point>& polygon) {
    std::string out;
    for (const svg_point p : polygon) {
        out += (out.empty() ? "" : " ") + coordinate(p.x) + "," + coordinate(p.y);
    }
    return out;
}

void draw_segment(writer& out, const window& w, svg_point p, svg_point q, attributes style) {
    if (!cut_segment(w, p, q)) {
        return;
    }
    out.leaf("line", style.set("x1", p.x).set("y1", p.y).set("x2", q.x).set("y2", q.y));
}

// A label readable over lines: white halo behind dark text.
void draw_label(writer& out, svg_point at, const std::string& text, double font_size,
                const char* color, const char* anchor = "middle") {
    out.text("text",
             attributes()
                 .set("x", at.x)
                 .set("y", at.y)
                 .set("font-size", font_size)
                 .set("fill", color)
                 .set("text-anchor", anchor)
                 .set("dominant-baseline", "central")
                 .set("stroke", "white")
                 .set("stroke-width", 2.5)
                 .set("paint-order", "stroke"),
             text);
}

// The window's square, as the attributes of a <rect> to which a style is added.
attributes window_square(const window& w) {
    attributes square;
    square.set("x", w.left).set("y", w.top).set("width", w.size).set("height", w.size);
    return square;
}

void clip_path(writer& out, const std::string& id, const window& w) {
    out.open("clipPath", attributes().set("id", id));
    out.leaf("rect", window_square(w));
    out.close();
}

// A quad: translucent fill, outline, corner dots and, for corners inside the
// window, their names placed outwards from the quad's middle (or, for a quad
// without corner names, a mark at its middle).
void draw_quad(writer& out, const window& w, const outline& quad, const char* color, const char* css_class,
               double stroke_width) {
    std::vector<svg_point> polygon;
    for (const world_point p : quad.corners) {
        polygon.push_back(w.at(p.x, p.y));
    }
    out.open("g", attributes().set("class", css_class));
    const std::vector<svg_point> fill = cut_polygon(w, polygon);
    if (fill.size() >= 3) {
        out.leaf("polygon", attributes()
                                .set("points", points_text(fill))
                                .set("fill", color)
                                .set("fill-opacity", "0.13")
                                .set("stroke", "none"));
    }
    for (std::size_t i = 0; i < 4; ++i) {
        draw_segment(out, w, polygon[i], polygon[(i + 1) % 4],
                     attributes().set("stroke", color).set("stroke-width", stroke_width));
    }
    svg_point middle{0, 0};
    for (const svg_point p : polygon) {
        middle.x += 0.25 * p.x;
        middle.y += 0.25 * p.y;
    }
    if (!quad.named_corners && w.contains(middle)) {
        out.leaf("circle", attributes()
                               .set("class", "center")
                               .set("cx", middle.x)
                               .set("cy", middle.y)
                               .set("r", 3)
                               .set("fill", "white")
                               .set("stroke", color)
                               .set("stroke-width", 1.5));
    }
    for (std::size_t i = 0; i < 4; ++i) {
        const svg_point p = polygon[i];
        if (!w.contains(p)) {
            continue;
        }
        out.leaf("circle", attributes().set("cx", p.x).set("cy", p.y).set("r", 2.4).set("fill", color));
        if (!quad.named_corners) {
            continue;
        }
        // Inside the quad, where a label cannot be taken for the corner of a
        // neighbour sharing it; outside when the quad is too small to hold it.
        double dx = middle.x - p.x, dy = middle.y - p.y;
        const double d = std::hypot(dx, dy);
        const double step = d > 30 ? 11 : -10;
        if (d < 1e-9) {
            dx = 1;
            dy = 1;
        } else {
            dx /= d;
            dy /= d;
        }
        draw_label(out, svg_point{p.x + step * dx, p.y + step * dy}, corner_names[i], 8, color);
    }
    out.close();
}

// The average of a quad's corners, in the window.
svg_point middle_of(const window& w, const outline& quad) {
    svg_point sum{0, 0};
    for (const world_point p : quad.corners) {
        const svg_point q = w.at(p.x, p.y);
        sum.x += 0.25 * q.x;
        sum.y += 0.25 * q.y;
    }
    return sum;
}

// The unit direction of an axis in the window (y flipped), or nothing for a
// zero or non-finite axis.
bool axis_direction(const axis_view& axis, svg_point& unit) {
    const double length = std::hypot(axis.axis_x, axis.axis_y);
    if (!(length > 0.0) || !std::isfinite(length)) {
        return false;
    }
    unit = {axis.axis_x / length, -axis.axis_y / length};
    return true;
}

// Where scalar `s` of `axis` lies along the axis line through the window's
// centre, in pixels from that centre (clamped far outside the window when
// the scalar overflowed); false for NaN.
bool scalar_offset(const window& w, const axis_view& axis, double s, double& offset) {
    const double length = std::hypot(axis.axis_x, axis.axis_y);
    if (std::isnan(s)) {
        return false;
    }
    const double origin_along = ((axis.origin_x - w.center.x) * axis.axis_x +
                                 (axis.origin_y - w.center.y) * axis.axis_y) /
                                length;
    const double along = s / length + origin_along;
    offset = std::clamp(along * w.scale, -4 * w.size, 4 * w.size);
    return !std::isnan(offset);
}

// The line where scalar `s` of `axis` is constant: one side of the gap.
void draw_extent_end(writer& out, const window& w, const axis_view& axis, double s,
                     const char* color) {
    svg_point unit{};
    double offset = 0;
    if (!axis_direction(axis, unit) || !scalar_offset(w, axis, s, offset)) {
        return;
    }
    const svg_point middle = w.middle();
    const svg_point foot{middle.x + offset * unit.x, middle.y + offset * unit.y};
    const svg_point across{-unit.y * 2 * w.size, unit.x * 2 * w.size};
    draw_segment(out, w, svg_point{foot.x - across.x, foot.y - across.y},
                 svg_point{foot.x + across.x, foot.y + across.y},
                 attributes()
                     .set("class", "extent-end")
                     .set("stroke", color)
                     .set("stroke-width", 1.2)
                     .set("stroke-dasharray", "5 3"));
}

// The two extent ends that face each other across the gap.
void draw_gap_lines(writer& out, const window& w, const axis_view& axis) {
    const bool a_first = axis.a_max < axis.b_min;
    draw_extent_end(out, w, axis, a_first ? axis.a_max : axis.a_min, color_a);
    draw_extent_end(out, w, axis, a_first ? axis.b_min : axis.b_max, color_b);
}

void draw_bar(writer& out, const window& w, const axis_view& axis, double lo, double hi,
              double side, const char* color, const char* css_class) {
    svg_point unit{};
    double from = 0, to = 0;
    if (!axis_direction(axis, unit) || !scalar_offset(w, axis, lo, from) ||
        !scalar_offset(w, axis, hi, to)) {
        return;
    }
    const svg_point middle = w.middle();
    const svg_point shift{-unit.y * side, unit.x * side};
    draw_segment(out, w, svg_point{middle.x + from * unit.x + shift.x, middle.y + from * unit.y + shift.y},
                 svg_point{middle.x + to * unit.x + shift.x, middle.y + to * unit.y + shift.y},
                 attributes()
                     .set("class", css_class)
                     .set("stroke", color)
                     .set("stroke-width", 5)
                     .set("stroke-linecap", "butt")
                     .set("stroke-opacity", "0.85"));
}

// `avoid`: the middles of both quads, which the separating axis's label keeps away from.
void draw_axis_line(writer& out, const window& w, const axis_view& axis, int slot, bool separating,
                    const std::array<svg_point, 2>& avoid) {
    svg_point unit{};
    if (!axis_direction(axis, unit)) {
        return;
    }
    const svg_point middle = w.middle();
    const double reach = 0.5 * w.size;
    attributes style;
    if (separating) {
        style.set("stroke", "#111").set("stroke-width", 2.6);
    } else {
        style.set("stroke", "#8a8a8a").set("stroke-width", 0.9).set("stroke-dasharray", "6 4");
    }
    draw_segment(out, w, svg_point{middle.x - reach * unit.x, middle.y - reach * unit.y},
                 svg_point{middle.x + reach * unit.x, middle.y + reach * unit.y}, style);
    if (separating) {
        // Beside the line, clear of the extent bars that run along it, at
        // whichever end and side lies farthest from both quads.
        const svg_point side{-unit.y, unit.x};
        svg_point best{};
        double best_room = -1;
        for (const double along : {0.42, -0.42}) {
            for (const double across : {18.0, -18.0}) {
                const svg_point at{middle.x + along * w.size * unit.x + across * side.x,
                                   middle.y + along * w.size * unit.y + across * side.y};
                const double room = std::min(std::hypot(at.x - avoid[0].x, at.y - avoid[0].y),
                                             std::hypot(at.x - avoid[1].x, at.y - avoid[1].y));
                if (room > best_room) {
                    best_room = room;
                    best = at;
                }
            }
        }
        draw_label(out, best, "axis " + axis.label, 11, "#111");
        return;
    }
    // Parallel axes would put their labels on top of each other: each label
    // sits at its own distance from the centre.
    const double at = (0.30 + 0.045 * slot) * w.size;
    draw_label(out, svg_point{middle.x + at * unit.x, middle.y + at * unit.y}, axis.label, 10, "#555");
}

// The status of an axis in a few words: "overlap", "gap 0.5", or why the
// extents cannot be measured (float scalars that overflowed).
std::string axis_status(const axis_view& axis) {
    if (axis.overlap) {
        return "overlap";
    }
    const double length = std::hypot(axis.axis_x, axis.axis_y);
    const double gap = std::max(axis.b_min - axis.a_max, axis.a_min - axis.b_max) / length;
    if (std::isnan(gap)) {
        return "apart (NaN scalars)";
    }
    if (!std::isfinite(gap)) {
        return "apart (scalars overflow)";
    }
    return "gap " + format("%.3g", gap);
}

void draw_main_view(writer& out, const panel_content& pair, const method_view& axes,
                    const contact_view& contact, const window& w, const std::string& id) {
    out.open("g", attributes().set("class", "main-view").set("clip-path", "url(#" + id + "-main)"));
    out.leaf("rect", window_square(w).set("fill", "#fbfbfb"));
    // A's outline is wider, so that an edge B shares with it still shows.
    draw_quad(out, w, pair.a, color_a, "rect-a", 3.0);
    draw_quad(out, w, pair.b, color_b, "rect-b", 1.4);
    const std::array<svg_point, 2> quad_middles = {middle_of(w, pair.a), middle_of(w, pair.b)};
    for (std::size_t k = 0; k < axes.axes.size(); ++k) {
        if (static_cast<int>(k) != axes.separating) {
            draw_axis_line(out, w, axes.axes[k], static_cast<int>(k), false, quad_middles);
        }
    }
    if (axes.separating >= 0) {
        const axis_view& axis = axes.axes[static_cast<std::size_t>(axes.separating)];
        out.open("g", attributes().set("class", "separating-axis").set("data-axis", axis.label));
        draw_gap_lines(out, w, axis);
        draw_axis_line(out, w, axis, axes.separating, true, quad_middles);
        draw_bar(out, w, axis, axis.a_min, axis.a_max, 6, color_a, "extent-a");
        draw_bar(out, w, axis, axis.b_min, axis.b_max, -6, color_b, "extent-b");
        out.close();
    }
    if (pair.library_contact) {
        draw_contact_overlay(out, w, *pair.library_contact);
    }
    if (contact.has_inset) {
        const svg_point spot = w.at(contact.inset_center.x, contact.inset_center.y);
        out.leaf("circle", attributes()
                               .set("class", "inset-marker")
                               .set("cx", spot.x)
                               .set("cy", spot.y)
                               .set("r", 7)
                               .set("fill", "none")
                               .set("stroke", "#222")
                               .set("stroke-width", 1.2));
        draw_label(out, svg_point{spot.x + 10, spot.y - 10}, "inset", 8, "#222", "start");
    }
    out.close();
    out.leaf("rect", window_square(w).set("fill", "none").set("stroke", "#bbb"));
}

void draw_inset(writer& out, const panel_content& pair, const method_view& axes,
                const contact_view& contact, const window& w, const window& main,
                const std::string& id) {
    out.open("g", attributes().set("class", "inset"));
    out.open("g", attributes().set("clip-path", "url(#" + id + "-inset)"));
    out.leaf("rect", window_square(w).set("fill", "white"));
    // A's outline is wider, so that an edge B shares with it still shows.
    draw_quad(out, w, pair.a, color_a, "rect-a", 3.0);
    draw_quad(out, w, pair.b, color_b, "rect-b", 1.4);
    if (axes.separating >= 0) {
        out.open("g", attributes().set("class", "separating-strip"));
        draw_gap_lines(out, w, axes.axes[static_cast<std::size_t>(axes.separating)]);
        out.close();
    }
    const svg_point on_a = w.at(contact.closest_a.x, contact.closest_a.y);
    const svg_point on_b = w.at(contact.closest_b.x, contact.closest_b.y);
    if (!contact.outlines_meet) {
        draw_segment(out, w, on_a, on_b,
                     attributes().set("class", "closest-gap").set("stroke", "#111").set("stroke-width", 1));
    }
    for (const svg_point p : {on_a, on_b}) {
        if (w.contains(p)) {
            out.leaf("circle", attributes().set("cx", p.x).set("cy", p.y).set("r", 1.8).set("fill", "#111"));
        }
    }
    out.close();
    out.leaf("rect", window_square(w).set("fill", "none").set("stroke", "#222").set("stroke-width", 1.2));
    const double zoom = w.scale / main.scale;
    draw_label(out, svg_point{w.left + 5, w.top + 9}, "inset, zoom \xC3\x97" + format("%.3g", zoom), 9,
               "#111", "start");
    draw_label(out, svg_point{w.left + 5, w.top + 21}, "width " + format("%.3g", contact.inset_span) + " = " +
                   format("%.3g", contact.inset_span / contact.inset_ulp) +
                   " " + contact.ulp_name + " ulps there", 8,
               "#333", "start");
    const std::string measure =
        contact.outlines_meet
            ? (contact.depth > 0 ? "outlines cross, depth " + format("%.3g", contact.depth) : "outlines meet")
            : "gap " + format("%.3g", contact.distance);
    draw_label(out, svg_point{w.left + 5, w.top + w.size - 9}, measure, 9, "#111", "start");
    out.close();
}

// Words per legend line: the side column holds about this many characters.
constexpr std::size_t legend_line_chars = 50;

void draw_legend(writer& out, const panel_content& pair, const method_view& axes,
                 const contact_view& contact, double left, double top) {
    out.open("g", attributes().set("class", "legend").set("font-size", 9.5));
    double y = top;
    const auto line = [&](const std::string& text, bool bold = false, const char* color = "#222") {
        // Wrapped at spaces, so that a long note stays inside the panel.
        std::string rest = text;
        while (!rest.empty()) {
            std::size_t cut = rest.size();
            if (cut > legend_line_chars) {
                cut = rest.rfind(' ', legend_line_chars);
                cut = cut == std::string::npos || cut == 0 ? legend_line_chars : cut;
            }
            attributes style;
            style.set("x", left).set("y", y).set("fill", color);
            if (bold) {
                style.set("font-weight", "bold");
            }
            out.text("text", style, rest.substr(0, cut));
            y += line_height;
            rest = cut < rest.size() ? rest.substr(rest[cut] == ' ' ? cut + 1 : cut) : std::string();
        }
    };
    line(std::string("axes of ") + method_name(pair.test) + " (" + axes.arithmetic + "):", true);
    for (std::size_t k = 0; k < axes.axes.size(); ++k) {
        const axis_view& axis = axes.axes[k];
        const bool separating = static_cast<int>(k) == axes.separating;
        std::string text = axis.label + "  " + axis.definition + "  " + axis_status(axis);
        if (separating) {
            text += "  \xE2\x97\x80 separates";
        }
        line(text, separating, separating ? "#111" : "#444");
    }
    if (axes.separating >= 0) {
        line("bars: the extents on that axis; dashed: their facing ends", false, "#666");
    }
    if (!axes.note.empty()) {
        line(axes.note, false, "#8a5a00");
    }
    for (const std::string& remark : pair.remarks) {
        line(remark, false, "#8a5a00");
    }
    if (contact.outlines_meet) {
        line(contact.depth > 0 ? "outlines cross; overlap depth " + format("%.3g", contact.depth)
                               : "outlines meet; interiors do not overlap");
    } else {
        line("closest outline points " + format("%.3g", contact.distance) + " apart");
    }
    line("pair size " + format("%.3g", contact.size) + ", y up", false, "#666");
    out.close();
}


void draw_panel(writer& out, const panel_content& pair, double left, double top) {
    const method_view& axes = pair.axes;
    const contact_view& contact = pair.contact;
    const bool exact_collides = pair.exact != oracle::contact::separated;
    const char* frame_color = pair.collides ? color_collide : color_apart;
    const std::string id = "panel-" + std::to_string(pair.pair_number);

    out.open("g", attributes()
                      .set("id", id)
                      .set("class", std::string("panel verdict-") + verdict_word(pair.collides))
                      .set("transform", "translate(" + coordinate(left) + "," + coordinate(top) + ")"));
    out.open("defs");
    const window main{contact.center, (main_size - 2 * main_padding) / contact.size, main_left,
                      main_top, main_size};
    clip_path(out, id + "-main", main);
    const window inset{contact.inset_center, inset_size / std::max(contact.inset_span, 1e-300),
                       side_left, main_top, inset_size};
    if (contact.has_inset) {
        clip_path(out, id + "-inset", inset);
    }
    out.close();

    out.leaf("rect", attributes()
                         .set("class", "frame")
                         .set("x", 1.5)
                         .set("y", 1.5)
                         .set("width", panel_width - 3)
                         .set("height", panel_height - 3)
                         .set("rx", 6)
                         .set("fill", "white")
                         .set("stroke", frame_color)
                         .set("stroke-width", 3));

    const std::string agreement =
        pair.collides == exact_collides
            ? "agrees with the exact answer"
            : (pair.collides ? "DISAGREES: a false collision" : "DISAGREES: a missed collision");
    out.open("text", attributes().set("class", "title").set("x", margin).set("y", 20).set("fill", "#111"));
    out.text("tspan", attributes().set("font-size", 14).set("font-weight", "bold"),
             "pair " + std::to_string(pair.pair_number) + ": " + method_name(pair.test) + " says " +
                 verdict_word(pair.collides) + "; exact class: " + contact_name(pair.exact));
    out.text("tspan",
             attributes()
                 .set("x", margin)
                 .set("dy", 17)
                 .set("font-size", 11)
                 .set("fill", pair.collides == exact_collides ? "#333" : "#b00000"),
             agreement + "   (" + pair.members + ")");
    out.close();

    // A badge in the verdict's colour, readable at a glance across a grid.
    const double badge_width = 70;
    out.leaf("rect", attributes()
                         .set("x", panel_width - margin - badge_width)
                         .set("y", 8)
                         .set("width", badge_width)
                         .set("height", 20)
                         .set("rx", 4)
                         .set("fill", frame_color));
    out.text("text",
             attributes()
                 .set("x", panel_width - margin - 0.5 * badge_width)
                 .set("y", 22)
                 .set("font-size", 11)
                 .set("font-weight", "bold")
                 .set("fill", "white")
                 .set("text-anchor", "middle"),
             pair.collides ? "COLLIDE" : "APART");

    draw_main_view(out, pair, axes, contact, main, id);
    double legend_top = main_top + 10;
    if (contact.has_inset) {
        draw_inset(out, pair, axes, contact, inset, main, id);
        legend_top = main_top + inset_size + 14;
    }
    draw_legend(out, pair, axes, contact, side_left, legend_top);

    out.open("g", attributes().set("class", "caption").set("font-family", "monospace").set("font-size", 6.5).set("fill", "#333"));
    out.text("text", attributes().set("x", margin).set("y", caption_top), pair.caption_a);
    out.text("text", attributes().set("x", margin).set("y", caption_top + 10), pair.caption_b);
    out.close();
    out.close();
}

// The shape of a pose in words, when it has no area or its rotation vector
// scales it noticeably; empty otherwise.
template <class Pose>
std::string pose_remark(const std::string& name, const Pose& p) {
    std::string shape;
    if (p.half_extents.x == 0 && p.half_extents.y == 0) {
        shape = name + " is a point (hx = hy = 0)";
    } else if (p.half_extents.x == 0 || p.half_extents.y == 0) {
        shape = name + " is a segment (" + (p.half_extents.x == 0 ? "hx" : "hy") + " = 0)";
    }
    const double length = std::hypot(static_cast<double>(p.rotation.x), static_cast<double>(p.rotation.y));
    if (std::fabs(length - 1.0) <= 1e-3) {
        return shape;
    }
    const std::string scale = "|(c, s)| = " + format("%.3g", length) + " scales it";
    return shape.empty() ? name + ": " + scale : shape + "; " + scale;
}

std::string hex_pose(const rect_pose& p) {
    return hex_float(p.center.x) + "," + hex_float(p.center.y) + "," + hex_float(p.half_extents.x) + "," +
           hex_float(p.half_extents.y) + "," + hex_float(p.rotation.x) + "," + hex_float(p.rotation.y);
}

std::string hex_double(double value) { return format("%a", value); }

std::string hex_pose(const rect_pose64& p) {
    return hex_double(p.center.x) + "," + hex_double(p.center.y) + "," + hex_double(p.half_extents.x) + "," +
           hex_double(p.half_extents.y) + "," + hex_double(p.rotation.x) + "," + hex_double(p.rotation.y);
}

std::string hex_rect(const rect64& r) {
    std::string out;
    for (const point64& c : {r.ul, r.ur, r.lr, r.ll}) {
        out += (out.empty() ? "" : ",") + hex_double(c.x) + "," + hex_double(c.y);
    }
    return out;
}

}  // namespace

const char* verdict_word(bool collides) { return collides ? "collide" : "apart"; }

void draw_pair_panel(writer& out, const pair_drawing& pair, double left, double top) {
    panel_content content{};
    content.pair_number = pair.pair_number;
    content.members = "A = rect " + std::to_string(pair.rects.a) + ", B = rect " + std::to_string(pair.rects.b);
    content.test = pair.test;
    content.collides = pair.collides;
    content.exact = pair.exact;
    content.a = outline_of(pair.a);
    content.b = outline_of(pair.b);
    content.axes = view_of_method(pair.test, pair.a, pair.b, pair.collides);
    content.contact = view_of_contact(pair.a, pair.b, pair.exact);
    content.library_contact = overlay_of(pair.a, pair.b);
    const oracle::quad_form form_a = oracle::region_of(pair.a).form;
    const oracle::quad_form form_b = oracle::region_of(pair.b).form;
    if (form_a != oracle::quad_form::convex || form_b != oracle::quad_form::convex) {
        content.remarks.push_back(std::string("as the exact oracle reads them: A is ") + quad_form_article(form_a) +
                                  ", B is " + quad_form_article(form_b));
    }
    content.caption_a = "A rect " + std::to_string(pair.rects.a) + ": " + hex_rect(pair.a);
    content.caption_b = "B rect " + std::to_string(pair.rects.b) + ": " + hex_rect(pair.b);
    draw_panel(out, content, left, top);
}

namespace {

// The pose test's view of a float or a double pose pair.
method_view view_of_poses(method m, const rect_pose& a, const rect_pose& b, bool collides) {
    return view_of_pose_method(m, a, b, collides);
}

method_view view_of_poses(method m, const rect_pose64& a, const rect_pose64& b, bool collides) {
    return view_of_pose64_method(m, a, b, collides);
}

// The panel of a pair of float or double poses.
template <class PoseDrawing>
void draw_pose_pair_panel(writer& out, const PoseDrawing& pair, double left, double top) {
    constexpr bool doubles = std::is_same_v<decltype(PoseDrawing::a), rect_pose64>;
    // Everything is measured from A's centre, where the axes' scalars start.
    const world_point origin{pair.a.center.x, pair.a.center.y};
    panel_content content{};
    content.pair_number = pair.pair_number;
    content.members = "A = pose " + std::to_string(pair.poses.a) + ", B = pose " + std::to_string(pair.poses.b) +
                      (doubles ? ", doubles" : "");
    content.test = pair.test;
    content.collides = pair.collides;
    content.exact = pair.exact;
    content.a = outline_of_pose(pair.a, origin);
    content.b = outline_of_pose(pair.b, origin);
    content.axes = view_of_poses(pair.test, pair.a, pair.b, pair.collides);
    content.contact = view_of_contact(content.a.corners, content.b.corners, pair.exact, origin,
                                      doubles ? value_type::float64 : value_type::float32);
    if constexpr (!doubles) {
        // The library's contacts are float32: drawn over float pairs only.
        content.library_contact = overlay_of(pair.a, pair.b, origin);
    }
    for (const std::string& remark : {pose_remark("A", pair.a), pose_remark("B", pair.b)}) {
        if (!remark.empty()) {
            content.remarks.push_back(remark);
        }
    }
    content.caption_a = "A pose " + std::to_string(pair.poses.a) + ": " + hex_pose(pair.a);
    content.caption_b = "B pose " + std::to_string(pair.poses.b) + ": " + hex_pose(pair.b);
    draw_panel(out, content, left, top);
}

}  // namespace

void draw_pair_panel(writer& out, const pose_pair_drawing& pair, double left, double top) {
    draw_pose_pair_panel(out, pair, left, top);
}

void draw_pair_panel(writer& out, const pose64_pair_drawing& pair, double left, double top) {
    draw_pose_pair_panel(out, pair, left, top);
}

void draw_pair_panel(writer& out, const rect64_pair_drawing& pair, double left, double top) {
    const world_point origin{pair.a.ul.x, pair.a.ul.y};
    panel_content content{};
    content.pair_number = pair.pair_number;
    content.members = "A = rect " + std::to_string(pair.rects.a) + ", B = rect " + std::to_string(pair.rects.b) +
                      ", doubles";
    content.test = pair.test;
    content.collides = pair.collides;
    content.exact = pair.exact;
    content.a = outline_of(pair.a, origin);
    content.b = outline_of(pair.b, origin);
    content.axes = view_of_rect64_method(pair.test, pair.a, pair.b, pair.collides, origin);
    content.contact =
        view_of_contact(content.a.corners, content.b.corners, pair.exact, origin, value_type::float64);
    content.caption_a = "A rect " + std::to_string(pair.rects.a) + ": " + hex_rect(pair.a);
    content.caption_b = "B rect " + std::to_string(pair.rects.b) + ": " + hex_rect(pair.b);
    draw_panel(out, content, left, top);
}

}  // namespace obbsat::svg
