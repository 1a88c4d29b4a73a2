// When a pair_finder (obbsat/find_pairs.hpp) keeps the candidates of widened
// bounds, seen through its stats: on frames where boxes teleport every call,
// it stops keeping after the first kept candidates answered no call
// (kept_paused, nothing kept) and answers as fresh queries; on still or
// slightly moving frames it keeps and reuses; when the motion calms down
// after a paused stretch it keeps and reuses again; a change of the row count
// starts over (the first call plain, the next one keeps). Every answer is
// compared with a fresh find_pairs.
#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

collide_options options_for(method m, unsigned threads = 1) {
    collide_options o;
    o.test = m;
    o.threads = threads;
    return o;
}

/// A uniform scene of `boxes` rectangles, about two colliding pairs each.
struct scene {
    std::vector<rect_pose> poses;
    float side = 0;
};

scene make_scene(std::size_t boxes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.seed = seed;
    spec.sizes = obbsat::scene_sizes::uniform;
    spec.pairs_per_box = 2.0;
    return {obbsat::make_pose_scene(spec), static_cast<float>(obbsat::pose_scene_side(spec))};
}

/// Every box drifts by up to `step` in x and y; every `jump_every`-th box (0: none) jumps anywhere.
void move(scene& s, float step, std::size_t jump_every, obbsat::seeded_random& random) {
    for (std::size_t i = 0; i < s.poses.size(); ++i) {
        rect_pose& p = s.poses[i];
        if (jump_every != 0 && random.below(jump_every) == 0) {
            p.center = {random.uniform(0.0f, s.side), random.uniform(0.0f, s.side)};
        } else {
            p.center.x += random.uniform(-step, step);
            p.center.y += random.uniform(-step, step);
        }
    }
}

/// One call of `finder` on `poses`, its answer checked against a fresh query.
void find_and_check(obbsat::pair_finder& finder, const std::vector<rect_pose>& poses, method m, unsigned threads,
                    const std::string& where) {
    const obbsat::pose_records store(poses);
    const std::vector<pair_index>& got = finder.find(store);
    EXPECT_TRUE(same_pairs(got, obbsat::find_pairs(store, options_for(m, threads))))
        << where << ": " << got.size() << " pairs";
}

TEST(keeping_policy, teleports_stop_keeping_after_a_miss_and_answer_as_fresh_queries) {
    for (const unsigned threads : {1u, 2u}) {
        for (const method m : {method::exact, method::local}) {
            const std::string name = std::string(obbsat::method_name(m)) + " / " + std::to_string(threads) + " threads";
            scene s = make_scene(40000, 11);
            obbsat::seeded_random random(12);
            obbsat::pair_finder finder(options_for(m, threads));
            std::size_t paused = 0;
            for (int f = 0; f < 24; ++f) {
                const std::string where = name + " / frame " + std::to_string(f);
                find_and_check(finder, s.poses, m, threads, where);
                const obbsat::find_pairs_stats& st = finder.stats();
                EXPECT_FALSE(st.reused_candidates) << where;
                if (f == 0) {
                    EXPECT_FALSE(st.kept_paused) << where;
                    EXPECT_EQ(st.kept_candidates, 0u) << where;
                } else if (f == 1) {
                    // The first full query on the scene keeps the candidates of widened bounds.
                    EXPECT_FALSE(st.kept_paused) << where;
                    EXPECT_GT(st.kept_candidates, 0u) << where;
                } else {
                    // Its kept candidates answered no call: keeping stays paused, nothing is kept.
                    EXPECT_TRUE(st.kept_paused) << where;
                    EXPECT_EQ(st.kept_candidates, 0u) << where;
                    paused += st.kept_paused ? 1u : 0u;
                }
                move(s, 0.01f, 50, random);  // a fiftieth of the boxes teleport every frame
            }
            EXPECT_EQ(paused, 22u) << name;
        }
    }
}

TEST(keeping_policy, still_and_slightly_moving_frames_keep_and_reuse) {
    for (const float step : {0.0f, 0.002f}) {
        const std::string name = "step " + std::to_string(step);
        scene s = make_scene(30000, 21);
        obbsat::seeded_random random(22);
        obbsat::pair_finder finder(options_for(method::exact));
        std::size_t reused = 0;
        for (int f = 0; f < 16; ++f) {
            const std::string where = name + " / frame " + std::to_string(f);
            find_and_check(finder, s.poses, method::exact, 1, where);
            EXPECT_FALSE(finder.stats().kept_paused) << where;
            if (f >= 2) {
                reused += finder.stats().reused_candidates ? 1u : 0u;
            }
            move(s, step, 0, random);
        }
        // From the third call on, (almost) every call is answered from kept candidates.
        EXPECT_GE(reused, 12u) << name;
        if (step == 0.0f) {
            EXPECT_EQ(reused, 14u) << name;
        }
    }
}

TEST(keeping_policy, keeping_resumes_when_the_motion_calms_down) {
    scene s = make_scene(30000, 31);
    obbsat::seeded_random random(32);
    obbsat::pair_finder finder(options_for(method::exact));
    // Teleports: keeping pauses.
    for (int f = 0; f < 12; ++f) {
        find_and_check(finder, s.poses, method::exact, 1, "teleports, frame " + std::to_string(f));
        move(s, 0.01f, 50, random);
    }
    EXPECT_TRUE(finder.stats().kept_paused);
    // Slight motion: after a few probes the finder keeps again, then answers from kept candidates.
    int resumed_at = -1, reused_at = -1;
    std::size_t paused_after_reuse = 0;
    for (int f = 0; f < 48; ++f) {
        const std::string where = "calm, frame " + std::to_string(f);
        find_and_check(finder, s.poses, method::exact, 1, where);
        const obbsat::find_pairs_stats& st = finder.stats();
        if (resumed_at < 0 && !st.kept_paused) {
            resumed_at = f;
            EXPECT_GT(st.kept_candidates, 0u) << where;
        }
        if (reused_at < 0 && st.reused_candidates) {
            reused_at = f;
        }
        if (reused_at >= 0) {
            paused_after_reuse += st.kept_paused ? 1u : 0u;
        }
        move(s, 0.002f, 0, random);
    }
    // A failed probe waits at most 16 calls before the next; two calm calls resume keeping.
    EXPECT_GE(resumed_at, 1);
    EXPECT_LE(resumed_at, 24);
    EXPECT_EQ(reused_at, resumed_at + 1);
    EXPECT_EQ(paused_after_reuse, 0u);
}

TEST(keeping_policy, a_change_of_the_row_count_starts_over) {
    scene s = make_scene(20000, 41);
    obbsat::seeded_random random(42);
    obbsat::pair_finder finder(options_for(method::exact));
    for (int f = 0; f < 6; ++f) {
        find_and_check(finder, s.poses, method::exact, 1, "teleports, frame " + std::to_string(f));
        move(s, 0.01f, 50, random);
    }
    EXPECT_TRUE(finder.stats().kept_paused);
    s.poses.pop_back();
    // The first call on the new count answers plainly; the next one keeps, and the one after reuses.
    find_and_check(finder, s.poses, method::exact, 1, "new count");
    EXPECT_FALSE(finder.stats().kept_paused);
    EXPECT_EQ(finder.stats().kept_candidates, 0u);
    find_and_check(finder, s.poses, method::exact, 1, "new count, second call");
    EXPECT_FALSE(finder.stats().kept_paused);
    EXPECT_GT(finder.stats().kept_candidates, 0u);
    find_and_check(finder, s.poses, method::exact, 1, "new count, third call");
    EXPECT_TRUE(finder.stats().reused_candidates);
}

}  // namespace
