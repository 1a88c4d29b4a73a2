// The double families: seeded pairs of double poses and double corners built
// on or near the boundary between separated, touching and overlapping at
// coordinates float32 rounds (UTM-like 1e5..1e7 with millimetre and 1-4 ulp
// gaps, exact contacts from decimal coordinates such as 500000.125, far out at
// 1e9..1e15, slivers, near-parallel pairs, rotation lengths 1e-60..1e60), for
// `obbsat gen --precision double` and `obbsat accuracy --precision double`.
// The makes are those of the double methods' tests
// (obbsat/suites/double_cases.hpp); the truth is the exact double oracle's
// (obbsat/oracle/pose_contact64.hpp, contact64.hpp).
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace obbsat::accuracy {

/// Pairs of one double family of poses: pair i is (poses[2i], poses[2i+1]).
struct double_pose_suite {
    std::string family;
    std::uint64_t seed = 0;
    std::vector<rect_pose64> poses;
    std::vector<pair_index> pairs;
    /// The tag of pair `index`: its family's name (the makes keep no finer tag).
    const std::string& tag_of(std::size_t) const { return family; }
};

/// Pairs of one double family of corners: pair i is (rects[2i], rects[2i+1]).
struct double_rect_suite {
    std::string family;
    std::uint64_t seed = 0;
    std::vector<rect64> rects;
    std::vector<pair_index> pairs;
    /// The tag of pair `index`: its family's name.
    const std::string& tag_of(std::size_t) const { return family; }
};

/// The names of the double pose families, in report order.
const std::vector<std::string_view>& double_pose_family_names();
/// The names of the double corner families, in report order.
const std::vector<std::string_view>& double_corner_family_names();

/// "a, b, c": the names, for help and errors.
std::string name_list(const std::vector<std::string_view>& names);

/// The index of `name` in `names`, or nothing.
std::optional<std::size_t> find_name(const std::vector<std::string_view>& names, std::string_view name);

/// Exactly `pairs` pairs of double pose family `family` (an index into
/// double_pose_family_names()), from `seed`: the same bytes for the same
/// arguments with one C library (unit rotations use std::cos and std::sin).
double_pose_suite make_double_pose_family(std::size_t family, std::uint64_t seed, std::size_t pairs);
/// The same for double corner family `family` (double_corner_family_names()).
double_rect_suite make_double_corner_family(std::size_t family, std::uint64_t seed, std::size_t pairs);

/// The exact double oracle's class of every pair of `s`.
std::vector<oracle::contact> double_truth(const double_pose_suite& s);
std::vector<oracle::contact> double_truth(const double_rect_suite& s);

}  // namespace obbsat::accuracy
