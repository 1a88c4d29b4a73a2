// The scalar reference of method sat4_centered: every corner moved by -A.UL
// in float, then sat4. Integer corners below 2^24 move exactly, so a pair of
// small integer rectangles anywhere in that range gets the verdict it has at
// the origin, which is exact; float sat4 cannot promise that far out.
#include "test_support/exact_intersection.hpp"
#include "test_support/float_text.hpp"
#include "test_support/hard_pairs.hpp"
#include "test_support/rect_shapes.hpp"

#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

using obbsat::point;
using obbsat::rect;
using obbsat::ref::moved_to_origin;
using obbsat::ref::sat4;
using obbsat::ref::sat4_centered;
using namespace obbsat::test_support;

bool same_rect(const rect& a, const rect& b) { return std::memcmp(&a, &b, sizeof(rect)) == 0; }

TEST(sat4_centered_ref, moved_to_origin_subtracts_once_per_coordinate) {
    const rect r{{5, 7}, {9, 10}, {6, 14}, {2, 11}};
    EXPECT_TRUE(same_rect(moved_to_origin(r, {5, 7}), rect{{0, 0}, {4, 3}, {1, 7}, {-3, 4}}));
    // One rounded float subtraction: 1e8 - 3 is 99999997, and the nearest float is 1e8.
    const rect far{{1.0e8f, 0}, {1.0e8f, 0}, {1.0e8f, 0}, {1.0e8f, 0}};
    EXPECT_EQ(moved_to_origin(far, {3, 0}).ul.x, 1.0e8f);
    // Sterbenz: within a factor of two the difference is exact.
    const float x = 8388607.5f, origin_x = 4194305.0f;
    EXPECT_EQ(moved_to_origin(rect{{x, 0}, {x, 0}, {x, 0}, {x, 0}}, {origin_x, 0}).ul.x,
              4194302.5f);
}

TEST(sat4_centered_ref, is_sat4_when_a_upper_left_is_the_origin) {
    obbsat::seeded_random random(31);
    for (int i = 0; i < 100000; ++i) {
        auto any = [&]() { return random.uniform(-50.0f, 50.0f); };
        const rect a{{0, 0}, {any(), any()}, {any(), any()}, {any(), any()}};
        const rect b{{any(), any()}, {any(), any()}, {any(), any()}, {any(), any()}};
        ASSERT_EQ(sat4_centered(a, b), sat4(a, b)) << "A " << describe(a) << "\nB " << describe(b);
    }
}

// Integer contacts (touching, one lattice step apart, one step in) moved far
// out: the moved corners are the ones at the origin, so the verdict is exact.
TEST(sat4_centered_ref, exact_on_integer_rectangles_far_from_the_origin) {
    std::size_t float_errors = 0, pairs = 0;
    for (const point origin : {point{0, 0}, point{8388000, -8388001}, point{-6000000, 16000}}) {
        for (int ea = -3; ea <= 3; ++ea) {
            for (int eb = -3; eb <= 3; ++eb) {
                if (ea == 0 && eb == 0) {
                    continue;
                }
                for (int k = 1; k <= 3; ++k) {
                    const rect a = integer_rect(origin, ea, eb, k);
                    for (const auto& c : hard_pairs_detail::integer_contacts(origin, ea, eb, k)) {
                        for (const rect& b : {c.b, translated(c.b, c.outward),
                                              translated(c.b, scaled(c.outward, -1.0f))}) {
                            const bool meet = convex_quads_meet(a, b);
                            ++pairs;
                            ASSERT_EQ(sat4_centered(a, b), meet)
                                << "A " << describe(a) << "\nB " << describe(b);
                            ASSERT_EQ(sat4_centered(b, a), meet)
                                << "swapped: A " << describe(a) << "\nB " << describe(b);
                            ASSERT_EQ(sat4_centered(reversed_winding(a), relabelled(b)), meet)
                                << "relabelled: A " << describe(a) << "\nB " << describe(b);
                            float_errors += sat4(a, b) != meet ? 1u : 0u;
                        }
                    }
                }
            }
        }
    }
    // The offsets are far enough out for float sat4 to err, or this shows nothing.
    EXPECT_GT(float_errors, 0u);
    RecordProperty("sat4_float_errors",
                   std::to_string(float_errors) + " of " + std::to_string(pairs));
}

}  // namespace
