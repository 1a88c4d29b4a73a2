// Method sat4_double: the article's test with float input and double
// arithmetic, the accuracy baseline among the float-style methods.
//
// Contract: every corner coordinate is converted to double (exactly), then
// sat4's steps run in the order sat4.hpp states, each operation rounded to
// double: axes by subtraction, scalars (x * ax) + (y * ay) without FMA, min
// and max picks folded UL, UR, LR, LL, overlap iff minB <= maxA and maxB >= minA.
// A product of a float coordinate and a double axis component is not always
// exact, so this method is more accurate than sat4, not exact.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::ref {

/// An axis of sat4_double: two double components.
struct double_axis {
    double x;
    double y;
};

/// The interval a rectangle's corners cover on one axis, as sat4_double's scalars.
struct double_extent {
    double min;
    double max;
};

/// The article's four axes for the pair (a, b) in double, in the order they are tested.
void sat4_double_axes(const rect& a, const rect& b, double_axis axes[4]);

/// min and max of the four corner scalars of `r` on `axis`, each step as the contract states.
double_extent sat4_double_projection(const rect& r, double_axis axis);

/// True iff the two extents overlap: b.min <= a.max and b.max >= a.min.
bool double_extents_overlap(double_extent a, double_extent b);

/// Method sat4_double: true iff no axis separates a and b, in double arithmetic.
bool sat4_double(const rect& a, const rect& b);

}  // namespace obbsat::ref
