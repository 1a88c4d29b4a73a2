// The exact sign of a sum of products of doubles, for every finite double.
//
// The oracles for double input (pose_contact64.hpp) reduce every decision to
// the sign of such a sum: a slack is a sum of products of three stored
// doubles. Neither a product of two doubles nor an error-free transform of it
// is safe over the whole double range (a product of three can reach 2^3072,
// or fall below 2^-3000), so the sum is taken in a wide binary integer: each
// double is m·2^e with an integer |m| < 2^53, a product of three is an integer
// below 2^159 times 2^(e1 + e2 + e3), and the terms are added at their exact
// bit positions. No rounding anywhere, no range limit, no tolerance.
#pragma once

namespace obbsat::oracle {

/// One term: factor[0]·factor[1]·factor[2] (a missing factor is 1.0, exactly).
struct product_term {
    double factor[3];
};

/// How many terms sign_of_product_sum takes at the most.
inline constexpr int product_sum_max_terms = 32;

/// +1, −1 or 0: the sign of the exact sum of the products of `terms[0, count)`;
/// throws std::invalid_argument for a count outside [0, product_sum_max_terms]
/// or a factor that is not finite.
int sign_of_product_sum(const product_term* terms, int count);

}  // namespace obbsat::oracle
