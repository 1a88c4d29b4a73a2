#include "draws.hpp"

#include <cmath>

namespace obbsat::suites::detail {

double uniform(seeded_random& random, double lo, double hi) {
    const double unit = static_cast<double>(random.next() >> 11) * 0x1p-53;
    return lo + (hi - lo) * unit;
}

std::int64_t integer(seeded_random& random, std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

bool chance(seeded_random& random, double p) {
    return uniform(random, 0.0, 1.0) < p;
}

double binary_log_uniform(seeded_random& random, int lo_exponent, int hi_exponent) {
    const auto exponent = static_cast<int>(integer(random, lo_exponent, hi_exponent));
    return std::ldexp(uniform(random, 1.0, 2.0), exponent);
}

double random_sign(seeded_random& random) {
    return (random.next() & 1u) != 0 ? 1.0 : -1.0;
}

vec random_axis(seeded_random& random) {
    // t in [-1, 1] covers angles in [-90, 90] degrees; a random quarter turn
    // covers the rest.
    vec axis = unit_from_parameter(uniform(random, -1.0, 1.0));
    const auto quarter_turns = random.below(4);
    for (std::uint64_t i = 0; i < quarter_turns; ++i) {
        axis = perp(axis);
    }
    return axis;
}

}  // namespace obbsat::suites::detail
