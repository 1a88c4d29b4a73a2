// The checks of the contact entry points (obbsat/contact.hpp): bad input is
// invalid_input naming the row and field, or the pair and index, at fault, and
// nothing is written; the backend asked for is the one that runs; every
// thread count gives the same contacts.
#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/contact.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::contact;
using obbsat::contact_options;
using obbsat::invalid_input;
using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_pose;

/// Unit squares 1.5 apart along x: each overlaps its neighbours by 0.5.
std::vector<rect_pose> row_of_poses(std::size_t n) {
    std::vector<rect_pose> poses;
    for (std::size_t i = 0; i < n; ++i) {
        poses.push_back(rect_pose{{1.5f * static_cast<float>(i), 0}, {1, 1}, {1, 0}});
    }
    return poses;
}

std::vector<rect> row_of_rects(std::size_t n) {
    std::vector<rect> rects;
    for (std::size_t i = 0; i < n; ++i) {
        const float x = 1.5f * static_cast<float>(i);
        rects.push_back(rect{{x - 1, 1}, {x + 1, 1}, {x + 1, -1}, {x - 1, -1}});
    }
    return rects;
}

std::vector<pair_index> neighbours(std::size_t n) {
    std::vector<pair_index> pairs;
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
        pairs.push_back(pair_index{i, i + 1});
    }
    return pairs;
}

/// Runs `call` expecting invalid_input whose message holds every one of `parts`,
/// and `out` untouched.
template <class Call>
void expect_refused(const Call& call, std::vector<contact>& out, std::initializer_list<std::string> parts) {
    std::memset(out.data(), 0x5a, out.size() * sizeof(contact));
    try {
        call();
        ADD_FAILURE() << "no invalid_input";
    } catch (const invalid_input& e) {
        for (const std::string& part : parts) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what() << " lacks " << part;
        }
    }
    for (const contact& c : out) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(&c);
        for (std::size_t k = 0; k < sizeof c; ++k) {
            ASSERT_EQ(bytes[k], 0x5a) << "nothing is written when the input is refused";
        }
    }
}

TEST(contact_checks, a_non_finite_pose_field_is_named_with_its_row) {
    std::vector<rect_pose> poses = row_of_poses(8);
    poses[3].center.y = std::numeric_limits<float>::quiet_NaN();
    const std::vector<pair_index> pairs = neighbours(8);
    std::vector<contact> out(pairs.size());
    expect_refused([&] { obbsat::contact_pairs(poses.data(), poses.size(), pairs.data(), pairs.size(), out.data()); },
                   out, {"pose 3", "cy"});
    EXPECT_THROW(obbsat::pose_records{poses}, invalid_input) << "a pose store refuses it as it is built";
}

TEST(contact_checks, a_non_finite_corner_is_named_with_its_row) {
    std::vector<rect> rects = row_of_rects(8);
    rects[5].lr.x = std::numeric_limits<float>::infinity();
    const std::vector<pair_index> pairs = neighbours(8);
    std::vector<contact> out(pairs.size());
    expect_refused([&] { obbsat::contact_pairs(rects.data(), rects.size(), pairs.data(), pairs.size(), out.data()); },
                   out, {"rectangle 5", "lrx"});
}

TEST(contact_checks, a_pair_index_out_of_range_is_named) {
    const obbsat::pose_records poses(row_of_poses(8));
    std::vector<pair_index> pairs = neighbours(8);
    pairs[4].b = 99;
    std::vector<contact> out(pairs.size());
    expect_refused([&] { obbsat::contact_pairs(poses, pairs.data(), pairs.size(), out.data()); }, out,
                   {"pair 4", "index 99", "8 poses"});
    const obbsat::rect_records rects(row_of_rects(8));
    expect_refused([&] { obbsat::contact_pairs(rects, pairs.data(), pairs.size(), out.data()); }, out,
                   {"pair 4", "index 99", "8 rectangles"});
}

TEST(contact_checks, a_margin_must_be_finite_and_not_negative) {
    const obbsat::pose_records poses(row_of_poses(4));
    const std::vector<pair_index> pairs = neighbours(4);
    std::vector<contact> out(pairs.size());
    constexpr float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const float margin : {-0.5f, nan, inf}) {
        contact_options options;
        options.margin = margin;
        expect_refused([&] { obbsat::contact_pairs(poses, pairs.data(), pairs.size(), out.data(), options); }, out,
                       {"margin"});
    }
}

TEST(contact_checks, corners_that_are_not_a_strictly_convex_quad_are_named) {
    std::vector<rect> rects = row_of_rects(6);
    rects[2] = rect{{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // a bow tie
    const obbsat::rect_records records(rects);
    const std::vector<pair_index> pairs = neighbours(6);
    std::vector<contact> out(pairs.size());
    expect_refused([&] { obbsat::contact_pairs(records, pairs.data(), pairs.size(), out.data()); }, out,
                   {"rectangle 2", "convex"});
    rects[2] = rect{{0, 1}, {1, 1}, {1, 1}, {0, 0}};  // two corners the same
    expect_refused([&] { obbsat::contact_pairs(rects.data(), rects.size(), pairs.data(), pairs.size(), out.data()); },
                   out, {"rectangle 2", "convex"});
}

TEST(contact_checks, a_rotation_too_short_for_its_square_is_named) {
    std::vector<rect_pose> poses = row_of_poses(4);
    poses[1].rotation = obbsat::point{1e-30f, 0};
    const obbsat::pose_records records(poses);
    const std::vector<pair_index> pairs = neighbours(4);
    std::vector<contact> out(pairs.size());
    expect_refused([&] { obbsat::contact_pairs(records, pairs.data(), pairs.size(), out.data()); }, out,
                   {"pose 1", "rotation"});
}

// A store is checked a vector of records at a time, the rows past the last
// whole vector one by one: a rotation too short (its square below the least
// normal float) or too long (its square past the largest float) is found in
// every lane of a vector and in the rows after, on every backend.
TEST(contact_checks, a_rejected_rotation_is_named_wherever_it_is_on_every_backend) {
    constexpr std::size_t rows = 39;  // two whole AVX-512 vectors and seven rows more
    for (const obbsat::backend use : obbsat::compiled_backends()) {
        if (!obbsat::cpu_supports(use)) {
            continue;
        }
        contact_options options;
        options.use = use;
        for (const std::size_t bad : {std::size_t{0}, std::size_t{5}, std::size_t{15}, std::size_t{16},
                                      std::size_t{31}, std::size_t{32}, std::size_t{38}}) {
            for (const float length : {1e-30f, 1e20f}) {
                std::vector<rect_pose> poses = row_of_poses(rows);
                poses[bad].rotation = obbsat::point{0, length};
                const obbsat::pose_records records(poses);
                const std::vector<pair_index> pairs = neighbours(rows);
                std::vector<contact> out(pairs.size());
                SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", pose " + std::to_string(bad));
                expect_refused(
                    [&] { obbsat::contact_pairs(records, pairs.data(), pairs.size(), out.data(), options); }, out,
                    {"pose " + std::to_string(bad) + ":", "rotation"});
            }
        }
    }
}

TEST(contact_checks, stream_batches_of_different_lengths_are_refused) {
    const obbsat::pose_records a(row_of_poses(4)), b(row_of_poses(5));
    std::vector<contact> out(5);
    expect_refused([&] { obbsat::contact_stream(a, b, out.data()); }, out, {"differ in length"});
}

TEST(contact_checks, output_sharing_memory_with_the_pairs_is_refused) {
    const obbsat::pose_records poses(row_of_poses(64));
    std::vector<contact> out(64);
    auto* pairs = reinterpret_cast<pair_index*>(out.data());
    for (std::uint32_t i = 0; i < 8; ++i) {
        pairs[i] = pair_index{i, i + 1};
    }
    EXPECT_THROW(obbsat::contact_pairs(poses, pairs, 8, out.data()), invalid_input);
}

TEST(distance_checks, bad_indices_and_quads_are_named_and_nothing_is_written) {
    const obbsat::pose_records poses(row_of_poses(8));
    std::vector<pair_index> pairs = neighbours(8);
    pairs[2].a = 40;
    std::vector<obbsat::closest_points> out(pairs.size(), obbsat::closest_points{7, 7, 7, 7, 7});
    try {
        obbsat::distance_pairs(poses, pairs.data(), pairs.size(), out.data());
        ADD_FAILURE() << "no invalid_input";
    } catch (const invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pair 2"), std::string::npos) << e.what();
    }
    std::vector<rect> rects = row_of_rects(8);
    rects[6] = rect{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    const obbsat::rect_records records(rects);
    pairs[2].a = 1;
    try {
        obbsat::distance_pairs(records, pairs.data(), pairs.size(), out.data());
        ADD_FAILURE() << "no invalid_input";
    } catch (const invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("rectangle 6"), std::string::npos) << e.what();
    }
    for (const obbsat::closest_points& c : out) {
        EXPECT_EQ(c.distance, 7.0f) << "nothing is written when the input is refused";
    }
}

// Squares 1.5 apart overlap their neighbours and lie 1 from the next but one.
TEST(distance_checks, neighbours_collide_and_the_next_but_one_are_one_apart) {
    const obbsat::pose_records poses(row_of_poses(3));
    const std::vector<obbsat::closest_points> d = obbsat::distance_pairs(poses, {{0, 1}, {0, 2}});
    EXPECT_EQ(d[0].distance, 0.0f);
    EXPECT_EQ(d[1].distance, 1.0f);
    EXPECT_EQ(d[1].ax, 1.0f);
    EXPECT_EQ(d[1].bx, 2.0f);
}

// Two threads split the list; the contacts are the reference's either way.
TEST(contact_checks, every_thread_count_gives_the_reference) {
    const std::size_t n = 40000;
    const std::vector<rect_pose> rows = row_of_poses(n);
    const obbsat::pose_records poses(rows);
    const std::vector<pair_index> pairs = neighbours(n);
    for (const unsigned threads : {1u, 2u, 0u}) {
        contact_options options;
        options.threads = threads;
        const std::vector<contact> got = obbsat::contact_pairs(poses, pairs, options);
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            const contact expected = obbsat::ref::contact_of(rows[pairs[i].a], rows[pairs[i].b]);
            ASSERT_EQ(std::memcmp(&expected, &got[i], sizeof(contact)), 0) << "pair " << i << ", " << threads;
        }
        ASSERT_EQ(got[0].point_count, 2u);
        EXPECT_EQ(got[0].nx, 1.0f);
        EXPECT_EQ(got[0].depth, 0.5f);
    }
}

}  // namespace
