// Method conservative (obbsat/ref/conservative.hpp) against exact rational
// arithmetic: every fused scalar is within the stated error bound of the
// exact dot product, every margin covers twice that bound, every "apart" it
// claims is an exact separation on that axis, and the margin is not so wide
// that it proves nothing: a gap of three margins is always proven.
#include <obbsat/ref/conservative.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/family.hpp>
#include <obbsat/suites/suite.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <vector>

namespace {

using obbsat::point;
using obbsat::rect;

mpq_class exact(float v) { return mpq_class(static_cast<double>(v)); }

const mpq_class unit_roundoff = mpq_class(1, 1 << 24);
const mpq_class underflow_slack = [] {
    mpq_class q(1);
    q /= mpq_class(mpz_class(1) << 149);
    return q;
}();

float largest_coordinate(const rect& a, const rect& b) {
    float k = 0.0f;
    for (const point p : {a.ul, a.ur, a.lr, a.ll, b.ul, b.ur, b.lr, b.ll}) {
        k = std::max({k, std::fabs(p.x), std::fabs(p.y)});
    }
    return k;
}

struct exact_extent {
    mpq_class min, max;
};

exact_extent exact_projection(const rect& r, point axis) {
    exact_extent e;
    bool first = true;
    for (const point p : {r.ul, r.ur, r.lr, r.ll}) {
        const mpq_class s = exact(p.x) * exact(axis.x) + exact(p.y) * exact(axis.y);
        if (first || s < e.min) e.min = s;
        if (first || s > e.max) e.max = s;
        first = false;
    }
    return e;
}

struct audit {
    std::size_t pairs = 0;
    std::size_t claims = 0;  // pairs some axis proves apart
    std::size_t failures = 0;
    double worst_error_ratio = 0.0;  // |computed - exact| / (u K (|ax| + |ay|))
};

// Checks the bound, the margin and every claim of one pair.
void audit_pair(const rect& a, const rect& b, audit& out) {
    ++out.pairs;
    bool claimed = false;
    const float k = largest_coordinate(a, b);
    const float scale = obbsat::ref::conservative_scale(a, b);
    point axes[4];
    obbsat::ref::sat4_axes(a, b, axes);
    for (const point axis : axes) {
        const float margin = obbsat::ref::conservative_margin(axis, scale);
        const obbsat::ref::extent fa = obbsat::ref::project_rect_fused(a, axis);
        const obbsat::ref::extent fb = obbsat::ref::project_rect_fused(b, axis);
        if (obbsat::ref::proven_apart(fa, fb, margin)) {
            claimed = true;
            const exact_extent ea = exact_projection(a, axis), eb = exact_projection(b, axis);
            if (!(eb.min > ea.max || ea.min > eb.max)) {
                ++out.failures;
                ADD_FAILURE() << std::hexfloat << "a claim of apart that exact projections deny, axis (" << axis.x
                              << ", " << axis.y << "), margin " << margin;
            }
        }
        if (!(k < 0x1p62f)) {
            EXPECT_FALSE(std::isfinite(scale));
            continue;  // beyond the guard: no claim can be made, none is checked
        }
        const mpq_class length = abs(exact(axis.x)) + abs(exact(axis.y));
        const mpq_class bound =
            (2 * unit_roundoff + unit_roundoff * unit_roundoff) * exact(k) * length + underflow_slack;
        if (!(exact(margin) >= 2 * bound)) {
            ++out.failures;
            ADD_FAILURE() << std::hexfloat << "margin " << margin << " below twice the error bound "
                          << bound.get_d() << " on axis (" << axis.x << ", " << axis.y << ")";
        }
        for (const rect* r : {&a, &b}) {
            for (const point p : {r->ul, r->ur, r->lr, r->ll}) {
                const mpq_class truth = exact(p.x) * exact(axis.x) + exact(p.y) * exact(axis.y);
                const mpq_class error = abs(exact(obbsat::ref::fused_scalar_on_axis(p, axis)) - truth);
                if (error > bound) {
                    ++out.failures;
                    ADD_FAILURE() << std::hexfloat << "scalar of (" << p.x << ", " << p.y << ") on (" << axis.x
                                  << ", " << axis.y << ") errs by " << error.get_d() << " > " << bound.get_d();
                }
                if (exact(k) * length >= mpq_class(1, 1) / mpq_class(mpz_class(1) << 90)) {
                    const double ratio = mpq_class(error / (unit_roundoff * exact(k) * length)).get_d();
                    out.worst_error_ratio = std::max(out.worst_error_ratio, ratio);
                }
            }
        }
    }
    out.claims += claimed ? 1 : 0;
}

rect rotated_box(float cx, float cy, float half_w, float half_h, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    auto corner = [&](float u, float v) { return point{cx + u * c - v * s, cy + u * s + v * c}; };
    return rect{corner(-half_w, half_h), corner(half_w, half_h), corner(half_w, -half_h), corner(-half_w, -half_h)};
}

TEST(conservative_margin, holds_on_every_suite_family_and_a_broadphase_scene) {
    audit total;
    for (const obbsat::suites::family f : obbsat::suites::all_families()) {
        const obbsat::suites::suite s = obbsat::suites::make_family(f, 11, 4000);
        for (const auto& pair : s.pairs) {
            audit_pair(s.rects[pair.a], s.rects[pair.b], total);
        }
        ASSERT_EQ(total.failures, 0u) << obbsat::suites::family_name(f);
    }
    obbsat::scene_spec spec;
    spec.rects = 20000;
    spec.pairs = 40000;
    spec.seed = 5;
    const obbsat::scene sc = obbsat::make_scene(spec);
    for (const auto& pair : sc.pairs) {
        audit_pair(sc.rects.at(pair.a), sc.rects.at(pair.b), total);
    }
    EXPECT_EQ(total.failures, 0u);
    EXPECT_GT(total.claims, total.pairs / 4) << "the margin must let separated pairs be proven";
    // Where no product underflows the bound is (2 + u); the largest error
    // seen is reported in docs/exact.md.
    EXPECT_LE(total.worst_error_ratio, 2.0 + 1e-6);
    std::printf("conservative: %zu pairs, %zu claims, worst scalar error %.4f u K (|ax| + |ay|)\n", total.pairs,
                total.claims, total.worst_error_ratio);
}

TEST(conservative_margin, holds_where_products_cancel_far_out_or_underflow) {
    // Corners whose two products nearly cancel make the largest relative
    // error; scales from subnormal to just under the guard.
    obbsat::seeded_random random(77);
    audit total;
    for (int i = 0; i < 60000; ++i) {
        const int e = static_cast<int>(random.below(200)) - 140;
        const float scale = std::ldexp(1.0f, std::min(e, 60));
        const float x = scale * random.uniform(-1.0f, 1.0f);
        const float y = scale * random.uniform(-1.0f, 1.0f);
        const float size = scale * std::ldexp(1.0f, -static_cast<int>(random.below(30)));
        const rect a = rotated_box(x, y, size * random.uniform(0.1f, 1.0f), size * random.uniform(0.1f, 1.0f),
                                   random.uniform(0.0f, 6.3f));
        const rect b = rotated_box(x + size * random.uniform(-3.0f, 3.0f), y + size * random.uniform(-3.0f, 3.0f),
                                   size * random.uniform(0.1f, 1.0f), size * random.uniform(0.1f, 1.0f),
                                   random.uniform(0.0f, 6.3f));
        audit_pair(a, b, total);
    }
    EXPECT_EQ(total.failures, 0u);
    EXPECT_GT(total.claims, 0u);
}

TEST(conservative_margin, a_gap_of_three_margins_is_always_proven_and_contact_never_is) {
    // B beside A along A's first axis, at an exact gap drawn from 0 to 6
    // margins (in projection units); coordinates from 1 to 2^40, box sizes
    // from 1 to 2^-8 of the offset.
    obbsat::seeded_random random(3);
    std::size_t wide = 0, touching = 0;
    for (int i = 0; i < 40000; ++i) {
        const float offset = std::ldexp(random.uniform(1.0f, 2.0f), static_cast<int>(random.below(41)));
        const float angle = random.uniform(0.0f, 6.3f);
        const float size = std::max(1.0f, std::ldexp(offset, -8));  // representable at that offset
        const rect a = rotated_box(offset, -offset, size, 0.5f * size, angle);
        const point axis = obbsat::ref::axis_between(a.ul, a.ur);
        const float margin =
            obbsat::ref::conservative_margin(axis, obbsat::ref::conservative_scale(a, a));
        const float axis_length = std::hypot(axis.x, axis.y);
        const float gap = (random.below(8) == 0 ? 0.0f : random.uniform(0.0f, 6.0f)) * margin / axis_length;
        const float c = axis.x / axis_length, s = axis.y / axis_length;
        // B's centre (2 + gap) size along the axis from A's centre: widths size + size.
        const float step = 2.0f * size + gap;
        const rect b = rotated_box(offset + step * c, -offset + step * s, size, 0.5f * size, angle);
        const exact_extent ea = exact_projection(a, axis), eb = exact_projection(b, axis);
        const mpq_class exact_gap = std::max(mpq_class(eb.min - ea.max), mpq_class(ea.min - eb.max));
        const bool says_collide = obbsat::ref::conservative(a, b);
        const float pair_margin = obbsat::ref::conservative_margin(axis, obbsat::ref::conservative_scale(a, b));
        if (exact_gap > 3 * exact(pair_margin)) {
            ++wide;
            EXPECT_FALSE(says_collide) << std::hexfloat << "offset " << offset << " gap " << exact_gap.get_d()
                                       << " margin " << pair_margin;
        }
        if (exact_gap <= 0) {
            ++touching;
            // Touching or overlapping along this axis is not a proof of
            // contact; it is when the exact SAT on every axis agrees.
            const exact_extent a2 = exact_projection(a, obbsat::ref::axis_between(a.lr, a.ur));
            const exact_extent b2 = exact_projection(b, obbsat::ref::axis_between(a.lr, a.ur));
            if (b2.min <= a2.max && a2.min <= b2.max) {
                EXPECT_TRUE(says_collide);
            }
        }
    }
    EXPECT_GT(wide, 10000u);
    EXPECT_GT(touching, 1000u);
}

}  // namespace
