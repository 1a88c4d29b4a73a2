// collide_pairs over the double stores: verdicts equal to the double scalar
// references pair by pair, whatever the thread count; methods that do not run on
// doubles, bad indices and overlapping buffers refused with
// invalid_input and nothing written; the slow-path count of exact reported.
#include "test_support/pose_cases64.hpp"

#include <obbsat/collide64.hpp>
#include <obbsat/error.hpp>
#include <obbsat/ref/exact64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;

// A scene of `n` footprints, half of them made in pairs at exact or nudged contact.
struct double_scene {
    std::vector<obbsat::rect_pose64> poses;
    std::vector<obbsat::rect64> corners;
    std::vector<pair_index> pairs;
};

double_scene scene_of(std::size_t n, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    double_scene s;
    for (std::size_t i = 0; i < n / 2; ++i) {
        const obbsat::test::pose_pair64 pair =
            i % 2 == 0 ? obbsat::test::utm_contact_pair(random) : obbsat::test::utm_random_pair(random);
        s.poses.push_back(pair.a);
        s.poses.push_back(pair.b);
    }
    for (const obbsat::rect_pose64& p : s.poses) {
        s.corners.push_back(obbsat::test::corners64(p));
    }
    const auto size = static_cast<std::uint32_t>(s.poses.size());
    for (std::uint32_t i = 0; i + 1 < size; i += 2) {
        s.pairs.push_back(pair_index{i, i + 1});
        s.pairs.push_back(pair_index{i + 1, i});
        s.pairs.push_back(pair_index{i, static_cast<std::uint32_t>(random.below(size))});
    }
    return s;
}

collide_options with(method m, unsigned threads = 1) {
    collide_options options;
    options.test = m;
    options.threads = threads;
    return options;
}

TEST(collide64, pose_verdicts_are_the_references_on_any_thread_count) {
    const double_scene s = scene_of(20000, 81);
    const obbsat::pose_records64 store(s.poses);
    for (const unsigned threads : {1u, 2u, 0u}) {
        for (const method m : {method::exact, method::conservative, method::local}) {
            std::size_t slow = 12345;
            collide_options options = with(m, threads);
            options.slow_path_pairs = &slow;
            std::vector<std::uint8_t> verdicts(s.pairs.size(), 7);
            obbsat::collide_pairs(store, s.pairs.data(), s.pairs.size(), verdicts.data(), options);
            std::size_t hits = 0;
            for (std::size_t i = 0; i < s.pairs.size(); ++i) {
                const auto& a = s.poses[s.pairs[i].a];
                const auto& b = s.poses[s.pairs[i].b];
                const bool expected = m == method::exact          ? obbsat::ref::exact(a, b)
                                      : m == method::conservative ? obbsat::ref::conservative(a, b)
                                                                  : obbsat::ref::local(a, b);
                ASSERT_EQ(verdicts[i], expected ? 1 : 0) << obbsat::method_name(m) << " pair " << i;
                hits += verdicts[i];
            }
            EXPECT_GT(hits, s.pairs.size() / 4);
            if (m == method::exact) {
                EXPECT_GT(slow, 100u);  // exact contacts went to the oracle, and were counted
                EXPECT_LT(slow, s.pairs.size() / 2);
            } else {
                EXPECT_EQ(slow, 0u);
            }
        }
    }
}

TEST(collide64, corner_verdicts_are_the_references_on_any_thread_count) {
    const double_scene s = scene_of(20000, 82);
    const obbsat::rect_records64 store(s.corners);
    for (const unsigned threads : {1u, 2u}) {
        for (const method m : {method::exact, method::conservative}) {
            const std::vector<std::uint8_t> verdicts = obbsat::collide_pairs(store, s.pairs, with(m, threads));
            ASSERT_EQ(verdicts.size(), s.pairs.size());
            for (std::size_t i = 0; i < s.pairs.size(); ++i) {
                const auto& a = s.corners[s.pairs[i].a];
                const auto& b = s.corners[s.pairs[i].b];
                const bool expected = m == method::exact ? obbsat::ref::exact(a, b) : obbsat::ref::conservative(a, b);
                ASSERT_EQ(verdicts[i], expected ? 1 : 0) << obbsat::method_name(m) << " pair " << i;
            }
        }
    }
}

std::string refusal(const std::function<void()>& call) {
    try {
        call();
    } catch (const obbsat::invalid_input& e) {
        return e.what();
    }
    return "";
}

TEST(collide64, refuses_what_does_not_run_on_doubles_and_writes_nothing) {
    const double_scene s = scene_of(100, 83);
    const obbsat::pose_records64 poses(s.poses);
    const obbsat::rect_records64 corners(s.corners);
    std::vector<std::uint8_t> verdicts(s.pairs.size(), 7);
    auto on_poses = [&](const collide_options& o) {
        return refusal([&] { obbsat::collide_pairs(poses, s.pairs.data(), s.pairs.size(), verdicts.data(), o); });
    };
    auto on_corners = [&](const collide_options& o) {
        return refusal([&] { obbsat::collide_pairs(corners, s.pairs.data(), s.pairs.size(), verdicts.data(), o); });
    };
    EXPECT_EQ(on_poses(with(method::sat4)), "method sat4 does not run on double poses (they take conservative, exact, local)");
    EXPECT_EQ(on_corners(with(method::local)),
              "method local does not run on double corners (they take conservative, exact)");
    EXPECT_EQ(on_corners(with(method::sat4_double)),
              "method sat4_double does not run on double corners (they take conservative, exact)");
    collide_options unknown = with(method::exact);
    unknown.test = static_cast<method>(200);
    EXPECT_EQ(on_corners(unknown), "collide_options::test holds 200, which names no method");
    std::vector<pair_index> bad = s.pairs;
    bad[5].b = 100;
    EXPECT_EQ(refusal([&] { obbsat::collide_pairs(poses, bad, with(method::exact)); }),
              "pair 5: index 100 is out of range (100 rectangles)");
    for (const std::uint8_t v : verdicts) {
        ASSERT_EQ(v, 7);  // nothing written by any refused call
    }
    collide_options scalar = with(method::exact);
    scalar.use = obbsat::backend::scalar;
    EXPECT_EQ(on_poses(scalar), "");
    // Verdicts over the pairs themselves.
    std::vector<pair_index> pairs = s.pairs;
    EXPECT_NE(refusal([&] {
                  obbsat::collide_pairs(poses, pairs.data(), pairs.size(), reinterpret_cast<std::uint8_t*>(pairs.data()),
                                        with(method::exact));
              }),
              "");
}

TEST(collide64, method_facts) {
    EXPECT_TRUE(obbsat::runs_on_doubles(method::local, obbsat::store_kind::poses));
    EXPECT_FALSE(obbsat::runs_on_doubles(method::local, obbsat::store_kind::corners));
    EXPECT_FALSE(obbsat::runs_on_doubles(method::sat4, obbsat::store_kind::corners));
    EXPECT_EQ(obbsat::methods_on_doubles(obbsat::store_kind::corners),
              (std::vector<method>{method::conservative, method::exact}));
}

}  // namespace
