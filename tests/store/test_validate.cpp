// Validation of rect shapes: each problem with the corner, side or coordinate
// it names, both windings, the first offender of a batch, and float-rounded
// rotated rectangles accepted at the default tolerance.
#include "test_support/float_text.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/validate.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::check_rect;
using obbsat::point;
using obbsat::rect;
using obbsat::rect_check;
using obbsat::rect_problem;
using obbsat::winding;
using obbsat::test_support::describe;

// The article's order with y up: UL, UR, LR, LL turn clockwise.
const rect unit_cw{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
// The same square walked the other way round.
const rect unit_ccw{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

float* coordinate(rect& r, unsigned k) {
    float* all[8] = {&r.ul.x, &r.ul.y, &r.ur.x, &r.ur.y, &r.lr.x, &r.lr.y, &r.ll.x, &r.ll.y};
    return all[k];
}

TEST(validate, an_axis_aligned_square_is_valid_in_both_windings) {
    const rect_check cw = check_rect(unit_cw);
    EXPECT_TRUE(cw.ok());
    EXPECT_EQ(cw.turn, winding::cw);
    EXPECT_EQ(cw.deviation, 0.0);
    EXPECT_STREQ(cw.where, "");
    const rect_check ccw = check_rect(unit_ccw);
    EXPECT_TRUE(ccw.ok());
    EXPECT_EQ(ccw.turn, winding::ccw);
    // Any corner may come first: the winding is the turn, not the start.
    const rect rotated_start{unit_cw.lr, unit_cw.ll, unit_cw.ul, unit_cw.ur};
    EXPECT_EQ(check_rect(rotated_start).turn, winding::cw);
    EXPECT_STREQ(obbsat::winding_name(winding::cw), "cw");
    EXPECT_STREQ(obbsat::winding_name(winding::ccw), "ccw");
    EXPECT_STREQ(obbsat::winding_name(winding::none), "none");
}

TEST(validate, a_non_finite_coordinate_is_named) {
    const char* names[8] = {"ulx", "uly", "urx", "ury", "lrx", "lry", "llx", "lly"};
    const float bad[3] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
    for (unsigned k = 0; k < 8; ++k) {
        for (const float value : bad) {
            rect r = unit_cw;
            *coordinate(r, k) = value;
            const rect_check c = check_rect(r);
            EXPECT_EQ(c.problem, rect_problem::non_finite) << names[k];
            EXPECT_STREQ(c.where, names[k]);
            EXPECT_EQ(c.turn, winding::none);
            EXPECT_FALSE(c.ok());
        }
    }
    EXPECT_STREQ(obbsat::problem_name(rect_problem::non_finite), "non-finite coordinate");
}

TEST(validate, a_side_of_length_zero_is_degenerate_and_named) {
    const char* sides[4] = {"side UL-UR", "side UR-LR", "side LR-LL", "side LL-UL"};
    for (unsigned k = 0; k < 4; ++k) {
        point corners[4] = {unit_cw.ul, unit_cw.ur, unit_cw.lr, unit_cw.ll};
        corners[(k + 1) % 4] = corners[k];
        const rect r{corners[0], corners[1], corners[2], corners[3]};
        const rect_check c = check_rect(r);
        EXPECT_EQ(c.problem, rect_problem::degenerate) << describe(r);
        EXPECT_STREQ(c.where, sides[k]) << describe(r);
        EXPECT_EQ(c.turn, winding::none);
    }
    const rect point_rect{{3, 4}, {3, 4}, {3, 4}, {3, 4}};
    EXPECT_EQ(check_rect(point_rect).problem, rect_problem::degenerate);
    // Zero width: a segment walked there and back has sides of length zero.
    const rect segment{{0, 0}, {0, 0}, {5, 0}, {5, 0}};
    EXPECT_EQ(check_rect(segment).problem, rect_problem::degenerate);
}

TEST(validate, four_corners_on_one_line_are_degenerate_at_any_tolerance) {
    // Every side has a length, but the quad folds onto a line: zero area.
    const rect on_a_line{{0, 0}, {2, 2}, {1, 1}, {3, 3}};
    const rect there_and_back{{0, 0}, {1, 0}, {0, 0}, {1, 0}};
    const float big = 0x1p100f;
    const rect far_line{{big, big}, {big + 0x1p80f, big + 0x1p80f}, {big, big}, {big - 0x1p90f, big - 0x1p90f}};
    for (const rect& r : {on_a_line, there_and_back, far_line}) {
        for (const float tolerance : {0.0f, obbsat::default_rect_tolerance, 0.999f}) {
            const rect_check c = check_rect(r, tolerance);
            EXPECT_EQ(c.problem, rect_problem::degenerate) << describe(r);
            EXPECT_STREQ(c.where, "all four corners");
            EXPECT_EQ(c.turn, winding::none);
        }
    }
    // A zigzag is not on one line: a real shape, just not a rectangle.
    const rect zigzag{{0, 0}, {1, 1}, {0, 2}, {1, 3}};
    EXPECT_EQ(check_rect(zigzag).problem, rect_problem::not_rectangle);
    EXPECT_STREQ(obbsat::problem_name(rect_problem::degenerate), "degenerate");
    EXPECT_STREQ(obbsat::problem_name(rect_problem::none), "ok");
}

TEST(validate, a_corner_that_is_not_a_right_angle_is_named) {
    // A parallelogram: the right side leans by 0.1 over a height of 1.
    const rect sheared{{0, 1}, {1.1f, 1}, {1, 0}, {-0.1f, 0}};
    const rect_check c = check_rect(sheared);
    EXPECT_EQ(c.problem, rect_problem::not_rectangle);
    EXPECT_EQ(c.turn, winding::cw);
    EXPECT_GT(c.deviation, 0.09);
    EXPECT_LT(c.deviation, 0.11);
    EXPECT_EQ(std::string(c.where).rfind("corner ", 0), 0u) << c.where;
    // A bow tie: the sides cross.
    const rect bow_tie{{0, 1}, {1, 0}, {1, 1}, {0, 0}};
    EXPECT_EQ(check_rect(bow_tie).problem, rect_problem::not_rectangle);
    EXPECT_STREQ(obbsat::problem_name(rect_problem::not_rectangle), "not a rectangle");
}

TEST(validate, opposite_sides_of_unequal_length_are_named) {
    // A tall trapezoid: its corners are within 1% of right angles, but the
    // bottom is twice as long as the top.
    const rect trapezoid{{0, 100}, {1, 100}, {1, 0}, {-1, 0}};
    const rect_check c = check_rect(trapezoid);
    EXPECT_EQ(c.problem, rect_problem::not_rectangle);
    EXPECT_STREQ(c.where, "sides UL-UR and LR-LL");
    EXPECT_DOUBLE_EQ(c.deviation, 0.5);
    const rect wide{{0, 1}, {100, 1}, {100, 0}, {0, -1}};
    const rect_check w = check_rect(wide);
    EXPECT_EQ(w.problem, rect_problem::not_rectangle);
    EXPECT_STREQ(w.where, "sides UR-LR and LL-UL");
    EXPECT_DOUBLE_EQ(w.deviation, 0.5);
}

TEST(validate, the_tolerance_decides_near_rectangles) {
    // Sheared by 2^-10 of its height: |cos| of about 0.000977.
    const rect nearly{{0, 1}, {1 + 0x1p-10f, 1}, {1, 0}, {-0x1p-10f, 0}};
    EXPECT_EQ(check_rect(nearly, 1e-3f).problem, rect_problem::none);
    EXPECT_EQ(check_rect(nearly, 9e-4f).problem, rect_problem::not_rectangle);
    EXPECT_EQ(check_rect(unit_cw, 0.0f).problem, rect_problem::none);
    for (const float bad : {-1e-6f, 1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity()}) {
        EXPECT_THROW(check_rect(unit_cw, bad), obbsat::invalid_input) << bad;
        EXPECT_THROW(obbsat::validate(&unit_cw, 1, bad), obbsat::invalid_input) << bad;
    }
}

TEST(validate, subnormal_and_huge_rectangles_are_measured_without_underflow_or_overflow) {
    // Corners a few steps of the smallest subnormal apart: in float every
    // product of two sides would be zero.
    const float d = std::numeric_limits<float>::denorm_min();
    const rect tiny{{0, 2 * d}, {3 * d, 2 * d}, {3 * d, 0}, {0, 0}};
    const rect_check t = check_rect(tiny, 0.0f);
    EXPECT_TRUE(t.ok());
    EXPECT_EQ(t.turn, winding::cw);
    const rect tiny_turned{{0, 0}, {2 * d, 2 * d}, {0, 4 * d}, {-2 * d, 2 * d}};
    EXPECT_TRUE(check_rect(tiny_turned, 0.0f).ok());
    // Sides as long as the float range is wide: in float every square overflows.
    const float m = std::numeric_limits<float>::max();
    const rect huge{{-m, m}, {m, m}, {m, -m}, {-m, -m}};
    EXPECT_TRUE(check_rect(huge, 0.0f).ok());
    const rect huge_sheared{{-m, m}, {m, m}, {m, -m}, {-m, -m / 2}};
    EXPECT_EQ(check_rect(huge_sheared).problem, rect_problem::not_rectangle);
}

TEST(validate, float_rounded_rotated_rectangles_pass_at_the_default_tolerance) {
    std::size_t checked = 0;
    std::size_t inexact = 0;
    for (int step = 0; step < 720; ++step) {
        const float angle = static_cast<float>(step) * 0.00872664626f;  // half a degree
        for (const float half_width : {0.01f, 1.0f, 37.5f, 1000.0f}) {
            for (const float aspect : {1.0f, 0.3f, 0.05f}) {
                const float half_height = half_width * aspect;
                // Centers up to 1000 times the shorter side away from the origin.
                const float reach = 1000.0f * half_height;
                for (const point center : {point{0, 0}, point{reach, -reach / 3}, point{-reach / 2, reach}}) {
                    const rect r = obbsat::corners_of(obbsat::pose{center, {half_width, half_height}, angle});
                    const rect_check c = check_rect(r);
                    ASSERT_TRUE(c.ok()) << describe(r) << "\n" << c.where << " " << c.deviation;
                    // corners_of puts UL top left and UR top right: clockwise with y up.
                    ASSERT_EQ(c.turn, winding::cw) << describe(r);
                    inexact += check_rect(r, 0.0f).ok() ? 0u : 1u;
                    ++checked;
                }
            }
        }
    }
    EXPECT_EQ(checked, 720u * 4u * 3u * 3u);
    // Rounding is real: most of these fail an exact check.
    EXPECT_GT(inexact, checked / 2);
}

TEST(validate, a_small_rectangle_far_from_the_origin_needs_a_larger_tolerance) {
    // Side 1 at a distance of 2^21, where floats are 0.25 apart: rounding
    // moves each corner by up to an eighth of the side.
    std::size_t refused = 0;
    for (int step = 0; step < 90; ++step) {
        const float angle = static_cast<float>(step) * 0.0174532925f;
        const rect r = obbsat::corners_of(obbsat::pose{{0x1p21f, -0x1p21f}, {0.5f, 0.5f}, angle});
        refused += check_rect(r).ok() ? 0u : 1u;
        EXPECT_TRUE(check_rect(r, 0.5f).ok()) << describe(r);
    }
    EXPECT_GT(refused, 45u);
}

TEST(validate, a_batch_reports_its_first_offender_and_why) {
    const rect sheared{{0, 1}, {1.1f, 1}, {1, 0}, {-0.1f, 0}};
    rect nan_rect = unit_cw;
    nan_rect.lr.y = std::numeric_limits<float>::quiet_NaN();
    const std::vector<rect> batch = {unit_cw, unit_ccw, unit_cw, sheared, nan_rect};
    const obbsat::validation_report report = obbsat::validate(batch.data(), batch.size());
    EXPECT_FALSE(report.ok);
    EXPECT_EQ(report.index, 3u);
    EXPECT_EQ(report.check.problem, rect_problem::not_rectangle);
    EXPECT_EQ(report.ccw_count, 1u);
    EXPECT_EQ(report.cw_count, 2u);
    EXPECT_EQ(report.message.rfind("rectangle 3: not a rectangle: corner ", 0), 0u) << report.message;
    EXPECT_NE(report.message.find("is not a right angle (|cos| 0.0"), std::string::npos) << report.message;
    EXPECT_NE(report.message.find(", tolerance 0.001)"), std::string::npos) << report.message;

    const obbsat::validation_report nan_first = obbsat::validate(&nan_rect, 1);
    EXPECT_EQ(nan_first.index, 0u);
    EXPECT_EQ(nan_first.message, "rectangle 0: coordinate lry is not finite");

    const rect degenerate{{0, 0}, {0, 0}, {1, 1}, {0, 1}};
    const std::vector<rect> with_degenerate = {unit_ccw, degenerate, sheared};
    const obbsat::validation_report d = obbsat::validate(with_degenerate.data(), with_degenerate.size());
    EXPECT_EQ(d.index, 1u);
    EXPECT_EQ(d.message, "rectangle 1: degenerate: side UL-UR has length zero");

    const rect trapezoid{{0, 100}, {1, 100}, {1, 0}, {-1, 0}};
    EXPECT_EQ(obbsat::validate(&trapezoid, 1).message,
              "rectangle 0: not a rectangle: sides UL-UR and LR-LL differ in length (relative 0.5, "
              "tolerance 0.001)");
    const rect line{{0, 0}, {2, 2}, {1, 1}, {3, 3}};
    EXPECT_EQ(obbsat::validate(&line, 1).message,
              "rectangle 0: degenerate: all four corners lie on one line (zero area)");
}

TEST(validate, a_valid_batch_counts_its_windings) {
    const std::vector<rect> batch = {unit_cw, unit_ccw, unit_ccw};
    const obbsat::validation_report report = obbsat::validate(batch.data(), batch.size());
    EXPECT_TRUE(report.ok);
    EXPECT_EQ(report.index, 3u);
    EXPECT_EQ(report.ccw_count, 2u);
    EXPECT_EQ(report.cw_count, 1u);
    EXPECT_EQ(report.message, "all 3 rectangles are valid (2 counter-clockwise, 1 clockwise)");
    const obbsat::validation_report empty = obbsat::validate(nullptr, 0);
    EXPECT_TRUE(empty.ok);
    EXPECT_EQ(empty.index, 0u);
    EXPECT_EQ(empty.message, "all 0 rectangles are valid (0 counter-clockwise, 0 clockwise)");
}

}  // namespace
