// Family integer_touching: rectangles with integer corners, built from an
// edge vector (a, b) and its quarter turn scaled by k, (-k b, k a), so every
// coordinate and every contact is exact in float. B is put against A edge on
// edge, corner on edge or corner on corner (all touching), then, for a share
// of pairs, shifted by one unit along x or y (tag suffix ":shift"). The whole
// pair is finally scaled by a power of two, which is exact too.
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace obbsat::suites::detail {

namespace {

struct ivec {
    std::int64_t x;
    std::int64_t y;
};

ivec operator+(ivec a, ivec b) { return ivec{a.x + b.x, a.y + b.y}; }
ivec operator*(std::int64_t s, ivec a) { return ivec{s * a.x, s * a.y}; }
std::int64_t dot(ivec a, ivec b) { return a.x * b.x + a.y * b.y; }
ivec quarter_turn(ivec a) { return ivec{-a.y, a.x}; }

std::int64_t gcd(std::int64_t a, std::int64_t b) {
    a = std::llabs(a);
    b = std::llabs(b);
    while (b != 0) {
        const std::int64_t r = a % b;
        a = b;
        b = r;
    }
    return a;
}

ivec random_edge_vector(seeded_random& random) {
    ivec v{0, 0};
    while (v.x == 0 && v.y == 0) {
        v = ivec{integer(random, -12, 12), integer(random, -12, 12)};
    }
    return v;
}

// Corners origin, origin + e1, origin + e1 + e2, origin + e2 with e2 = k e1
// turned a quarter counter-clockwise: a counter-clockwise rectangle.
struct integer_rect {
    ivec corner[4];
};

integer_rect make_integer_rect(ivec origin, ivec e1, ivec e2) {
    return integer_rect{{origin, origin + e1, origin + e1 + e2, origin + e2}};
}

rect to_float_rect(const integer_rect& r, ivec shift, double scale) {
    quad q;
    for (std::size_t i = 0; i < 4; ++i) {
        const ivec c = r.corner[i] + shift;
        q[i] = vec{static_cast<double>(c.x) * scale, static_cast<double>(c.y) * scale};
    }
    return to_rect(q);
}

}  // namespace

void build_integer_touching(suite_builder& out, seeded_random& random) {
    while (!out.full()) {
        const ivec origin{integer(random, -1000, 1000), integer(random, -1000, 1000)};
        const ivec e1 = random_edge_vector(random);
        const integer_rect a =
            make_integer_rect(origin, e1, integer(random, 1, 3) * quarter_turn(e1));

        // Edge k runs corner[k] -> corner[k+1]; A is counter-clockwise, so its
        // outward normal is the edge direction turned a quarter clockwise.
        const auto k = static_cast<std::size_t>(random.below(4));
        const ivec from = a.corner[k];
        const ivec along{a.corner[(k + 1) % 4].x - from.x, a.corner[(k + 1) % 4].y - from.y};
        const std::int64_t steps = gcd(along.x, along.y);
        const ivec unit{along.x / steps, along.y / steps};  // primitive lattice direction
        const ivec outward{unit.y, -unit.x};

        std::string kind;
        integer_rect b;
        const double u = uniform(random, 0.0, 1.0);
        if (u < 0.4) {
            // Edge on edge: B's facing edge on A's edge line, sliding from touching
            // A's first corner only to touching its last corner only.
            kind = "edge";
            const std::int64_t length = integer(random, 1, 8);
            const std::int64_t start = integer(random, -length, steps);
            b = make_integer_rect(from + start * unit, length * unit,
                                  integer(random, 1, 8) * outward);
        } else {
            // A corner of B on A's edge (at one of A's corners for "vertex"), B
            // wholly on the outer side: both of B's edge vectors point outwards.
            const bool at_vertex = u >= 0.8;
            kind = at_vertex ? "vertex" : "corner";
            const std::int64_t at = at_vertex ? steps * integer(random, 0, 1) : integer(random, 0, steps);
            ivec w1 = random_edge_vector(random);
            if (dot(w1, outward) < 0) {
                w1 = -1 * w1;
            }
            ivec w2 = integer(random, 1, 3) * quarter_turn(w1);
            if (dot(w2, outward) < 0) {
                w2 = -1 * w2;
            }
            b = make_integer_rect(from + at * unit, w1, w2);
        }
        ivec shift{0, 0};
        if (chance(random, 0.4)) {
            const ivec shifts[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            shift = shifts[random.below(4)];
            kind += ":shift";
        } else {
            kind += ":touch";
        }
        // Coordinates stay below 2^12, so any scale 2^-8 .. 2^8 keeps them exact.
        const double scale = std::ldexp(1.0, static_cast<int>(integer(random, -8, 8)));
        const bool b_first = chance(random, 0.5);
        const rect ra = to_float_rect(a, ivec{0, 0}, scale);
        const rect rb = to_float_rect(b, shift, scale);
        out.add_two(b_first ? rb : ra, b_first ? ra : rb, kind);
    }
}

}  // namespace obbsat::suites::detail
