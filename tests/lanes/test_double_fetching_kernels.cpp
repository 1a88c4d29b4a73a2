// The double lanes for pair lists, in each of their three ways of reading
// the records (fetching nothing ahead, 16 pairs ahead into L1, 128 pairs
// ahead into L2), must give on every backend and for every method on double
// poses and double corners the scalar references' verdicts bit for bit and
// the same count of pairs left to the exact slow path. Pairs from a scene of
// touching and overlapping boxes, in sweep-like runs (vectors where some
// lanes collide) and at random (whole vectors of separated pairs, which the
// corner lanes decide without scanning the second box's edges), of every
// length up to a few vectors past a whole block.
#include "backends/backend_cases.hpp"
#include "dispatch/double_kernel_table.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

using obbsat::store_kind;

struct double_scene {
    obbsat::pose_records64 poses;
    obbsat::rect_records64 corners;
    std::vector<obbsat::pair_index> pairs;
};

obbsat::point64 wide(const obbsat::point& p) { return obbsat::point64{p.x, p.y}; }

const double_scene& scene() {
    static const double_scene s = [] {
        obbsat::pose_scene_spec spec;
        spec.seed = 23;
        spec.boxes = 3000;
        spec.pairs_per_box = 3.0;
        const obbsat::pose_records poses(obbsat::make_pose_scene(spec));
        const obbsat::rect_records corners = obbsat::corner_records_of(poses, obbsat::backend::scalar);
        std::vector<obbsat::rect_pose64> poses64;
        std::vector<obbsat::rect64> corners64;
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const obbsat::rect_pose p = poses[i];
            poses64.push_back({wide(p.center), wide(p.half_extents), wide(p.rotation)});
            const obbsat::rect r = corners[i];
            corners64.push_back({wide(r.ul), wide(r.ur), wide(r.lr), wide(r.ll)});
        }
        double_scene out{obbsat::pose_records64(poses64), obbsat::rect_records64(corners64), {}};
        obbsat::collide_options options;
        options.test = obbsat::method::exact;
        const std::vector<obbsat::pair_index> colliding = obbsat::find_pairs(poses, options);
        obbsat::seeded_random random(7);
        for (std::size_t i = 0; i < colliding.size(); ++i) {
            out.pairs.push_back(colliding[i]);
            if (i % 16 == 0) {
                // Runs of random pairs: whole vectors of them, nearly all separated.
                for (int k = 0; k < 24; ++k) {
                    out.pairs.push_back({static_cast<std::uint32_t>(random.below(spec.boxes)),
                                         static_cast<std::uint32_t>(random.below(spec.boxes))});
                }
            }
        }
        return out;
    }();
    return s;
}

/// The three ways of one method's pair list on one double store.
template <class Fn>
struct three_ways {
    Fn in_cache, fetching, far;
};

class double_fetching_kernels : public ::testing::TestWithParam<obbsat_test::backend_case> {};

TEST_P(double_fetching_kernels, equal_the_scalar_references_in_every_way_of_reading) {
    const obbsat_test::backend_case& backend = GetParam();
    if (backend.table == nullptr) {
        GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(backend.id);
    }
    const obbsat::detail::double_kernel_table* poses = obbsat::detail::double_kernels_for(backend.id);
    const obbsat::detail::corner64_kernel_table* corners = obbsat::detail::corner64_kernels_for(backend.id);
    if (backend.id == obbsat::backend::scalar) {
        EXPECT_EQ(poses, nullptr);
        EXPECT_EQ(corners, nullptr);
        return;
    }
    ASSERT_NE(poses, nullptr);
    ASSERT_NE(corners, nullptr);
    const double_scene& s = scene();
    const double* pose_rows = s.poses.data();
    const obbsat::rect64* corner_rows = s.corners.data();
    const double* corner_doubles = reinterpret_cast<const double*>(corner_rows);
    const std::size_t lengths[] = {1, 7, 8, 9, 100, 2048, 2063, s.pairs.size()};
    std::size_t checked = 0;
    auto check = [&](obbsat::method m, store_kind kind, const auto& ways, const auto* rows) {
        for (const std::size_t count : lengths) {
            ASSERT_LE(count, s.pairs.size());
            std::vector<std::uint8_t> want(count), in_cache(count), fetching(count), far(count);
            const std::size_t want_slow =
                kind == store_kind::poses
                    ? obbsat::detail::scalar_pose64_indexed(m, pose_rows, s.pairs.data(), count, want.data())
                    : obbsat::detail::scalar_rect64_indexed(m, corner_doubles, s.pairs.data(), count, want.data());
            const std::size_t in_cache_slow = ways.in_cache(rows, s.pairs.data(), count, in_cache.data());
            const std::size_t fetching_slow = ways.fetching(rows, s.pairs.data(), count, fetching.data());
            const std::size_t far_slow = ways.far(rows, s.pairs.data(), count, far.data());
            const std::string what = std::string(obbsat::method_name(m)) + " on double " + obbsat::store_name(kind) +
                                     ", " + std::to_string(count) + " pairs";
            EXPECT_EQ(in_cache, want) << what;
            EXPECT_EQ(fetching, want) << what;
            EXPECT_EQ(far, want) << what;
            EXPECT_EQ(in_cache_slow, want_slow) << what;
            EXPECT_EQ(fetching_slow, want_slow) << what;
            EXPECT_EQ(far_slow, want_slow) << what;
            ++checked;
        }
    };
    using pose_ways = three_ways<obbsat::detail::pose64_indexed_fn>;
    check(obbsat::method::exact, store_kind::poses,
          pose_ways{poses->exact, poses->exact_kernels.indexed_fetching, poses->exact_kernels.indexed_far}, pose_rows);
    check(obbsat::method::conservative, store_kind::poses,
          pose_ways{poses->conservative, poses->conservative_kernels.indexed_fetching,
                    poses->conservative_kernels.indexed_far},
          pose_rows);
    check(obbsat::method::local, store_kind::poses,
          pose_ways{poses->local, poses->local_kernels.indexed_fetching, poses->local_kernels.indexed_far}, pose_rows);
    using corner_ways = three_ways<obbsat::detail::rect64_indexed_fn>;
    check(obbsat::method::exact, store_kind::corners,
          corner_ways{corners->exact, corners->exact_kernels.indexed_fetching, corners->exact_kernels.indexed_far},
          corner_rows);
    check(obbsat::method::conservative, store_kind::corners,
          corner_ways{corners->conservative, corners->conservative_kernels.indexed_fetching,
                      corners->conservative_kernels.indexed_far},
          corner_rows);
    EXPECT_EQ(checked, 5 * std::size(lengths));
}

INSTANTIATE_TEST_SUITE_P(every_backend, double_fetching_kernels, ::testing::ValuesIn(obbsat_test::backends_here()),
                         obbsat_test::backend_case_name);

}  // namespace
