// How far the float32 contact reference (obbsat/ref/contact.hpp), and the
// double contacts of the public entry points (obbsat/contact.hpp on
// pose_records64 and rect_records64), are from the exact contact of the same
// pair (contact_exact.hpp), per pair and per family.
//
// Errors are taken against the exact result of the reference face and the
// incident face the float reference chose ("same choice"): that isolates
// rounding from the decisions.
// Where the exact steps choose another face (a near tie of two separations,
// or of A's and B's within the tolerance), the pair is counted apart and its
// distance from the exact result of the exact choice is kept too.
//
// Units: u = 2^-24, half an ulp of 1 in float32 (2^-53 for the double contacts). A pair's reach R is the
// largest coordinate of its eight vertices relative to the reference's origin
// (A's center for poses, A's UL corner for corners): the magnitude its float
// arithmetic works at. Its size is the larger geometric half extent of its
// two boxes. Its offset O is the largest coordinate of that origin: positions
// are given back as origin + point, so their error is at least u·O.
#pragma once

#include "contact_exact.hpp"
#include "contact_families.hpp"

#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace obbsat::accuracy {

/// 2^-24.
inline constexpr double unit_roundoff = 5.9604644775390625e-08;

/// The errors of one pair.
struct pair_errors {
    bool measured = false;        ///< false: the corners are not strictly convex (rounded or exact)
    double unit = unit_roundoff;  ///< the rounding unit of the contact measured: 2^-24, or 2^-53 in double
    bool choice_matches_normal = true;  ///< the float normal is the face this file takes as the float choice
    bool choice_differs = false;  ///< the exact steps chose another reference face
    bool incident_differs = false;  ///< for the float's reference face, step 5 exact chose another incident face
    bool count_differs = false;   ///< point counts differ (same choice)
    double size = 0, reach = 0, offset = 0;
    double normal_angle = 0;      ///< radians, same choice
    double depth_error = 0;       ///< absolute, same choice
    double point_error = 0;       ///< largest distance of a point, same choice (counts equal)
    double separation_error = 0;  ///< largest error of a point's separation, same choice (counts equal)
    /// Against the exact choice (when it differs): normal angle, depth difference, point count.
    double normal_angle_exact_choice = 0;
    double depth_error_exact_choice = 0;
    bool count_differs_exact_choice = false;
    /// For a count difference: the least |exact separation| over sa, sb and
    /// every exact point, and the least distance between two exact points, in u·R.
    double count_boundary = 0;
};

/// The errors of the float reference's contact of poses a, b, or of corner quads a, b.
pair_errors measure_poses(const rect_pose& a, const rect_pose& b);
pair_errors measure_corners(const rect& a, const rect& b);

/// The errors of `c`, the double contact of poses a, b or of corner quads a, b.
pair_errors measure_poses(const rect_pose64& a, const rect_pose64& b, const contact64& c);
pair_errors measure_corners(const rect64& a, const rect64& b, const contact64& c);

/// Whether the contact of double quads a, b is defined and measurable: both
/// accepted by the entry points and strictly convex in exact arithmetic.
bool corners_measurable(const rect64& a, const rect64& b);

/// The double contacts of a family's pairs from the public entry points
/// (contact_stream): of the poses, one per pair; of the corner forms
/// (corners_of), one per pair whose corners are measurable, in order.
struct double_contacts {
    std::vector<contact64> poses;
    std::vector<bool> corners_measured;  ///< per pair
    std::vector<contact64> corners;      ///< per measured pair
};
double_contacts contacts_through_the_api(const std::vector<pose_pair64>& pairs);

/// The largest errors over a family, in the units the tables print.
struct family_errors {
    std::size_t pairs = 0, skipped = 0, mismatched_normals = 0, incident_differs = 0, choice_differs = 0, count_differs = 0, count_differs_exact_choice = 0;
    double normal_u = 0;          ///< normal angle / u (each pair's own u)
    double depth_size = 0;        ///< depth error / size
    double depth_u_reach = 0;     ///< depth error / (u·R)
    double point_size = 0;        ///< point error / size
    double point_u_scale = 0;     ///< point error / (u·(O + R))
    double separation_u_reach = 0;
    double count_boundary_u_reach = 0;  ///< the largest count_boundary over count differences
    double normal_exact_choice = 0;     ///< radians
    double depth_exact_choice_size = 0;
    void add(const pair_errors& e);
};

/// Both forms of `pairs`: the poses, then their corners (corners_of).
struct family_result {
    family_errors poses;
    family_errors corners;
};
family_result measure_family(const std::vector<pose_pair>& pairs);

/// Both forms of double `pairs`, their contacts from the public entry points.
family_result measure_family(const std::vector<pose_pair64>& pairs);

}  // namespace obbsat::accuracy
