// pair_finder::find_contacts64 over frames of double rows far from the
// origin: every frame's pairs are find's and its contacts contact_pairs'
// over the double store, bit for bit, whether the frame was a full query or
// answered from kept candidates, with ids (rows that come, go and change
// places) or without, within one set or across two, on every backend and
// thread count; a persisting contact keeps its feature keys from one frame
// to the next; refusals change nothing.
#include <obbsat/collide.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/ref/contact.hpp>

#include "scene/contact_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::contact64;
using obbsat::pair_index;
using obbsat::rect_pose64;
using contact_scenes::exact_on;

// At UTM-like coordinates (far_x, far_y) a float32 steps by 0.03125 in x
// and 0.5 in y, so the float bounds of the broadphase are that coarse and a
// finder's kept candidates rarely serve a frame (a box whose bounds cross a
// step leaves its widened bounds); near_x and near_y keep the bounds fine.
using contact_scenes::far_x;
using contact_scenes::far_y;
constexpr double near_x = 1000.25;
constexpr double near_y = -2000.5;

/// A seeded double scene moved by (dx, dy), by default to UTM-like coordinates.
std::vector<rect_pose64> far_scene(std::size_t boxes, std::uint64_t seed, double dx = far_x, double dy = far_y) {
    return contact_scenes::double_scene_of(boxes, seed, dx, dy);
}

/// Frame `f` of a scene whose boxes drift and turn a little each frame, in
/// double: each box as its id says (keys[i]; its row i without keys).
std::vector<rect_pose64> frame_of(const std::vector<rect_pose64>& start, int f,
                                  const std::vector<std::uint64_t>* keys = nullptr) {
    std::vector<rect_pose64> rows = start;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const double key = static_cast<double>(keys == nullptr ? i : (*keys)[i]);
        const double phase = 0.37 * key + 0.2 * f;
        rows[i].center.x += 0.004 * f * std::cos(phase);
        rows[i].center.y += 0.004 * f * std::sin(phase);
        const double turn = 0.002 * f * std::sin(0.11 * key);
        const double c = rows[i].rotation.x, s = rows[i].rotation.y;
        rows[i].rotation = {c * std::cos(turn) - s * std::sin(turn), s * std::cos(turn) + c * std::sin(turn)};
    }
    return rows;
}

/// The frame's pairs must be `pairs` and each contact contact_pairs' on the
/// scalar backend over the double rows `a` and `b` (a within one set).
void expect_frame(const obbsat::scene_contacts64& got, const std::vector<pair_index>& pairs,
                  const std::vector<rect_pose64>& a, const std::vector<rect_pose64>& b) {
    ASSERT_EQ(got.pairs.size(), pairs.size());
    ASSERT_EQ(got.contacts.size(), pairs.size());
    std::vector<contact64> within;
    if (&a == &b) {
        obbsat::contact_options64 scalar;
        scalar.use = obbsat::backend::scalar;
        within = obbsat::contact_pairs(obbsat::pose_records64(a), pairs, scalar);
    }
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        ASSERT_EQ(got.pairs[k].a, pairs[k].a) << "row " << k;
        ASSERT_EQ(got.pairs[k].b, pairs[k].b) << "row " << k;
        // Across two sets, the double reference contact_pairs computes (obbsat/ref/contact.hpp).
        const contact64 want = &a == &b ? within[k] : obbsat::ref::contact_of(a[pairs[k].a], b[pairs[k].b]);
        EXPECT_EQ(std::memcmp(&got.contacts[k], &want, sizeof(contact64)), 0)
            << "pair " << pairs[k].a << "," << pairs[k].b;
    }
}

TEST(PairFinderContacts64, EveryFrameIsContactPairsOverFindsPairs) {
  for (const bool far : {false, true}) {
    const std::vector<rect_pose64> start = far ? far_scene(30000, 31) : far_scene(30000, 31, near_x, near_y);
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 2u, 3u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + std::to_string(threads) + " threads" +
                         (far ? ", far" : ", near"));
            obbsat::pair_finder finder(exact_on(use, threads));
            bool reused = false;
            for (int f = 0; f < 6; ++f) {
                const std::vector<rect_pose64> rows = frame_of(start, f);
                const obbsat::pose_records64 store(rows);
                const obbsat::scene_contacts64& got =
                    finder.find_contacts64(f % 2 == 0 ? obbsat::box_view(store) : obbsat::box_view(rows));
                reused = reused || finder.stats().reused_candidates;
                expect_frame(got, obbsat::find_pairs(rows, exact_on(obbsat::backend::scalar, 1)), rows, rows);
            }
            EXPECT_TRUE(far || reused) << "no frame was answered from kept candidates";
        }
    }
  }
}

TEST(PairFinderContacts64, FramesWithIdsWhoseRowsComeGoAndMove) {
    // Every box drifts a little each frame; every other frame from the third
    // on, a few boxes are swap-removed, a few erased, a few appended and two
    // rows swapped, the ids following the boxes. Every frame is checked
    // against a fresh query on its rows. (On double rows a frame whose rows
    // changed is a full query, kernel/scene/kept_pairs.cpp; the frames of
    // drift alone are answered from the kept candidates.)
    for (const unsigned threads : {1u, 2u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        std::vector<rect_pose64> rows = far_scene(5000, 34, near_x, near_y);
        std::vector<std::uint64_t> ids(rows.size());
        for (std::size_t i = 0; i < ids.size(); ++i) {
            ids[i] = 7 * i + 3;
        }
        std::mt19937_64 random(35);
        std::uniform_real_distribution<double> step(-0.002, 0.002);
        obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, threads));
        std::size_t reused = 0;
        for (int f = 0; f < 16; ++f) {
            for (rect_pose64& p : rows) {
                p.center.x += step(random);
                p.center.y += step(random);
            }
            if (f > 1 && f % 2 == 0) {
                for (int c = 0; c < 10; ++c) {
                    const std::size_t gone = random() % rows.size();
                    rows[gone] = rows.back();
                    ids[gone] = ids.back();
                    rows.pop_back();
                    ids.pop_back();
                    const std::size_t erased = random() % rows.size();
                    rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(erased));
                    ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(erased));
                }
                for (int c = 0; c < 20; ++c) {
                    rect_pose64 added = rows[random() % rows.size()];
                    added.center.x += 0.3;
                    rows.push_back(added);
                    ids.push_back(1000000 + 100 * static_cast<std::uint64_t>(f) + static_cast<std::uint64_t>(c));
                }
                const std::size_t x = random() % rows.size(), y = random() % rows.size();
                std::swap(rows[x], rows[y]);
                std::swap(ids[x], ids[y]);
            }
            const obbsat::scene_contacts64& got = finder.find_contacts64(obbsat::box_view(rows).with_ids(ids));
            reused += finder.stats().reused_candidates ? 1u : 0u;
            expect_frame(got, obbsat::find_pairs(rows, exact_on(obbsat::backend::scalar, 1)), rows, rows);
        }
        EXPECT_GE(reused, 4u) << "frames answered from kept candidates";
    }
}

TEST(PairFinderContacts64, AcrossTwoSetsTheRowsOfEach) {
    const std::vector<rect_pose64> all = far_scene(20000, 32);
    const std::vector<rect_pose64> a(all.begin(), all.begin() + 7000);
    const std::vector<rect_pose64> b(all.begin() + 7000, all.end());
    obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, 2));
    for (int f = 0; f < 3; ++f) {
        const std::vector<rect_pose64> fa = frame_of(a, f), fb = frame_of(b, f);
        const obbsat::pose_records64 store_b(fb);
        const obbsat::scene_contacts64& got =
            f == 1 ? finder.find_contacts64(fa, store_b) : finder.find_contacts64(fa, fb);
        ASSERT_FALSE(got.pairs.empty());
        expect_frame(got, obbsat::find_pairs(fa, fb, exact_on(obbsat::backend::scalar, 1)), fa, fb);
    }
}

TEST(PairFinderContacts64, APersistingContactKeepsItsFeatureKeys) {
    // A box resting on a long plank far from the origin slides along it,
    // frame by frame, while other boxes come and go around them (rows follow
    // ids): the same two corners of the box touch the plank's top face
    // throughout, so both points keep their feature keys.
    obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, 1));
    std::vector<obbsat::contact_feature> last;
    for (int f = 0; f < 12; ++f) {
        std::vector<rect_pose64> rows;
        std::vector<std::uint64_t> ids;
        contact_scenes::plank_frame(f, far_x, far_y, rows, ids);
        const obbsat::scene_contacts64& got = finder.find_contacts64(obbsat::box_view(rows).with_ids(ids));
        expect_frame(got, obbsat::find_pairs(rows, exact_on(obbsat::backend::scalar, 1)), rows, rows);
        contact_scenes::expect_plank_keys_kept(got, ids, f, last);
    }
}

TEST(PairFinderContacts64, RefusalsChangeNothing) {
    const std::vector<rect_pose64> rows = far_scene(3000, 33);
    obbsat::pair_finder finder(exact_on(obbsat::backend::automatic, 1));
    finder.track_events(true);
    const std::vector<pair_index> first = finder.find_contacts64(rows).pairs;
    ASSERT_FALSE(first.empty());
    std::vector<rect_pose64> bad = rows;
    bad[17].rotation = {1e-200, 0.0};  // a valid pose, but too short a rotation for contacts
    EXPECT_THROW(finder.find_contacts64(bad), obbsat::invalid_input);
    bad = rows;
    bad[18].center.x = std::nan("");
    try {
        finder.find_contacts64(bad);
        FAIL() << "a NaN center was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pose 18"), std::string::npos) << e.what();
    }
    const std::vector<obbsat::rect_pose> floats(2, obbsat::rect_pose{{0, 0}, {1, 1}, {1, 0}});
    EXPECT_THROW(finder.find_contacts64(floats), obbsat::invalid_input);
    EXPECT_THROW(finder.find_contacts(rows), obbsat::invalid_input);
    // The refused calls were no frames: nothing began or ended since the first.
    const obbsat::scene_contacts64& again = finder.find_contacts64(rows);
    expect_frame(again, first, rows, rows);
    EXPECT_TRUE(finder.began().empty());
    EXPECT_TRUE(finder.ended().empty());

    obbsat::pair_finder moved = std::move(finder);
    EXPECT_THROW(finder.find_contacts64(rows), obbsat::invalid_input);  // NOLINT(bugprone-use-after-move)
    expect_frame(moved.find_contacts64(rows), first, rows, rows);
}

}  // namespace
