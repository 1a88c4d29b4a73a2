// pair_finder::find_contacts over frames: every frame's pairs are find's and
// its contacts contact_pairs' over them, bit for bit, whether the frame was a
// full query or answered from kept candidates, with ids or without, within
// one set or across two; a persisting contact keeps its feature keys from
// one frame to the next; refusals change nothing.
#include <obbsat/collide.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/ref/contact.hpp>

#include "scene/contact_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::contact;
using obbsat::pair_index;
using contact_scenes::exact_on;
using contact_scenes::scene_of;


/// Frame `f` of a scene whose boxes drift and turn a little each frame.
std::vector<obbsat::rect_pose> frame_of(const std::vector<obbsat::rect_pose>& start, int f) {
    std::vector<obbsat::rect_pose> rows = start;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const double phase = 0.37 * static_cast<double>(i) + 0.2 * f;
        rows[i].center.x += static_cast<float>(0.02 * f * std::cos(phase));
        rows[i].center.y += static_cast<float>(0.02 * f * std::sin(phase));
        const double turn = 0.01 * f * std::sin(0.11 * static_cast<double>(i));
        const float c = rows[i].rotation.x, s = rows[i].rotation.y;
        rows[i].rotation = {static_cast<float>(c * std::cos(turn) - s * std::sin(turn)),
                            static_cast<float>(s * std::cos(turn) + c * std::sin(turn))};
    }
    return rows;
}

/// The frame's pairs must be `pairs` and each contact contact_pairs' on
/// the scalar backend, over rows `a` and `b` (a within one set).
void expect_frame(const obbsat::scene_contacts& got, const std::vector<pair_index>& pairs,
                  const std::vector<obbsat::rect_pose>& a, const std::vector<obbsat::rect_pose>& b) {
    ASSERT_EQ(got.pairs.size(), pairs.size());
    ASSERT_EQ(got.contacts.size(), pairs.size());
    std::vector<contact> within(pairs.size());
    if (&a == &b) {
        obbsat::contact_options scalar;
        scalar.use = obbsat::backend::scalar;
        obbsat::contact_pairs(a.data(), a.size(), pairs.data(), pairs.size(), within.data(), scalar);
    }
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        ASSERT_EQ(got.pairs[k].a, pairs[k].a) << "row " << k;
        ASSERT_EQ(got.pairs[k].b, pairs[k].b) << "row " << k;
        // Across two sets, the reference contact_pairs computes (obbsat/ref/contact.hpp).
        const contact want = &a == &b ? within[k] : obbsat::ref::contact_of(a[pairs[k].a], b[pairs[k].b]);
        EXPECT_EQ(std::memcmp(&got.contacts[k], &want, sizeof(contact)), 0)
            << "pair " << pairs[k].a << "," << pairs[k].b;
    }
}


TEST(PairFinderContacts, EveryFrameIsContactPairsOverFindsPairs) {
    const std::vector<obbsat::rect_pose> start = scene_of(40000, 31);
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 3u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + std::to_string(threads) + " threads");
            obbsat::pair_finder finder(exact_on(use, threads));
            bool reused = false;
            for (int f = 0; f < 6; ++f) {
                const std::vector<obbsat::rect_pose> rows = frame_of(start, f);
                const obbsat::pose_records store(rows);
                const obbsat::scene_contacts& got = finder.find_contacts(f % 2 == 0 ? obbsat::box_view(store)
                                                                                     : obbsat::box_view(rows));
                reused = reused || finder.stats().reused_candidates;
                expect_frame(got, obbsat::find_pairs(rows, exact_on(obbsat::backend::scalar, 1)), rows, rows);
            }
            EXPECT_TRUE(reused) << "no frame was answered from kept candidates";
        }
    }
}

TEST(PairFinderContacts, AcrossTwoSetsTheRowsOfEach) {
    const std::vector<obbsat::rect_pose> all = scene_of(20000, 32);
    const std::vector<obbsat::rect_pose> a(all.begin(), all.begin() + 7000);
    const std::vector<obbsat::rect_pose> b(all.begin() + 7000, all.end());
    obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, 2));
    for (int f = 0; f < 3; ++f) {
        const std::vector<obbsat::rect_pose> fa = frame_of(a, f), fb = frame_of(b, f);
        const obbsat::scene_contacts& got = finder.find_contacts(fa, fb);
        ASSERT_FALSE(got.pairs.empty());
        expect_frame(got, obbsat::find_pairs(fa, fb, exact_on(obbsat::backend::scalar, 1)), fa, fb);
    }
}

TEST(PairFinderContacts, APersistingContactKeepsItsFeatureKeys) {
    // A box resting on a long plank slides along it, frame by frame, while
    // other boxes come and go around them (rows follow ids): the same two
    // corners of the box touch the plank's top face throughout, so both
    // points keep their feature keys from one frame to the next.
    obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, 1));
    std::vector<obbsat::contact_feature> last;
    for (int f = 0; f < 12; ++f) {
        std::vector<obbsat::rect_pose> rows;
        std::vector<std::uint64_t> ids;
        contact_scenes::plank_frame(f, 0.0, 0.0, rows, ids);
        const obbsat::scene_contacts& got = finder.find_contacts(obbsat::box_view(rows).with_ids(ids));
        expect_frame(got, obbsat::find_pairs(rows, exact_on(obbsat::backend::scalar, 1)), rows, rows);
        contact_scenes::expect_plank_keys_kept(got, ids, f, last);
    }
}

TEST(PairFinderContacts, RefusalsChangeNothing) {
    const std::vector<obbsat::rect_pose> rows = scene_of(3000, 33);
    obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, 1));
    finder.track_events(true);
    const std::vector<pair_index> first = finder.find_contacts(rows).pairs;
    std::vector<obbsat::rect_pose> bad = rows;
    bad[17].rotation = {1e-30f, 0.0f};  // a valid pose, but too short a rotation for contacts
    EXPECT_THROW(finder.find_contacts(bad), obbsat::invalid_input);
    const std::vector<obbsat::rect_pose64> doubles(2, obbsat::rect_pose64{{0, 0}, {1, 1}, {1, 0}});
    EXPECT_THROW(finder.find_contacts(doubles), obbsat::invalid_input);
    // The refused calls were no frames: nothing began or ended since the first.
    const obbsat::scene_contacts& again = finder.find_contacts(rows);
    EXPECT_EQ(again.pairs.size(), first.size());
    EXPECT_TRUE(finder.began().empty());
    EXPECT_TRUE(finder.ended().empty());

    obbsat::pair_finder moved = std::move(finder);
    EXPECT_THROW(finder.find_contacts(rows), obbsat::invalid_input);  // NOLINT(bugprone-use-after-move)
    expect_frame(moved.find_contacts(rows), first, rows, rows);
}

}  // namespace
