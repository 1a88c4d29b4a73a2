// Validation: whether the four corners of a rect really form a rectangle.
//
// The collision methods take any four finite corners and answer for the
// quadrilateral as given; they check nothing about its shape. These functions
// are for callers who want to know what they hand over, e.g. rectangles read
// from a file.
//
// A rect is checked in this order; the first failing check is the verdict:
//   1. non_finite    a coordinate is an infinity or a NaN.
//   2. degenerate    two adjacent corners coincide (a side of length zero), or
//                    all four corners lie on one line (zero area); decided
//                    exactly (oracle::orientation).
//   3. not_rectangle with the sides e0 = UR - UL, e1 = LR - UR, e2 = LL - LR,
//                    e3 = UL - LL, computed in double (where a float difference,
//                    square or product can neither overflow nor underflow):
//                      |e_k . e_k+1| > tolerance * |e_k| * |e_k+1|   (a corner is
//                        not a right angle: its cosine exceeds the tolerance), or
//                      ||e_k| - |e_k+2|| > tolerance * max(|e_k|, |e_k+2|)
//                        (opposite sides differ in length by more than the
//                        tolerance, relative to the longer).
//   Otherwise ok. The tolerance lies in [0, 1) and is relative to the
//   rectangle's own sides, so it does not depend on scale; but corners rounded
//   to float carry an error relative to their distance from the origin, so a
//   rectangle with shorter side s at distance d from the origin deviates by up
//   to about 2^-22 * d / s from a true one. The default, 1e-3, accepts any
//   rotation of a rectangle up to roughly 4000 times its shorter side away from
//   the origin; pass a larger tolerance for smaller ones farther out.
//
// Winding: ccw when UL -> UR -> LR turns counter-clockwise with x to the right
// and y up (the article's UL, UR, LR, LL with y up is clockwise). It is the
// exact sign of that turn, reported for quads that are not degenerate (an ok
// rect always has ccw or cw) and none otherwise; both windings are valid input.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <string>

namespace obbsat {

/// Why a rect is not a valid rectangle (none: it is).
enum class rect_problem { none, non_finite, degenerate, not_rectangle };

/// The direction of the turn UL -> UR -> LR (none: the corners make no turn).
enum class winding { none, ccw, cw };

/// The tolerance of check_rect and validate when none is given.
inline constexpr float default_rect_tolerance = 1e-3f;

/// What check_rect found about one rect.
struct rect_check {
    rect_problem problem = rect_problem::none;
    winding turn = winding::none;
    /// For not_rectangle, the largest relative deviation measured (see above); else 0.
    double deviation = 0.0;
    /// For a problem, which corner, side or coordinate is at fault, e.g. "corner UR"; else "".
    const char* where = "";

    /// True iff the rect is a valid rectangle.
    bool ok() const { return problem == rect_problem::none; }
};

/// "ok", "non-finite coordinate", "degenerate", "not a rectangle".
const char* problem_name(rect_problem p);

/// "none", "ccw", "cw".
const char* winding_name(winding w);

/// Checks one rect as stated above; throws invalid_input unless 0 <= tolerance < 1.
rect_check check_rect(const rect& r, float tolerance = default_rect_tolerance);

/// The first invalid rect of a batch, if any.
struct validation_report {
    /// True iff every rect is a valid rectangle.
    bool ok = true;
    /// The index of the first invalid rect; the batch size when ok.
    std::size_t index = 0;
    /// What check_rect said about that rect (default when ok).
    rect_check check;
    /// How many rects were checked and found valid with each winding (all of them when ok).
    std::size_t ccw_count = 0;
    std::size_t cw_count = 0;
    /// The index and the reason, e.g. "rectangle 17: not a rectangle: corner UR is
    /// not a right angle (|cos| 0.0312, tolerance 0.001)"; when ok, "all N
    /// rectangles are valid (C counter-clockwise, W clockwise)".
    std::string message;
};

/// Checks rects[0..n) in order and stops at the first invalid one; throws
/// invalid_input unless 0 <= tolerance < 1.
validation_report validate(const rect* rects, std::size_t n, float tolerance = default_rect_tolerance);

}  // namespace obbsat
