// The pose oracle against an independent construction in GMP rationals: the
// four true corners of each pose, C ± hx·(c, s) ± hy·(−s, c), computed
// exactly, and the two quads they bound compared by rational_model.hpp
// (segment intersection, ray-crossing containment, the area of the clipped
// intersection): no axis and no slack anywhere. Pose pairs of several makes:
// on a small lattice (exact contacts), a corner placed on the other's outline
// then rounded to float and moved by float steps (near contacts, where the
// double filter cannot decide), the lattice moved far from the origin,
// rotation vectors from 2^-66 to 2^50 in length, and rotations with one
// component 2^20 to 2^60 times smaller than the other (slacks that cancel far
// below double precision); every make has poses with a zero half extent. Any
// difference fails with the pair in hex floats.
#include "rational_model.hpp"

#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace {

using obbsat::point;
using obbsat::rect_pose;
using obbsat::test::rational_point;

std::string show(const rect_pose& p) {
    char text[200];
    std::snprintf(text, sizeof text, "{c %a,%a h %a,%a r %a,%a}", static_cast<double>(p.center.x),
                  static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                  static_cast<double>(p.half_extents.y), static_cast<double>(p.rotation.x),
                  static_cast<double>(p.rotation.y));
    return text;
}

mpq_class exact(float v) { return mpq_class(static_cast<double>(v)); }

// UL, UR, LR, LL of the pose's set, exactly.
obbsat::test::rational_corners true_corners(const rect_pose& p) {
    const mpq_class cx = exact(p.center.x), cy = exact(p.center.y);
    const mpq_class hx = exact(p.half_extents.x), hy = exact(p.half_extents.y);
    const mpq_class c = exact(p.rotation.x), s = exact(p.rotation.y);
    const mpq_class ux = hx * c, uy = hx * s;    // hx·(c, s)
    const mpq_class vx = -hy * s, vy = hy * c;   // hy·(−s, c)
    return {rational_point{cx - ux + vx, cy - uy + vy}, rational_point{cx + ux + vx, cy + uy + vy},
            rational_point{cx + ux - vx, cy + uy - vy}, rational_point{cx - ux - vx, cy - uy - vy}};
}

char model_contact(const rect_pose& a, const rect_pose& b) {
    return obbsat::test::rational_contact(obbsat::test::rational_region_of(true_corners(a)),
                                          obbsat::test::rational_region_of(true_corners(b)));
}

float nudged(float v, int steps) {
    for (; steps > 0; --steps) v = std::nextafter(v, INFINITY);
    for (; steps < 0; ++steps) v = std::nextafter(v, -INFINITY);
    return v;
}

int integer(obbsat::seeded_random& random, int lo, int hi) {
    return lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

// A half extent: zero one time in eight, else uniform in (0, top).
float half_extent(obbsat::seeded_random& random, float top) {
    return random.below(8) == 0 ? 0.0f : random.uniform(0.0f, top);
}

// A rotation vector of integers from -4 to 4, not (0, 0).
point integer_rotation(obbsat::seeded_random& random) {
    point r{0, 0};
    while (r.x == 0 && r.y == 0) {
        r = point{static_cast<float>(integer(random, -4, 4)), static_cast<float>(integer(random, -4, 4))};
    }
    return r;
}

// Small integer rotation, center and half extents (halves allowed), so that
// contacts between two such poses are frequent and exact.
rect_pose lattice_pose(obbsat::seeded_random& random) {
    auto half_integer = [&](int lo, int hi) { return 0.5f * static_cast<float>(integer(random, lo, hi)); };
    const point center{half_integer(-12, 12), half_integer(-12, 12)};
    const point half_extents{half_integer(0, 4), half_integer(0, 4)};
    return rect_pose{center, half_extents, integer_rotation(random)};
}

// A rotation vector of one of four kinds: small integers, a float unit vector
// (cos t, sin t), the same scaled by a random power of two, or two random floats.
point random_rotation(obbsat::seeded_random& random) {
    const float angle = random.uniform(-3.2f, 3.2f);
    switch (random.below(4)) {
        case 0: return integer_rotation(random);
        case 1: return point{std::cos(angle), std::sin(angle)};
        case 2: {
            const int k = integer(random, -66, 50);
            return point{std::ldexp(std::cos(angle), k), std::ldexp(std::sin(angle), k)};
        }
        default: {
            point r{0, 0};
            while (r.x == 0 && r.y == 0) {
                r = point{random.uniform(-3.0f, 3.0f), random.uniform(-3.0f, 3.0f)};
            }
            return r;
        }
    }
}

// A pose of random rotation whose true size is about `size` whatever the
// rotation vector's length.
rect_pose random_pose(obbsat::seeded_random& random, point center, float size) {
    const point r = random_rotation(random);
    const float length = std::sqrt(r.x * r.x + r.y * r.y);
    return rect_pose{center, {half_extent(random, size) / length, half_extent(random, size) / length}, r};
}

// The true corners of a pose in double (rounded), for placing another pose.
void rounded_corners(const rect_pose& p, double x[4], double y[4]) {
    const double ux = static_cast<double>(p.half_extents.x) * p.rotation.x;
    const double uy = static_cast<double>(p.half_extents.x) * p.rotation.y;
    const double vx = -static_cast<double>(p.half_extents.y) * p.rotation.y;
    const double vy = static_cast<double>(p.half_extents.y) * p.rotation.x;
    const double su[4] = {-1, 1, 1, -1}, sv[4] = {1, 1, -1, -1};
    for (int i = 0; i < 4; ++i) {
        x[i] = p.center.x + su[i] * ux + sv[i] * vx;
        y[i] = p.center.y + su[i] * uy + sv[i] * vy;
    }
}

// B placed so that one of its corners lies on A's outline (a corner of A or a
// point of an edge), in double; then rounded to float, and its center moved
// by up to two float steps half of the time. B is turned as A, a quarter turn
// from it, or freely, so that edges lie on edges too.
rect_pose near_contact(obbsat::seeded_random& random, const rect_pose& a, float size) {
    rect_pose b = random_pose(random, point{0, 0}, size);
    switch (random.below(4)) {
        case 0: b.rotation = a.rotation; break;
        case 1: b.rotation = point{-a.rotation.y, a.rotation.x}; break;
        default: break;
    }
    if (b.rotation.x != a.rotation.x || b.rotation.y != a.rotation.y) {
        // Keep B's size near `size` for its new rotation vector.
        const float length = std::sqrt(b.rotation.x * b.rotation.x + b.rotation.y * b.rotation.y);
        b.half_extents = point{half_extent(random, size) / length, half_extent(random, size) / length};
    }
    double ax[4], ay[4], bx[4], by[4];
    rounded_corners(a, ax, ay);
    rounded_corners(b, bx, by);  // B centered at the origin
    const std::size_t edge = random.below(4), corner = random.below(4);
    const double t = random.below(3) == 0 ? 0.0 : static_cast<double>(random.uniform(0.0f, 1.0f));
    const double target_x = ax[edge] + t * (ax[(edge + 1) % 4] - ax[edge]);
    const double target_y = ay[edge] + t * (ay[(edge + 1) % 4] - ay[edge]);
    b.center = point{static_cast<float>(target_x - bx[corner]), static_cast<float>(target_y - by[corner])};
    if (random.below(2) == 0) {
        b.center.x = nudged(b.center.x, integer(random, -2, 2));
        b.center.y = nudged(b.center.y, integer(random, -2, 2));
    }
    return b;
}

// The four-axis test in plain double, as a first attempt would write it: to
// count the pairs where rounding alone gets the class wrong.
char naive_double_contact(const rect_pose& a, const rect_pose& b) {
    const double ca = a.rotation.x, sa = a.rotation.y, cb = b.rotation.x, sb = b.rotation.y;
    const double hxa = a.half_extents.x, hya = a.half_extents.y;
    const double hxb = b.half_extents.x, hyb = b.half_extents.y;
    const double dx = static_cast<double>(b.center.x) - a.center.x;
    const double dy = static_cast<double>(b.center.y) - a.center.y;
    const double na = ca * ca + sa * sa, nb = cb * cb + sb * sb;
    const double p = std::fabs(ca * cb + sa * sb), q = std::fabs(ca * sb - sa * cb);
    const double slacks[4] = {
        hxa * na + hxb * p + hyb * q - std::fabs(dx * ca + dy * sa),
        hya * na + hxb * q + hyb * p - std::fabs(-dx * sa + dy * ca),
        hxb * nb + hxa * p + hya * q - std::fabs(dx * cb + dy * sb),
        hyb * nb + hxa * q + hya * p - std::fabs(-dx * sb + dy * cb),
    };
    bool all_positive = hxa > 0 && hya > 0 && hxb > 0 && hyb > 0;
    for (const double slack : slacks) {
        if (slack < 0) {
            return 'S';
        }
        all_positive = all_positive && slack > 0;
    }
    return all_positive ? 'O' : 'T';
}

// Returns the model's letter; fails the test on a difference.
char expect_agreement(const rect_pose& a, const rect_pose& b) {
    const char model = model_contact(a, b);
    const char oracle = obbsat::oracle::contact_letter(obbsat::oracle::classify(a, b));
    EXPECT_EQ(oracle, model) << "A " << show(a) << "\nB " << show(b);
    if (model == 'T') {
        // Touching pairs always take the exact path; check the unfiltered one too.
        EXPECT_EQ(obbsat::oracle::contact_letter(obbsat::oracle::classify_exact(a, b)), model)
            << "A " << show(a) << "\nB " << show(b);
    }
    return model;
}

// Runs `count` pairs from `make(random)` and prints the classes found and how
// many pairs plain double arithmetic classifies wrongly (key 'D' of the result).
template <class Make>
std::map<char, int> cross_check(const char* name, std::uint64_t seed, int count, Make make) {
    obbsat::seeded_random random(seed);
    std::map<char, int> classes;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const auto [a, b] = make(random);
        const char model = expect_agreement(a, b);
        ++classes[model];
        classes['D'] += naive_double_contact(a, b) != model ? 1 : 0;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ model    ] %-24s %6d pairs  S %6d  T %6d  O %6d  double wrong %5d  %.1f s\n", name, count,
                classes['S'], classes['T'], classes['O'], classes['D'], seconds);
    return classes;
}

struct pose_pair {
    rect_pose a;
    rect_pose b;
};

TEST(pose_cross_check, lattice_pairs) {
    const auto classes = cross_check("lattice", 1, 30000, [](obbsat::seeded_random& random) {
        return pose_pair{lattice_pose(random), lattice_pose(random)};
    });
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 3000) << c;
    }
}

TEST(pose_cross_check, lattice_pairs_far_from_the_origin) {
    // Lattice lengths times 4 (even integers), centers moved by (1e7, 3e7):
    // floats there are 1 and 2 apart, so the centers stay exact and so do the
    // contacts.
    const auto classes = cross_check("lattice at (1e7, 3e7)", 2, 30000, [](obbsat::seeded_random& random) {
        pose_pair p{lattice_pose(random), lattice_pose(random)};
        for (rect_pose* q : {&p.a, &p.b}) {
            q->center = point{4 * q->center.x + 1e7f, 4 * q->center.y + 3e7f};
            q->half_extents = point{4 * q->half_extents.x, 4 * q->half_extents.y};
        }
        return p;
    });
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 2000) << c;
    }
}

TEST(pose_cross_check, lattice_pairs_with_rotation_vectors_far_from_unit) {
    // The rotation vector scaled by 2^k and the half extents by 2^-k: the same
    // sets, with k from -66 (rotation lengths near 1e-20) to 50 (near 1e15).
    const auto classes = cross_check("lattice, 2^k rotations", 3, 30000, [](obbsat::seeded_random& random) {
        pose_pair p{lattice_pose(random), lattice_pose(random)};
        for (rect_pose* q : {&p.a, &p.b}) {
            const int k = integer(random, -66, 50);
            q->rotation = point{std::ldexp(q->rotation.x, k), std::ldexp(q->rotation.y, k)};
            q->half_extents = point{std::ldexp(q->half_extents.x, -k), std::ldexp(q->half_extents.y, -k)};
        }
        return p;
    });
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 2000) << c;
    }
}

TEST(pose_cross_check, a_corner_on_the_other_outline) {
    const auto classes = cross_check("corner on outline", 4, 40000, [](obbsat::seeded_random& random) {
        const float size = std::ldexp(1.0f, integer(random, -20, 20));
        const point center{random.uniform(-4, 4) * size, random.uniform(-4, 4) * size};
        const rect_pose a = random_pose(random, center, size);
        return pose_pair{a, near_contact(random, a, size)};
    });
    for (const char c : {'S', 'O'}) {
        EXPECT_GT(classes.at(c), 10000) << c;
    }
}

TEST(pose_cross_check, a_corner_on_the_other_outline_far_from_the_origin) {
    // Boxes of size 1 to 100 at 1e7 to 3e7, where the float grid is 1 or 2.
    const auto classes = cross_check("corner on outline, far", 5, 30000, [](obbsat::seeded_random& random) {
        const float size = random.uniform(1, 100);
        const point center{random.uniform(1e7f, 3e7f), -random.uniform(1e7f, 3e7f)};
        const rect_pose a = random_pose(random, center, size);
        return pose_pair{a, near_contact(random, a, size)};
    });
    for (const char c : {'S', 'O'}) {
        EXPECT_GT(classes.at(c), 5000) << c;
    }
}

TEST(pose_cross_check, lattice_pairs_with_rotation_components_of_two_scales) {
    // A rotation (a, b·2^-k) or (a·2^-k, b), k from 27 to 60, on the lattice:
    // each slack is a lattice part plus parts of order 2^-k and 2^-2k. When the
    // lattice part cancels, as at a lattice contact, the rest decides, and
    // 2^-2k is below what the double evaluation resolves. B is turned as A,
    // or a quarter turn from it, three times in four: edges then lie along
    // edges and the parts of order 2^-k cancel too.
    const auto classes = cross_check("lattice, two-scale turns", 7, 40000, [](obbsat::seeded_random& random) {
        pose_pair p{lattice_pose(random), lattice_pose(random)};
        for (rect_pose* q : {&p.a, &p.b}) {
            const float small = std::ldexp(1.0f, -integer(random, 27, 60));
            const float large = static_cast<float>(integer(random, 1, 4) * (random.below(2) == 0 ? 1 : -1));
            const float other = static_cast<float>(integer(random, -4, 4)) * small;
            q->rotation = random.below(2) == 0 ? point{large, other} : point{other, large};
        }
        switch (random.below(4)) {
            case 0:
            case 1: p.b.rotation = p.a.rotation; break;
            case 2: p.b.rotation = point{-p.a.rotation.y, p.a.rotation.x}; break;
            default: break;
        }
        return p;
    });
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 2000) << c;
    }
    EXPECT_GT(classes.at('D'), 150);
}

TEST(pose_cross_check, random_pairs) {
    // Any two poses in a square of side 16, sizes up to 4.
    const auto classes = cross_check("random", 6, 20000, [](obbsat::seeded_random& random) {
        auto center = [&] { return point{random.uniform(-8, 8), random.uniform(-8, 8)}; };
        return pose_pair{random_pose(random, center(), 4), random_pose(random, center(), 4)};
    });
    EXPECT_GT(classes.at('S'), 10000);
    EXPECT_GT(classes.at('O'), 1500);
}

}  // namespace
