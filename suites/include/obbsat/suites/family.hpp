// The families of hard cases for the accuracy work: each is built so that a
// real share of its pairs sits on, or within a few float steps of, the
// boundary between separated, touching and overlapping.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace obbsat::suites {

enum class family : std::uint8_t {
    random,            ///< broadphase-like scenes, plus rects built to kiss scene rects
    far,               ///< the random family's scenes moved to 1e4, 1e6 and 3e7
    integer_touching,  ///< integer rectangles edge on edge, corner on edge, corner on corner, and 1-unit shifts
    tiles,             ///< axis-aligned and rotated tile maps (grids, brick bonds, near and far) with shared edges
    grazing,           ///< gaps and overlaps of 0 to 4 float steps along an axis-aligned separating line
    near_parallel,     ///< facing edges parallel or within 1e-6 rad, at tiny signed gaps
    slivers,           ///< aspect ratios up to 1e6: crossing, side by side, against rects, tip on edge
    tiny,              ///< near-contact groups scaled to 1e-30, 2^-100, 1e-38 and into the subnormals
    huge,              ///< near-contact groups scaled to 1e15 .. 1e30, and offset to 1e30
    degenerate,        ///< points, segments, triangles and sub-ulp-thin quads against each other
    nested_cross,      ///< nested, identical, plus and X crosses, inner touching, T-shapes
};

/// The family's name, e.g. "near_parallel".
const char* family_name(family f);

/// The family called `name`; throws obbsat::invalid_input listing the names otherwise.
family parse_family(std::string_view name);

/// Every family, in declaration order.
const std::vector<family>& all_families();

}  // namespace obbsat::suites
