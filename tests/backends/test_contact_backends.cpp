// Every backend against the contact reference (obbsat/ref/contact.hpp), bit
// for bit: every float and feature key of every contact, through every entry
// point of obbsat/contact.hpp, on one thread and on two, at margin 0 and with
// a speculative margin; on the pose families of the suites, on plain random
// pairs, on families of contact's own hard cases and on convex quads that are
// not rectangles; and the golden digests of the reference's contacts, which
// every backend reproduces, in float and in double.
#include "test_support/contact_cases.hpp"
#include "test_support/float_text.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>
#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/distance.hpp>
#include <obbsat/ref/pose_corners.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/pose_suite.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::contact;
using obbsat::pair_index;
using obbsat::pose_records;
using obbsat::rect;
using obbsat::rect_pose;
using obbsat::rect_records;
using obbsat::test_support::hex_float;
using obbsat::test::hard_pairs;
using obbsat::test::pose_pairs;
using obbsat::test::poses_accepted;
using obbsat::test::random_pairs;


// The digest of the reference's contacts on golden_pairs() at margin 0 and at
// margin 2^-4 (from integer arithmetic and exact float operations only, so the
// same on every machine). Change it only with a deliberate change of the
// contact steps or of the generator, and say so in the commit.
constexpr std::uint64_t golden_pose_digest = 0xa10d44894117974b;
constexpr std::uint64_t golden_corner_digest = 0x6183806be370f38b;

/// FNV-1a (64-bit) over the bytes of the contacts.
std::uint64_t contact_digest(const std::vector<contact>& contacts) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(contacts.data());
    for (std::size_t i = 0; i < contacts.size() * sizeof(contact); ++i) {
        h = (h ^ bytes[i]) * 0x100000001b3ull;
    }
    return h;
}

std::string hex_digest(std::uint64_t digest) {
    char text[32];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(digest));
    return text;
}

using obbsat::test_support::describe;

std::string describe(const rect_pose& p) {
    return "center (" + hex_float(p.center.x) + ", " + hex_float(p.center.y) + ") half (" +
           hex_float(p.half_extents.x) + ", " + hex_float(p.half_extents.y) + ") rotation (" +
           hex_float(p.rotation.x) + ", " + hex_float(p.rotation.y) + ")";
}

std::string describe(const contact& c) {
    std::string text = "n (" + hex_float(c.nx) + ", " + hex_float(c.ny) + ") depth " + hex_float(c.depth) +
                       " points " + std::to_string(c.point_count);
    for (const auto& p : c.points) {
        text += " [(" + hex_float(p.x) + ", " + hex_float(p.y) + ") sep " + hex_float(p.separation) + " key " +
                std::to_string(p.feature.index_a) + "/" + std::to_string(static_cast<int>(p.feature.type_a)) + " " +
                std::to_string(p.feature.index_b) + "/" + std::to_string(static_cast<int>(p.feature.type_b)) + "]";
    }
    return text;
}


/// Only the pairs whose corners (ref::corners_of) contacts accept: no segment,
/// point or sliver whose corners coincide or line up in float32.
pose_pairs corners_accepted(const pose_pairs& in) {
    pose_pairs out;
    for (std::size_t i = 0; i < in.a.size(); ++i) {
        if (obbsat::ref::corners_accepted(obbsat::ref::corners_of(in.a[i])) &&
            obbsat::ref::corners_accepted(obbsat::ref::corners_of(in.b[i]))) {
            out.a.push_back(in.a[i]);
            out.b.push_back(in.b[i]);
        }
    }
    return out;
}

pose_pairs suite_pairs(std::uint64_t seed, std::size_t count) {
    obbsat::seeded_random random(seed);
    const obbsat::suites::pose_pairs drawn = obbsat::suites::random_pose_pairs(random, count);
    return poses_accepted(pose_pairs{drawn.a, drawn.b});
}

pose_pairs golden_pairs() { return suite_pairs(20261126, 100000); }



std::vector<contact> reference_poses(const pose_pairs& pairs, float margin) {
    std::vector<contact> out(pairs.a.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = obbsat::ref::contact_of(pairs.a[i], pairs.b[i], margin);
    }
    return out;
}

std::vector<rect> corners_of(const std::vector<rect_pose>& poses) {
    std::vector<rect> out;
    for (const rect_pose& p : poses) {
        out.push_back(obbsat::ref::corners_of(p));
    }
    return out;
}

std::vector<contact> reference_corners(const pose_pairs& pairs, float margin) {
    const std::vector<rect> a = corners_of(pairs.a), b = corners_of(pairs.b);
    std::vector<contact> out(a.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = obbsat::ref::contact_of(a[i], b[i], margin);
    }
    return out;
}

testing::AssertionResult same_contacts(const std::vector<contact>& expected, const std::vector<contact>& got,
                                       const pose_pairs& pairs) {
    std::size_t mismatches = 0;
    std::string report;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (std::memcmp(&expected[i], &got[i], sizeof(contact)) != 0 && ++mismatches <= 3) {
            report += "\n  pair " + std::to_string(i) + "\n    A " + describe(pairs.a[i]) + "\n    B " +
                      describe(pairs.b[i]) + "\n    reference " + describe(expected[i]) + "\n    backend   " +
                      describe(got[i]);
        }
    }
    if (mismatches == 0) {
        return testing::AssertionSuccess();
    }
    return testing::AssertionFailure() << mismatches << " of " << expected.size() << " contacts differ" << report;
}

/// The pairs as one pool with every box at a shuffled place, and the index
/// pairs into it: pair i of the result is pair i of `pairs`.
struct scattered_pairs {
    std::vector<rect_pose> pool;
    std::vector<pair_index> pairs;
};

scattered_pairs scattered(const pose_pairs& pairs, std::uint64_t seed) {
    const std::size_t n = pairs.a.size();
    std::vector<std::uint32_t> place(2 * n);
    std::iota(place.begin(), place.end(), 0u);
    obbsat::seeded_random random(seed);
    for (std::size_t i = place.size(); i > 1; --i) {
        std::swap(place[i - 1], place[random.below(i)]);
    }
    scattered_pairs out;
    out.pool.resize(2 * n);
    out.pairs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        out.pool[place[2 * i]] = pairs.a[i];
        out.pool[place[2 * i + 1]] = pairs.b[i];
        out.pairs[i] = pair_index{place[2 * i], place[2 * i + 1]};
    }
    return out;
}

class contact_backends : public testing::TestWithParam<backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << "backend " << obbsat::backend_name(GetParam())
                         << " is not compiled in or this CPU cannot run it: not tested here";
        }
    }

    obbsat::contact_options forced(unsigned threads, float margin) const {
        obbsat::contact_options options;
        options.use = GetParam();
        options.threads = threads;
        options.margin = margin;
        return options;
    }

    /// Every entry point of obbsat/contact.hpp gives the reference's contacts.
    void expect_every_path_matches(const pose_pairs& pairs, unsigned threads, float margin) {
        SCOPED_TRACE(std::to_string(threads) + " threads, margin " + hex_float(margin));
        const obbsat::contact_options options = forced(threads, margin);
        const std::size_t n = pairs.a.size();
        const std::vector<contact> expected = reference_poses(pairs, margin);
        std::vector<contact> got(n);
        auto clear = [&] { std::memset(got.data(), 0xee, n * sizeof(contact)); };

        const pose_records a(pairs.a), b(pairs.b);
        clear();
        EXPECT_EQ(obbsat::contact_stream(a, b, got.data(), options), GetParam());
        EXPECT_TRUE(same_contacts(expected, got, pairs)) << "contact_stream over pose_records";

        const scattered_pairs indexed = scattered(pairs, 77);
        const pose_records pool(indexed.pool);
        clear();
        EXPECT_EQ(obbsat::contact_pairs(pool, indexed.pairs.data(), n, got.data(), options), GetParam());
        EXPECT_TRUE(same_contacts(expected, got, pairs)) << "contact_pairs over pose_records";

        clear();
        EXPECT_EQ(obbsat::contact_pairs(indexed.pool.data(), indexed.pool.size(), indexed.pairs.data(), n,
                                        got.data(), options),
                  GetParam());
        EXPECT_TRUE(same_contacts(expected, got, pairs)) << "contact_pairs over rect_pose rows";

        expect_every_corner_path_matches(corners_accepted(pairs), threads, margin);
    }

    /// Every entry point of obbsat/contact.hpp over corners gives the reference's contacts.
    void expect_every_corner_path_matches(const pose_pairs& pairs, unsigned threads, float margin) {
        const obbsat::contact_options options = forced(threads, margin);
        const std::size_t n = pairs.a.size();
        std::vector<contact> got(n);
        auto clear = [&] { std::memset(got.data(), 0xee, n * sizeof(contact)); };
        const scattered_pairs indexed = scattered(pairs, 78);
        const std::vector<contact> expected_corners = reference_corners(pairs, margin);
        const rect_records ca(corners_of(pairs.a)), cb(corners_of(pairs.b));
        clear();
        EXPECT_EQ(obbsat::contact_stream(ca, cb, got.data(), options), GetParam());
        EXPECT_TRUE(same_contacts(expected_corners, got, pairs)) << "contact_stream over rect_records";

        const std::vector<rect> corner_pool = corners_of(indexed.pool);
        const rect_records corner_records(corner_pool);
        clear();
        EXPECT_EQ(obbsat::contact_pairs(corner_records, indexed.pairs.data(), n, got.data(), options), GetParam());
        EXPECT_TRUE(same_contacts(expected_corners, got, pairs)) << "contact_pairs over rect_records";

        clear();
        EXPECT_EQ(obbsat::contact_pairs(corner_pool.data(), corner_pool.size(), indexed.pairs.data(), n,
                                        got.data(), options),
                  GetParam());
        EXPECT_TRUE(same_contacts(expected_corners, got, pairs)) << "contact_pairs over rect rows";
    }
};

TEST_P(contact_backends, match_the_reference_on_the_pose_families) {
    const pose_pairs pairs = suite_pairs(11, 300000);
    ASSERT_GT(pairs.a.size(), 250000u) << "most suite pairs are accepted";
    ASSERT_GT(corners_accepted(pairs).a.size(), 200000u) << "most suite pairs' corners are accepted";
    for (const unsigned threads : {1u, 2u}) {
        expect_every_path_matches(pairs, threads, 0.0f);
    }
    expect_every_path_matches(pairs, 2, 0x1p-4f);
}

TEST_P(contact_backends, match_the_reference_on_a_million_random_pairs) {
    const pose_pairs pairs = random_pairs(12, 1100000);
    ASSERT_GT(pairs.a.size(), 1000000u);
    for (const unsigned threads : {1u, 2u}) {
        expect_every_path_matches(pairs, threads, 0.0f);
    }
    expect_every_path_matches(pairs, 1, 0.5f);
}

TEST_P(contact_backends, match_the_reference_on_contacts_own_hard_cases) {
    struct scale_case {
        float scale, far;
    };
    for (const scale_case sc : {scale_case{1.0f, 0.0f}, scale_case{0x1p-20f, 0.0f}, scale_case{0x1p20f, 0.0f},
                                scale_case{1.0f, 1.0e7f}, scale_case{0x1p-20f, 1.0f}}) {
        SCOPED_TRACE("scale " + hex_float(sc.scale) + ", far " + hex_float(sc.far));
        const pose_pairs pairs = hard_pairs(13, 60000, sc.scale, sc.far);
        ASSERT_GT(pairs.a.size(), 1000u);
        for (const unsigned threads : {1u, 2u}) {
            expect_every_path_matches(pairs, threads, 0.0f);
        }
        expect_every_path_matches(pairs, 1, sc.scale);
    }
}

/// Convex quads that are not rectangles: the corners of random pairs, each
/// corner moved by up to a tenth of the box's smaller half extent, kept when
/// still strictly convex.
struct quad_pairs {
    std::vector<rect> a, b;
};

quad_pairs jittered_quads(std::uint64_t seed, std::size_t count) {
    const pose_pairs poses = random_pairs(seed, count);
    obbsat::seeded_random random(seed + 1);
    auto jitter = [&](const rect_pose& p) {
        rect r = obbsat::ref::corners_of(p);
        const float step = 0.1f * std::fmin(p.half_extents.x, p.half_extents.y);
        for (obbsat::point* c : {&r.ul, &r.ur, &r.lr, &r.ll}) {
            c->x += random.uniform(-step, step);
            c->y += random.uniform(-step, step);
        }
        return r;
    };
    quad_pairs out;
    for (std::size_t i = 0; i < poses.a.size(); ++i) {
        const rect qa = jitter(poses.a[i]), qb = jitter(poses.b[i]);
        if (obbsat::ref::corners_accepted(qa) && obbsat::ref::corners_accepted(qb)) {
            out.a.push_back(qa);
            out.b.push_back(qb);
        }
    }
    return out;
}

TEST_P(contact_backends, match_the_reference_on_convex_quads_that_are_not_rectangles) {
    const quad_pairs quads = jittered_quads(14, 200000);
    ASSERT_GT(quads.a.size(), 150000u);
    const rect_records a(quads.a), b(quads.b);
    for (const float margin : {0.0f, 0.25f}) {
        std::vector<contact> expected(quads.a.size());
        std::size_t with_points = 0;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            expected[i] = obbsat::ref::contact_of(quads.a[i], quads.b[i], margin);
            with_points += expected[i].point_count > 0 ? 1u : 0u;
        }
        EXPECT_GT(with_points, expected.size() / 5);
        for (const unsigned threads : {1u, 2u}) {
            std::vector<contact> got(expected.size());
            std::memset(got.data(), 0xee, got.size() * sizeof(contact));
            EXPECT_EQ(obbsat::contact_stream(a, b, got.data(), forced(threads, margin)), GetParam());
            std::size_t mismatches = 0;
            for (std::size_t i = 0; i < expected.size(); ++i) {
                if (std::memcmp(&expected[i], &got[i], sizeof(contact)) != 0 && ++mismatches <= 3) {
                    ADD_FAILURE() << "pair " << i << ", margin " << hex_float(margin) << ", " << threads
                                  << " threads\n  A " << obbsat::test_support::describe(quads.a[i]) << "\n  B "
                                  << obbsat::test_support::describe(quads.b[i]) << "\n  reference "
                                  << describe(expected[i]) << "\n  backend   " << describe(got[i]);
                }
            }
            EXPECT_EQ(mismatches, 0u);
        }
    }
}

// The hard cases do reach what they are for: no points, one and two, points
// of A's corners on B's faces as well as the reverse, touching pairs.
TEST(contact_hard_cases, reach_every_kind_of_answer) {
    const pose_pairs pairs = hard_pairs(13, 60000, 1.0f, 0.0f);
    std::size_t by_count[3] = {}, corner_of_a = 0, corner_of_b = 0, touching = 0;
    for (std::size_t i = 0; i < pairs.a.size(); ++i) {
        const contact c = obbsat::ref::contact_of(pairs.a[i], pairs.b[i]);
        ++by_count[c.point_count];
        touching += c.point_count > 0 && c.depth == 0.0f ? 1 : 0;
        for (std::uint32_t k = 0; k < c.point_count; ++k) {
            const bool a_vertex = c.points[k].feature.type_a == obbsat::feature_type::vertex;
            corner_of_a += a_vertex ? 1 : 0;
            corner_of_b += a_vertex ? 0 : 1;
        }
    }
    EXPECT_GT(by_count[0], 1000u);
    EXPECT_GT(by_count[1], 1000u);
    EXPECT_GT(by_count[2], 1000u);
    EXPECT_GT(corner_of_a, 1000u);
    EXPECT_GT(corner_of_b, 1000u);
    EXPECT_GT(touching, 100u);
}

TEST(contact_golden, the_reference_reproduces_the_golden_digests) {
    const pose_pairs pairs = golden_pairs();
    std::vector<contact> all = reference_poses(pairs, 0.0f);
    const std::vector<contact> with_margin = reference_poses(pairs, 0x1p-4f);
    all.insert(all.end(), with_margin.begin(), with_margin.end());
    EXPECT_EQ(hex_digest(contact_digest(all)), hex_digest(golden_pose_digest)) << "poses";

    const pose_pairs corner_pairs = corners_accepted(pairs);
    std::vector<contact> corners = reference_corners(corner_pairs, 0.0f);
    const std::vector<contact> corners_margin = reference_corners(corner_pairs, 0x1p-4f);
    corners.insert(corners.end(), corners_margin.begin(), corners_margin.end());
    EXPECT_EQ(hex_digest(contact_digest(corners)), hex_digest(golden_corner_digest)) << "corners";
}

TEST_P(contact_backends, reproduce_the_golden_digests) {
    const pose_pairs pairs = golden_pairs();
    const pose_records a(pairs.a), b(pairs.b);
    const pose_pairs corner_pairs = corners_accepted(pairs);
    const rect_records ca(corners_of(corner_pairs.a)), cb(corners_of(corner_pairs.b));
    std::vector<contact> poses, corners;
    for (const float margin : {0.0f, 0x1p-4f}) {
        const std::vector<contact> p = obbsat::contact_stream(a, b, forced(2, margin));
        poses.insert(poses.end(), p.begin(), p.end());
        std::vector<contact> c(ca.size());
        obbsat::contact_stream(ca, cb, c.data(), forced(2, margin));
        corners.insert(corners.end(), c.begin(), c.end());
    }
    EXPECT_EQ(hex_digest(contact_digest(poses)), hex_digest(golden_pose_digest));
    EXPECT_EQ(hex_digest(contact_digest(corners)), hex_digest(golden_corner_digest));
}

// The double contacts and distances (obbsat/contact.hpp's *64 overloads, the
// double references) on golden_pairs() widened to double, every float exactly: poses
// and their float corners, at margin 0 and at margin 2^-4. The double
// reference uses correctly rounded operations only, so these digests are the
// same on every machine; changed only with the contact steps or the generator.
constexpr std::uint64_t golden_pose64_digest = 0x7cd99a02a6dc3b60;
constexpr std::uint64_t golden_corner64_digest = 0x134141c53c14794a;
/// The double distances of the same rows, poses then corners.
constexpr std::uint64_t golden_distance64_digest = 0x70a9a089c095af62;

template <class T>
std::uint64_t bytes_digest(const std::vector<T>& values);

obbsat::rect_pose64 widened(const rect_pose& p) {
    return {{p.center.x, p.center.y}, {p.half_extents.x, p.half_extents.y}, {p.rotation.x, p.rotation.y}};
}

obbsat::rect64 widened(const rect& r) {
    return {{r.ul.x, r.ul.y}, {r.ur.x, r.ur.y}, {r.lr.x, r.lr.y}, {r.ll.x, r.ll.y}};
}

template <class Wide, class Narrow>
std::vector<Wide> widened(const std::vector<Narrow>& rows) {
    std::vector<Wide> out;
    for (const Narrow& row : rows) {
        out.push_back(widened(row));
    }
    return out;
}

/// The golden pairs in double: poses (first) and corners (second), each as A's and B's rows.
struct golden_rows64 {
    std::vector<obbsat::rect_pose64> pose_a, pose_b;
    std::vector<obbsat::rect64> corner_a, corner_b;
};

golden_rows64 golden_rows64_of() {
    const pose_pairs pairs = golden_pairs();
    const pose_pairs corner_pairs = corners_accepted(pairs);
    return golden_rows64{widened<obbsat::rect_pose64>(pairs.a), widened<obbsat::rect_pose64>(pairs.b),
                         widened<obbsat::rect64>(corners_of(corner_pairs.a)),
                         widened<obbsat::rect64>(corners_of(corner_pairs.b))};
}

TEST(contact_golden, the_double_references_reproduce_the_double_golden_digests) {
    const golden_rows64 rows = golden_rows64_of();
    std::vector<obbsat::contact64> poses, corners;
    for (const double margin : {0.0, 0x1p-4}) {
        for (std::size_t i = 0; i < rows.pose_a.size(); ++i) {
            poses.push_back(obbsat::ref::contact_of(rows.pose_a[i], rows.pose_b[i], margin));
        }
        for (std::size_t i = 0; i < rows.corner_a.size(); ++i) {
            corners.push_back(obbsat::ref::contact_of(rows.corner_a[i], rows.corner_b[i], margin));
        }
    }
    EXPECT_EQ(hex_digest(bytes_digest(poses)), hex_digest(golden_pose64_digest)) << "poses";
    EXPECT_EQ(hex_digest(bytes_digest(corners)), hex_digest(golden_corner64_digest)) << "corners";
    std::vector<obbsat::closest_points64> distances;
    for (std::size_t i = 0; i < rows.pose_a.size(); ++i) {
        distances.push_back(obbsat::ref::distance_of(rows.pose_a[i], rows.pose_b[i]));
    }
    for (std::size_t i = 0; i < rows.corner_a.size(); ++i) {
        distances.push_back(obbsat::ref::distance_of(rows.corner_a[i], rows.corner_b[i]));
    }
    EXPECT_EQ(hex_digest(bytes_digest(distances)), hex_digest(golden_distance64_digest)) << "distances";
}

TEST_P(contact_backends, reproduce_the_double_golden_digests) {
    const golden_rows64 rows = golden_rows64_of();
    const obbsat::pose_records64 a(rows.pose_a), b(rows.pose_b);
    const obbsat::rect_records64 ca(rows.corner_a), cb(rows.corner_b);
    std::vector<obbsat::contact64> poses, corners;
    for (const double margin : {0.0, 0x1p-4}) {
        obbsat::contact_options64 options;
        options.use = GetParam();
        options.threads = 2;
        options.margin = margin;
        std::vector<obbsat::contact64> p(a.size()), c(ca.size());
        EXPECT_EQ(obbsat::contact_stream(a, b, p.data(), options), GetParam());
        EXPECT_EQ(obbsat::contact_stream(ca, cb, c.data(), options), GetParam());
        poses.insert(poses.end(), p.begin(), p.end());
        corners.insert(corners.end(), c.begin(), c.end());
    }
    EXPECT_EQ(hex_digest(bytes_digest(poses)), hex_digest(golden_pose64_digest)) << "poses";
    EXPECT_EQ(hex_digest(bytes_digest(corners)), hex_digest(golden_corner64_digest)) << "corners";
    obbsat::distance_options options;
    options.use = GetParam();
    options.threads = 2;
    std::vector<obbsat::closest_points64> distances(a.size() + ca.size());
    EXPECT_EQ(obbsat::distance_stream(a, b, distances.data(), options), GetParam());
    EXPECT_EQ(obbsat::distance_stream(ca, cb, distances.data() + a.size(), options), GetParam());
    EXPECT_EQ(hex_digest(bytes_digest(distances)), hex_digest(golden_distance64_digest)) << "distances";
}

// Distances of separated pairs (obbsat/ref/distance.hpp), bit for bit.

template <class T>
std::uint64_t bytes_digest(const std::vector<T>& values) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (std::size_t i = 0; i < values.size() * sizeof(T); ++i) {
        h = (h ^ bytes[i]) * 0x100000001b3ull;
    }
    return h;
}

// The digest of the distance reference on golden_pairs(), poses then their
// corners; changed only with the distance steps or the generator.
constexpr std::uint64_t golden_distance_digest = 0x8eedd6a89e520092;

std::string describe(const obbsat::closest_points& c) {
    return "distance " + hex_float(c.distance) + " A (" + hex_float(c.ax) + ", " + hex_float(c.ay) + ") B (" +
           hex_float(c.bx) + ", " + hex_float(c.by) + ")";
}

template <class Shape>
testing::AssertionResult same_distances(const std::vector<obbsat::closest_points>& expected,
                                        const std::vector<obbsat::closest_points>& got, const std::vector<Shape>& a,
                                        const std::vector<Shape>& b) {
    std::size_t mismatches = 0;
    std::string report;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (std::memcmp(&expected[i], &got[i], sizeof expected[i]) != 0 && ++mismatches <= 3) {
            report += "\n  pair " + std::to_string(i) + "\n    A " + describe(a[i]) + "\n    B " + describe(b[i]) +
                      "\n    reference " + describe(expected[i]) + "\n    backend   " + describe(got[i]);
        }
    }
    if (mismatches == 0) {
        return testing::AssertionSuccess();
    }
    return testing::AssertionFailure() << mismatches << " of " << expected.size() << " distances differ" << report;
}

template <class Shape>
std::vector<obbsat::closest_points> reference_distances(const std::vector<Shape>& a, const std::vector<Shape>& b) {
    std::vector<obbsat::closest_points> out(a.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = obbsat::ref::distance_of(a[i], b[i]);
    }
    return out;
}

/// Every distance entry point on poses `pairs` (and on their corners, where
/// accepted) gives the reference's bits, on `threads` threads.
void expect_every_distance_path_matches(backend use, const pose_pairs& pairs, unsigned threads) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    obbsat::distance_options options;
    options.use = use;
    options.threads = threads;
    const std::size_t n = pairs.a.size();
    const std::vector<obbsat::closest_points> expected = reference_distances(pairs.a, pairs.b);
    std::vector<obbsat::closest_points> got(n);
    const pose_records a(pairs.a), b(pairs.b);
    std::memset(got.data(), 0xee, n * sizeof got[0]);
    EXPECT_EQ(obbsat::distance_stream(a, b, got.data(), options), use);
    EXPECT_TRUE(same_distances(expected, got, pairs.a, pairs.b)) << "distance_stream over pose_records";

    const scattered_pairs indexed = scattered(pairs, 79);
    const pose_records pool(indexed.pool);
    std::memset(got.data(), 0xee, n * sizeof got[0]);
    EXPECT_EQ(obbsat::distance_pairs(pool, indexed.pairs.data(), n, got.data(), options), use);
    EXPECT_TRUE(same_distances(expected, got, pairs.a, pairs.b)) << "distance_pairs over pose_records";

    const pose_pairs quads = corners_accepted(pairs);
    const std::vector<rect> qa = corners_of(quads.a), qb = corners_of(quads.b);
    const std::vector<obbsat::closest_points> expected_corners = reference_distances(qa, qb);
    std::vector<obbsat::closest_points> got_corners(qa.size());
    EXPECT_EQ(obbsat::distance_stream(rect_records(qa), rect_records(qb), got_corners.data(), options), use);
    EXPECT_TRUE(same_distances(expected_corners, got_corners, qa, qb)) << "distance_stream over rect_records";
    const scattered_pairs quad_indexed = scattered(quads, 80);
    const rect_records quad_pool(corners_of(quad_indexed.pool));
    std::memset(got_corners.data(), 0xee, got_corners.size() * sizeof got_corners[0]);
    EXPECT_EQ(obbsat::distance_pairs(quad_pool, quad_indexed.pairs.data(), qa.size(), got_corners.data(), options),
              use);
    EXPECT_TRUE(same_distances(expected_corners, got_corners, qa, qb)) << "distance_pairs over rect_records";
}

TEST_P(contact_backends, distances_match_the_reference) {
    const pose_pairs random = random_pairs(15, 1100000);
    const pose_pairs suite = suite_pairs(16, 200000);
    for (const unsigned threads : {1u, 2u}) {
        expect_every_distance_path_matches(GetParam(), random, threads);
        expect_every_distance_path_matches(GetParam(), suite, threads);
    }
    for (const float scale : {1.0f, 0x1p-20f, 0x1p20f}) {
        expect_every_distance_path_matches(GetParam(), hard_pairs(17, 60000, scale, 0.0f), 1);
    }
    expect_every_distance_path_matches(GetParam(), hard_pairs(17, 60000, 1.0f, 1.0e7f), 2);

    const quad_pairs quads = jittered_quads(18, 200000);
    obbsat::distance_options options;
    options.use = GetParam();
    std::vector<obbsat::closest_points> got(quads.a.size());
    obbsat::distance_stream(rect_records(quads.a), rect_records(quads.b), got.data(), options);
    EXPECT_TRUE(same_distances(reference_distances(quads.a, quads.b), got, quads.a, quads.b)) << "convex quads";
}

TEST_P(contact_backends, distances_reproduce_the_golden_digest) {
    const pose_pairs pairs = golden_pairs();
    const pose_pairs quads = corners_accepted(pairs);
    obbsat::distance_options options;
    options.use = GetParam();
    options.threads = 2;
    std::vector<obbsat::closest_points> all(pairs.a.size());
    obbsat::distance_stream(pose_records(pairs.a), pose_records(pairs.b), all.data(), options);
    std::vector<obbsat::closest_points> of_corners(quads.a.size());
    obbsat::distance_stream(rect_records(corners_of(quads.a)), rect_records(corners_of(quads.b)), of_corners.data(),
                            options);
    all.insert(all.end(), of_corners.begin(), of_corners.end());
    EXPECT_EQ(hex_digest(bytes_digest(all)), hex_digest(golden_distance_digest));
}

TEST(distance_golden, the_reference_reproduces_the_golden_digest) {
    const pose_pairs pairs = golden_pairs();
    const pose_pairs quads = corners_accepted(pairs);
    std::vector<obbsat::closest_points> all = reference_distances(pairs.a, pairs.b);
    const std::vector<obbsat::closest_points> of_corners =
        reference_distances(corners_of(quads.a), corners_of(quads.b));
    all.insert(all.end(), of_corners.begin(), of_corners.end());
    std::size_t separated = 0;
    for (const obbsat::closest_points& c : all) {
        separated += c.distance > 0.0f ? 1u : 0u;
    }
    EXPECT_GT(separated, all.size() / 10) << "the golden pairs hold separated pairs";
    EXPECT_EQ(hex_digest(bytes_digest(all)), hex_digest(golden_distance_digest));
}

INSTANTIATE_TEST_SUITE_P(every_backend, contact_backends,
                         testing::Values(backend::scalar, backend::sse2, backend::avx2, backend::avx512),
                         [](const testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace
