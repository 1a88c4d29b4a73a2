// A generated hard-case suite: rects, candidate pairs and a tag per pair that
// says how the pair was built. Generation is deterministic: the same family,
// seed and size give the same bytes on every machine (only IEEE basic
// arithmetic, correctly rounded, is used; no sin, cos, exp or log).
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/suites/family.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace obbsat::suites {

struct suite {
    family source = family::random;
    std::uint64_t seed = 0;
    std::vector<rect> rects;
    std::vector<pair_index> pairs;
    std::vector<std::string> tag_names;  ///< the distinct tags, in order of first use
    std::vector<std::uint16_t> tags;     ///< per pair, an index into tag_names

    /// The tag of pair `index`, e.g. "corner:gap0".
    const std::string& tag_of(std::size_t index) const { return tag_names[tags[index]]; }
};

/// Exactly `pairs` pairs of family `f`, built from `seed`.
suite make_family(family f, std::uint64_t seed, std::size_t pairs);

}  // namespace obbsat::suites
