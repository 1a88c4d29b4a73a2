// The kernels for pair lists whose records lie near each other (the scene
// queries' indexed_records_near and indexed_near, which fetch no records
// ahead) and for stores read from DRAM (indexed_records_far and indexed_far,
// which fetch 128 pairs ahead into L2) must give, on every backend and for
// every method on each store, the scalar path's verdicts bit for bit and the
// same count of pairs left to the slow path as the same backend's entry that
// fetches 16 pairs ahead into L1. Pairs from a scene
// of touching and overlapping boxes, in sweep-like runs and at random, of
// every length up to a few vectors past a whole block.
#include "backends/backend_cases.hpp"

#include "test_support/mixed_pair_list.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

using obbsat::store_kind;

struct near_scene {
    obbsat::pose_records poses;
    obbsat::rect_records corners;
    std::vector<obbsat::pair_index> pairs;
};

const near_scene& scene() {
    static const near_scene s = [] {
        near_scene out;
        obbsat::pose_scene_spec spec;
        spec.seed = 11;
        spec.boxes = 3000;
        spec.pairs_per_box = 3.0;
        out.poses = obbsat::pose_records(obbsat::make_pose_scene(spec));
        out.corners = obbsat::corner_records_of(out.poses, obbsat::backend::scalar);
        out.pairs = obbsat::test_support::colliding_pairs_mixed_with_random(out.poses, 5);
        return out;
    }();
    return s;
}

class near_kernels : public ::testing::TestWithParam<obbsat_test::backend_case> {};

TEST_P(near_kernels, equal_the_scalar_verdicts_and_the_prefetching_entry) {
    const obbsat_test::backend_case& backend = GetParam();
    if (backend.table == nullptr) {
        GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(backend.id);
    }
    const near_scene& s = scene();
    const obbsat::detail::kernel_table& scalar = obbsat::detail::kernels_for(obbsat::backend::scalar);
    const std::size_t lengths[] = {1, 15, 16, 17, 100, 2048, 2063, s.pairs.size()};
    std::size_t checked = 0;
    for (const obbsat::method m : obbsat::all_methods()) {
        for (const store_kind kind : {store_kind::corners, store_kind::poses}) {
            if (!obbsat::runs_on(m, kind)) {
                continue;
            }
            for (const std::size_t count : lengths) {
                ASSERT_LE(count, s.pairs.size());
                std::vector<std::uint8_t> want(count), near(count), ahead(count), far(count);
                std::size_t near_slow = 0, ahead_slow = 0, far_slow = 0;
                if (kind == store_kind::corners) {
                    const auto& mine = backend.table->of(m);
                    scalar.of(m).indexed_records(s.corners.data(), s.pairs.data(), count, want.data());
                    near_slow = mine.indexed_records_near(s.corners.data(), s.pairs.data(), count, near.data());
                    ahead_slow = mine.indexed_records(s.corners.data(), s.pairs.data(), count, ahead.data());
                    far_slow = mine.indexed_records_far(s.corners.data(), s.pairs.data(), count, far.data());
                } else {
                    const auto& mine = backend.table->on_poses(m);
                    scalar.on_poses(m).indexed(s.poses.data(), s.pairs.data(), count, want.data());
                    near_slow = mine.indexed_near(s.poses.data(), s.pairs.data(), count, near.data());
                    ahead_slow = mine.indexed(s.poses.data(), s.pairs.data(), count, ahead.data());
                    far_slow = mine.indexed_far(s.poses.data(), s.pairs.data(), count, far.data());
                }
                const std::string what = std::string(obbsat::method_name(m)) + " on " + obbsat::store_name(kind) +
                                         ", " + std::to_string(count) + " pairs";
                EXPECT_EQ(near, want) << what;
                EXPECT_EQ(ahead, want) << what;
                EXPECT_EQ(far, want) << what;
                EXPECT_EQ(near_slow, ahead_slow) << what;
                EXPECT_EQ(far_slow, ahead_slow) << what;
                ++checked;
            }
        }
    }
    // Every method on each store it runs on: none was skipped by mistake.
    std::size_t expected = 0;
    for (const obbsat::method m : obbsat::all_methods()) {
        expected += (obbsat::runs_on(m, store_kind::corners) ? 1u : 0u) + (obbsat::runs_on(m, store_kind::poses) ? 1u : 0u);
    }
    EXPECT_EQ(checked, expected * std::size(lengths));
}

INSTANTIATE_TEST_SUITE_P(every_backend, near_kernels, ::testing::ValuesIn(obbsat_test::backends_here()),
                         obbsat_test::backend_case_name);

}  // namespace
