// pair_finder with everything a game engine hands it at once: rows with
// stable ids that come, go and change places, pair filters that travel with
// their rows (and change now and then), and the engine's own executor. Every
// frame must answer what a fresh find_pairs with the same filters answers,
// on the built-in pool.
#include <obbsat/collide.hpp>
#include <obbsat/executor.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_pose64.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include "scene/pair_finder_id_pairs.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::id_pair;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat_test::by_id;
using obbsat_test::id_less;
using obbsat_test::minus;

/// Runs the ranges of a task last to first, on the calling thread.
void* enqueue_backwards(obbsat::executor_task task, std::size_t count, std::size_t, void* task_context, void*) {
    for (std::size_t end = count; end > 0; --end) {
        task(end - 1, end, task_context);
    }
    return nullptr;
}
void finish_nothing(void*, void*) {}

/// One row: its pose, id and filter values, moved together.
struct row {
    rect_pose pose;
    std::uint64_t id;
    std::uint64_t category;
    std::uint64_t mask;
    std::int32_t group;
};

struct frames {
    std::vector<row> rows;
    std::vector<rect_pose> pool;
    std::size_t pool_next = 0;
    std::uint64_t next_id = 1;
    obbsat::seeded_random random;

    explicit frames(std::size_t boxes, std::uint64_t seed) : random(seed) {
        obbsat::pose_scene_spec spec;
        spec.boxes = 2 * boxes;
        spec.seed = seed;
        spec.sizes = obbsat::scene_sizes::mixed;
        spec.pairs_per_box = 3.0;
        pool = obbsat::make_pose_scene(spec);
        for (std::size_t i = 0; i < boxes; ++i) {
            rows.push_back(fresh_row());
        }
    }

    row fresh_row() {
        row r;
        r.pose = pool[pool_next++ % pool.size()];
        r.id = next_id;
        next_id += 1 + random.below(4);
        r.category = std::uint64_t{1} << random.below(3);
        r.mask = random.below(4) == 0 ? ~(std::uint64_t{1} << random.below(3)) : ~std::uint64_t{0};
        r.group = random.below(3) == 0 ? static_cast<std::int32_t>(1 + random.below(40)) : 0;
        return r;
    }

    /// Drift, about 1% of the rows erased, swap-removed or appended, now and then a filter changed.
    void step() {
        drift();
        const std::size_t changes = rows.size() / 100 + 1;
        for (std::size_t c = 0; c < changes; ++c) {
            const std::size_t at = random.below(rows.size());
            const std::uint64_t what = random.below(3);
            if (what < 2) {
                remove_row(at, what == 1);
            }
            rows.push_back(fresh_row());
        }
        if (random.below(5) == 0) {
            rows[random.below(rows.size())].group = 7;
        }
    }

    /// Row `at` erased (the rows after it shift) or, with `swap_last`, replaced by the last row.
    void remove_row(std::size_t at, bool swap_last) {
        if (swap_last) {
            rows[at] = rows.back();
            rows.pop_back();
        } else {
            rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(at));
        }
    }

    void drift() {
        for (row& r : rows) {
            r.pose.center.x += random.uniform(-0.02f, 0.02f);
            r.pose.center.y += random.uniform(-0.02f, 0.02f);
        }
    }

    /// A new category, mask or group for one row.
    void change_filter(row& r) {
        const std::uint64_t what = random.below(3);
        if (what == 0) {
            r.category = std::uint64_t{1} << random.below(3);
        } else if (what == 1) {
            r.mask = random.below(2) == 0 ? ~(std::uint64_t{1} << random.below(3)) : ~std::uint64_t{0};
        } else {
            r.group = random.below(2) == 0 ? static_cast<std::int32_t>(1 + random.below(40)) : 0;
        }
    }

    /// Drift, and `changes` of these at random: a row erased, swap-removed,
    /// appended or inserted, two rows swapped, a row's filters changed; now
    /// and then a run of rows reversed. The count stays about steady.
    void step_mixed(std::size_t changes) {
        drift();
        const std::size_t target = rows.size();
        for (std::size_t c = 0; c < changes; ++c) {
            const std::size_t at = random.below(rows.size());
            const std::uint64_t what = random.below(7);
            if (what < 2) {
                remove_row(at, what == 1);
            } else if (what == 2) {
                rows.push_back(fresh_row());
            } else if (what == 3) {
                rows.insert(rows.begin() + static_cast<std::ptrdiff_t>(at), fresh_row());
            } else if (what == 4) {
                std::swap(rows[at], rows[random.below(rows.size())]);
            } else {
                change_filter(rows[at]);
            }
        }
        if (random.below(8) == 0) {
            const std::size_t at = random.below(rows.size() - 8);
            std::reverse(rows.begin() + static_cast<std::ptrdiff_t>(at), rows.begin() + static_cast<std::ptrdiff_t>(at + 8));
        }
        while (rows.size() < target) {
            rows.push_back(fresh_row());
        }
    }

    std::vector<rect_pose> poses() const {
        std::vector<rect_pose> out;
        for (const row& r : rows) out.push_back(r.pose);
        return out;
    }
};

collide_options options_for(method m) {
    collide_options options;
    options.test = m;
    return options;
}

/// The arrays of one frame's rows, which a box_view reads in place.
struct frame_arrays {
    std::vector<rect_pose> poses;
    std::vector<std::uint64_t> ids, categories, masks;
    std::vector<std::int32_t> groups;

    explicit frame_arrays(const frames& world) : poses(world.poses()) {
        for (const row& r : world.rows) {
            ids.push_back(r.id);
            categories.push_back(r.category);
            masks.push_back(r.mask);
            groups.push_back(r.group);
        }
    }
    obbsat::pair_filters filters() const { return {categories.data(), masks.data(), groups.data()}; }
    obbsat::box_view view() const { return obbsat::box_view(poses).with_filters(filters()); }
};

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

void run(method m, unsigned threads, const obbsat::executor* engine) {
    frames world(2500, 29 + threads);
    collide_options with_engine;
    with_engine.test = m;
    with_engine.threads = threads;
    with_engine.executor = engine;
    collide_options plain = with_engine;
    plain.executor = nullptr;
    obbsat::pair_finder finder(with_engine);
    std::size_t filtered_away = 0;
    for (int frame = 0; frame < 30; ++frame) {
        if (frame > 0) {
            world.step();
        }
        const std::vector<rect_pose> poses = world.poses();
        std::vector<std::uint64_t> ids, categories, masks;
        std::vector<std::int32_t> groups;
        for (const row& r : world.rows) {
            ids.push_back(r.id);
            categories.push_back(r.category);
            masks.push_back(r.mask);
            groups.push_back(r.group);
        }
        const obbsat::pair_filters filters{categories.data(), masks.data(), groups.data()};
        const obbsat::box_view view = obbsat::box_view(poses).with_filters(filters);
        const std::vector<pair_index> got = finder.find(view.with_ids(ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, plain);
        ASSERT_EQ(got.size(), want.size()) << "frame " << frame;
        for (std::size_t k = 0; k < got.size(); ++k) {
            ASSERT_TRUE(got[k].a == want[k].a && got[k].b == want[k].b) << "frame " << frame << ", pair " << k;
        }
        filtered_away += obbsat::find_pairs(obbsat::box_view(poses), plain).size() - want.size();
    }
    EXPECT_GT(filtered_away, 0u) << "the filters refused no pair: the test would not see them";
}

TEST(pair_finder_together, ids_filters_and_the_pool_on_one_thread) { run(method::exact, 1, nullptr); }

TEST(pair_finder_together, ids_filters_and_the_pool_on_two_threads) { run(method::local, 2, nullptr); }

TEST(pair_finder_together, ids_filters_and_an_engine_executor) {
    const obbsat::executor engine{&enqueue_backwards, &finish_nothing, nullptr};
    run(method::exact, 4, &engine);
}

// Double rows at UTM-like coordinates with ids that come and go: every frame
// is the fresh double query's answer.
TEST(pair_finder_together, double_rows_with_ids_that_come_and_go) {
    frames world(2000, 41);
    const collide_options options = options_for(method::exact);
    obbsat::pair_finder finder(options);
    for (int frame = 0; frame < 20; ++frame) {
        if (frame > 0) {
            world.step();
        }
        std::vector<obbsat::rect_pose64> poses;
        std::vector<std::uint64_t> ids;
        for (const row& r : world.rows) {
            const rect_pose& p = r.pose;
            poses.push_back({{500000.0 + p.center.x + 1e-3 * static_cast<double>(r.id % 7), 5700000.0 + p.center.y},
                             {p.half_extents.x, p.half_extents.y},
                             {p.rotation.x, p.rotation.y}});
            ids.push_back(r.id);
        }
        const obbsat::box_view view(poses);
        const std::vector<pair_index> got = finder.find(view.with_ids(ids));
        const std::vector<pair_index> want = obbsat::find_pairs(view, options);
        ASSERT_EQ(got.size(), want.size()) << "frame " << frame;
        for (std::size_t k = 0; k < got.size(); ++k) {
            ASSERT_TRUE(got[k].a == want[k].a && got[k].b == want[k].b) << "frame " << frame << ", pair " << k;
        }
    }
}

// Random sequences of adds, removes, reorders and filter changes with ids:
// every frame is the fresh filtered query's answer, the events are the
// differences of consecutive answers read as ids, and the kept candidates
// answer most frames (the filters follow the ids: a row whose filters
// changed is carried over as a new row, not a reason for a full query).
void run_mixed(method m, unsigned threads, std::uint64_t seed) {
    frames world(3000, seed);
    collide_options options;
    options.test = m;
    options.threads = threads;
    obbsat::pair_finder finder(options);
    finder.track_events(true);
    std::vector<id_pair> last;
    std::size_t changed_frames = 0;
    std::size_t from_kept = 0;
    for (int frame = 0; frame < 40; ++frame) {
        if (frame > 0) {
            world.step_mixed(1 + world.random.below(40));
        }
        const frame_arrays now(world);
        const std::vector<pair_index>& got = finder.find(now.view().with_ids(now.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(now.view(), options);
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << frame << ": " << got.size() << " pairs, want " << want.size();
        const std::vector<id_pair> ids_now = by_id(got, now.ids, nullptr);
        ASSERT_EQ(finder.began_ids(), minus(ids_now, last)) << "frame " << frame;
        ASSERT_EQ(finder.ended_ids(), minus(last, ids_now)) << "frame " << frame;
        last = ids_now;
        if (frame > 2) {
            ++changed_frames;
            from_kept += finder.stats().reused_candidates ? 1u : 0u;
        }
    }
    EXPECT_GT(2 * from_kept, changed_frames) << from_kept << " of " << changed_frames << " frames from kept candidates";
}

TEST(pair_finder_together, filters_follow_ids_through_adds_removes_reorders_and_filter_changes_exact) {
    run_mixed(method::exact, 1, 51);
}

TEST(pair_finder_together, filters_follow_ids_through_adds_removes_reorders_and_filter_changes_local) {
    run_mixed(method::local, 1, 52);
}

TEST(pair_finder_together, filters_follow_ids_through_adds_removes_reorders_and_filter_changes_two_threads) {
    run_mixed(method::conservative, 2, 53);
}

// Only filters change, the rows stay: a pair a group now refuses ends, a
// pair a mask now lets through begins, both answered from kept candidates.
TEST(pair_finder_together, a_filter_change_alone_ends_and_begins_pairs_from_kept_candidates) {
    frames world(2000, 61);
    for (row& r : world.rows) {
        r.category = 1;
        r.mask = ~std::uint64_t{0};
        r.group = 0;
    }
    const collide_options options = options_for(method::exact);
    obbsat::pair_finder finder(options);
    finder.track_events(true);
    const auto answer = [&]() {
        const frame_arrays now(world);
        const std::vector<pair_index> got = finder.find(now.view().with_ids(now.ids));
        EXPECT_TRUE(same_pairs(got, obbsat::find_pairs(now.view(), options)));
        return got;
    };
    answer();
    const std::vector<pair_index> all = answer();
    ASSERT_FALSE(all.empty());
    // The first pair's rows share a group now; a row that refused everything lets everything through.
    const pair_index p = all.front();
    world.rows[p.a].group = 5;
    world.rows[p.b].group = 5;
    const pair_index q = all.back();
    world.rows[q.a].mask = 0;
    answer();
    EXPECT_TRUE(finder.stats().reused_candidates);
    const std::vector<id_pair> ended = finder.ended_ids();
    const std::uint64_t pa = world.rows[p.a].id;
    const std::uint64_t pb = world.rows[p.b].id;
    EXPECT_TRUE(std::binary_search(ended.begin(), ended.end(), id_pair{std::min(pa, pb), std::max(pa, pb)}, id_less));
    world.rows[q.a].mask = ~std::uint64_t{0};
    answer();
    EXPECT_TRUE(finder.stats().reused_candidates);
    const std::vector<id_pair> began = finder.began_ids();
    const std::uint64_t qa = world.rows[q.a].id;
    const std::uint64_t qb = world.rows[q.b].id;
    EXPECT_TRUE(std::binary_search(began.begin(), began.end(), id_pair{std::min(qa, qb), std::max(qa, qb)}, id_less));
}

// Across two sets, each with its filters and ids, rows and filters changing on both sides.
TEST(pair_finder_together, filters_follow_ids_on_both_sides_of_two_sets) {
    frames a(2000, 71);
    frames b(2000, 72);
    const collide_options options = options_for(method::exact);
    obbsat::pair_finder finder(options);
    std::size_t from_kept = 0;
    for (int frame = 0; frame < 25; ++frame) {
        if (frame > 0) {
            a.step_mixed(1 + a.random.below(20));
            b.step_mixed(1 + b.random.below(20));
        }
        const frame_arrays na(a);
        const frame_arrays nb(b);
        const std::vector<pair_index>& got = finder.find(na.view().with_ids(na.ids), nb.view().with_ids(nb.ids));
        const std::vector<pair_index> want = obbsat::find_pairs(na.view(), nb.view(), options);
        ASSERT_TRUE(same_pairs(got, want)) << "frame " << frame << ": " << got.size() << " pairs, want " << want.size();
        from_kept += frame > 2 && finder.stats().reused_candidates ? 1u : 0u;
    }
    EXPECT_GT(from_kept, 11u);
}

// Filters given, taken away and given again between frames with ids: each such frame is a full query, right.
TEST(pair_finder_together, filters_given_and_taken_away_with_ids_answer_right) {
    frames world(2000, 81);
    const collide_options options = options_for(method::local);
    obbsat::pair_finder finder(options);
    for (int frame = 0; frame < 12; ++frame) {
        if (frame > 0) {
            world.step_mixed(5);
        }
        const frame_arrays now(world);
        const bool with = (frame / 3) % 2 == 0;
        const obbsat::box_view view = with ? now.view() : obbsat::box_view(now.poses);
        const std::vector<pair_index>& got = finder.find(view.with_ids(now.ids));
        ASSERT_TRUE(same_pairs(got, obbsat::find_pairs(view, options))) << "frame " << frame;
        if (frame % 3 == 0 && frame > 0) {
            EXPECT_FALSE(finder.stats().reused_candidates) << "frame " << frame;
        }
    }
}

}  // namespace
