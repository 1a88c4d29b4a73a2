// The certified fast path (obbsat/ref/certified.hpp) behind method exact:
// its stated error bound holds against determinants
// computed exactly, its decisions never contradict the oracle, and its
// decision threshold sits where the derivation puts it.
#include <obbsat/collide.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/ref/certified.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/family.hpp>
#include <obbsat/suites/suite.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using obbsat::point;
using obbsat::rect;

constexpr double unit_roundoff = 0x1p-24;

mpq_class exact(float v) { return mpq_class(static_cast<double>(v)); }

struct corners {
    point c[4];
    explicit corners(const rect& r) : c{r.ul, r.ur, r.lr, r.ll} {}
};

// The float area and bound exactly as the specification computes them.
struct filter_scale {
    float area;
    float bound;
    bool in_range;
};

filter_scale scale_of(const rect& a, const rect& b) {
    const point all[8] = {a.ul, a.ur, a.lr, a.ll, b.ul, b.ur, b.lr, b.ll};
    float xmin = all[0].x, xmax = all[0].x, ymin = all[0].y, ymax = all[0].y;
    for (const point& p : all) {
        xmin = p.x < xmin ? p.x : xmin;
        xmax = p.x > xmax ? p.x : xmax;
        ymin = p.y < ymin ? p.y : ymin;
        ymax = p.y > ymax ? p.y : ymax;
    }
    const float area = (xmax - xmin) * (ymax - ymin);
    return filter_scale{area, area * 0x1p-20f, area >= 0x1p-80f && area <= 0x1p100f};
}

// Largest |computed - exact| / (u * area) over every determinant the filter
// evaluates for the pair: 32 edge-corner orientations and 8 turns.
double worst_error_ratio(const rect& a, const rect& b, const filter_scale& s) {
    double worst = 0.0;
    auto record = [&](float computed, const mpq_class& truth) {
        const mpq_class error = abs(exact(computed) - truth);
        const double ratio = error.get_d() / (unit_roundoff * static_cast<double>(s.area));
        worst = std::max(worst, ratio);
    };
    const corners qa(a), qb(b);
    for (int side = 0; side < 2; ++side) {
        const corners& q = side == 0 ? qa : qb;
        const corners& other = side == 0 ? qb : qa;
        for (int k = 0; k < 4; ++k) {
            const point p = q.c[k], next = q.c[(k + 1) % 4], after = q.c[(k + 2) % 4];
            const float ex = next.x - p.x, ey = next.y - p.y;
            const float fx = after.x - next.x, fy = after.y - next.y;
            const mpq_class tex = exact(next.x) - exact(p.x), tey = exact(next.y) - exact(p.y);
            const mpq_class tfx = exact(after.x) - exact(next.x), tfy = exact(after.y) - exact(next.y);
            record((ex * fy) - (ey * fx), tex * tfy - tey * tfx);
            for (const point& r : other.c) {
                const float d = (ex * (r.y - p.y)) - (ey * (r.x - p.x));
                record(d, tex * (exact(r.y) - exact(p.y)) - tey * (exact(r.x) - exact(p.x)));
            }
        }
    }
    return worst;
}

rect moved(const rect& r, float dx, float dy, float scale) {
    auto f = [&](point p) { return point{p.x * scale + dx, p.y * scale + dy}; };
    return rect{f(r.ul), f(r.ur), f(r.lr), f(r.ll)};
}

std::vector<std::pair<rect, rect>> varied_pairs() {
    std::vector<std::pair<rect, rect>> out;
    obbsat::seeded_random random(77);
    const obbsat::scene s = obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::typical, 2000, 4000, 3));
    for (const auto& p : s.pairs) {
        const int exponent = static_cast<int>(random.below(141)) - 70;  // 2^-70 .. 2^70
        const float scale = std::ldexp(1.0f, exponent);
        const float offset = (random.below(3) == 0) ? 0.0f : random.uniform(-1.0f, 1.0f) * std::ldexp(1.0f, exponent + 20);
        out.emplace_back(moved(s.rects[p.a], offset, -offset, scale), moved(s.rects[p.b], offset, -offset, scale));
    }
    for (const auto f : {obbsat::suites::family::grazing, obbsat::suites::family::slivers,
                         obbsat::suites::family::near_parallel, obbsat::suites::family::tiny,
                         obbsat::suites::family::huge, obbsat::suites::family::far}) {
        const auto suite = obbsat::suites::make_family(f, 5, 3000);
        for (const auto& p : suite.pairs) {
            out.emplace_back(suite.rects[p.a], suite.rects[p.b]);
        }
    }
    return out;
}

TEST(certified_bound, every_determinant_is_within_six_units_of_the_area) {
    // The specification derives |computed - exact| <= 6.001 u * area for every
    // determinant on a pair inside the guard, and uses 16 u * area.
    double worst = 0.0;
    std::size_t checked = 0;
    for (const auto& [a, b] : varied_pairs()) {
        const filter_scale s = scale_of(a, b);
        if (!s.in_range) {
            continue;
        }
        const double ratio = worst_error_ratio(a, b, s);
        ASSERT_LE(ratio, 6.001) << "pair " << checked;
        worst = std::max(worst, ratio);
        ++checked;
    }
    std::printf("checked %zu pairs, worst error %.3f u*area (bound used: 16)\n", checked, worst);
    EXPECT_GT(checked, 10000u);
    EXPECT_GT(worst, 0.1) << "the inputs never exercised rounding; the test would prove nothing";
}

TEST(certified_decisions, never_contradict_the_oracle) {
    std::size_t decided = 0, total = 0;
    for (const auto f : obbsat::suites::all_families()) {
        const auto suite = obbsat::suites::make_family(f, 11, 10000);
        for (const auto& p : suite.pairs) {
            const rect& a = suite.rects[p.a];
            const rect& b = suite.rects[p.b];
            const auto v = obbsat::ref::certify(a, b);
            ASSERT_FALSE(v.separated && v.intersecting);
            const bool truth = obbsat::oracle::intersects(a, b);
            if (v.separated) {
                ASSERT_FALSE(truth) << obbsat::suites::family_name(f) << " pair " << total;
            }
            if (v.intersecting) {
                ASSERT_TRUE(truth) << obbsat::suites::family_name(f) << " pair " << total;
            }
            decided += (v.separated || v.intersecting) ? 1 : 0;
            ++total;
        }
    }
    // The suites sit on or near the contact boundary by design, so a large
    // share is left to the slow path there (broadphase scenes: almost none).
    std::printf("decided %zu of %zu suite pairs on the fast path\n", decided, total);
    EXPECT_GT(decided, total / 4);
}

// A square of side s at the origin offset by `offset`, and a second square
// n float steps to its right (n < 0: overlapping by |n| steps). Only A's
// right edge and B's left edge come near deciding, with |d| = s * gap.
TEST(certified_threshold, decides_exactly_where_the_bound_says) {
    for (const float side : {1.0f, 0x1p-35f, 0x1p30f}) {
        for (const float offset : {0.0f, 1000.0f}) {
            const float o = offset * side;
            const float right = o + side;
            for (int n = -40; n <= 40; ++n) {
                float left_b = right;
                for (int k = 0; k < std::abs(n); ++k) {
                    left_b = std::nextafter(left_b, n > 0 ? INFINITY : -INFINITY);
                }
                const rect a{{o, side}, {right, side}, {right, 0}, {o, 0}};
                const rect b{{left_b, side}, {left_b + side, side}, {left_b + side, 0}, {left_b, 0}};
                const auto v = obbsat::ref::certify(a, b);
                const bool truth = obbsat::oracle::intersects(a, b);
                const filter_scale s = scale_of(a, b);
                // |d| on the critical edges, exactly: side * |gap|.
                const mpq_class d = abs(exact(side) * (exact(left_b) - exact(right)));
                const mpq_class margin = exact(s.bound) / 2;  // 6.001 u * area < bound / 2
                const bool must_decide = d > exact(s.bound) + margin;
                const bool must_not = d < exact(s.bound) - margin;
                if (v.separated) {
                    EXPECT_FALSE(truth);
                }
                if (v.intersecting) {
                    EXPECT_TRUE(truth);
                }
                if (must_decide && n != 0) {
                    EXPECT_TRUE(v.separated || v.intersecting) << "side " << side << " n " << n;
                }
                if (must_not) {
                    EXPECT_FALSE(v.separated || v.intersecting) << "side " << side << " n " << n;
                }
            }
        }
    }
}

TEST(certified_guard, out_of_range_areas_decide_nothing) {
    const rect unit{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const rect tiny = moved(unit, 0, 0, 0x1p-45f);       // area 2^-90 < 2^-80
    const rect far_tiny = moved(unit, 0x1p-44f, 0, 0x1p-45f);
    EXPECT_FALSE(obbsat::ref::certify(tiny, far_tiny).separated);
    EXPECT_FALSE(obbsat::ref::certify(tiny, far_tiny).intersecting);
    const rect huge = moved(unit, 0, 0, 0x1p60f);        // area 2^120 > 2^100
    const rect huge_far = moved(unit, 0x1p62f, 0, 0x1p60f);
    EXPECT_FALSE(obbsat::ref::certify(huge, huge_far).separated);
}

TEST(certified_winding, both_windings_and_non_convex_quads) {
    const rect ccw{{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // UL UR LR LL: clockwise in y-up axes
    const rect cw{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const rect far_right = moved(ccw, 5, 0, 1);
    EXPECT_TRUE(obbsat::ref::certify(ccw, far_right).separated);
    EXPECT_TRUE(obbsat::ref::certify(cw, far_right).separated);
    EXPECT_TRUE(obbsat::ref::certify(cw, moved(ccw, 0.5f, 0.5f, 1)).intersecting);
    const rect bow_tie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // self-crossing: never decided
    EXPECT_FALSE(obbsat::ref::certify(bow_tie, far_right).separated);
    EXPECT_FALSE(obbsat::ref::certify(bow_tie, far_right).intersecting);
}

TEST(exact_method, matches_the_oracle_and_conservative_never_misses_on_every_backend) {
    std::vector<rect> rects;
    std::vector<obbsat::pair_index> pairs;
    for (const auto f : obbsat::suites::all_families()) {
        const auto suite = obbsat::suites::make_family(f, 23, 4000);
        const auto base = static_cast<std::uint32_t>(rects.size());
        rects.insert(rects.end(), suite.rects.begin(), suite.rects.end());
        for (const auto& p : suite.pairs) {
            pairs.push_back({base + p.a, base + p.b});
        }
    }
    std::vector<std::uint8_t> truth(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        truth[i] = obbsat::oracle::intersects(rects[pairs[i].a], rects[pairs[i].b]) ? 1 : 0;
    }
    const obbsat::rect_records records(rects);
    for (const obbsat::backend b : obbsat::compiled_backends()) {
        if (!obbsat::cpu_supports(b)) {
            continue;
        }
        obbsat::collide_options options;
        options.use = b;
        std::size_t slow = 0;
        options.slow_path_pairs = &slow;
        options.test = obbsat::method::exact;
        EXPECT_EQ(obbsat::collide_pairs(records, pairs, options), truth) << obbsat::backend_name(b);
        options.test = obbsat::method::conservative;
        const auto loose = obbsat::collide_pairs(records, pairs, options);
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            ASSERT_TRUE(loose[i] >= truth[i]) << "conservative missed pair " << i << " on " << obbsat::backend_name(b);
        }
    }
}

}  // namespace
