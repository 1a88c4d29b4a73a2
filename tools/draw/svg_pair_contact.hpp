// Where two quads come closest, for drawing: the closest points of their
// outlines, how far apart (or how deep into each other) they are, and, for a
// grazing contact too fine to see at the scale of the pair, the region a
// zoomed inset should show.
//
// For corner rectangles, whether two edges meet is decided by exact
// orientation signs, so touching and one-ulp gaps are told apart exactly;
// distances, depths and points are then computed in double, relative to the
// pair's centre so that they keep their precision far from the world origin.
// Quads given by corners in double (the corners of poses, themselves rounded)
// are measured the same way with every sign taken in double: the exact class
// comes from the oracle, the picture only has to show it.
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect.hpp>

#include <array>

namespace obbsat::svg {

/// A point in double, in world coordinates.
struct world_point {
    double x;
    double y;
};

struct contact_view {
    world_point center;  ///< centre of the pair's bounding box
    double size = 0;     ///< the larger side of that box (positive, even for two equal points)

    world_point closest_a;  ///< on A's outline, closest to B's outline
    world_point closest_b;  ///< on B's outline, closest to A's outline
    bool outlines_meet = false;  ///< the outlines share a point (exact)
    double distance = 0;         ///< between the outlines; 0 when they meet
    double depth = 0;            ///< how far the interiors overlap along the best edge normal

    bool has_inset = false;  ///< the closest features are too close to see at the pair's scale
    world_point inset_center;
    double inset_span = 0;  ///< side of the square region the inset shows
    double inset_ulp = 0;   ///< the float (or double) spacing at the inset's centre, in the world
    const char* ulp_name = "float";  ///< which spacing inset_ulp is: "float" or "double"
};

/// The numbers a pair is given in, which set the spacing an inset measures in.
enum class value_type { float32, float64 };

/// A contact is grazing when the outline distance, or the overlap depth of
/// outlines that meet, is below this fraction of the pair's size.
inline constexpr double grazing_fraction = 0.01;

/// The contact view of (a, b); `exact` is the oracle's class of the pair.
contact_view view_of_contact(const rect& a, const rect& b, oracle::contact exact);

/// The same for two quads whose corners (in order around each) are given in
/// double, measured from the world point `origin`; the view's points are
/// measured from it too, and its float spacings are those at origin + point.
/// With `values` float64 (the double pairs of --precision double), the
/// spacings are double's.
contact_view view_of_contact(const std::array<world_point, 4>& a, const std::array<world_point, 4>& b,
                             oracle::contact exact, world_point origin, value_type values = value_type::float32);

/// The spacing of float values near `magnitude` (the float ulp there).
double float_spacing(double magnitude);

/// The spacing of double values near `magnitude` (the double ulp there).
double double_spacing(double magnitude);

}  // namespace obbsat::svg
