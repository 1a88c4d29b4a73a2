// How the oracle reads four corners as a point set: rectangles of either
// winding, points, segments (including corners out of order along the line),
// repeated and straight corners, a quad with a reflex corner, a bow-tie and an
// outline that doubles back.
#include <obbsat/oracle/orientation.hpp>
#include <obbsat/oracle/quad_region.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace {

using obbsat::point;
using obbsat::rect;
using namespace obbsat::oracle;

bool same(point a, point b) { return a.x == b.x && a.y == b.y; }

// A polygon piece must be counter-clockwise and strictly convex.
void expect_valid_piece(const convex_piece& piece) {
    ASSERT_GE(piece.count, 1);
    ASSERT_LE(piece.count, 4);
    for (int i = 0; i < piece.count; ++i) {
        for (int j = i + 1; j < piece.count; ++j) {
            EXPECT_FALSE(same(piece.corners[i], piece.corners[j])) << "repeated corner";
        }
    }
    if (piece.count >= 3) {
        for (int i = 0; i < piece.count; ++i) {
            EXPECT_EQ(orientation(piece.corners[i], piece.corners[(i + 1) % piece.count],
                                  piece.corners[(i + 2) % piece.count]),
                      1);
        }
    }
}

bool has_corner(const convex_piece& piece, point p) {
    for (int i = 0; i < piece.count; ++i) {
        if (same(piece.corners[i], p)) return true;
    }
    return false;
}

TEST(quad_region, rectangles_of_either_winding_are_convex_and_counter_clockwise) {
    const rect clockwise{{0, 2}, {3, 2}, {3, 0}, {0, 0}};
    const rect counter{{0, 0}, {3, 0}, {3, 2}, {0, 2}};
    for (const rect& r : {clockwise, counter}) {
        const quad_region region = region_of(r);
        EXPECT_EQ(region.form, quad_form::convex);
        ASSERT_EQ(region.piece_count, 1);
        EXPECT_EQ(region.pieces[0].count, 4);
        expect_valid_piece(region.pieces[0]);
    }
}

TEST(quad_region, four_equal_corners_are_a_point) {
    const quad_region region = region_of(rect{{1.5f, -2}, {1.5f, -2}, {1.5f, -2}, {1.5f, -2}});
    EXPECT_EQ(region.form, quad_form::point);
    ASSERT_EQ(region.pieces[0].count, 1);
    EXPECT_TRUE(same(region.pieces[0].corners[0], point{1.5f, -2}));
}

TEST(quad_region, zero_width_is_the_segment_between_the_extreme_corners) {
    const quad_region flat = region_of(rect{{0, 0}, {4, 2}, {4, 2}, {0, 0}});
    EXPECT_EQ(flat.form, quad_form::segment);
    ASSERT_EQ(flat.pieces[0].count, 2);
    // Corners out of order along the line: the span is still min .. max.
    const quad_region shuffled = region_of(rect{{1, 1}, {3, 3}, {0, 0}, {2, 2}});
    EXPECT_EQ(shuffled.form, quad_form::segment);
    ASSERT_EQ(shuffled.pieces[0].count, 2);
    EXPECT_TRUE(has_corner(shuffled.pieces[0], point{0, 0}));
    EXPECT_TRUE(has_corner(shuffled.pieces[0], point{3, 3}));
}

TEST(quad_region, a_repeated_or_straight_corner_leaves_a_triangle) {
    const quad_region repeated = region_of(rect{{0, 0}, {0, 0}, {4, 0}, {0, 3}});
    EXPECT_EQ(repeated.form, quad_form::convex);
    ASSERT_EQ(repeated.pieces[0].count, 3);
    expect_valid_piece(repeated.pieces[0]);
    const quad_region straight = region_of(rect{{0, 0}, {2, 0}, {4, 0}, {0, 3}});
    EXPECT_EQ(straight.form, quad_form::convex);
    ASSERT_EQ(straight.pieces[0].count, 3);
    EXPECT_FALSE(has_corner(straight.pieces[0], point{2, 0}));
}

TEST(quad_region, a_reflex_corner_splits_into_two_triangles_along_its_diagonal) {
    // An arrowhead: the corner (2, 1) points inwards.
    const rect dart{{0, 0}, {2, 1}, {4, 0}, {2, 4}};
    const quad_region region = region_of(dart);
    EXPECT_EQ(region.form, quad_form::concave);
    ASSERT_EQ(region.piece_count, 2);
    for (int i = 0; i < 2; ++i) {
        ASSERT_EQ(region.pieces[i].count, 3);
        expect_valid_piece(region.pieces[i]);
        EXPECT_TRUE(has_corner(region.pieces[i], point{2, 1}));
        EXPECT_TRUE(has_corner(region.pieces[i], point{2, 4}));
    }
}

TEST(quad_region, a_bow_tie_is_read_as_its_convex_hull) {
    const quad_region region = region_of(rect{{0, 0}, {4, 4}, {4, 0}, {0, 4}});
    EXPECT_EQ(region.form, quad_form::non_simple);
    ASSERT_EQ(region.piece_count, 1);
    EXPECT_EQ(region.pieces[0].count, 4);
    expect_valid_piece(region.pieces[0]);
}

TEST(quad_region, an_outline_that_doubles_back_is_read_as_its_convex_hull) {
    // UL -> UR -> LR -> back to UR: a spike, the set would be two segments.
    const quad_region spike = region_of(rect{{0, 0}, {4, 0}, {4, 3}, {4, 0}});
    EXPECT_EQ(spike.form, quad_form::non_simple);
    EXPECT_EQ(spike.pieces[0].count, 3);
    expect_valid_piece(spike.pieces[0]);
    // Opposite corners equal: the same two-segment outline.
    const quad_region folded = region_of(rect{{0, 0}, {4, 0}, {0, 0}, {0, 3}});
    EXPECT_EQ(folded.form, quad_form::non_simple);
    EXPECT_EQ(folded.pieces[0].count, 3);
}

TEST(quad_region, non_finite_corners_are_rejected) {
    const float inf = INFINITY;
    EXPECT_THROW(region_of(rect{{0, 0}, {inf, 0}, {1, 1}, {0, 1}}), std::invalid_argument);
    EXPECT_THROW(region_of(rect{{0, 0}, {1, 0}, {1, NAN}, {0, 1}}), std::invalid_argument);
}

TEST(quad_region, form_names) {
    EXPECT_STREQ(quad_form_name(quad_form::point), "point");
    EXPECT_STREQ(quad_form_name(quad_form::segment), "segment");
    EXPECT_STREQ(quad_form_name(quad_form::convex), "convex");
    EXPECT_STREQ(quad_form_name(quad_form::concave), "concave");
    EXPECT_STREQ(quad_form_name(quad_form::non_simple), "non_simple");
}

}  // namespace
