#include "contact_construction.hpp"

#include "draws.hpp"

#include <algorithm>
#include <cmath>

namespace obbsat::suites::detail {

namespace {

// The unit normal of edge k of `a` that points away from a's centroid.
vec outward_normal(const quad& a, std::size_t k) {
    const vec along = a[(k + 1) % 4] - a[k];
    vec n = normalized(perp(along));
    if (dot(n, a[k] - centroid(a)) < 0.0) {
        n = -1.0 * n;
    }
    return n;
}

// The corner of `b` that reaches farthest against `direction`.
vec support_against(const quad& b, vec direction) {
    vec best = b[0];
    for (const vec& c : b) {
        if (dot(c, direction) < dot(best, direction)) {
            best = c;
        }
    }
    return best;
}

}  // namespace

const char* contact_mode_name(contact_mode mode) {
    switch (mode) {
        case contact_mode::corner: return "corner";
        case contact_mode::edge: return "edge";
        case contact_mode::vertex: return "vertex";
    }
    return "corner";
}

contact_mode random_contact_mode(seeded_random& random) {
    const double u = uniform(random, 0.0, 1.0);
    if (u < 0.45) {
        return contact_mode::corner;
    }
    return u < 0.8 ? contact_mode::edge : contact_mode::vertex;
}

gap random_gap(seeded_random& random) {
    const double u = uniform(random, 0.0, 1.0);
    if (u < 0.4) {
        return gap{0.0, "gap0"};
    }
    const double magnitude =
        u < 0.8 ? binary_log_uniform(random, -30, -21) : binary_log_uniform(random, -12, -5);
    const double sign = random_sign(random);
    return gap{sign * magnitude, sign > 0 ? "gap+" : "gap-"};
}

double size_of(const quad& a) {
    double longest = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
        const vec edge = a[(k + 1) % 4] - a[k];
        longest = std::max(longest, std::sqrt(dot(edge, edge)));
    }
    return longest;
}

quad place_against(seeded_random& random, const quad& a, contact_mode mode, double half_width,
                   double half_height, double signed_gap, int edge) {
    const auto k = edge >= 0 ? static_cast<std::size_t>(edge % 4) : static_cast<std::size_t>(random.below(4));
    switch (mode) {
        case contact_mode::corner: {
            const vec n = outward_normal(a, k);
            const vec on_edge = a[k] + uniform(random, 0.05, 0.95) * (a[(k + 1) % 4] - a[k]);
            const quad b = box(vec{0.0, 0.0}, random_axis(random), half_width, half_height);
            return translated(b, on_edge + signed_gap * n - support_against(b, n));
        }
        case contact_mode::edge: {
            const vec n = outward_normal(a, k);
            // B's own -y side must face a: its x axis is a's edge direction, turned
            // so that B's +y (perp of the axis) points along n.
            vec axis = normalized(a[(k + 1) % 4] - a[k]);
            if (dot(perp(axis), n) < 0.0) {
                axis = -1.0 * axis;
            }
            const vec on_line = a[k] + uniform(random, -0.2, 1.2) * (a[(k + 1) % 4] - a[k]);
            return box(on_line + (signed_gap + half_height) * n, axis, half_width, half_height);
        }
        case contact_mode::vertex: {
            const vec corner = a[k];
            const vec away = normalized(corner - centroid(a));
            const quad b = box(vec{0.0, 0.0}, random_axis(random), half_width, half_height);
            return translated(b, corner + signed_gap * away - support_against(b, away));
        }
    }
    return a;
}

}  // namespace obbsat::suites::detail
