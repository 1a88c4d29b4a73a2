// The scene queries (obbsat/find_pairs.hpp) on double rows: rect_pose64 and
// rect64 rows and their stores, at UTM-like coordinates (3e5 .. 6e6 metres)
// with millimetre gaps and exact touching. For method exact the answer is
// the double oracle's over all N(N-1)/2 pairs; for conservative and local,
// the pairs whose outward float bounds (obbsat/ref/bounds64.hpp) overlap and
// that the double reference calls colliding. Also: the outward bounds contain
// every corner, a pair_finder over moving frames answers as fresh queries,
// cross queries, the errors, and a scene whose float32 rounding flips
// verdicts that the double query gets right. The double-corner candidates
// are decided on every backend this CPU runs.
#include <obbsat/backend.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/bounds64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect64;
using obbsat::rect_pose64;

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

bool before(const pair_index& p, const pair_index& q) { return p.a < q.a || (p.a == q.a && p.b < q.b); }

/// A UTM-like scene: footprints 5 .. 50 m across near (x0, y0), some at
/// random angles, some axis-aligned or turned by (3, 4) with a partner that
/// touches exactly, or lies a millimetre apart or over; every coordinate a
/// multiple of 1/8 where touching must be exact.
std::vector<rect_pose64> utm_scene(std::size_t n, std::uint64_t seed, double span) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double x0 = 300000.0 + std::floor(unit(rng) * 2.7e6) + 0.125;
    const double y0 = 3000000.0 + std::floor(unit(rng) * 2.9e6) + 0.375;
    const auto eighths = [&](double lo, double hi) { return std::round((lo + unit(rng) * (hi - lo)) * 8.0) / 8.0; };
    std::vector<rect_pose64> boxes;
    while (boxes.size() < n) {
        const double cx = x0 + eighths(0, span);
        const double cy = y0 + eighths(0, span);
        const double hx = eighths(2.5, 25);
        const double hy = eighths(2.5, 25);
        const int shape = static_cast<int>(unit(rng) * 4);
        if (shape == 0) {
            const double angle = unit(rng) * 6.283185307179586;
            boxes.push_back({{cx, cy}, {hx, hy}, {std::cos(angle), std::sin(angle)}});
            continue;
        }
        // A partner along the box's own x axis: exactly touching, or a millimetre apart or over.
        const bool turned = shape == 1;
        const double c = turned ? 0.6 : 1.0, s = turned ? 0.8 : 0.0;
        const double scale = turned ? 5.0 : 1.0;  // (3, 4) has length 5: half extents in units of it
        const double ax = hx / scale, bx = eighths(2.5, 25) / scale, ay = hy / scale;
        const double gap = shape == 3 ? (unit(rng) < 0.5 ? 0.001 : -0.001) : 0.0;
        const double along = (ax + bx) * scale + gap;
        const rect_pose64 first{{cx, cy}, {ax, ay}, {turned ? 3.0 : 1.0, turned ? 4.0 : 0.0}};
        const rect_pose64 second{{cx + along * c, cy + along * s}, {bx, ay}, first.rotation};
        boxes.push_back(first);
        if (boxes.size() < n) {
            boxes.push_back(second);
        }
    }
    return boxes;
}

rect64 corners_of(const rect_pose64& p) {
    const double ux = p.half_extents.x * p.rotation.x, uy = p.half_extents.x * p.rotation.y;
    const double vx = -(p.half_extents.y * p.rotation.y), vy = p.half_extents.y * p.rotation.x;
    const double cx = p.center.x, cy = p.center.y;
    return rect64{{(cx - ux) + vx, (cy - uy) + vy}, {(cx + ux) + vx, (cy + uy) + vy},
                  {(cx + ux) - vx, (cy + uy) - vy}, {(cx - ux) - vx, (cy - uy) - vy}};
}

std::vector<rect64> corners_of(const std::vector<rect_pose64>& poses) {
    std::vector<rect64> out;
    for (const rect_pose64& p : poses) {
        out.push_back(corners_of(p));
    }
    return out;
}

bool decide(method m, const rect_pose64& a, const rect_pose64& b) {
    switch (m) {
        case method::exact: return obbsat::oracle::intersects(a, b);
        case method::conservative: return obbsat::ref::conservative(a, b);
        default: return obbsat::ref::local(a, b);
    }
}

bool decide(method m, const rect64& a, const rect64& b) {
    return m == method::exact ? obbsat::oracle::intersects(a, b) : obbsat::ref::conservative(a, b);
}

/// The answer by brute force: exact over all pairs; other methods over the pairs whose outward bounds overlap.
template <class Box>
std::vector<pair_index> brute_force(method m, const std::vector<Box>& a, const std::vector<Box>* b) {
    std::vector<pair_index> out;
    const std::vector<Box>& other = b != nullptr ? *b : a;
    for (std::uint32_t i = 0; i < a.size(); ++i) {
        for (std::uint32_t j = b != nullptr ? 0 : i + 1; j < other.size(); ++j) {
            const bool near = obbsat::ref::bounds_overlap(obbsat::ref::bounds_of(a[i]), obbsat::ref::bounds_of(other[j]));
            if ((m == method::exact || near) && decide(m, a[i], other[j])) {
                out.push_back({i, j});
            }
        }
    }
    return out;
}

collide_options options_for(method m, unsigned threads) {
    collide_options o;
    o.test = m;
    o.threads = threads;
    return o;
}

TEST(FindPairs64, BoundsContainEveryCornerAndRoundOutward) {
    std::size_t rounded_wrong_way = 0;
    for (const rect_pose64& p : utm_scene(2000, 7, 400)) {
        const obbsat::ref::box_bounds b = obbsat::ref::bounds_of(p);
        const rect64 r = corners_of(p);
        for (const obbsat::point64 q : {r.ul, r.ur, r.lr, r.ll}) {
            // Corners computed in double lie within a few ulps of the exact ones, far inside the float spacing.
            EXPECT_LE(static_cast<double>(b.lo_x), q.x - 1e-6);
            EXPECT_GE(static_cast<double>(b.hi_x), q.x + 1e-6);
            EXPECT_LE(static_cast<double>(b.lo_y), q.y - 1e-6);
            EXPECT_GE(static_cast<double>(b.hi_y), q.y + 1e-6);
        }
        const obbsat::ref::box_bounds c = obbsat::ref::bounds_of(r);
        const double lo = std::min(std::min(r.ul.x, r.ur.x), std::min(r.lr.x, r.ll.x));
        EXPECT_LE(static_cast<double>(c.lo_x), lo);
        rounded_wrong_way += static_cast<double>(static_cast<float>(lo)) > lo;
    }
    EXPECT_GT(rounded_wrong_way, 0u) << "the scene should hold bounds that a plain conversion rounds inward";
    EXPECT_EQ(obbsat::ref::float_at_most(1e300), std::numeric_limits<float>::max());
    EXPECT_EQ(obbsat::ref::float_at_least(-1e300), -std::numeric_limits<float>::max());
    EXPECT_EQ(obbsat::ref::float_at_least(std::numeric_limits<double>::infinity()), std::numeric_limits<float>::infinity());
    EXPECT_EQ(obbsat::ref::float_at_most(0.1), std::nextafter(0.1f, 0.0f));  // 0.1f lies above 0.1
    EXPECT_EQ(obbsat::ref::float_at_least(0.1), 0.1f);
}

TEST(FindPairs64, EveryMethodEqualsBruteForceOnPosesAndCorners) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        const std::vector<rect_pose64> poses = utm_scene(500, seed, 300);
        const std::vector<rect64> rects = corners_of(poses);
        const obbsat::pose_records64 pose_store(poses);
        const obbsat::rect_records64 rect_store(rects);
        for (const method m : {method::exact, method::conservative, method::local}) {
            const std::vector<pair_index> expected = brute_force(m, poses, static_cast<const std::vector<rect_pose64>*>(nullptr));
            if (m == method::exact) {
                ASSERT_GT(expected.size(), 100u);
            }
            for (const unsigned threads : {1u, 2u}) {
                const collide_options o = options_for(m, threads);
                EXPECT_TRUE(same_pairs(obbsat::find_pairs(poses, o), expected)) << obbsat::method_name(m) << " seed " << seed;
                EXPECT_TRUE(same_pairs(obbsat::find_pairs(pose_store, o), expected)) << obbsat::method_name(m);
                std::vector<pair_index> streamed;
                obbsat::find_pairs_each(pose_store, o, [&](const pair_index* p, std::size_t count) {
                    streamed.insert(streamed.end(), p, p + count);
                });
                std::sort(streamed.begin(), streamed.end(), before);
                EXPECT_TRUE(same_pairs(streamed, expected)) << obbsat::method_name(m);
            }
            if (m == method::local) {
                continue;  // no corner reference
            }
            const std::vector<pair_index> on_corners = brute_force(m, rects, static_cast<const std::vector<rect64>*>(nullptr));
            for (const unsigned threads : {1u, 2u}) {
                const collide_options o = options_for(m, threads);
                EXPECT_TRUE(same_pairs(obbsat::find_pairs(rects, o), on_corners)) << obbsat::method_name(m);
                EXPECT_TRUE(same_pairs(obbsat::find_pairs(rect_store, o), on_corners)) << obbsat::method_name(m);
            }
            // The candidates on double corners through every backend's lanes.
            for (const obbsat::backend b : obbsat::compiled_backends()) {
                if (!obbsat::cpu_supports(b)) {
                    continue;
                }
                collide_options o = options_for(m, 1);
                o.use = b;
                EXPECT_TRUE(same_pairs(obbsat::find_pairs(rect_store, o), on_corners))
                    << obbsat::method_name(m) << " on " << obbsat::backend_name(b);
            }
        }
    }
}

TEST(FindPairs64, TwoThreadsOnALargeSceneAnswerAsOne) {
    // Large enough for two parts (16384 boxes a part); brute force is out of reach here, so
    // the 1-thread answer, checked against the oracle pair by pair, is the reference.
    const std::vector<rect_pose64> poses = utm_scene(40000, 11, 4000);
    const std::vector<pair_index> one = obbsat::find_pairs(poses, options_for(method::exact, 1));
    const std::vector<pair_index> two = obbsat::find_pairs(poses, options_for(method::exact, 2));
    EXPECT_TRUE(same_pairs(one, two));
    ASSERT_GT(one.size(), 1000u);
    for (const pair_index& p : one) {
        ASSERT_TRUE(obbsat::oracle::intersects(poses[p.a], poses[p.b]));
    }
}

TEST(FindPairs64, CrossQueriesEqualBruteForce) {
    const std::vector<rect_pose64> all = utm_scene(600, 5, 300);
    const std::vector<rect_pose64> a(all.begin(), all.begin() + 250);
    const std::vector<rect_pose64> b(all.begin() + 250, all.end());
    for (const method m : {method::exact, method::conservative, method::local}) {
        EXPECT_TRUE(same_pairs(obbsat::find_pairs(a, b, options_for(m, 1)), brute_force(m, a, &b))) << obbsat::method_name(m);
    }
    const std::vector<rect64> ra = corners_of(a), rb = corners_of(b);
    EXPECT_TRUE(same_pairs(obbsat::find_pairs(ra, rb, options_for(method::exact, 2)), brute_force(method::exact, ra, &rb)));
    EXPECT_TRUE(obbsat::find_pairs(a, std::vector<rect_pose64>{}, options_for(method::exact, 1)).empty());
}

TEST(FindPairs64, PairFinderOverMovingFramesAnswersAsFreshQueries) {
    std::vector<rect_pose64> poses = utm_scene(3000, 9, 900);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> step(-0.01, 0.01);
    for (const method m : {method::exact, method::conservative, method::local}) {
        obbsat::pair_finder finder(options_for(m, 2));
        finder.track_events(true);
        std::vector<pair_index> last;
        std::size_t reused = 0;
        for (int frame = 0; frame < 12; ++frame) {
            for (rect_pose64& p : poses) {
                p.center.x += step(rng);
                p.center.y += step(rng);
            }
            const std::vector<pair_index> fresh = obbsat::find_pairs(poses, options_for(m, 1));
            ASSERT_TRUE(same_pairs(finder.find(poses), fresh)) << obbsat::method_name(m) << " frame " << frame;
            reused += finder.stats().reused_candidates;
            std::vector<pair_index> began;
            std::set_difference(fresh.begin(), fresh.end(), last.begin(), last.end(), std::back_inserter(began), before);
            EXPECT_TRUE(same_pairs(finder.began(), began));
            last = fresh;
        }
        EXPECT_GT(reused, 0u) << "kept candidates should serve calls of small motion";
    }
}

TEST(FindPairs64, Float32RoundingFlipsVerdictsTheDoubleQueryKeeps) {
    const std::vector<rect_pose64> poses = utm_scene(1500, 21, 500);
    std::vector<obbsat::rect_pose> rounded;
    for (const rect_pose64& p : poses) {
        rounded.push_back({{static_cast<float>(p.center.x), static_cast<float>(p.center.y)},
                           {static_cast<float>(p.half_extents.x), static_cast<float>(p.half_extents.y)},
                           {static_cast<float>(p.rotation.x), static_cast<float>(p.rotation.y)}});
    }
    const collide_options o = options_for(method::exact, 1);
    const std::vector<pair_index> truth = brute_force(method::exact, poses, static_cast<const std::vector<rect_pose64>*>(nullptr));
    const std::vector<pair_index> in_float = obbsat::find_pairs(rounded, o);
    std::vector<pair_index> flipped;
    std::set_symmetric_difference(truth.begin(), truth.end(), in_float.begin(), in_float.end(),
                                  std::back_inserter(flipped), before);
    EXPECT_GT(flipped.size(), 10u) << "float32 rounding should change some verdicts of this scene";
    EXPECT_TRUE(same_pairs(obbsat::find_pairs(poses, o), truth));
}

TEST(FindPairs64, Errors) {
    std::vector<rect_pose64> poses = utm_scene(10, 1, 50);
    const collide_options exact = options_for(method::exact, 1);
    // Another method than the double ones.
    EXPECT_THROW(obbsat::find_pairs(poses, options_for(method::sat4, 1)), obbsat::invalid_input);
    EXPECT_THROW(obbsat::find_pairs(corners_of(poses), options_for(method::local, 1)), obbsat::invalid_input);
    // Mixed precision or kind across two sets.
    const std::vector<obbsat::rect_pose> floats(3, obbsat::rect_pose{{0, 0}, {1, 1}, {1, 0}});
    try {
        obbsat::find_pairs(poses, floats, exact);
        ADD_FAILURE() << "mixed precision was taken";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("double poses"), std::string::npos) << e.what();
    }
    EXPECT_THROW(obbsat::find_pairs(poses, corners_of(poses), exact), obbsat::invalid_input);
    // Bad rows, named, whatever the count.
    const auto message = [&](const obbsat::box_view& a, const obbsat::box_view* b) {
        try {
            if (b != nullptr) {
                obbsat::find_pairs(a, *b, exact);
            } else {
                obbsat::find_pairs(a, exact);
            }
        } catch (const obbsat::invalid_input& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    poses[7].half_extents.y = -1;
    EXPECT_NE(message(poses, nullptr).find("pose 7"), std::string::npos) << message(poses, nullptr);
    EXPECT_NE(message(poses, nullptr).find("hy"), std::string::npos) << message(poses, nullptr);
    poses[7].half_extents.y = 1;
    poses[4].rotation = {0, 0};
    EXPECT_NE(message(poses, nullptr).find("pose 4"), std::string::npos);
    poses[4].rotation = {1, 0};
    poses[9].center.x = std::numeric_limits<double>::quiet_NaN();
    const obbsat::box_view empty(static_cast<const rect_pose64*>(nullptr), 0);
    const obbsat::box_view with_nan(poses);
    EXPECT_NE(message(with_nan, &empty).find("a: pose 9"), std::string::npos) << message(with_nan, &empty);
    const std::vector<rect_pose64> one(poses.begin() + 9, poses.begin() + 10);
    EXPECT_NE(message(one, nullptr).find("pose 0"), std::string::npos);
    std::vector<rect64> rects = corners_of(utm_scene(10, 2, 50));
    rects[3].lr.y = std::numeric_limits<double>::infinity();
    EXPECT_NE(message(rects, nullptr).find("rectangle 3"), std::string::npos) << message(rects, nullptr);
    // The view says what it holds.
    EXPECT_EQ(obbsat::box_view(poses).precision(), obbsat::precision::float64);
    EXPECT_EQ(obbsat::box_view(floats).precision(), obbsat::precision::float32);
    EXPECT_EQ(obbsat::box_view(poses).floats(), nullptr);
    EXPECT_EQ(obbsat::box_view(poses).doubles(), &poses[0].center.x);
}

}  // namespace

namespace {

TEST(FindPairs64, OutwardRoundingStepsAsNextafter) {
    // float_step against std::nextafter on values around every kind of float: zero, subnormal, normal, the largest, infinite.
    const float inf = std::numeric_limits<float>::infinity();
    for (const float f : {0.0f, -0.0f, 1e-45f, -1e-45f, 1e-38f, 1.0f, -1.0f, 5712345.5f, -3e5f,
                          std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), inf, -inf}) {
        if (f != inf) {
            EXPECT_EQ(obbsat::ref::float_step(f, true), std::nextafter(f, inf)) << f;
        }
        if (f != -inf) {
            EXPECT_EQ(obbsat::ref::float_step(f, false), std::nextafter(f, -inf)) << f;
        }
    }
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coordinate(-6e6, 6e6);
    for (int i = 0; i < 100000; ++i) {
        const double d = coordinate(rng);
        const float lo = obbsat::ref::float_at_most(d), hi = obbsat::ref::float_at_least(d);
        ASSERT_LE(static_cast<double>(lo), d);
        ASSERT_GE(static_cast<double>(hi), d);
        ASSERT_LE(hi, std::nextafter(lo, inf));  // the tightest: at most one float apart
    }
}

}  // namespace

namespace {

TEST(FindPairs64, PairFinderAcrossTwoSetsAndBetweenPrecisions) {
    std::vector<rect_pose64> poses = utm_scene(2000, 13, 700);
    const collide_options o = options_for(method::exact, 1);
    obbsat::pair_finder finder(o);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> step(-0.01, 0.01);
    for (int frame = 0; frame < 8; ++frame) {
        for (rect_pose64& p : poses) {
            p.center.x += step(rng);
        }
        const std::vector<rect_pose64> a(poses.begin(), poses.begin() + 800), b(poses.begin() + 800, poses.end());
        ASSERT_TRUE(same_pairs(finder.find(a, b), obbsat::find_pairs(a, b, o))) << "frame " << frame;
    }
    // The same number of rows in float and then in double: the kept candidates of the float
    // calls serve the double ones only through their bounds, and the double rows are read anew.
    obbsat::pair_finder switching(o);
    std::vector<obbsat::rect64> corners = corners_of(poses);
    for (int frame = 0; frame < 8; ++frame) {
        for (obbsat::rect64& r : corners) {
            for (obbsat::point64* q : {&r.ul, &r.ur, &r.lr, &r.ll}) {
                q->y += 0.002;
            }
        }
        if (frame % 3 == 0) {
            std::vector<obbsat::rect> rounded;
            for (const obbsat::rect64& r : corners) {
                const auto f = [](obbsat::point64 q) { return obbsat::point{static_cast<float>(q.x), static_cast<float>(q.y)}; };
                rounded.push_back({f(r.ul), f(r.ur), f(r.lr), f(r.ll)});
            }
            ASSERT_TRUE(same_pairs(switching.find(rounded), obbsat::find_pairs(rounded, o))) << "frame " << frame;
        } else {
            ASSERT_TRUE(same_pairs(switching.find(corners), obbsat::find_pairs(corners, o))) << "frame " << frame;
        }
    }
}

}  // namespace

TEST(FindPairs64, PairFiltersDropTheirPairsFromTheDoubleQuery) {
    // A double query with pair filters: its records and filters are copied
    // into the query's order together, and the sweep drops what the filters
    // refuse; the answer is the brute force's pairs that the filters pass.
    const std::vector<rect_pose64> poses = utm_scene(900, 17, 900);
    std::vector<std::int32_t> groups(poses.size());
    std::vector<std::uint64_t> categories(poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        groups[i] = static_cast<std::int32_t>(i % 7);
        categories[i] = std::uint64_t{1} << (i % 3);
    }
    std::vector<std::uint64_t> masks(poses.size(), ~std::uint64_t{4});
    obbsat::pair_filters filters;
    filters.groups = groups.data();
    filters.categories = categories.data();
    filters.masks = masks.data();
    const auto pass = [&](std::uint32_t i, std::uint32_t j) {
        return (categories[i] & masks[j]) != 0 && (categories[j] & masks[i]) != 0 &&
               !(groups[i] == groups[j] && groups[i] != 0);
    };
    std::vector<pair_index> want;
    for (const pair_index& p : brute_force<rect_pose64>(method::exact, poses, nullptr)) {
        if (pass(p.a, p.b)) {
            want.push_back(p);
        }
    }
    ASSERT_GT(want.size(), 50u);
    for (const unsigned threads : {1u, 2u}) {
        const std::vector<pair_index> got =
            obbsat::find_pairs(obbsat::box_view(poses).with_filters(filters), options_for(method::exact, threads));
        EXPECT_TRUE(same_pairs(got, want)) << threads << " threads";
    }
}

namespace {

/// The message of the invalid_input find_pairs throws on `rows`, or "" when it takes them.
template <class Rows>
std::string refusal_of_rows(const Rows& rows, unsigned threads) {
    try {
        obbsat::find_pairs(rows, options_for(method::exact, threads));
    } catch (const obbsat::invalid_input& e) {
        return e.what();
    }
    return "";
}

TEST(FindPairs64, EveryBadFieldIsRefusedAtItsRowWhereverTheRowFalls) {
    // Unchecked rows are checked a run of rows at a time: a bad value in any
    // field, in the first, last or any row of a run or of a thread's share,
    // is refused with its row; values at the edge of valid (a negative zero
    // half extent, a subnormal rotation) are taken.
    const std::vector<rect_pose64> poses = utm_scene(3000, 11, 900);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const unsigned threads : {1u, 2u}) {
        for (const std::size_t row : {std::size_t{0}, std::size_t{255}, std::size_t{256}, std::size_t{2999}}) {
            const std::string name = "pose " + std::to_string(row) + ":";
            for (int field = 0; field < 6; ++field) {
                for (const double bad : {nan, inf, -inf}) {
                    std::vector<rect_pose64> rows = poses;
                    (&rows[row].center.x)[field] = bad;
                    EXPECT_NE(refusal_of_rows(rows, threads).find(name), std::string::npos)
                        << "field " << field << " value " << bad << " threads " << threads;
                }
            }
            for (const double below : {-1.0, -0x1p-1074}) {
                std::vector<rect_pose64> rows = poses;
                rows[row].half_extents.y = below;
                EXPECT_NE(refusal_of_rows(rows, threads).find(name), std::string::npos) << below;
            }
            for (const obbsat::point64 zero : {obbsat::point64{0.0, 0.0}, obbsat::point64{-0.0, 0.0},
                                               obbsat::point64{0.0, -0.0}}) {
                std::vector<rect_pose64> rows = poses;
                rows[row].rotation = zero;
                EXPECT_NE(refusal_of_rows(rows, threads).find(name), std::string::npos);
            }
            std::vector<rect_pose64> edge = poses;
            edge[row].half_extents.x = -0.0;
            edge[row].rotation = {0x1p-1074, -0.0};
            EXPECT_EQ(refusal_of_rows(edge, threads), "");
            std::vector<rect64> rects = corners_of(poses);
            for (int field = 0; field < 8; ++field) {
                std::vector<rect64> rows = rects;
                (&rows[row].ul.x)[field] = field % 2 == 0 ? nan : -inf;
                EXPECT_NE(refusal_of_rows(rows, threads).find("rectangle " + std::to_string(row)), std::string::npos)
                    << "field " << field;
            }
        }
    }
}

}  // namespace
