// Seeded makes of double pose and corner pairs for the soak of the double
// methods (tests/oracle/double_backend_soak.cpp) and their golden digests
// (tests/backends/test_double_golden.cpp), beside the hard families of
// pose_cases64.hpp: uniformly random pairs at scales from 1e-3 to 1e12, pairs
// fuzzed from touching ones by a few ulps of any field, and bit-fuzzed ones
// (fields from random bits). Every make here uses integer arithmetic and
// correctly rounded double operations only (no std::cos or std::sin), so
// its pairs are the same bytes on every machine; the hard families it mixes in
// are those of pose_cases64.hpp (whose unit rotations come from the C library).
#pragma once

#include "test_support/pose_cases64.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace obbsat::test {

/// A rotation vector of random length in [2^-2, 2^2) and random direction (not
/// unit: the stored vector is taken as given).
inline point64 free_rotation64(seeded_random& random) {
    const double length = std::ldexp(1.0, integer_in(random, -2, 1));
    point64 r{0, 0};
    while (r.x == 0 && r.y == 0) {
        r = point64{length * uniform64(random, -1.0, 1.0), length * uniform64(random, -1.0, 1.0)};
    }
    return r;
}

/// Two poses with centers in [-scale, scale]², half extents up to scale
/// (zero one time in sixteen) and free rotations: at any scale about a third of the
/// pairs collide.
inline pose_pair64 uniform_pair_at_scale(seeded_random& random, double scale) {
    auto pose = [&] {
        auto extent = [&] { return random.below(16) == 0 ? 0.0 : uniform64(random, 0.0, scale); };
        const point64 center{uniform64(random, -scale, scale), uniform64(random, -scale, scale)};
        const point64 half{extent(), extent()};
        return rect_pose64{center, half, free_rotation64(random)};
    };
    const rect_pose64 a = pose();
    return pose_pair64{a, pose()};
}

/// A scale 10^k, k from -3 to 12 (decimal literals: the same double everywhere, unlike std::pow).
inline double decimal_scale(seeded_random& random) {
    constexpr double scales[] = {1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12};
    return scales[random.below(sizeof scales / sizeof scales[0])];
}

/// uniform_pair_at_scale at a decimal_scale.
inline pose_pair64 uniform_pair(seeded_random& random) { return uniform_pair_at_scale(random, decimal_scale(random)); }

/// `v` moved by 1 to 4 ulps either way.
inline double ulp_fuzzed(seeded_random& random, double v) {
    const int steps = integer_in(random, 1, 4);
    return nudged64(v, random.below(2) == 0 ? steps : -steps);
}

/// A pose pair in exact contact or nudged off it by a millimetre or a few ulps: the
/// contact makes of pose_cases64.hpp (UTM eastings and northings, far out, scaled rotations).
inline pose_pair64 touching_pose_pair(seeded_random& random) {
    switch (random.below(4)) {
        case 0: return utm_contact_pair(random);
        case 1: return utm_northing_contact_pair(random);
        case 2: return far_contact_pair(random);
        default: return scaled_rotation_pair(random);
    }
}

/// A touching or grazing pose pair with one to three of its twelve fields moved
/// by 1 to 4 ulps; a half extent that would turn negative is mirrored to stay a pose.
inline pose_pair64 ulp_fuzzed_pose_pair(seeded_random& random) {
    pose_pair64 pair = touching_pose_pair(random);
    const int moves = integer_in(random, 1, 3);
    for (int i = 0; i < moves; ++i) {
        rect_pose64& p = random.below(2) == 0 ? pair.a : pair.b;
        double* const fields[] = {&p.center.x, &p.center.y, &p.half_extents.x,
                                  &p.half_extents.y, &p.rotation.x, &p.rotation.y};
        double* const field = fields[random.below(6)];
        *field = ulp_fuzzed(random, *field);
    }
    for (rect_pose64* p : {&pair.a, &pair.b}) {
        p->half_extents = point64{std::fabs(p->half_extents.x), std::fabs(p->half_extents.y)};
    }
    return pair;
}

/// A finite double from 64 random bits with its exponent limited to
/// [-`range`, `range`] around 0 (so products stay finite when asked to).
inline double bit_fuzzed64(seeded_random& random, int range) {
    const std::uint64_t bits = random.next();
    double mantissa;  // in [1, 2)
    const std::uint64_t one_bits = (bits & 0x000fffffffffffffull) | 0x3ff0000000000000ull;
    std::memcpy(&mantissa, &one_bits, sizeof mantissa);
    const double v = std::ldexp(mantissa, integer_in(random, -range, range));
    return (bits >> 63) != 0 ? -v : v;
}

/// Two poses whose twelve fields are random bits (exponents within ±`range`),
/// half extents made non-negative, a rotation (0, 0) replaced by (1, 0).
inline pose_pair64 bit_fuzzed_pose_pair_in(seeded_random& random, int range) {
    auto pose = [&] {
        rect_pose64 p{{bit_fuzzed64(random, range), bit_fuzzed64(random, range)},
                      {std::fabs(bit_fuzzed64(random, range)), std::fabs(bit_fuzzed64(random, range))},
                      {bit_fuzzed64(random, range), bit_fuzzed64(random, range)}};
        if (p.rotation.x == 0 && p.rotation.y == 0) p.rotation.x = 1;
        return p;
    };
    const rect_pose64 a = pose();
    return pose_pair64{a, pose()};
}

/// bit_fuzzed_pose_pair_in with exponents within ±8 (often colliding) or ±300.
inline pose_pair64 bit_fuzzed_pose_pair(seeded_random& random) {
    return bit_fuzzed_pose_pair_in(random, random.below(4) == 0 ? 300 : 8);
}

/// The corners of uniform_pair (rectangles as corners).
inline rect_pair64 uniform_corner_pair(seeded_random& random) { return corner_pair<uniform_pair>(random); }

/// Two quads of eight random corner coordinates each in [-scale, scale] at a
/// decimal_scale: convex, reflex and self-crossing outlines alike.
inline rect_pair64 free_quad_pair(seeded_random& random) {
    const double scale = decimal_scale(random);
    auto quad = [&] {
        auto at = [&] { return point64{uniform64(random, -scale, scale), uniform64(random, -scale, scale)}; };
        const point64 ul = at(), ur = at(), lr = at();
        return rect64{ul, ur, lr, at()};
    };
    const rect64 a = quad();
    return rect_pair64{a, quad()};
}

/// The corners of a touching pose pair with one to three of the sixteen
/// corner coordinates moved by 1 to 4 ulps.
inline rect_pair64 ulp_fuzzed_corner_pair(seeded_random& random) {
    const pose_pair64 touching = touching_pose_pair(random);
    rect_pair64 pair{corners64(touching.a), corners64(touching.b)};
    const int moves = integer_in(random, 1, 3);
    for (int i = 0; i < moves; ++i) {
        rect64& r = random.below(2) == 0 ? pair.a : pair.b;
        double* const fields[] = {&r.ul.x, &r.ul.y, &r.ur.x, &r.ur.y, &r.lr.x, &r.lr.y, &r.ll.x, &r.ll.y};
        double* const field = fields[random.below(8)];
        *field = ulp_fuzzed(random, *field);
    }
    return pair;
}

/// Two quads of sixteen random-bit coordinates (exponents within ±8 or ±300).
inline rect_pair64 bit_fuzzed_corner_pair(seeded_random& random) {
    const int range = random.below(4) == 0 ? 300 : 8;
    auto quad = [&] {
        auto at = [&] { return point64{bit_fuzzed64(random, range), bit_fuzzed64(random, range)}; };
        const point64 ul = at(), ur = at(), lr = at();
        return rect64{ul, ur, lr, at()};
    };
    const rect64 a = quad();
    return rect_pair64{a, quad()};
}

/// A named make of double pairs; `portable` when its bytes are the same on
/// every machine (no unit rotation from the C library): golden digests draw
/// from those only.
template <class Pair>
struct soak_family64 {
    const char* name;
    Pair (*make)(seeded_random&);
    bool portable;
};

/// The pose families of the soak: the hard families of pose_cases64.hpp and the
/// makes above, each drawn equally often.
inline constexpr soak_family64<pose_pair64> pose_soak_families[] = {
    {"uniform 1e-3..1e12", uniform_pair, true},
    {"UTM random", utm_random_pair, false},
    {"UTM contacts 500000.125", utm_contact_pair, true},
    {"UTM contacts 6e6", utm_northing_contact_pair, true},
    {"contacts 1e9..1e15", far_contact_pair, true},
    {"random 1e9..1e15", far_random_pair, false},
    {"slivers", sliver_pair, true},
    {"near parallel", near_parallel_pair, false},
    {"scaled rotations", scaled_rotation_pair, true},
    {"ulp-fuzzed contacts", ulp_fuzzed_pose_pair, true},
    {"bit-fuzzed", bit_fuzzed_pose_pair, true},
};

/// The corner families of the soak: the pose families as corners, and quads
/// the poses cannot give.
inline constexpr soak_family64<rect_pair64> corner_soak_families[] = {
    {"uniform 1e-3..1e12", uniform_corner_pair, true},
    {"UTM random", corner_pair<utm_random_pair>, false},
    {"UTM contacts 500000.125", corner_pair<utm_contact_pair>, true},
    {"UTM contacts 6e6", corner_pair<utm_northing_contact_pair>, true},
    {"contacts 1e9..1e15", corner_pair<far_contact_pair>, true},
    {"random 1e9..1e15", corner_pair<far_random_pair>, false},
    {"slivers", corner_pair<sliver_pair>, true},
    {"near parallel", corner_pair<near_parallel_pair>, false},
    {"scaled rotations", corner_pair<scaled_rotation_pair>, true},
    {"ulp-fuzzed contacts", ulp_fuzzed_corner_pair, true},
    {"ulp-fuzzed quads", nudged_corner_pair, true},
    {"free quads", free_quad_pair, true},
    {"bit-fuzzed", bit_fuzzed_corner_pair, true},
};

/// The portable families among `families`, in their order.
template <class Pair, std::size_t family_count>
std::vector<soak_family64<Pair>> portable_families(const soak_family64<Pair> (&families)[family_count]) {
    std::vector<soak_family64<Pair>> out;
    for (const soak_family64<Pair>& f : families) {
        if (f.portable) out.push_back(f);
    }
    return out;
}

/// `count` pairs, each from one of `families` drawn at random, as the two
/// sides' items: pair i is (a[i], b[i]).
template <class Item, class Pair>
void draw_pairs(seeded_random& random, const std::vector<soak_family64<Pair>>& families, std::size_t count,
                std::vector<Item>& a, std::vector<Item>& b) {
    for (std::size_t i = 0; i < count; ++i) {
        const Pair p = families[random.below(families.size())].make(random);
        a.push_back(p.a);
        b.push_back(p.b);
    }
}

}  // namespace obbsat::test
