// Family degenerate: quads without area (a point: four equal corners; a
// segment: UL = LL and UR = LR) and quads that lose area or convexity in
// rounding, against each other and against rects. Tag "<A>-<B>:<where>":
//   kinds  pt, seg, rect, tri (two neighbouring corners equal), thin (width
//          2^-27 .. 2^-17 of its length, around one float step: rounds to a
//          segment or to a quad thinner than a float step);
//   where  int: small integer lattice, so contacts are exact and frequent;
//          flt: B built through a point of A's boundary in double, rounded once.
#include "contact_construction.hpp"
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <cmath>
#include <string>

namespace obbsat::suites::detail {

namespace {

enum class kind { pt, seg, rect, tri, thin };

const char* kind_name(kind k) {
    switch (k) {
        case kind::pt: return "pt";
        case kind::seg: return "seg";
        case kind::rect: return "rect";
        case kind::tri: return "tri";
        case kind::thin: return "thin";
    }
    return "pt";
}

quad point_quad(vec p) { return quad{p, p, p, p}; }
quad segment_quad(vec s0, vec s1) { return quad{s0, s1, s1, s0}; }

vec lattice_point(seeded_random& random) {
    return vec{static_cast<double>(integer(random, -4, 4)), static_cast<double>(integer(random, -4, 4))};
}

vec lattice_vector(seeded_random& random) {
    vec v{0.0, 0.0};
    while (v.x == 0.0 && v.y == 0.0) {
        v = vec{static_cast<double>(integer(random, -3, 3)), static_cast<double>(integer(random, -3, 3))};
    }
    return v;
}

quad lattice_shape(seeded_random& random, kind k) {
    const vec origin = lattice_point(random);
    const vec e1 = lattice_vector(random);
    const vec e2 = static_cast<double>(integer(random, 1, 2)) * perp(e1);
    switch (k) {
        case kind::pt: return point_quad(origin);
        case kind::seg: return segment_quad(origin, origin + e1);
        case kind::tri: return quad{origin, origin, origin + e1, origin + e2};
        default: return quad{origin, origin + e1, origin + e1 + e2, origin + e2};
    }
}

// A shape of kind k in general float position, around `center`.
quad float_shape(seeded_random& random, kind k, vec center) {
    const vec axis = random_axis(random);
    const double half_w = uniform(random, 0.5, 5.0);
    switch (k) {
        case kind::pt: return point_quad(center);
        case kind::seg: return segment_quad(center - half_w * axis, center + half_w * axis);
        case kind::tri: {
            const quad b = box(center, axis, half_w, uniform(random, 0.5, 5.0));
            return quad{b[0], b[0], b[2], b[3]};
        }
        case kind::thin:
            return box(center, axis, half_w, half_w * binary_log_uniform(random, -27, -18));
        case kind::rect: break;
    }
    return box(center, axis, half_w, uniform(random, 0.5, 5.0));
}

// A point of a's boundary: on a random edge of the quad (for a point or a
// segment quad, on the point or the segment).
vec boundary_point(seeded_random& random, const quad& a) {
    const auto k = static_cast<std::size_t>(random.below(4));
    return a[k] + uniform(random, 0.0, 1.0) * (a[(k + 1) % 4] - a[k]);
}

// A shape of kind k that passes through p (a corner of it, an end of a
// segment, or a segment's inner point), in double.
quad shape_through(seeded_random& random, kind k, vec p, const quad& a) {
    const vec axis = random_axis(random);
    switch (k) {
        case kind::pt: return point_quad(p);
        case kind::seg: {
            // Along one of a's edges half of the time, so collinear overlaps occur.
            vec direction = axis;
            const auto edge = static_cast<std::size_t>(random.below(4));
            const vec along = a[(edge + 1) % 4] - a[edge];
            if (chance(random, 0.5) && (along.x != 0.0 || along.y != 0.0)) {
                direction = normalized(along);
            }
            const double before = chance(random, 0.5) ? 0.0 : uniform(random, 0.0, 5.0);
            return segment_quad(p - before * direction, p + uniform(random, 0.5, 5.0) * direction);
        }
        default: {
            const quad shape = float_shape(random, k, vec{0.0, 0.0});
            return translated(shape, p - shape[random.below(4)]);
        }
    }
}

}  // namespace

void build_degenerate(suite_builder& out, seeded_random& random) {
    const kind kinds_a[] = {kind::pt, kind::seg, kind::rect, kind::tri, kind::thin};
    while (!out.full()) {
        // Points, segments and rects against each other most of the time.
        const kind ka = chance(random, 0.8) ? kinds_a[random.below(3)] : kinds_a[random.below(5)];
        const kind kb = kinds_a[random.below(3)];
        const bool on_lattice = ka != kind::thin && chance(random, 0.5);
        quad a;
        quad b;
        if (on_lattice) {
            a = lattice_shape(random, ka);
            b = lattice_shape(random, kb);
        } else {
            a = float_shape(random, ka,
                            vec{uniform(random, -20.0, 20.0), uniform(random, -20.0, 20.0)});
            vec p = boundary_point(random, a);
            if (chance(random, 0.3)) {
                // Off the boundary by a few float steps of the coordinates.
                const double distance = binary_log_uniform(random, -24, -20) * (std::fabs(p.x) + std::fabs(p.y));
                const vec direction = random_axis(random);
                p = p + distance * direction;
            }
            b = shape_through(random, kb, p, a);
        }
        const std::string tag = std::string(kind_name(ka)) + "-" + kind_name(kb) +
                                (on_lattice ? ":int" : ":flt");
        out.add_two(to_rect(a), to_rect(b), tag);
    }
}

}  // namespace obbsat::suites::detail
