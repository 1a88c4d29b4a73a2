#include "accuracy/double_families.hpp"

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/double_cases.hpp>

namespace obbsat::accuracy {

namespace {

using pose_make = suites::pose_pair64 (*)(seeded_random&);
using corner_make = suites::rect_pair64 (*)(seeded_random&);

struct pose_family_entry {
    std::string_view name;
    pose_make make;
};

struct corner_family_entry {
    std::string_view name;
    corner_make make;
};

// The families of tests/reference/test_pose_methods64.cpp, in its order.
const std::vector<pose_family_entry>& pose_entries() {
    static const std::vector<pose_family_entry> entries = {
        {"utm_random", suites::utm_random_pair},
        {"utm_contact", suites::utm_contact_pair},
        {"utm_northing_contact", suites::utm_northing_contact_pair},
        {"far_contact", suites::far_contact_pair},
        {"far_random", suites::far_random_pair},
        {"slivers", suites::sliver_pair},
        {"near_parallel", suites::near_parallel_pair},
        {"scaled_rotation", suites::scaled_rotation_pair},
    };
    return entries;
}

// The same makes as corners (exact for the dyadic ones), and quads nudged by
// ulps until they turn concave or cross themselves.
const std::vector<corner_family_entry>& corner_entries() {
    static const std::vector<corner_family_entry> entries = {
        {"utm_random", suites::corner_pair<suites::utm_random_pair>},
        {"utm_contact", suites::corner_pair<suites::utm_contact_pair>},
        {"utm_northing_contact", suites::corner_pair<suites::utm_northing_contact_pair>},
        {"far_contact", suites::corner_pair<suites::far_contact_pair>},
        {"far_random", suites::corner_pair<suites::far_random_pair>},
        {"slivers", suites::corner_pair<suites::sliver_pair>},
        {"near_parallel", suites::corner_pair<suites::near_parallel_pair>},
        {"nudged_corners", suites::nudged_corner_pair},
    };
    return entries;
}

template <class Entries>
std::vector<std::string_view> names_of(const Entries& entries) {
    std::vector<std::string_view> names;
    for (const auto& e : entries) {
        names.push_back(e.name);
    }
    return names;
}

// One stream of draws per family and seed, so that a family's pairs do not
// depend on which other families were made.
seeded_random random_for(std::size_t family, std::uint64_t seed, std::uint64_t kind) {
    return seeded_random(seed * 0x9e3779b97f4a7c15ull + (kind << 32) + family + 1);
}

}  // namespace

const std::vector<std::string_view>& double_pose_family_names() {
    static const std::vector<std::string_view> names = names_of(pose_entries());
    return names;
}

const std::vector<std::string_view>& double_corner_family_names() {
    static const std::vector<std::string_view> names = names_of(corner_entries());
    return names;
}

std::string name_list(const std::vector<std::string_view>& names) {
    std::string out;
    for (const std::string_view n : names) {
        out += out.empty() ? "" : ", ";
        out += n;
    }
    return out;
}

std::optional<std::size_t> find_name(const std::vector<std::string_view>& names, std::string_view name) {
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) {
            return i;
        }
    }
    return std::nullopt;
}

namespace {

// `pairs` pairs of `entry`'s make into a suite whose shapes are `Suite::*shapes`:
// pair i is shapes 2i and 2i+1.
template <class Suite, class Entry, class Shapes>
Suite make_suite(const Entry& entry, std::size_t family, std::uint64_t seed, std::size_t pairs, std::uint64_t kind,
                 Shapes Suite::*shapes) {
    seeded_random random = random_for(family, seed, kind);
    Suite s;
    s.family = std::string(entry.name);
    s.seed = seed;
    (s.*shapes).reserve(2 * pairs);
    s.pairs.reserve(pairs);
    for (std::size_t i = 0; i < pairs; ++i) {
        const auto p = entry.make(random);
        s.pairs.push_back(pair_index{static_cast<std::uint32_t>(2 * i), static_cast<std::uint32_t>(2 * i + 1)});
        (s.*shapes).push_back(p.a);
        (s.*shapes).push_back(p.b);
    }
    return s;
}

}  // namespace

double_pose_suite make_double_pose_family(std::size_t family, std::uint64_t seed, std::size_t pairs) {
    return make_suite(pose_entries().at(family), family, seed, pairs, 1, &double_pose_suite::poses);
}

double_rect_suite make_double_corner_family(std::size_t family, std::uint64_t seed, std::size_t pairs) {
    return make_suite(corner_entries().at(family), family, seed, pairs, 2, &double_rect_suite::rects);
}

std::vector<oracle::contact> double_truth(const double_pose_suite& s) {
    std::vector<oracle::contact> truth;
    truth.reserve(s.pairs.size());
    for (const pair_index& p : s.pairs) {
        truth.push_back(oracle::classify(s.poses[p.a], s.poses[p.b]));
    }
    return truth;
}

std::vector<oracle::contact> double_truth(const double_rect_suite& s) {
    std::vector<oracle::contact> truth;
    truth.reserve(s.pairs.size());
    for (const pair_index& p : s.pairs) {
        truth.push_back(oracle::classify(s.rects[p.a], s.rects[p.b]));
    }
    return truth;
}

}  // namespace obbsat::accuracy
