// Family slivers: rectangles with aspect ratios 10^K .. 10^(K+1), K = 0 .. 5
// (tag suffix "a1eK"): two slivers crossing near the middle ("cross"), side by
// side along their long edges ("side"), a sliver against a plain rect
// ("rect"), and a sliver's tip against another sliver's long edge ("tip"),
// the last three at zero, float-scale or visible gaps.
#include "contact_construction.hpp"
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <string>

namespace obbsat::suites::detail {

namespace {

constexpr double decades[] = {1.0, 1e1, 1e2, 1e3, 1e4, 1e5};

// Edges 0 (UL-UR) and 2 (LR-LL) run along a box's width, its long side here.
int long_edge(seeded_random& random) { return random.below(2) == 0 ? 0 : 2; }

}  // namespace

void build_slivers(suite_builder& out, seeded_random& random) {
    while (!out.full()) {
        const auto decade = static_cast<std::size_t>(random.below(6));
        const double aspect = decades[decade] * uniform(random, 1.0, 10.0);
        const double half_length = uniform(random, 1.0, 10.0);
        const double half_thickness = half_length / aspect;
        const vec center{uniform(random, -50.0, 50.0), uniform(random, -50.0, 50.0)};
        const vec axis = random_axis(random);
        const quad a = box(center, axis, half_length, half_thickness);
        const std::string suffix = ":a1e" + std::to_string(decade);

        const auto kind = random.below(4);
        if (kind == 0) {
            // Another sliver through a point near A's middle, at any angle.
            const double along = uniform(random, -0.5, 0.5) * half_length;
            const double across = uniform(random, -3.0, 3.0) * half_thickness;
            const vec b_axis = random_axis(random);
            const double b_half_length = uniform(random, 1.0, 10.0);
            const double b_half_thickness = uniform(random, 1.0, 10.0) / aspect;
            const quad b = box(center + along * axis + across * perp(axis), b_axis, b_half_length,
                               b_half_thickness);
            out.add_two(to_rect(a), to_rect(b), "cross" + suffix);
            continue;
        }
        const gap g = random_gap(random);
        const double signed_gap = g.relative * 2.0 * half_thickness;
        if (kind == 1) {
            // A parallel sliver along one of A's long edges (edges 0 and 2).
            const double b_half_length = uniform(random, 1.0, 10.0);
            const double b_half_thickness = uniform(random, 1.0, 10.0) / aspect;
            const int edge = long_edge(random);
            const quad b = place_against(random, a, contact_mode::edge, b_half_length,
                                         b_half_thickness, signed_gap, edge);
            out.add_two(to_rect(a), to_rect(b), std::string("side:") + g.name + suffix);
        } else if (kind == 2) {
            const contact_mode mode = random_contact_mode(random);
            const double b_half_width = uniform(random, 0.5, 5.0);
            const double b_half_height = uniform(random, 0.5, 5.0);
            const quad b = place_against(random, a, mode, b_half_width, b_half_height, signed_gap);
            out.add_two(to_rect(a), to_rect(b), std::string("rect:") + g.name + suffix);
        } else {
            const double b_half_length = uniform(random, 1.0, 10.0);
            const double b_half_thickness = uniform(random, 1.0, 10.0) / aspect;
            const int edge = long_edge(random);
            const quad b = place_against(random, a, contact_mode::corner, b_half_length,
                                         b_half_thickness, signed_gap, edge);
            out.add_two(to_rect(a), to_rect(b), std::string("tip:") + g.name + suffix);
        }
    }
}

}  // namespace obbsat::suites::detail
