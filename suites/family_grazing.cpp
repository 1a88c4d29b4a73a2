// Family grazing: an axis-aligned box A and a rect B (rotated, or axis-aligned)
// whose extreme corner (or edge) towards A lies exactly k float steps beyond
// A's edge line, k in -4 .. 4. In the frame where A's edge is its right edge
// x = X, every corner of B is rounded from X + d with d >= 0, so B's smallest
// x is exactly X stepped k times: k > 0 separated, k = 0 touching, k < 0
// overlapping, whatever B's other corners round to. The pair is then mirrored
// or transposed (exact float operations) so the edge is A's right, left, top
// or bottom edge. Tag "<side>:<k>", e.g. "top:-3"; A is always the pair's first
// rect.
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <cmath>
#include <string>

namespace obbsat::suites::detail {

namespace {

float step_floats(float from, int steps) {
    const float towards = steps > 0 ? INFINITY : -INFINITY;
    for (int i = 0; i < (steps > 0 ? steps : -steps); ++i) {
        from = std::nextafter(from, towards);
    }
    return from;
}

// The frame change for each side: right keeps (x, y); left mirrors x; top swaps
// x and y; bottom swaps them and mirrors the new y.
point to_side(point p, int side) {
    switch (side) {
        case 1: return point{-p.x, p.y};
        case 2: return point{p.y, p.x};
        case 3: return point{p.y, -p.x};
        default: return p;
    }
}

rect to_side(const rect& r, int side) {
    return rect{to_side(r.ul, side), to_side(r.ur, side), to_side(r.lr, side), to_side(r.ll, side)};
}

}  // namespace

void build_grazing(suite_builder& out, seeded_random& random) {
    static const char* const side_names[4] = {"right", "left", "top", "bottom"};
    while (!out.full()) {
        // Magnitude of the coordinates: from 2^-12 to 2^20, so float steps vary.
        const double magnitude = binary_log_uniform(random, -12, 20);
        const auto edge_x = static_cast<float>(magnitude * uniform(random, 1.0, 2.0));
        const auto width = static_cast<float>(magnitude * uniform(random, 0.5, 2.0));
        const auto height = static_cast<float>(magnitude * uniform(random, 0.5, 2.0));
        const auto bottom = static_cast<float>(magnitude * uniform(random, -1.0, 1.0));
        const float left = edge_x - width;
        const float top = bottom + height;
        const rect a{{left, top}, {edge_x, top}, {edge_x, bottom}, {left, bottom}};

        const int k = static_cast<int>(integer(random, -4, 4));
        const float target_x = step_floats(edge_x, k);
        // The touching corner's height, well inside A's edge (as a double).
        const double contact_y = static_cast<double>(bottom) +
                                 uniform(random, 0.1, 0.9) * (static_cast<double>(top) - bottom);
        const double half_w = magnitude * uniform(random, 0.2, 1.0);
        const double half_h = magnitude * uniform(random, 0.2, 1.0);
        const bool rotated = chance(random, 0.7);
        const quad b_shape = box(vec{0.0, 0.0}, rotated ? random_axis(random) : vec{1.0, 0.0},
                                 half_w, half_h);
        // The anchor: B's leftmost corner (for an axis-aligned B, its lower-left,
        // so the edge above it overlaps A's edge over a positive length).
        vec anchor = b_shape[3];
        for (const vec& c : b_shape) {
            if (c.x < anchor.x) {
                anchor = c;
            }
        }
        quad b_quad;
        for (std::size_t i = 0; i < 4; ++i) {
            // Differences of doubles round monotonically: d.x >= 0 for every corner.
            const vec d = b_shape[i] - anchor;
            b_quad[i] = vec{static_cast<double>(target_x) + d.x, contact_y + d.y};
        }
        const rect b = to_rect(b_quad);

        const auto side = static_cast<int>(random.below(4));
        const std::string tag =
            std::string(side_names[side]) + ":" + (k > 0 ? "+" : "") + std::to_string(k);
        out.add_two(to_side(a, side), to_side(b, side), tag);
    }
}

}  // namespace obbsat::suites::detail
