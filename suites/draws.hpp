// Random draws for case building, on top of seeded_random, in portable
// arithmetic only (no log or exp: spreads over decades use powers of two).
//
// Callers make each draw its own statement (or an element of a braced list,
// which is evaluated in order): the order in which a function's arguments, or
// the operands of *, are evaluated is unspecified and differs between
// compilers, and so would the suites.
#pragma once

#include "geometry.hpp"

#include <obbsat/scene.hpp>

#include <cstdint>

namespace obbsat::suites::detail {

/// A double uniform in [lo, hi), from 53 random bits.
double uniform(seeded_random& random, double lo, double hi);

/// An integer uniform in [lo, hi].
std::int64_t integer(seeded_random& random, std::int64_t lo, std::int64_t hi);

/// True with probability `p`.
bool chance(seeded_random& random, double p);

/// (1 + u) * 2^e with u in [0, 1) and e uniform in [lo_exponent, hi_exponent]:
/// spread evenly over the binary decades.
double binary_log_uniform(seeded_random& random, int lo_exponent, int hi_exponent);

/// +1 or -1.
double random_sign(seeded_random& random);

/// A unit vector at a uniform-ish random angle (any quadrant).
vec random_axis(seeded_random& random);

}  // namespace obbsat::suites::detail
