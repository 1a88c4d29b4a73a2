// The begin/end events of a pair_finder (obbsat/find_pairs.hpp): after each
// call, began() and ended() equal the set differences of consecutive fresh
// find_pairs answers (rows matched by position), on frames of small motion
// (answered from kept candidates), large jumps (full queries) and changes of
// the row count, within one set and across two; the first call reports every
// pair as begun; a change of the kind of query ends every pair of the last
// call; events are off by default (began() and ended() refuse); a call that
// throws changes no events; a moved-from finder refuses every call.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;

bool less(const pair_index& x, const pair_index& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

/// The pairs of `x` that are not in `y`, both sorted.
std::vector<pair_index> minus(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    std::vector<pair_index> out;
    std::set_difference(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(out), less);
    return out;
}

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

std::string describe(const std::vector<pair_index>& got, const std::vector<pair_index>& want) {
    std::string text = std::to_string(got.size()) + " pairs, want " + std::to_string(want.size());
    const auto extra = minus(got, want), missing = minus(want, got);
    if (!extra.empty()) {
        text += "; first extra (" + std::to_string(extra[0].a) + ", " + std::to_string(extra[0].b) + ")";
    }
    if (!missing.empty()) {
        text += "; first missing (" + std::to_string(missing[0].a) + ", " + std::to_string(missing[0].b) + ")";
    }
    if (!std::is_sorted(got.begin(), got.end(), less)) {
        text += "; not sorted";
    }
    return text;
}

#define EXPECT_SAME_PAIRS(got, want) EXPECT_TRUE(same_pairs(got, want)) << describe(got, want)

collide_options options_for(method m, unsigned threads = 1) {
    collide_options o;
    o.test = m;
    o.threads = threads;
    return o;
}

obbsat::pose_scene_spec spec_of(std::size_t boxes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.seed = seed;
    spec.sizes = obbsat::scene_sizes::mixed;
    spec.pairs_per_box = 2.0;
    return spec;
}

/// Moves the rows of `poses` for the next frame: mostly a little; every
/// fourth frame a twentieth of them jump anywhere in the scene's square
/// (the finder then runs a full query); every fifth frame rows are dropped
/// from or added at the end.
void next_frame(std::vector<rect_pose>& poses, int frame, float side, obbsat::seeded_random& random) {
    for (rect_pose& p : poses) {
        p.center.x += random.uniform(-0.02f, 0.02f);
        p.center.y += random.uniform(-0.02f, 0.02f);
    }
    if (frame % 4 == 3) {
        for (std::size_t k = 0; k < poses.size() / 20; ++k) {
            rect_pose& p = poses[random.below(poses.size())];
            p.center = {random.uniform(0.0f, side), random.uniform(0.0f, side)};
        }
    }
    if (frame % 5 == 4) {
        if (frame % 10 == 4) {
            poses.resize(poses.size() - 1 - random.below(poses.size() / 10));
        } else {
            const std::size_t more = 1 + random.below(poses.size() / 10);
            for (std::size_t k = 0; k < more; ++k) {
                rect_pose p = poses[random.below(poses.size())];
                p.center = {random.uniform(0.0f, side), random.uniform(0.0f, side)};
                poses.push_back(p);
            }
        }
    }
}

void expect_events(const obbsat::pair_finder& finder, const std::vector<pair_index>& before,
                   const std::vector<pair_index>& now) {
    EXPECT_SAME_PAIRS(finder.began(), minus(now, before));
    EXPECT_SAME_PAIRS(finder.ended(), minus(before, now));
}

TEST(pair_events, every_frame_gives_the_set_differences_of_fresh_queries) {
    for (const method m : {method::exact, method::local}) {
        for (const unsigned threads : {1u, 2u}) {
            SCOPED_TRACE(std::string(obbsat::method_name(m)) + ", threads " + std::to_string(threads));
            const obbsat::pose_scene_spec spec = spec_of(4000, 7 + threads);
            const float side = static_cast<float>(obbsat::pose_scene_side(spec));
            std::vector<rect_pose> poses = obbsat::make_pose_scene(spec);
            obbsat::seeded_random random(11 + threads);
            obbsat::pair_finder finder(options_for(m, threads));
            finder.track_events(true);
            std::vector<pair_index> before;
            std::size_t from_kept = 0, full = 0, began = 0, ended = 0;
            for (int frame = 0; frame < 30; ++frame) {
                SCOPED_TRACE("frame " + std::to_string(frame) + ", " + std::to_string(poses.size()) + " rows");
                const std::vector<pair_index> now = obbsat::find_pairs(poses, options_for(m));
                EXPECT_SAME_PAIRS(finder.find(poses), now);
                (finder.stats().reused_candidates ? from_kept : full) += 1;
                expect_events(finder, before, now);
                began += finder.began().size();
                ended += finder.ended().size();
                before = now;
                next_frame(poses, frame, side, random);
            }
            // The sequence exercised both ways of answering, and events of both kinds.
            EXPECT_GE(from_kept, 5u);
            EXPECT_GE(full, 5u);
            EXPECT_GT(ended, 100u);
            EXPECT_GT(began, before.size() + 100u);
        }
    }
}

TEST(pair_events, across_two_sets_pairs_are_a_then_b_and_follow_the_counts_of_both) {
    const obbsat::pose_scene_spec spec = spec_of(4000, 21);
    const float side = static_cast<float>(obbsat::pose_scene_side(spec));
    const std::vector<rect_pose> all = obbsat::make_pose_scene(spec);
    std::vector<rect_pose> a(all.begin(), all.begin() + 1500), b(all.begin() + 1500, all.end());
    obbsat::seeded_random random(22);
    obbsat::pair_finder finder(options_for(method::exact, 2));
    finder.track_events(true);
    std::vector<pair_index> before;
    for (int frame = 0; frame < 24; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame) + ", " + std::to_string(a.size()) + " x " +
                     std::to_string(b.size()));
        const std::vector<pair_index> now = obbsat::find_pairs(a, b, options_for(method::exact));
        EXPECT_SAME_PAIRS(finder.find(a, b), now);
        expect_events(finder, before, now);
        before = now;
        next_frame(a, frame, side, random);
        next_frame(b, frame + 2, side, random);  // b's count changes on other frames than a's
    }
}

TEST(pair_events, the_first_call_begins_every_pair_and_a_change_of_kind_starts_over) {
    const std::vector<rect_pose> poses = obbsat::make_pose_scene(spec_of(3000, 31));
    const std::vector<rect_pose> a(poses.begin(), poses.begin() + 1000), b(poses.begin() + 1000, poses.end());
    const std::vector<pair_index> within = obbsat::find_pairs(poses, options_for(method::exact));
    const std::vector<pair_index> across = obbsat::find_pairs(a, b, options_for(method::exact));
    ASSERT_FALSE(within.empty());
    ASSERT_FALSE(across.empty());

    obbsat::pair_finder finder(options_for(method::exact));
    finder.track_events(true);
    EXPECT_TRUE(finder.began().empty());  // no call yet
    EXPECT_TRUE(finder.ended().empty());
    finder.find(poses);
    EXPECT_SAME_PAIRS(finder.began(), within);
    EXPECT_TRUE(finder.ended().empty());
    finder.find(poses);  // the same frame: nothing changed
    EXPECT_TRUE(finder.began().empty());
    EXPECT_TRUE(finder.ended().empty());
    // Within one set, then across two: positions mean other rows; everything ends and begins.
    finder.find(a, b);
    EXPECT_SAME_PAIRS(finder.began(), across);
    EXPECT_SAME_PAIRS(finder.ended(), within);
    finder.find(a, b);
    EXPECT_TRUE(finder.began().empty());
    EXPECT_TRUE(finder.ended().empty());
    finder.find(poses);
    EXPECT_SAME_PAIRS(finder.began(), within);
    EXPECT_SAME_PAIRS(finder.ended(), across);
    // No rows at all: every pair ends.
    finder.find(std::vector<rect_pose>());
    EXPECT_TRUE(finder.began().empty());
    EXPECT_SAME_PAIRS(finder.ended(), within);
    // A first call on an empty scene then a full one.
    obbsat::pair_finder fresh(options_for(method::exact));
    fresh.track_events(true);
    fresh.find(std::vector<rect_pose>());
    EXPECT_TRUE(fresh.began().empty());
    EXPECT_TRUE(fresh.ended().empty());
    fresh.find(poses);
    EXPECT_SAME_PAIRS(fresh.began(), within);
}

TEST(pair_events, off_by_default_refused_until_turned_on_and_turned_on_anew_after_off) {
    const std::vector<rect_pose> poses = obbsat::make_pose_scene(spec_of(2000, 41));
    const std::vector<pair_index> want = obbsat::find_pairs(poses, options_for(method::exact));
    obbsat::pair_finder finder(options_for(method::exact));
    EXPECT_FALSE(finder.tracks_events());
    finder.find(poses);
    try {
        finder.began();
        ADD_FAILURE() << "began() answered with events off";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pair_finder::began: begin/end events are off"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(finder.ended(), obbsat::invalid_input);
    // Turned on between calls: the next call has nothing to compare with.
    finder.track_events(true);
    EXPECT_TRUE(finder.tracks_events());
    EXPECT_TRUE(finder.began().empty());
    finder.find(poses);
    EXPECT_SAME_PAIRS(finder.began(), want);
    EXPECT_TRUE(finder.ended().empty());
    finder.track_events(true);  // on again: kept
    finder.find(poses);
    EXPECT_TRUE(finder.began().empty());
    // Off: refused again; on: starts over.
    finder.track_events(false);
    EXPECT_FALSE(finder.tracks_events());
    EXPECT_SAME_PAIRS(finder.find(poses), want);
    EXPECT_THROW(finder.began(), obbsat::invalid_input);
    finder.track_events(true);
    finder.find(poses);
    EXPECT_SAME_PAIRS(finder.began(), want);
}

TEST(pair_events, a_call_that_throws_changes_no_events) {
    std::vector<rect_pose> poses = obbsat::make_pose_scene(spec_of(2000, 51));
    obbsat::pair_finder finder(options_for(method::exact));
    finder.track_events(true);
    const std::vector<pair_index> first = obbsat::find_pairs(poses, options_for(method::exact));
    finder.find(poses);
    const rect_pose kept = poses[5];
    poses[5].center = poses[6].center;  // onto another: a pair begins, and those of its old place end
    const std::vector<pair_index> second = obbsat::find_pairs(poses, options_for(method::exact));
    finder.find(poses);
    const std::vector<pair_index> began = finder.began(), ended = finder.ended();
    ASSERT_FALSE(began.empty() && ended.empty());
    std::vector<rect_pose> bad = poses;
    bad[7].center.y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(finder.find(bad), obbsat::invalid_input);
    EXPECT_SAME_PAIRS(finder.began(), began);
    EXPECT_SAME_PAIRS(finder.ended(), ended);
    // The next call is compared with the last one that answered.
    poses[5] = kept;
    finder.find(poses);
    expect_events(finder, second, first);
}

TEST(pair_events, moved_from_finders_refuse_and_the_events_move_along) {
    std::vector<rect_pose> poses = obbsat::make_pose_scene(spec_of(2000, 61));
    const std::vector<pair_index> first = obbsat::find_pairs(poses, options_for(method::exact));
    obbsat::pair_finder finder(options_for(method::exact));
    finder.track_events(true);
    finder.find(poses);
    obbsat::pair_finder moved(std::move(finder));
    EXPECT_TRUE(moved.tracks_events());
    EXPECT_SAME_PAIRS(moved.began(), first);
    EXPECT_FALSE(finder.tracks_events());  // NOLINT(bugprone-use-after-move): the moved-from state is the test
    EXPECT_THROW(finder.find(poses), obbsat::invalid_input);
    EXPECT_THROW(finder.stats(), obbsat::invalid_input);
    EXPECT_THROW(finder.began(), obbsat::invalid_input);
    EXPECT_THROW(finder.ended(), obbsat::invalid_input);
    EXPECT_THROW(finder.track_events(true), obbsat::invalid_input);
    try {
        finder.began();
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("moved-from"), std::string::npos) << e.what();
    }
    // The moved-to finder goes on from the same last answer.
    poses[3].center = poses[4].center;
    const std::vector<pair_index> second = obbsat::find_pairs(poses, options_for(method::exact));
    moved.find(poses);
    EXPECT_FALSE(moved.began().empty());
    expect_events(moved, first, second);
    // Assigned a finder, the moved-from one works again, with that finder's settings (events off).
    finder = obbsat::pair_finder(options_for(method::exact));
    EXPECT_FALSE(finder.tracks_events());
    EXPECT_SAME_PAIRS(finder.find(poses), second);
    EXPECT_THROW(finder.began(), obbsat::invalid_input);
    finder.track_events(true);
    finder.find(poses);
    EXPECT_SAME_PAIRS(finder.began(), second);
}

}  // namespace
