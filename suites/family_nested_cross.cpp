// Family nested_cross: pairs whose interiors clearly meet or whose contact is
// exact by construction, to check that no method loses the easy answers:
//   nested        B well inside A (same centre region, smaller, any angle);
//   identical     B has A's very corners, relabelled (a cyclic shift, maybe reversed);
//   nested_touch  B inside A with one edge on A's edge line (in double; rounded);
//   cross         a plus sign: two bars of the same frame crossing at right angles;
//   xcross        an X: the second bar turned by 45 degrees;
//   tee_touch     integer T-shape: B's end exactly on A's long edge;
//   tee_gap       the same, one lattice unit apart;
//   tee_ovl       the same, one lattice unit in.
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <cmath>
#include <string>

namespace obbsat::suites::detail {

namespace {

rect relabelled(const rect& r, seeded_random& random) {
    point c[4] = {r.ul, r.ur, r.lr, r.ll};
    const auto shift = static_cast<std::size_t>(random.below(4));
    const bool reverse = chance(random, 0.5);
    point o[4];
    for (std::size_t i = 0; i < 4; ++i) {
        o[i] = c[reverse ? (shift + 4 - i) % 4 : (shift + i) % 4];
    }
    return rect{o[0], o[1], o[2], o[3]};
}

}  // namespace

void build_nested_cross(suite_builder& out, seeded_random& random) {
    static const char* const kinds[] = {"nested",  "identical", "nested_touch", "cross",
                                        "xcross",  "tee_touch", "tee_gap",      "tee_ovl"};
    for (std::size_t n = 0; !out.full(); ++n) {
        const std::string kind = kinds[n % 8];
        const vec center{uniform(random, -100.0, 100.0), uniform(random, -100.0, 100.0)};
        const vec axis = random_axis(random);
        const double half_w = uniform(random, 1.0, 10.0);
        const double half_h = uniform(random, 1.0, 10.0);
        const quad a = box(center, axis, half_w, half_h);
        if (kind == "nested") {
            const double inner = 0.45 * (half_w < half_h ? half_w : half_h);
            const vec inside = center + rotate(vec{uniform(random, -0.5, 0.5) * half_w,
                                                   uniform(random, -0.5, 0.5) * half_h},
                                               axis);
            const vec inner_axis = random_axis(random);
            const double inner_w = uniform(random, 0.1, 0.7) * inner;
            const double inner_h = uniform(random, 0.1, 0.7) * inner;
            const quad b = box(inside, inner_axis, inner_w, inner_h);
            out.add_two(to_rect(a), to_rect(b), kind);
        } else if (kind == "identical") {
            const rect ra = to_rect(a);
            out.add_two(ra, relabelled(ra, random), kind);
        } else if (kind == "nested_touch") {
            // B's upper edge on A's upper edge line, B inside in double.
            const double bw = uniform(random, 0.1, 0.5) * half_w;
            const double bh = uniform(random, 0.1, 0.9) * half_h;
            const double along = uniform(random, -1.0, 1.0) * (half_w - bw);
            const quad b = box(center + rotate(vec{along, half_h - bh}, axis), axis, bw, bh);
            out.add_two(to_rect(a), to_rect(b), kind);
        } else if (kind == "cross" || kind == "xcross") {
            const quad bar_a = box(center, axis, half_w, 0.2 * half_h);
            const vec turn = kind == "cross" ? vec{0.0, 1.0} : vec{std::sqrt(0.5), std::sqrt(0.5)};
            const quad bar_b = box(center + rotate(vec{uniform(random, -0.5, 0.5) * half_w, 0.0}, axis),
                                   rotate(turn, axis), half_h, 0.2 * half_w);
            out.add_two(to_rect(bar_a), to_rect(bar_b), kind);
        } else {
            // A T on the integer lattice, in the frame of e1 = (p, q) and e2 = e1
            // turned a quarter: the bar spans 8 e1 by 1 e2; the stem spans 2 e1 by
            // 3 e2 and stands on the bar's upper edge, or one frame unit (e2)
            // above it or into it. Every coordinate is a small integer.
            vec e1{0.0, 0.0};
            while (e1.x == 0.0 && e1.y == 0.0) {
                e1 = vec{static_cast<double>(integer(random, -6, 6)),
                         static_cast<double>(integer(random, -6, 6))};
            }
            const vec e2 = perp(e1);
            const vec origin{static_cast<double>(integer(random, -500, 500)),
                             static_cast<double>(integer(random, -500, 500))};
            const quad bar{origin + e2, origin + 8.0 * e1 + e2, origin + 8.0 * e1, origin};
            const double lift = kind == "tee_touch" ? 0.0 : (kind == "tee_gap" ? 1.0 : -1.0);
            const vec foot =
                origin + (1.0 + lift) * e2 + static_cast<double>(integer(random, -1, 7)) * e1;
            const quad stem{foot + 3.0 * e2, foot + 2.0 * e1 + 3.0 * e2, foot + 2.0 * e1, foot};
            out.add_two(to_rect(bar), to_rect(stem), kind);
        }
    }
}

}  // namespace obbsat::suites::detail
