// A square window of a picture onto the world, and the cutting of lines and
// polygons to it.
//
// World points are placed in double relative to the window's centre, so a
// window may magnify a pair of one-ulp features anywhere in float range; a
// corner far outside it (an inset magnifies by up to about 1e46) then lands at
// a huge but finite position, and geometry is cut to a little more than the
// window before it is written, so that such positions never reach the file:
// the cut points are kept inside that box even where the rounding error of
// such a huge position would put them elsewhere.
// The window's SVG clip path makes the final, exact cut.
#pragma once

#include "draw/svg_pair_contact.hpp"

#include <obbsat/rect.hpp>

#include <vector>

namespace obbsat::svg {

/// A position in the picture, in pixels, y pointing down.
struct svg_point {
    double x;
    double y;
};

/// `center` drawn at the window's middle, `scale` pixels per world unit, y up.
struct window {
    world_point center;
    double scale;
    double left;
    double top;
    double size;

    svg_point at(double x, double y) const {
        return {left + 0.5 * size + (x - center.x) * scale, top + 0.5 * size - (y - center.y) * scale};
    }
    svg_point at(point p) const { return at(static_cast<double>(p.x), static_cast<double>(p.y)); }
    svg_point middle() const { return {left + 0.5 * size, top + 0.5 * size}; }
    bool contains(svg_point p) const {
        return p.x >= left && p.x <= left + size && p.y >= top && p.y <= top + size;
    }
};

/// Shortens [p, q] to its part inside the window's cut box; false if none is left.
bool cut_segment(const window& w, svg_point& p, svg_point& q);

/// The part of a polygon inside the window's cut box (empty if none).
std::vector<svg_point> cut_polygon(const window& w, std::vector<svg_point> polygon);

}  // namespace obbsat::svg
