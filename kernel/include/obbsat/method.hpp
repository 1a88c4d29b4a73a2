// Methods: the collision tests obbsat offers. Each has a scalar reference in
// scalar_ref/ that defines it, and every backend follows that definition.
// Inside the library every table indexed by method is derived from one list,
// kernel/method_catalogue.hpp, checked at compile time against this enum.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace obbsat {

enum class method {
    sat4,           ///< the article's separating axis test in float32, world coordinates
    sat4_centered,  ///< sat4 after moving the origin to A.UL: precision independent of position
    sat4_double,    ///< sat4's steps in double arithmetic on the float input
    conservative,   ///< collides unless proven separated: never misses a collision
    exact,          ///< the exact answer for the quads (poses) as given (touching collides)
    local,          ///< poses only: the article's test in A's local frame, float32
};

/// The number of methods, for tables indexed by method.
inline constexpr unsigned method_count = 6;

/// The two kinds of store a method can run on: corners (rect_records,
/// rect_soa; see obbsat/rect.hpp) and poses (pose_records; see obbsat/rect_pose.hpp).
enum class store_kind { corners, poses };

/// True iff `m` runs on stores of kind `s`: sat4, sat4_centered and sat4_double
/// on corners; local on poses; conservative and exact on both (each with its
/// own reference per store). Any other pairing is refused with invalid_input.
bool runs_on(method m, store_kind s);

/// The methods that run on stores of kind `s`, in declaration order.
std::vector<method> methods_on(store_kind s);

/// "corners" or "poses".
const char* store_name(store_kind s);

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

/// The scalar reference of `m` on corners (for exact: the exact oracle,
/// obbsat::oracle::intersects); nullptr when `m` does not run on corners.
reference_fn method_reference(method m);

/// A method's scalar reference on poses.
using pose_reference_fn = bool (*)(const rect_pose& a, const rect_pose& b);

/// The scalar reference of `m` on poses (for exact: the exact pose oracle,
/// obbsat::oracle::intersects); nullptr when `m` does not run on poses.
pose_reference_fn pose_method_reference(method m);

}  // namespace obbsat
