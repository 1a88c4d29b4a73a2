// Every backend against the scalar references of the methods on double corners
// (exact and conservative over rect_records64), verdict for verdict:
// collide_pairs forced to each backend this CPU runs (the forced one must be
// the one that ran), on one, two and three threads, on the double hard
// families of the suites (UTM-like contacts nudged by a millimetre or 1 to 4
// ulps, decimal-like centers, far 1e9..1e15, slivers, near-parallel, rotation
// lengths far from one, corners moved by ulps), on quadrilaterals that are no
// rectangles (concave, crossed, degenerate), on coordinates whose arithmetic
// overflows or underflows, on a million pairs, and on every short batch up to
// a vector and a half; the exact slow-path count must be the scalar
// backend's, and the verdicts of a fixed set must hash to golden digests.
#include "test_support/pose_cases64.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/ref/certified64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/exact64.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::point64;
using obbsat::rect64;
using obbsat::test::rect_pair64;
using verdicts = std::vector<std::uint8_t>;

bool reference(method m, const rect64& a, const rect64& b) {
    return m == method::exact ? obbsat::ref::exact(a, b) : obbsat::ref::conservative(a, b);
}

/// Whether exact leaves the pair to the oracle.
bool undecided(const rect64& a, const rect64& b) {
    const obbsat::ref::certified_verdict fast = obbsat::ref::certify(a, b);
    return !fast.separated && !fast.intersecting;
}

/// Four corners anywhere in a square of side `reach` around `center`: convex,
/// concave or crossed quadrilaterals of either winding.
rect64 random_quad(obbsat::seeded_random& random, point64 center, double reach) {
    auto corner = [&] {
        return point64{center.x + obbsat::test::uniform64(random, -reach, reach),
                       center.y + obbsat::test::uniform64(random, -reach, reach)};
    };
    const point64 ul = corner(), ur = corner(), lr = corner(), ll = corner();
    return rect64{ul, ur, lr, ll};
}

/// Two quads of random_quad at UTM-like coordinates, within reach of each other.
rect_pair64 random_quad_pair(obbsat::seeded_random& random) {
    const point64 c{obbsat::test::uniform64(random, 1e5, 1e7), obbsat::test::uniform64(random, 1e5, 1e7)};
    const double reach = obbsat::test::uniform64(random, 1.0, 40.0);
    const point64 d{c.x + obbsat::test::uniform64(random, -2 * reach, 2 * reach),
                    c.y + obbsat::test::uniform64(random, -2 * reach, 2 * reach)};
    return rect_pair64{random_quad(random, c, reach), random_quad(random, d, reach)};
}

/// A trapezoid (a rectangle with one side shortened by an eighth) in contact with
/// a rectangle's corner set at UTM-like coordinates: exact dyadic arithmetic.
rect_pair64 trapezoid_pair(obbsat::seeded_random& random) {
    rect_pair64 pair = obbsat::test::corner_pair<obbsat::test::utm_contact_pair>(random);
    pair.a.ur.x -= 0.125 * (pair.a.ur.x - pair.a.ul.x);
    pair.a.ur.y -= 0.125 * (pair.a.ur.y - pair.a.ul.y);
    return pair;
}

/// `r` moved by t times (dx, dy), each coordinate rounded once.
rect64 moved(const rect64& r, double t, point64 d) {
    auto at = [&](point64 p) { return point64{p.x + t * d.x, p.y + t * d.y}; };
    return rect64{at(r.ul), at(r.ur), at(r.lr), at(r.ll)};
}

/// A rectangle and its copy moved along its UL->UR edge to within a few ulps
/// of where conservative's margin starts to prove them apart (found by
/// bisecting on the reference itself): every rounding of the margin counts.
rect_pair64 margin_pair(obbsat::seeded_random& random) {
    const rect64 a = obbsat::test::corners64(obbsat::test::utm_contact_pair(random).a);
    const point64 edge{a.ur.x - a.ul.x, a.ur.y - a.ul.y};
    double together = 1.0;       // touching: conservative says they collide
    double apart = 1.0 + 1e-6;   // a gap of a micrometre per metre of edge: proven apart
    for (int step = 0; step < 80 && obbsat::test::nudged64(together, 1) < apart; ++step) {
        const double middle = together + 0.5 * (apart - together);
        (obbsat::ref::conservative(a, moved(a, middle, edge)) ? together : apart) = middle;
    }
    return rect_pair64{a, moved(a, obbsat::test::nudged64(apart, obbsat::test::integer_in(random, -3, 3)), edge)};
}

using pair_make = rect_pair64 (*)(obbsat::seeded_random&);

// Families whose makes use integer and correctly rounded double operations only
// (no cos or sin), so their corners, and the verdicts, are the same on every machine.
std::vector<pair_make> portable_families() {
    return {
        obbsat::test::corner_pair<obbsat::test::utm_contact_pair>,
        obbsat::test::corner_pair<obbsat::test::utm_northing_contact_pair>,
        obbsat::test::corner_pair<obbsat::test::far_contact_pair>,
        obbsat::test::corner_pair<obbsat::test::sliver_pair>,
        obbsat::test::corner_pair<obbsat::test::scaled_rotation_pair>,
        obbsat::test::nudged_corner_pair,
        random_quad_pair,
        trapezoid_pair,
        margin_pair,
    };
}

// Those and the families of the suites at random angles.
std::vector<pair_make> hard_families() {
    std::vector<pair_make> all = portable_families();
    all.push_back(obbsat::test::corner_pair<obbsat::test::utm_random_pair>);
    all.push_back(obbsat::test::corner_pair<obbsat::test::far_random_pair>);
    all.push_back(obbsat::test::corner_pair<obbsat::test::near_parallel_pair>);
    return all;
}

/// Quads at the ends of the double range: overflowing products and areas
/// (|coordinates| near 1e308, or at and above 2^511 where conservative's
/// scale is infinite), areas below the certified range, subnormal and zero
/// coordinates, a point and a segment.
std::vector<rect64> extreme_quads() {
    return {
        rect64{{-1e308, 1}, {-0.9e308, 1}, {-0.9e308, 0}, {-1e308, 0}},
        rect64{{0.9e308, 1}, {1e308, 1}, {1e308, 0}, {0.9e308, 0}},
        rect64{{-1e308, 1e308}, {1e308, 1e308}, {1e308, -1e308}, {-1e308, -1e308}},
        rect64{{0x1p511, 0}, {0x1p511 + 0x1p460, 0}, {0x1p511 + 0x1p460, -0x1p460}, {0x1p511, -0x1p460}},
        rect64{{0x1p600, 0x1p600}, {0x1p601, 0x1p600}, {0x1p601, 0x1p599}, {0x1p600, 0x1p599}},
        rect64{{0, 1e-300}, {1e-300, 1e-300}, {1e-300, 0}, {0, 0}},
        rect64{{0, 0x1p-1070}, {0x1p-1074, 0x1p-1070}, {0x1p-1074, 0}, {0, 0}},
        rect64{{0, 0}, {0, 0}, {0, 0}, {0, 0}},
        rect64{{-1, 0}, {1, 0}, {1, 0}, {-1, 0}},
        rect64{{-1, 1}, {1, 1}, {1, -1}, {-1, -1}},
        rect64{{500000.125, 6e6}, {500020.125, 6e6}, {500020.125, 6e6 - 10}, {500000.125, 6e6 - 10}},
    };
}

struct corner_batch {
    std::vector<rect64> rects;
    std::vector<pair_index> pairs;
};

/// Pairs (2i, 2i+1) of `pairs_per_family` pairs of every family, both ways round,
/// some across families, and every extreme quad against every other and a few
/// others; odd in number, so that every width leaves a partial last vector.
corner_batch batch_of(const std::vector<pair_make>& families, std::size_t pairs_per_family, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    corner_batch b;
    for (const pair_make make : families) {
        for (std::size_t i = 0; i < pairs_per_family; ++i) {
            const rect_pair64 p = make(random);
            b.rects.push_back(p.a);
            b.rects.push_back(p.b);
        }
    }
    const auto made = static_cast<std::uint32_t>(b.rects.size());
    for (const rect64& r : extreme_quads()) {
        b.rects.push_back(r);
    }
    const auto size = static_cast<std::uint32_t>(b.rects.size());
    for (std::uint32_t i = 0; i + 1 < made; i += 2) {
        b.pairs.push_back(pair_index{i, i + 1});
        b.pairs.push_back(pair_index{i + 1, i});
        b.pairs.push_back(pair_index{i, static_cast<std::uint32_t>(random.below(made))});
    }
    for (std::uint32_t i = made; i < size; ++i) {
        for (std::uint32_t j = made; j < size; ++j) {
            b.pairs.push_back(pair_index{i, j});
        }
        b.pairs.push_back(pair_index{i, 0});
        b.pairs.push_back(pair_index{1, i});
    }
    if (b.pairs.size() % 2 == 0) {
        b.pairs.push_back(pair_index{0, size - 1});
    }
    return b;
}

/// The references' verdicts on every pair of `b`, and how many pairs exact left to the oracle.
struct expected_run {
    verdicts out;
    std::size_t slow = 0;
};

expected_run expected_of(method m, const corner_batch& b) {
    expected_run e;
    e.out.resize(b.pairs.size());
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
        const rect64& a = b.rects[b.pairs[i].a];
        const rect64& other = b.rects[b.pairs[i].b];
        e.out[i] = reference(m, a, other) ? 1 : 0;
        e.slow += m == method::exact && undecided(a, other) ? 1u : 0u;
    }
    return e;
}

struct backend_run {
    verdicts out;
    std::size_t slow = 0;
};

backend_run run_on(backend b, method m, unsigned threads, const obbsat::rect_records64& store,
                   const std::vector<pair_index>& pairs) {
    obbsat::collide_options options;
    options.test = m;
    options.use = b;
    options.threads = threads;
    backend_run r;
    options.slow_path_pairs = &r.slow;
    r.out.assign(pairs.size(), 9);
    EXPECT_EQ(obbsat::collide_pairs(store, pairs.data(), pairs.size(), r.out.data(), options), b)
        << "the forced backend is the one that ran";
    return r;
}

std::string describe(const rect64& r) {
    char text[256];
    std::snprintf(text, sizeof text, "{(%a, %a) (%a, %a) (%a, %a) (%a, %a)}", r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x,
                  r.lr.y, r.ll.x, r.ll.y);
    return text;
}

/// The first pair whose verdict differs from the expected one, described; "" if none.
std::string first_difference(const corner_batch& b, const verdicts& expected, const verdicts& got) {
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (got[i] != expected[i]) {
            return "pair " + std::to_string(i) + ": got " + std::to_string(got[i]) + ", expected " +
                   std::to_string(expected[i]) + " for " + describe(b.rects[b.pairs[i].a]) + " against " +
                   describe(b.rects[b.pairs[i].b]);
        }
    }
    return "";
}

class corner64_backends : public ::testing::TestWithParam<backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << obbsat::backend_name(GetParam()) << " does not run on this CPU";
        }
    }

    /// Every method on `b`, on each thread count of `threads`, against the references.
    void check_batch(const corner_batch& b, std::initializer_list<unsigned> threads_to_run) {
        const obbsat::rect_records64 store(b.rects);
        for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::corners)) {
            const expected_run expected = expected_of(m, b);
            for (const unsigned threads : threads_to_run) {
                const backend_run got = run_on(GetParam(), m, threads, store, b.pairs);
                ASSERT_EQ(first_difference(b, expected.out, got.out), "")
                    << obbsat::method_name(m) << " on " << obbsat::backend_name(GetParam()) << ", " << threads
                    << " threads";
                EXPECT_EQ(got.slow, expected.slow) << obbsat::method_name(m) << ", " << threads << " threads";
            }
            if (m == method::exact && GetParam() != backend::scalar) {
                EXPECT_EQ(run_on(backend::scalar, m, 1, store, b.pairs).slow, expected.slow)
                    << "the scalar backend's slow-path count";
            }
        }
    }
};

TEST_P(corner64_backends, hard_families_are_the_references_bit_for_bit) {
    const corner_batch b = batch_of(hard_families(), 3000, 113);
    check_batch(b, {1u, 2u, 3u});
    EXPECT_GT(expected_of(method::exact, b).slow, 5000u);  // the slow path ran inside the lanes
}

// A million pairs over 2^17 quads: the pairs of the hard families' makes, each
// many times over and in every lane position, and (three in four) random
// pairs among them.
TEST_P(corner64_backends, a_million_pairs_are_the_references_bit_for_bit) {
    corner_batch b = batch_of(hard_families(), (std::size_t{1} << 16) / hard_families().size(), 127);
    obbsat::seeded_random random(131);
    const auto made = static_cast<std::uint32_t>(b.rects.size());
    b.pairs.clear();
    while (b.pairs.size() < 1000001) {
        const auto i = static_cast<std::uint32_t>(random.below(made / 2)) * 2;
        const bool neighbours = random.below(4) == 0;
        const auto j = neighbours ? i + 1 : static_cast<std::uint32_t>(random.below(made));
        b.pairs.push_back(random.below(2) == 0 ? pair_index{i, j} : pair_index{j, i});
    }
    check_batch(b, {1u, 2u});
}

// Every batch of 1 to 17 pairs (up to a vector and a half of AVX-512's 8 or
// more), at several starts in the pair list: only its own verdicts are written.
TEST_P(corner64_backends, short_batches_write_only_their_verdicts) {
    const corner_batch b = batch_of(hard_families(), 4, 137);
    const obbsat::rect_records64 store(b.rects);
    for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::corners)) {
        const expected_run expected = expected_of(m, b);
        for (std::size_t count = 1; count <= 17; ++count) {
            for (std::size_t start = 0; start < 5; ++start) {
                const std::vector<pair_index> pairs(b.pairs.begin() + static_cast<std::ptrdiff_t>(start),
                                                    b.pairs.begin() + static_cast<std::ptrdiff_t>(start + count));
                obbsat::collide_options options;
                options.test = m;
                options.use = GetParam();
                verdicts out(count + 16, 9);
                obbsat::collide_pairs(store, pairs.data(), count, out.data(), options);
                for (std::size_t i = 0; i < count; ++i) {
                    ASSERT_EQ(out[i], expected.out[start + i])
                        << obbsat::method_name(m) << ", " << count << " pairs from " << start << ", pair " << i;
                }
                for (std::size_t i = count; i < out.size(); ++i) {
                    ASSERT_EQ(out[i], 9) << "written past the batch of " << count;
                }
            }
        }
    }
}

// The digests of the references' verdicts on the portable families (seed
// 20261126, 20000 pairs each, as batch_of builds them). Every backend must
// reproduce them. Change one only with a deliberate change of the method or
// of the makes, and say so in the commit.
struct golden_entry {
    method test;
    std::uint64_t digest;
};
constexpr golden_entry golden_digests[] = {
    {method::exact, 0xf915a01b757f803a},
    {method::conservative, 0x7d81f168a4bd9fa3},
};

TEST_P(corner64_backends, golden_digests) {
    const corner_batch b = batch_of(portable_families(), 20000, 20261126);
    const obbsat::rect_records64 store(b.rects);
    for (const golden_entry& g : golden_digests) {
        const backend_run got = run_on(GetParam(), g.test, 2, store, b.pairs);
        char text[32];
        std::snprintf(text, sizeof text, "0x%016llx",
                      static_cast<unsigned long long>(obbsat::verdict_digest(got.out.data(), got.out.size())));
        char want[32];
        std::snprintf(want, sizeof want, "0x%016llx", static_cast<unsigned long long>(g.digest));
        EXPECT_STREQ(text, want) << obbsat::method_name(g.test) << " on " << obbsat::backend_name(GetParam());
    }
}

INSTANTIATE_TEST_SUITE_P(every_backend, corner64_backends, ::testing::ValuesIn(obbsat::compiled_backends()),
                         [](const ::testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace
