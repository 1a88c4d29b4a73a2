// The exact oracle for double corners: how two rect64, taken exactly as their
// double corners give them, relate as closed sets (separated, touching or
// overlapping, as contact.hpp defines them).
//
// The reading of four corners as a region is quad_region.hpp's, word for word,
// with double corners: a point, a segment, a convex polygon, a polygon with one
// reflex corner split in two triangles, or the convex hull of a self-crossing
// outline. The steps are the float oracle's, written once over the point type
// (scalar_ref/oracle/region_steps.hpp); every decision is an exact orientation
// sign (orientation64.hpp) or an exact comparison of input doubles.
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/quad_region.hpp>
#include <obbsat/rect64.hpp>

#include <cstdint>

namespace obbsat::oracle {

/// A closed convex piece with double corners: 1 corner (a point), 2 (a segment) or 3-4
/// (a polygon with positive area), counter-clockwise, no two equal, no three collinear.
struct convex_piece64 {
    std::uint8_t count;
    point64 corners[4];
};

/// The region of a rect64: the union of `piece_count` (1 or 2) convex pieces.
struct quad_region64 {
    quad_form form;
    std::uint8_t piece_count;
    convex_piece64 pieces[2];
};

/// The region the corners of `r` stand for; throws std::invalid_argument if a
/// coordinate is not finite.
quad_region64 region_of(const rect64& r);

/// How the regions of `a` and `b` relate; symmetric. Throws std::invalid_argument if a
/// coordinate is not finite.
contact classify(const rect64& a, const rect64& b);

/// True iff the closed regions of `a` and `b` share a point (touching counts).
bool intersects(const rect64& a, const rect64& b);

}  // namespace obbsat::oracle
