// The library's contact of a pair drawn over its panel: the normal as an
// arrow from A's side towards B, and each contact point as a dot, so that a
// picture shows what obbsat::contact_pairs (obbsat/contact.hpp) hands a
// solver. The SVG group is <g class="contact-overlay">, with
// <line class="contact-normal"> and one <circle class="contact-point"> per point.
#pragma once

#include "draw/svg_window.hpp"
#include "draw/svg_writer.hpp"

#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <optional>

namespace obbsat::svg {

/// A contact to draw, its points measured from the panel's world origin.
struct contact_overlay {
    contact found;
    world_point origin;  ///< subtracted from the contact's points (A's centre for poses)
};

/// The contact of two corner quads when they have points; nothing when they
/// have none or a quad is not one the contacts take (not strictly convex).
std::optional<contact_overlay> overlay_of(const rect& a, const rect& b);

/// The contact of two poses when they have points, measured from `origin`;
/// nothing when they have none or a pose is refused.
std::optional<contact_overlay> overlay_of(const rect_pose& a, const rect_pose& b, world_point origin);

/// Draws the normal and the points of `overlay` in the window `w`.
void draw_contact_overlay(writer& out, const window& w, const contact_overlay& overlay);

}  // namespace obbsat::svg
