// Families tiny and huge: groups of unit-size rects in near contact (a rect A
// and up to three rects placed against it at zero, float-scale or visible
// gaps), scaled by a tiny or huge factor in double and rounded to float once.
// Tiny scales reach the subnormals (1e-40, and 1e-43 where a unit spans only
// about 70 float steps); huge ones reach 1e30, and 1e26 offset by 1e30, where
// the offset swallows all but a few bits of the shape. Tag
// "<scale>:<mode>:<gap>".
#include "contact_construction.hpp"
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <cmath>
#include <string>

namespace obbsat::suites::detail {

namespace {

struct scaling {
    const char* name;
    double scale;
    double offset;
};

void build_scaled_groups(suite_builder& out, seeded_random& random, const scaling* scalings,
                         std::size_t count) {
    for (std::size_t group = 0; !out.full(); ++group) {
        const scaling& s = scalings[group % count];
        const vec center{uniform(random, -1.0, 1.0), uniform(random, -1.0, 1.0)};
        const vec axis = random_axis(random);
        const double half_width = uniform(random, 0.5, 2.0);
        const double half_height = uniform(random, 0.5, 2.0);
        const quad a = box(center, axis, half_width, half_height);
        const vec offset{s.offset, s.offset};
        const std::uint32_t index_a = out.add_rect(to_rect(scaled(a, s.scale, offset)));
        const auto partners = integer(random, 1, 3);
        for (std::int64_t i = 0; i < partners; ++i) {
            const contact_mode mode = random_contact_mode(random);
            const gap g = random_gap(random);
            const double b_half_width = uniform(random, 0.5, 2.0);
            const double b_half_height = uniform(random, 0.5, 2.0);
            const quad b = place_against(random, a, mode, b_half_width, b_half_height,
                                         g.relative * size_of(a));
            const std::uint32_t index_b = out.add_rect(to_rect(scaled(b, s.scale, offset)));
            out.add_pair(index_a, index_b,
                         std::string(s.name) + ":" + contact_mode_name(mode) + ":" + g.name);
        }
    }
}

}  // namespace

void build_tiny(suite_builder& out, seeded_random& random) {
    const scaling scalings[] = {{"1e-30", 1e-30, 0.0},
                                {"2^-100", std::ldexp(1.0, -100), 0.0},
                                {"1e-38", 1e-38, 0.0},
                                {"1e-40d", 1e-40, 0.0},
                                {"1e-43d", 1e-43, 0.0}};
    build_scaled_groups(out, random, scalings, sizeof(scalings) / sizeof(scalings[0]));
}

void build_huge(suite_builder& out, seeded_random& random) {
    const scaling scalings[] = {{"1e15", 1e15, 0.0},
                                {"1e19", 1e19, 0.0},
                                {"1e25", 1e25, 0.0},
                                {"1e30", 1e30, 0.0},
                                {"1e26@1e30", 1e26, 1e30}};
    build_scaled_groups(out, random, scalings, sizeof(scalings) / sizeof(scalings[0]));
}

}  // namespace obbsat::suites::detail
