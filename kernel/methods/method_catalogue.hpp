// The one list of methods. Each method has one row here: its name as the CLI
// spells it, the guarantee it gives, whether its lanes can leave a pair to an
// exact slow path, and for each store it runs on its scalar reference and its
// lane template. Everything indexed by method is derived from this list: the
// kernel table of every backend (lanes/backend_isa/verdict_kernels.cpp), the scalar path
// (scalar_kernels.cpp), the names and references of obbsat/method.hpp
// (method.cpp). The static_asserts at the end tie row k to obbsat::method k.
//
// Adding a method: its enumerator in obbsat/method.hpp, its scalar reference
// in scalar_ref/, its lane template in kernel/, and one row here. A method
// that does not run on a store says so with not_offered for it.
//
// The rows live in an unnamed namespace, as the lane templates they name do:
// this header is compiled into one translation unit per instruction set.
#pragma once

#include "support/type_list.hpp"

#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/local.hpp>
#include <obbsat/ref/pose_conservative.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>

#include <cstddef>
#include <type_traits>

namespace obbsat::detail {
namespace {

// Lane templates: defined in kernel/lanes/*_lanes.hpp and instantiated only in the
// per-ISA translation units; declared here so that baseline sources can read
// the catalogue without compiling SIMD code.
template <class Arch>
struct sat4_lanes;
template <class Arch>
struct sat4_centered_lanes;
template <class Arch>
struct sat4_double_lanes;
template <class Arch>
struct conservative_lanes;
template <class Arch>
struct exact_lanes;
template <class Arch>
struct local_lanes;
template <class Arch>
struct pose_conservative_lanes;
template <class Arch>
struct pose_exact_lanes;

/// How a method runs on the corner stores (rect_soa, rect_records): its
/// scalar reference (the definition every backend reproduces) and its lanes.
template <reference_fn Reference, template <class> class Lanes>
struct on_corners {
    static constexpr reference_fn reference = Reference;
    template <class Arch>
    using lanes = Lanes<Arch>;
};

/// How a method runs on the pose store (pose_records): its scalar reference
/// and its lanes over pose_lanes.
template <pose_reference_fn Reference, template <class> class Lanes>
struct on_poses {
    static constexpr pose_reference_fn reference = Reference;
    template <class Arch>
    using lanes = Lanes<Arch>;
};

/// The method does not run on this store; asking for it there is refused.
struct not_offered {};

template <class Store>
constexpr bool offered = !std::is_same<Store, not_offered>::value;

struct sat4_row {
    static constexpr method id = method::sat4;
    static constexpr const char* name = "sat4";
    static constexpr method_guarantee guarantee = method_guarantee::none;
    static constexpr bool has_slow_path = false;
    using corners = on_corners<ref::sat4, sat4_lanes>;
    using poses = not_offered;
};

struct sat4_centered_row {
    static constexpr method id = method::sat4_centered;
    static constexpr const char* name = "sat4_centered";
    static constexpr method_guarantee guarantee = method_guarantee::none;
    static constexpr bool has_slow_path = false;
    using corners = on_corners<ref::sat4_centered, sat4_centered_lanes>;
    using poses = not_offered;
};

struct sat4_double_row {
    static constexpr method id = method::sat4_double;
    static constexpr const char* name = "sat4_double";
    static constexpr method_guarantee guarantee = method_guarantee::none;
    static constexpr bool has_slow_path = false;
    using corners = on_corners<ref::sat4_double, sat4_double_lanes>;
    using poses = not_offered;
};

struct conservative_row {
    static constexpr method id = method::conservative;
    static constexpr const char* name = "conservative";
    static constexpr method_guarantee guarantee = method_guarantee::no_false_negatives;
    static constexpr bool has_slow_path = false;
    using corners = on_corners<ref::conservative, conservative_lanes>;
    using poses = on_poses<ref::conservative, pose_conservative_lanes>;
};

struct exact_row {
    static constexpr method id = method::exact;
    static constexpr const char* name = "exact";
    static constexpr method_guarantee guarantee = method_guarantee::exact;
    static constexpr bool has_slow_path = true;
    using corners = on_corners<oracle::intersects, exact_lanes>;
    using poses = on_poses<oracle::intersects, pose_exact_lanes>;
};

struct local_row {
    static constexpr method id = method::local;
    static constexpr const char* name = "local";
    static constexpr method_guarantee guarantee = method_guarantee::none;
    static constexpr bool has_slow_path = false;
    using corners = not_offered;
    using poses = on_poses<ref::local, local_lanes>;
};

/// Every method, in the order of obbsat::method.
using method_catalogue =
    type_list<sat4_row, sat4_centered_row, sat4_double_row, conservative_row, exact_row, local_row>;

constexpr bool rows_follow_enum_order() {
    constexpr auto ids = method_catalogue::map([](auto row) { return decltype(row)::id; });
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (static_cast<std::size_t>(ids[k]) != k) {
            return false;
        }
    }
    return true;
}

static_assert(method_catalogue::size == method_count, "one catalogue row per obbsat::method");
static_assert(rows_follow_enum_order(), "catalogue row k must describe obbsat::method k");

}  // namespace
}  // namespace obbsat::detail
