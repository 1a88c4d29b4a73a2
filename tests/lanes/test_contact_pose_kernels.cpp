// Each backend's two contact kernels over pose records (contact_kernel_table's
// poses, which asks for the records of the pairs ahead into L2, and
// poses_in_l2, which asks for nothing: contact_pairs picks it for a store L2
// holds) must give the contact reference's contacts bit for bit, on pairs of a
// scene that touch and overlap, in sweep-like runs and at random, of every
// length up to a few vectors past a whole block of the two-pass driver, at
// margin 0 and with a speculative margin; and the double kernels (poses64,
// poses64_in_l2) on the same poses as pose_records64 against the double
// reference.
#include "dispatch/contact_kernel_table.hpp"

#include "test_support/mixed_pair_list.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/contact_manifold.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/ref/contact.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

using obbsat::contact;
using obbsat::pair_index;

struct contact_scene {
    obbsat::pose_records poses;
    std::vector<pair_index> pairs;
};

/// The colliding pairs of a scene of 3000 boxes in the query's order, and
/// after every third one a pair at random (mostly apart).
const contact_scene& scene() {
    static const contact_scene s = [] {
        contact_scene out;
        obbsat::pose_scene_spec spec;
        spec.seed = 23;
        spec.boxes = 3000;
        spec.pairs_per_box = 3.0;
        out.poses = obbsat::pose_records(obbsat::make_pose_scene(spec));
        out.pairs = obbsat::test_support::colliding_pairs_mixed_with_random(out.poses, 9);
        return out;
    }();
    return s;
}

/// The scene's poses as double records, every float taken exactly.
const obbsat::pose_records64& scene_poses64() {
    static const obbsat::pose_records64 poses = [] {
        std::vector<obbsat::rect_pose64> rows;
        for (std::size_t i = 0; i < scene().poses.size(); ++i) {
            const obbsat::rect_pose p = scene().poses[i];
            rows.push_back(
                {{p.center.x, p.center.y}, {p.half_extents.x, p.half_extents.y}, {p.rotation.x, p.rotation.y}});
        }
        return obbsat::pose_records64(rows);
    }();
    return poses;
}

/// The two pose kernels of a table for one real type, over the scene's poses of that type.
struct float_kernels {
    using real = float;
    using contact_type = contact;
    static const float* records() { return scene().poses.data(); }
    static constexpr std::size_t stride = obbsat::pose_records::record_floats;
    static obbsat::rect_pose pose(std::size_t i) { return scene().poses[i]; }
    static obbsat::detail::contact_fn kernel(const obbsat::detail::contact_kernel_table& t, bool in_l2) {
        return in_l2 ? t.poses_in_l2 : t.poses;
    }
};

struct double_kernels {
    using real = double;
    using contact_type = obbsat::contact64;
    static const double* records() { return scene_poses64().data(); }
    static constexpr std::size_t stride = obbsat::pose_records64::record_doubles;
    static obbsat::rect_pose64 pose(std::size_t i) { return scene_poses64()[i]; }
    static obbsat::detail::contact64_fn kernel(const obbsat::detail::contact_kernel_table& t, bool in_l2) {
        return in_l2 ? t.poses64_in_l2 : t.poses64;
    }
};

/// Both pose kernels of backend `use` for Kernels' real type against the reference.
template <class Kernels>
void expect_both_pose_entries_equal_the_reference(obbsat::backend use) {
    using real = typename Kernels::real;
    using contact_type = typename Kernels::contact_type;
    const contact_scene& s = scene();
    ASSERT_GT(s.pairs.size(), 4000u);
    const obbsat::detail::contact_kernel_table& table = obbsat::detail::contact_kernels_for(use);
    ASSERT_NE(Kernels::kernel(table, false), nullptr);
    ASSERT_NE(Kernels::kernel(table, true), nullptr);
    const real* records = Kernels::records();
    constexpr std::size_t stride = Kernels::stride;
    const std::size_t lengths[] = {1, 15, 16, 17, 100, 511, 512, 513, 1023, 1024, 1025, 2063, s.pairs.size()};
    for (const real margin : {real(0), real(0.25)}) {
        const std::size_t all = s.pairs.size();
        std::vector<contact_type> want(all);
        std::size_t with_points = 0;
        for (std::size_t i = 0; i < all; ++i) {
            want[i] = obbsat::ref::contact_of(Kernels::pose(s.pairs[i].a), Kernels::pose(s.pairs[i].b), margin);
            with_points += want[i].point_count > 0 ? 1u : 0u;
        }
        // Both passes of the driver run: pairs with points and pairs without.
        EXPECT_GT(with_points, all / 4);
        EXPECT_LT(with_points, all - all / 8);
        for (const std::size_t count : lengths) {
            for (const bool in_l2 : {false, true}) {
                const auto kernel = Kernels::kernel(table, in_l2);
                std::vector<contact_type> got(count + 1);
                std::memset(got.data(), 0xee, got.size() * sizeof(contact_type));
                kernel(records, stride, records, stride, s.pairs.data(), count, margin, got.data());
                const std::string what = std::string(in_l2 ? "poses_in_l2" : "poses") + ", " +
                                         std::to_string(count) + " pairs, margin " + std::to_string(margin);
                std::size_t differ = 0;
                for (std::size_t i = 0; i < count; ++i) {
                    differ += std::memcmp(&got[i], &want[i], sizeof(contact_type)) != 0 ? 1u : 0u;
                }
                EXPECT_EQ(differ, 0u) << what;
                // Nothing past the last pair is written.
                const contact_type& past = got[count];
                const auto* bytes = reinterpret_cast<const unsigned char*>(&past);
                for (std::size_t k = 0; k < sizeof(contact_type); ++k) {
                    ASSERT_EQ(bytes[k], 0xee) << what << ": byte " << k << " past the output written";
                }
            }
        }
    }
}

class contact_pose_kernels : public ::testing::TestWithParam<obbsat::backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(GetParam());
        }
    }
};

TEST_P(contact_pose_kernels, both_pose_entries_equal_the_reference) {
    expect_both_pose_entries_equal_the_reference<float_kernels>(GetParam());
}

TEST_P(contact_pose_kernels, both_double_pose_entries_equal_the_double_reference) {
    expect_both_pose_entries_equal_the_reference<double_kernels>(GetParam());
}

INSTANTIATE_TEST_SUITE_P(every_backend, contact_pose_kernels, ::testing::ValuesIn(obbsat::compiled_backends()),
                         [](const ::testing::TestParamInfo<obbsat::backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace
