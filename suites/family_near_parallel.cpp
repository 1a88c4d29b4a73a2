// Family near_parallel: B's lower edge faces A's upper edge (in A's frame),
// parallel before rounding (tag "par") or turned by 1e-9 .. 1e-6 rad (tag
// "tilt", the lower end of B's edge being the one placed), at a signed gap of
// 0 or 1e-9 .. 1e-4 times A's half height. Rotations are rational unit
// vectors composed in double; each corner is rounded to float once.
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <string>

namespace obbsat::suites::detail {

namespace {

constexpr double decades[] = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4};

}  // namespace

void build_near_parallel(suite_builder& out, seeded_random& random) {
    while (!out.full()) {
        const vec center_a{uniform(random, -20.0, 20.0), uniform(random, -20.0, 20.0)};
        const vec axis_a = random_axis(random);
        const double half_w_a = uniform(random, 0.5, 5.0);
        const double half_h_a = uniform(random, 0.5, 5.0);
        const double half_w_b = uniform(random, 0.5, 5.0);
        const double half_h_b = uniform(random, 0.5, 5.0);

        const bool tilted = chance(random, 0.7);
        // A small turn: the unit vector of parameter t turns by 2 atan(t) ~ 2t.
        double turn = 0.0;
        if (tilted) {
            const double sign = random_sign(random);
            const double decade = decades[random.below(3)];
            turn = sign * 0.5 * decade * uniform(random, 1.0, 10.0);
        }
        const vec relative_axis = unit_from_parameter(turn);

        const double u = uniform(random, 0.0, 1.0);
        double gap = 0.0;
        const char* gap_name = "gap0";
        if (u >= 0.2) {
            const double sign = random_sign(random);
            const double decade = decades[random.below(6)];
            gap = sign * half_h_a * decade * uniform(random, 1.0, 10.0);
            gap_name = sign > 0 ? "gap+" : "gap-";
        }

        // In A's frame: place B's lower edge end that sits lowest (its left end
        // when B turns counter-clockwise) at height half_h_a + gap.
        const double anchor_x = uniform(random, -half_w_a - half_w_b, half_w_a);
        const quad b_local = box(vec{0.0, 0.0}, relative_axis, half_w_b, half_h_b);
        const vec lowest = turn >= 0.0 ? b_local[3] : b_local[2];
        const vec shift = vec{anchor_x, half_h_a + gap} - lowest;
        quad b_world;
        for (std::size_t i = 0; i < 4; ++i) {
            b_world[i] = center_a + rotate(b_local[i] + shift, axis_a);
        }
        const quad a_world = box(center_a, axis_a, half_w_a, half_h_a);
        out.add_two(to_rect(a_world), to_rect(b_world),
                    std::string(tilted ? "tilt:" : "par:") + gap_name);
    }
}

}  // namespace obbsat::suites::detail
