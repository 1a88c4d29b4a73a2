// What the tests of find_contacts and pair_finder::find_contacts (and their
// double calls) share: the options they run with, the scenes they run on,
// the answer of every pair decided alone, and the comparison of answers.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace contact_scenes {

/// Method exact on `use` with `threads`.
inline obbsat::collide_options exact_on(obbsat::backend use, unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.use = use;
    options.threads = threads;
    return options;
}

/// A seeded scene of `boxes` poses of mixed sizes, about two pairs a box.
inline std::vector<obbsat::rect_pose> scene_of(std::size_t boxes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.seed = seed;
    spec.boxes = boxes;
    spec.sizes = obbsat::scene_sizes::mixed;
    return obbsat::make_pose_scene(spec);
}

/// UTM-like coordinates: a float32 there steps by 0.03125 in x and 0.5 in y.
constexpr double far_x = 500000.125;
constexpr double far_y = 5712345.5;

/// A seeded scene of `boxes` double poses of mixed sizes (scene_of's),
/// moved by (dx, dy), each center nudged by a fraction of a float step so
/// that its doubles are not floats.
inline std::vector<obbsat::rect_pose64> double_scene_of(std::size_t boxes, std::uint64_t seed, double dx,
                                                        double dy) {
    std::vector<obbsat::rect_pose64> rows;
    for (const obbsat::rect_pose& p : scene_of(boxes, seed)) {
        const double nudge = 1e-3 * std::sin(static_cast<double>(rows.size()));
        rows.push_back({{dx + p.center.x + nudge, dy + p.center.y - nudge},
                        {p.half_extents.x, p.half_extents.y},
                        {p.rotation.x, p.rotation.y}});
    }
    return rows;
}

/// The ids of the plank and of the box on it in plank_frame.
constexpr std::uint64_t plank_id = 100;
constexpr std::uint64_t box_id = 200;

/// Frame `f` of a box resting on a long plank centered at (x0, y0), sliding
/// along it frame by frame, while other boxes come and go around them: the
/// same two corners of the box touch the plank's top face throughout. Rows
/// of `Pose` (rect_pose or rect_pose64) with their ids; frame f has f % 3
/// boxes far away before the pair, and a new one after it.
template <class Pose>
void plank_frame(int f, double x0, double y0, std::vector<Pose>& rows, std::vector<std::uint64_t>& ids) {
    using real = decltype(Pose{}.center.x);
    const auto pose = [&](double cx, double cy, double hx, double hy) {
        return Pose{{static_cast<real>(x0 + cx), static_cast<real>(y0 + cy)},
                    {static_cast<real>(hx), static_cast<real>(hy)},
                    {1, 0}};
    };
    rows.clear();
    ids.clear();
    for (int k = 0; k < f % 3; ++k) {
        rows.push_back(pose(50.0 + 3.0 * k, 50.0, 1, 1));
        ids.push_back(static_cast<std::uint64_t>(1000 + k));
    }
    rows.push_back(pose(0, 0, 8, 0.5));
    ids.push_back(plank_id);
    rows.push_back(pose(-3.0 + 0.5 * f, 0.95, 0.5, 0.5));
    ids.push_back(box_id);
    rows.push_back(pose(-50.0, -50.0 - f, 1, 1));
    ids.push_back(static_cast<std::uint64_t>(2000 + f));
}

/// Checks that `got`, a frame of plank_frame rows `ids`, holds the contact
/// of the plank and the box with two points, whose feature keys are those of
/// `last` unless it is empty (the first frame); then keeps them in `last`.
template <class Answer>
void expect_plank_keys_kept(const Answer& got, const std::vector<std::uint64_t>& ids, int f,
                            std::vector<obbsat::contact_feature>& last) {
    const typename decltype(Answer::contacts)::value_type* c = nullptr;
    for (std::size_t k = 0; k < got.pairs.size(); ++k) {
        if (ids[got.pairs[k].a] == plank_id && ids[got.pairs[k].b] == box_id) {
            c = &got.contacts[k];
        }
    }
    ASSERT_NE(c, nullptr) << "frame " << f;
    ASSERT_EQ(c->point_count, 2u) << "frame " << f;
    const std::vector<obbsat::contact_feature> keys = {c->points[0].feature, c->points[1].feature};
    if (!last.empty()) {
        for (std::size_t p = 0; p < 2; ++p) {
            EXPECT_EQ(std::memcmp(&keys[p], &last[p], sizeof keys[p]), 0) << "frame " << f << ", point " << p;
        }
    }
    last = keys;
}

/// Every pair i < j of `count` boxes.
inline std::vector<obbsat::pair_index> all_pairs(std::size_t count) {
    std::vector<obbsat::pair_index> pairs;
    for (std::uint32_t i = 0; i < count; ++i) {
        for (std::uint32_t j = i + 1; j < count; ++j) {
            pairs.push_back({i, j});
        }
    }
    return pairs;
}

/// What find_contacts must give on `store` (a float or a double store), from
/// every pair decided alone on the scalar backend: those exact calls
/// colliding and, with margin > 0, those whose contact has points. `Answer`
/// is scene_contacts (Options contact_options) or scene_contacts64
/// (contact_options64).
template <class Answer, class Options, class Store>
Answer contacts_decided_alone(const Store& store, decltype(Options::margin) margin) {
    const std::vector<obbsat::pair_index> pairs = all_pairs(store.size());
    const std::vector<std::uint8_t> verdicts =
        obbsat::collide_pairs(store, pairs, exact_on(obbsat::backend::scalar, 1));
    Options options;
    options.margin = margin;
    options.use = obbsat::backend::scalar;
    const auto contacts = obbsat::contact_pairs(store, pairs, options);
    Answer expected;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (verdicts[k] || (margin > 0 && contacts[k].point_count > 0)) {
            expected.pairs.push_back(pairs[k]);
            expected.contacts.push_back(contacts[k]);
        }
    }
    return expected;
}

/// Checks that `found` holds the pairs of `expected` in order, each contact
/// bit for bit (scene_contacts or scene_contacts64).
template <class Answer>
void expect_same(const Answer& found, const Answer& expected) {
    ASSERT_EQ(found.pairs.size(), expected.pairs.size());
    ASSERT_EQ(found.contacts.size(), expected.contacts.size());
    for (std::size_t k = 0; k < found.pairs.size(); ++k) {
        ASSERT_EQ(found.pairs[k].a, expected.pairs[k].a) << "row " << k;
        ASSERT_EQ(found.pairs[k].b, expected.pairs[k].b) << "row " << k;
        EXPECT_EQ(std::memcmp(&found.contacts[k], &expected.contacts[k], sizeof found.contacts[k]), 0)
            << "pair " << found.pairs[k].a << "," << found.pairs[k].b;
    }
}

}  // namespace contact_scenes
