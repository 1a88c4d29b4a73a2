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

#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;

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
        for (row& r : rows) {
            r.pose.center.x += random.uniform(-0.02f, 0.02f);
            r.pose.center.y += random.uniform(-0.02f, 0.02f);
        }
        const std::size_t changes = rows.size() / 100 + 1;
        for (std::size_t c = 0; c < changes; ++c) {
            const std::size_t at = random.below(rows.size());
            const std::uint64_t what = random.below(3);
            if (what == 0) {
                rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(at));
            } else if (what == 1) {
                rows[at] = rows.back();
                rows.pop_back();
            }
            rows.push_back(fresh_row());
        }
        if (random.below(5) == 0) {
            rows[random.below(rows.size())].group = 7;
        }
    }

    std::vector<rect_pose> poses() const {
        std::vector<rect_pose> out;
        for (const row& r : rows) out.push_back(r.pose);
        return out;
    }
};

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
    collide_options options;
    options.test = method::exact;
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

}  // namespace
