// pair_finder with ids (box_view::with_ids): rows come, go and change places
// between calls. On random sequences of frames (drift, removals by erase and
// by swap-remove, appends, inserts, swaps, whole permutations), every call
// answers what a fresh find_pairs answers on that frame, within one set and
// across two, for an exact and float methods, on one and two threads; the
// kept candidates serve the frames of small change; the events are id pairs
// equal to the differences of consecutive answers read as ids; duplicate
// ids, a wrong count of ids, ids on one side of two, and a moved-from finder
// are refused, and a refused call changes nothing.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/ref/pose_corners.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include "scene/pair_finder_id_pairs.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::id_pair;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat_test::by_id;
using obbsat_test::minus;

bool less(const pair_index& x, const pair_index& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

std::string describe(const std::vector<pair_index>& got, const std::vector<pair_index>& want) {
    std::vector<pair_index> extra, missing;
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra), less);
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing), less);
    std::string text = std::to_string(got.size()) + " pairs, want " + std::to_string(want.size());
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

collide_options options_for(method m, unsigned threads = 1) {
    collide_options o;
    o.test = m;
    o.threads = threads;
    return o;
}

/// Boxes with ids, and a pool of boxes of the same scene to add from.
struct world {
    std::vector<rect_pose> poses;
    std::vector<std::uint64_t> ids;
    std::vector<rect_pose> pool;
    std::size_t pool_next = 0;
    std::uint64_t next_id = 0;
    obbsat::seeded_random random{7};

    world(std::size_t boxes, std::uint64_t seed) : random(seed) {
        obbsat::pose_scene_spec spec;
        spec.boxes = 2 * boxes;
        spec.seed = seed;
        spec.sizes = obbsat::scene_sizes::mixed;
        spec.pairs_per_box = 2.0;
        pool = obbsat::make_pose_scene(spec);
        for (std::size_t i = 0; i < boxes; ++i) {
            add_at(poses.size());
        }
    }
    /// A new box (the pool's next) at row `at`, with a new id.
    void add_at(std::size_t at) {
        const rect_pose p = pool[pool_next++ % pool.size()];
        poses.insert(poses.begin() + static_cast<std::ptrdiff_t>(at), p);
        ids.insert(ids.begin() + static_cast<std::ptrdiff_t>(at), next_id);
        next_id += 1 + random.below(3);  // increasing, with gaps
    }
    void erase(std::size_t at) {
        poses.erase(poses.begin() + static_cast<std::ptrdiff_t>(at));
        ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(at));
    }
    /// The last row moves into the hole.
    void swap_remove(std::size_t at) {
        poses[at] = poses.back();
        ids[at] = ids.back();
        poses.pop_back();
        ids.pop_back();
    }
    void drift(float step) {
        for (rect_pose& p : poses) {
            p.center.x += random.uniform(-step, step);
            p.center.y += random.uniform(-step, step);
        }
    }
    void permute() {
        for (std::size_t i = poses.size(); i > 1; --i) {
            const std::size_t j = random.below(i);
            std::swap(poses[i - 1], poses[j]);
            std::swap(ids[i - 1], ids[j]);
        }
    }
    /// One frame of small change (about `share` of the rows come or go), or now and then a large one.
    /// Returns true when the change is small.
    bool step(double share) {
        drift(0.02f);
        const std::size_t n = poses.size();
        const auto changes = static_cast<std::size_t>(share * static_cast<double>(n)) + 1;
        const std::uint64_t kind = random.below(10);
        if (kind == 0) {
            permute();
            return false;
        }
        for (std::size_t c = 0; c < changes && poses.size() > 2; ++c) {
            const std::uint64_t what = random.below(6);
            const std::size_t at = random.below(poses.size());
            if (what == 0) {
                erase(at);
            } else if (what == 1 || what == 2) {
                swap_remove(at);
            } else if (what == 3) {
                add_at(poses.size());
            } else if (what == 4) {
                add_at(at);
            } else {
                const std::size_t other = random.below(poses.size());
                std::swap(poses[at], poses[other]);
                std::swap(ids[at], ids[other]);
            }
        }
        // Keep the count about steady.
        while (poses.size() + changes / 2 < 2 * pool.size() / 4) {
            add_at(poses.size());
        }
        return true;
    }
};

/// Frames of `w` through a pair_finder with ids, each checked against a fresh find_pairs.
void run_frames(world& w, method m, unsigned threads, std::size_t frames, double share) {
    obbsat::pair_finder finder(options_for(m, threads));
    std::size_t small_frames = 0;
    std::size_t reused_small = 0;
    for (std::size_t f = 0; f < frames; ++f) {
        const bool small = f > 1 && w.step(share);
        const obbsat::box_view view(w.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(m, threads));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        if (small) {
            ++small_frames;
            reused_small += finder.stats().reused_candidates ? 1u : 0u;
        }
    }
    // The kept candidates serve most frames of small change: a full query
    // after a permutation and now and then when slots pile up or a box
    // leaves its widened bounds.
    EXPECT_GT(2 * reused_small, small_frames) << reused_small << " of " << small_frames << " small frames reused";
}

TEST(pair_finder_ids, every_frame_equals_a_fresh_query_exact) { world w(3000, 11); run_frames(w, method::exact, 1, 60, 0.01); }

TEST(pair_finder_ids, every_frame_equals_a_fresh_query_conservative) { world w(3000, 12); run_frames(w, method::conservative, 1, 60, 0.01); }

TEST(pair_finder_ids, every_frame_equals_a_fresh_query_local) { world w(2000, 13); run_frames(w, method::local, 1, 40, 0.02); }

TEST(pair_finder_ids, every_frame_equals_a_fresh_query_on_two_threads) {
    // Enough boxes for two shares of work.
    world w(40000, 14);
    run_frames(w, method::exact, 2, 12, 0.005);
    world v(40000, 15);
    run_frames(v, method::local, 2, 12, 0.005);
}

TEST(pair_finder_ids, corner_rows_with_a_float_method_equal_fresh_queries) {
    // sat4 runs on corners: the same frames as corner rows.
    world w(3000, 16);
    obbsat::pair_finder finder(options_for(method::sat4));
    std::size_t reused = 0;
    for (std::size_t f = 0; f < 40; ++f) {
        if (f > 1) {
            w.step(0.01);
        }
        std::vector<obbsat::rect> corners;
        for (const rect_pose& p : w.poses) {
            corners.push_back(obbsat::ref::corners_of(p));
        }
        const obbsat::box_view view(corners);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(method::sat4));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        reused += finder.stats().reused_candidates ? 1u : 0u;
    }
    EXPECT_GE(reused, 20u);
}

TEST(pair_finder_ids, spawn_and_despawn_without_count_change_are_absorbed) {
    // 1% removed by erase, 1% appended, every frame: every frame after the
    // first keeping one is answered from the kept candidates.
    world w(5000, 21);
    obbsat::pair_finder finder(options_for(method::local));
    std::size_t reused = 0;
    const std::size_t frames = 20;
    for (std::size_t f = 0; f < frames; ++f) {
        if (f > 1) {
            w.drift(0.01f);
            for (int c = 0; c < 50; ++c) {
                w.erase(w.random.below(w.poses.size()));
            }
            for (int c = 0; c < 50; ++c) {
                w.add_at(w.poses.size());
            }
        }
        const obbsat::box_view view(w.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(method::local));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        reused += finder.stats().reused_candidates ? 1u : 0u;
    }
    EXPECT_GE(reused, frames - 6) << "frames answered from kept candidates";
}

TEST(pair_finder_ids, swap_remove_frames_are_absorbed) {
    world w(5000, 22);
    obbsat::pair_finder finder(options_for(method::exact));
    std::size_t reused = 0;
    for (std::size_t f = 0; f < 20; ++f) {
        if (f > 1) {
            w.drift(0.01f);
            for (int c = 0; c < 30; ++c) {
                w.swap_remove(w.random.below(w.poses.size()));
                w.add_at(w.poses.size());
            }
        }
        const obbsat::box_view view(w.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(method::exact));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        reused += finder.stats().reused_candidates ? 1u : 0u;
    }
    EXPECT_GE(reused, 14u);
}

/// Frames that mix the changes the kept pairs take in different ways: rows
/// erased and appended (the kept pairs stay in the last full query's rows and
/// only reported pairs are mapped, by rank), frames with the same rows, then
/// a swap-remove and an insertion in the middle (the rows no longer keep that
/// order: the kept pairs are written anew in this call's rows), then erases
/// and appends again. Each frame equals a fresh find_pairs and is answered
/// from kept candidates.
void run_mixed_changes(std::size_t boxes, std::uint64_t seed, method m, unsigned threads) {
    world w(boxes, seed);
    obbsat::pair_finder finder(options_for(m, threads));
    const std::size_t churn = std::max<std::size_t>(1, boxes / 400);
    const auto erase_and_append = [&] {
        for (std::size_t c = 0; c < churn; ++c) {
            w.erase(w.random.below(w.poses.size()));
        }
        for (std::size_t c = 0; c < churn; ++c) {
            w.add_at(w.poses.size());
        }
    };
    // What changes before each frame after the first two.
    const std::vector<int> plan = {1, 1, 1, 0, 1, 2, 1, 1, 3, 0, 1, 1, 1};
    std::size_t reused = 0;
    for (std::size_t f = 0; f < plan.size() + 2; ++f) {
        if (f > 1) {
            w.drift(0.002f);
            switch (plan[f - 2]) {
            case 1:
                erase_and_append();
                break;
            case 2:
                w.swap_remove(w.random.below(w.poses.size()));
                erase_and_append();
                break;
            case 3:
                w.add_at(w.poses.size() / 2);
                erase_and_append();
                break;
            default:
                break;  // the same rows
            }
        }
        const obbsat::box_view view(w.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(m, threads));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        reused += f > 1 && finder.stats().reused_candidates ? 1u : 0u;
    }
    EXPECT_GE(reused, plan.size() - 2) << "frames answered from kept candidates";
}

TEST(pair_finder_ids, erase_and_append_frames_mixed_with_reorders_equal_fresh_queries) {
    run_mixed_changes(4000, 31, method::exact, 1);
    run_mixed_changes(4000, 32, method::local, 1);
}

TEST(pair_finder_ids, erase_and_append_frames_mixed_with_reorders_on_two_threads) {
    // Enough boxes for two shares of work: the answer is read in two shares.
    run_mixed_changes(40000, 33, method::exact, 2);
    run_mixed_changes(40000, 34, method::local, 2);
}

TEST(pair_finder_ids, erase_and_append_frames_across_two_sets) {
    // Across two sets the kept pairs are written anew in this call's rows.
    world a(3000, 35);
    world b(3000, 36);
    obbsat::pair_finder finder(options_for(method::exact));
    for (std::size_t f = 0; f < 10; ++f) {
        if (f > 1) {
            for (world* w : {&a, &b}) {
                w->drift(0.002f);
                for (int c = 0; c < 10; ++c) {
                    w->erase(w->random.below(w->poses.size()));
                    w->add_at(w->poses.size());
                }
            }
        }
        const obbsat::box_view va(a.poses);
        const obbsat::box_view vb(b.poses);
        const std::vector<pair_index>& got = finder.find(va.with_ids(a.ids), vb.with_ids(b.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(va, vb, options_for(method::exact));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
    }
}

TEST(pair_finder_ids, events_are_the_differences_of_consecutive_answers_by_id) {
    world w(3000, 31);
    obbsat::pair_finder finder(options_for(method::local));
    finder.track_events(true);
    std::vector<id_pair> last;
    for (std::size_t f = 0; f < 30; ++f) {
        if (f > 0) {
            w.step(0.01);
        }
        const obbsat::box_view view(w.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        const std::vector<id_pair> now = by_id(got, w.ids, nullptr);
        const std::vector<id_pair> began = minus(now, last);
        const std::vector<id_pair> ended = minus(last, now);
        ASSERT_EQ(finder.began_ids(), began) << "frame " << f;
        ASSERT_EQ(finder.ended_ids(), ended) << "frame " << f;
        EXPECT_THROW(finder.began(), obbsat::invalid_input);
        last = now;
    }
}

TEST(pair_finder_ids, a_gone_box_ends_its_pairs_and_a_new_box_begins_its_own) {
    // Two boxes that overlap, then one removed and a new one on the other.
    std::vector<rect_pose> poses = {{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1, 0}}, {{50, 50}, {1, 1}, {1, 0}}};
    std::vector<std::uint64_t> ids = {10, 20, 30};
    obbsat::pair_finder finder(options_for(method::exact));
    finder.track_events(true);
    finder.find(obbsat::box_view(poses).with_ids(ids));
    ASSERT_EQ(finder.began_ids(), (std::vector<id_pair>{{10, 20}}));
    // Swap-remove box 10: box 30 moves to row 0; a new box 5 appears on box 30.
    poses[0] = poses[2];
    ids[0] = ids[2];
    poses[2] = {{50.5f, 50}, {1, 1}, {1, 0}};
    ids[2] = 5;
    const std::vector<pair_index>& got = finder.find(obbsat::box_view(poses).with_ids(ids));
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].a, 0u);
    EXPECT_EQ(got[0].b, 2u);
    EXPECT_EQ(finder.began_ids(), (std::vector<id_pair>{{5, 30}}));
    EXPECT_EQ(finder.ended_ids(), (std::vector<id_pair>{{10, 20}}));
}

TEST(pair_finder_ids, cross_queries_follow_ids_on_both_sides) {
    world a(2000, 41);
    world b(2000, 42);
    obbsat::pair_finder finder(options_for(method::local));
    finder.track_events(true);
    std::vector<id_pair> last;
    std::size_t reused = 0;
    for (std::size_t f = 0; f < 30; ++f) {
        if (f > 1) {
            a.drift(0.01f);
            b.drift(0.01f);
            for (int c = 0; c < 10; ++c) {
                a.swap_remove(a.random.below(a.poses.size()));
                b.erase(b.random.below(b.poses.size()));
                (f % 2 == 0 ? a : b).add_at(0);  // a count that changes, rows that shift
            }
            a.add_at(a.poses.size());
        }
        const obbsat::box_view va(a.poses);
        const obbsat::box_view vb(b.poses);
        const std::vector<pair_index>& got = finder.find(va.with_ids(a.ids), vb.with_ids(b.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(va, vb, options_for(method::local));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        reused += finder.stats().reused_candidates ? 1u : 0u;
        const std::vector<id_pair> now = by_id(got, a.ids, &b.ids);
        ASSERT_EQ(finder.began_ids(), minus(now, last)) << "frame " << f;
        ASSERT_EQ(finder.ended_ids(), minus(last, now)) << "frame " << f;
        last = now;
    }
    EXPECT_GE(reused, 20u);
}

TEST(pair_finder_ids, duplicate_ids_are_refused_naming_both_rows_and_change_nothing) {
    world w(1000, 51);
    obbsat::pair_finder finder(options_for(method::local));
    finder.track_events(true);
    const obbsat::box_view view(w.poses);
    finder.find(view.with_ids(w.ids));
    w.drift(0.01f);
    finder.find(obbsat::box_view(w.poses).with_ids(w.ids));
    const std::vector<id_pair> began = finder.began_ids();
    const std::vector<id_pair> ended = finder.ended_ids();
    // A duplicate of a row that stayed in place, and one among new rows.
    for (int variant = 0; variant < 3; ++variant) {
        std::vector<std::uint64_t> ids = w.ids;
        std::size_t first = 17, second = 600;
        if (variant == 0) {
            ids[second] = ids[first];
        } else if (variant == 1) {
            ids[first] = 1000000;
            ids[second] = 1000000;
        } else {
            std::swap(ids[3], ids[900]);
            ids[second] = ids[3];
            first = 3;
        }
        try {
            finder.find(obbsat::box_view(w.poses).with_ids(ids));
            ADD_FAILURE() << "variant " << variant << ": duplicate ids accepted";
        } catch (const obbsat::invalid_input& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("rows " + std::to_string(first) + " and " + std::to_string(second)),
                      std::string::npos)
                << message;
            EXPECT_NE(message.find(std::to_string(ids[second])), std::string::npos) << message;
        }
        EXPECT_EQ(finder.began_ids(), began);
        EXPECT_EQ(finder.ended_ids(), ended);
    }
    // The finder carries on from the last good call: small motion is answered from the kept candidates.
    w.drift(0.01f);
    const obbsat::box_view next(w.poses);
    const std::vector<pair_index>& got = finder.find(next.with_ids(w.ids));
    EXPECT_TRUE(same_pairs(got, obbsat::find_pairs(next, options_for(method::local))));
    EXPECT_TRUE(finder.stats().reused_candidates);
}

TEST(pair_finder_ids, a_wrong_count_of_ids_and_ids_on_one_side_are_refused) {
    world w(100, 61);
    const obbsat::box_view view(w.poses);
    std::vector<std::uint64_t> short_ids(w.ids.begin(), w.ids.end() - 1);
    EXPECT_THROW(view.with_ids(short_ids), obbsat::invalid_input);
    EXPECT_THROW(view.with_ids(nullptr, w.ids.size()), obbsat::invalid_input);
    EXPECT_NO_THROW(obbsat::box_view(std::vector<rect_pose>{}).with_ids(nullptr, 0));
    obbsat::pair_finder finder(options_for(method::local));
    EXPECT_THROW(finder.find(view.with_ids(w.ids), view), obbsat::invalid_input);
    EXPECT_THROW(finder.find(view, view.with_ids(w.ids)), obbsat::invalid_input);
    // find_pairs ignores ids.
    EXPECT_TRUE(same_pairs(obbsat::find_pairs(view.with_ids(w.ids), options_for(method::local)),
                           obbsat::find_pairs(view, options_for(method::local))));
}

TEST(pair_finder_ids, a_moved_from_finder_refuses_calls_with_ids) {
    world w(100, 71);
    obbsat::pair_finder finder(options_for(method::local));
    finder.track_events(true);
    finder.find(obbsat::box_view(w.poses).with_ids(w.ids));
    obbsat::pair_finder other(std::move(finder));
    EXPECT_THROW(finder.find(obbsat::box_view(w.poses).with_ids(w.ids)), obbsat::invalid_input);
    EXPECT_THROW(finder.began_ids(), obbsat::invalid_input);
    EXPECT_THROW(finder.ended_ids(), obbsat::invalid_input);
    EXPECT_FALSE(other.began_ids().empty());
    EXPECT_THROW(other.began(), obbsat::invalid_input);
}

TEST(pair_finder_ids, calls_with_and_without_ids_mix) {
    // Without ids rows match by position; switching either way answers right and restarts the events.
    world w(3000, 81);
    obbsat::pair_finder finder(options_for(method::local));
    finder.track_events(true);
    for (std::size_t f = 0; f < 24; ++f) {
        if (f > 1) {
            w.step(0.01);
        }
        const obbsat::box_view view(w.poses);
        const bool with = (f / 3) % 2 == 0;
        const std::vector<pair_index>& got = with ? finder.find(view.with_ids(w.ids)) : finder.find(view);
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(method::local));
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << f << ": " << describe(got, want);
        if (with) {
            EXPECT_THROW(finder.began(), obbsat::invalid_input);
            if (f % 3 == 0) {
                EXPECT_EQ(finder.began_ids(), by_id(got, w.ids, nullptr)) << "frame " << f;
                EXPECT_TRUE(finder.ended_ids().empty());
            }
        } else {
            EXPECT_THROW(finder.began_ids(), obbsat::invalid_input);
        }
    }
}

}  // namespace

namespace {

TEST(pair_finder_ids, keeping_resumes_after_a_miss_while_rows_keep_coming_and_going) {
    // Frames 2 and 3 jump (the kept candidates miss, keeping pauses); then
    // calm frames that each swap-remove and append rows: the probe follows
    // the rows by id, and keeping resumes.
    world w(3000, 91);
    obbsat::pair_finder finder(options_for(method::exact));
    bool paused = false;
    std::size_t reused_late = 0;
    for (std::size_t f = 0; f < 30; ++f) {
        if (f > 1) {
            w.drift(f < 4 ? 30.0f : 0.01f);
            for (int c = 0; c < 10; ++c) {
                w.swap_remove(w.random.below(w.poses.size()));
                w.add_at(w.poses.size());
            }
        }
        const obbsat::box_view view(w.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        ASSERT_TRUE(same_pairs(got, obbsat::find_pairs(view, options_for(method::exact)))) << "frame " << f;
        paused |= finder.stats().kept_paused;
        if (f >= 20) {
            reused_late += finder.stats().reused_candidates ? 1u : 0u;
        }
    }
    EXPECT_TRUE(paused) << "the jumps should have paused keeping";
    EXPECT_GE(reused_late, 8u);
}

}  // namespace

namespace {

TEST(pair_finder_ids, an_invalid_new_row_is_refused_and_the_next_call_answers_right) {
    world w(3000, 101);
    obbsat::pair_finder finder(options_for(method::exact));
    for (std::size_t f = 0; f < 12; ++f) {
        if (f > 1) {
            w.drift(0.01f);
            w.swap_remove(w.random.below(w.poses.size()));
            w.add_at(w.poses.size());
        }
        std::vector<rect_pose> poses = w.poses;
        if (f == 6) {
            poses.back().half_extents.x = -1.0f;  // the new row is invalid
            try {
                finder.find(obbsat::box_view(poses).with_ids(w.ids));
                ADD_FAILURE() << "an invalid row was accepted";
            } catch (const obbsat::invalid_input& e) {
                EXPECT_NE(std::string(e.what()).find(std::to_string(poses.size() - 1)), std::string::npos) << e.what();
            }
            continue;
        }
        const obbsat::box_view view(poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(w.ids));
        ASSERT_TRUE(same_pairs(got, obbsat::find_pairs(view, options_for(method::exact)))) << "frame " << f;
    }
}

TEST(pair_finder_ids, empty_and_tiny_sets_with_ids) {
    obbsat::pair_finder finder(options_for(method::exact));
    finder.track_events(true);
    const std::vector<rect_pose> two = {{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1, 0}}};
    const std::vector<std::uint64_t> ids = {~std::uint64_t{0}, 0};
    for (std::size_t count : {0u, 1u, 2u, 1u, 2u, 0u, 2u}) {
        const std::vector<rect_pose> rows(two.begin(), two.begin() + static_cast<std::ptrdiff_t>(count));
        const std::vector<std::uint64_t> row_ids(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(count));
        const std::vector<pair_index>& got = finder.find(obbsat::box_view(rows).with_ids(row_ids));
        EXPECT_EQ(got.size(), count == 2 ? 1u : 0u);
        if (count == 2) {
            // The smaller id first: the pair of rows (0, 1) is the id pair (0, 2^64 - 1); the last call
            // was across two sets, so every pair of this one begins.
            const std::vector<id_pair> all = {{0, ~std::uint64_t{0}}};
            EXPECT_EQ(finder.began_ids(), all);
        }
        // Across two sets, one of them empty.
        const std::vector<pair_index>& cross =
            finder.find(obbsat::box_view(rows).with_ids(row_ids), obbsat::box_view(two).with_ids(ids));
        EXPECT_TRUE(
            same_pairs(cross, obbsat::find_pairs(obbsat::box_view(rows), obbsat::box_view(two), options_for(method::exact))));
    }
}

}  // namespace
