// Methods: the collision tests obbsat offers. Each has a scalar reference in
// scalar_ref/ that defines it, and every backend follows that definition.
// Inside the library every table indexed by method is derived from one list,
// kernel/method_catalogue.hpp, checked at compile time against this enum.
#pragma once

#include <obbsat/rect.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace obbsat {

enum class method {
    sat4,           ///< the article's separating axis test in float32, world coordinates
    sat4_centered,  ///< sat4 after moving the origin to A.UL: precision independent of position
    sat4_double,    ///< sat4's steps in double arithmetic on the float input
    conservative,   ///< collides unless proven separated: never misses a collision
    exact,          ///< the exact answer for the quads as given (touching collides)
};

/// The number of methods, for tables indexed by method.
inline constexpr unsigned method_count = 5;

/// What a method promises about its verdicts, against the exact answer.
enum class method_guarantee {
    none,                ///< float arithmetic: may err either way near the boundary
    no_false_negatives,  ///< never calls a colliding pair apart
    exact,               ///< always the exact answer, touching included
};

/// The guarantee of `m`.
method_guarantee guarantee_of(method m);

/// True iff `m` names a method (an enumerator of obbsat::method).
bool is_method(method m);

/// The name of a method, as the CLI spells it.
const char* method_name(method m);

/// The method called `name`, or nothing if there is none.
std::optional<method> parse_method(std::string_view name);

/// Every method, in declaration order.
std::vector<method> all_methods();

/// A method's scalar reference: the plain definition every backend follows.
using reference_fn = bool (*)(const rect& a, const rect& b);

/// The scalar reference of `m` (for exact: the exact oracle, obbsat::oracle::intersects).
reference_fn method_reference(method m);

}  // namespace obbsat
