// The contact overlay of svg_contact_overlay.hpp.
#include "draw/svg_contact_overlay.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>

#include <cmath>
#include <vector>

namespace obbsat::svg {

namespace {

constexpr const char* color_contact = "#e07b00";
constexpr double arrow_pixels = 40;

template <class Box>
std::optional<contact> contact_with_points(const Box& a, const Box& b) {
    contact found{};
    const pair_index pair{0, 1};
    const Box boxes[] = {a, b};
    try {
        contact_pairs(boxes, 2, &pair, 1, &found, contact_options{});
    } catch (const invalid_input&) {
        return std::nullopt;  // a quad the contacts do not take: the panel shows it without an overlay
    }
    if (found.point_count == 0) {
        return std::nullopt;
    }
    return found;
}

/// The normal's line from `tail` to `head`, with a head of two barbs.
void draw_arrow(writer& out, svg_point tail, svg_point head, const contact& c) {
    out.leaf("line", attributes()
                         .set("class", "contact-normal")
                         .set("x1", tail.x)
                         .set("y1", tail.y)
                         .set("x2", head.x)
                         .set("y2", head.y)
                         .set("stroke", color_contact)
                         .set("stroke-width", 2));
    const double side_x = -c.ny;  // across the arrow, in SVG coordinates (y down)
    const double side_y = -c.nx;
    const svg_point barb_a{head.x - 8 * c.nx + 4 * side_x, head.y + 8 * c.ny + 4 * side_y};
    const svg_point barb_b{head.x - 8 * c.nx - 4 * side_x, head.y + 8 * c.ny - 4 * side_y};
    out.leaf("polygon", attributes()
                            .set("class", "contact-arrowhead")
                            .set("points", coordinate(head.x) + "," + coordinate(head.y) + " " +
                                               coordinate(barb_a.x) + "," + coordinate(barb_a.y) + " " +
                                               coordinate(barb_b.x) + "," + coordinate(barb_b.y))
                            .set("fill", color_contact));
}

}  // namespace

std::optional<contact_overlay> overlay_of(const rect& a, const rect& b) {
    if (const auto found = contact_with_points(a, b)) {
        return contact_overlay{*found, world_point{0, 0}};
    }
    return std::nullopt;
}

std::optional<contact_overlay> overlay_of(const rect_pose& a, const rect_pose& b, world_point origin) {
    if (const auto found = contact_with_points(a, b)) {
        return contact_overlay{*found, origin};
    }
    return std::nullopt;
}

void draw_contact_overlay(writer& out, const window& w, const contact_overlay& overlay) {
    const contact& c = overlay.found;
    out.open("g", attributes().set("class", "contact-overlay"));
    double mean_x = 0;
    double mean_y = 0;
    for (std::uint32_t k = 0; k < c.point_count; ++k) {
        mean_x += (static_cast<double>(c.points[k].x) - overlay.origin.x) / c.point_count;
        mean_y += (static_cast<double>(c.points[k].y) - overlay.origin.y) / c.point_count;
    }
    // The arrow ends at the points' middle and starts a fixed length back
    // along the normal, on A's side: it points from A towards B.
    // Extreme poses can put a point far outside the panel (or beyond double
    // range at the panel's scale): only what lies inside the view is drawn.
    const svg_point head = w.at(mean_x, mean_y);
    svg_point tail{head.x - arrow_pixels * c.nx, head.y + arrow_pixels * c.ny};
    svg_point tip = head;
    if (w.contains(head) && std::isfinite(tail.x) && std::isfinite(tail.y) && cut_segment(w, tail, tip)) {
        draw_arrow(out, tail, tip, c);
    }
    for (std::uint32_t k = 0; k < c.point_count; ++k) {
        const svg_point p = w.at(static_cast<double>(c.points[k].x) - overlay.origin.x,
                                 static_cast<double>(c.points[k].y) - overlay.origin.y);
        if (!w.contains(p)) {
            continue;
        }
        out.leaf("circle", attributes()
                               .set("class", "contact-point")
                               .set("cx", p.x)
                               .set("cy", p.y)
                               .set("r", 3.5)
                               .set("fill", color_contact)
                               .set("stroke", "white"));
    }
    out.close();
}

}  // namespace obbsat::svg
