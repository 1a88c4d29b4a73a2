// A generated suite of pose pairs (pose_family.hpp), and the mixed stream of
// pairs from every pose family that the tests of the methods on poses use.
//
// Generation is deterministic: seeded integers and correctly rounded IEEE
// operations only (+, -, *, /, sqrt, nextafter, ldexp; no sin or cos), each
// draw in a fixed order, so the same family, seed and size give the same
// bytes on every machine.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/pose_family.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace obbsat::suites {

/// Pose pairs of one family. Pair i is (poses[2i], poses[2i+1]); every pose is
/// valid (finite, no negative half extent, rotation not (0, 0)).
struct pose_suite {
    pose_family source = pose_family::near;
    std::uint64_t seed = 0;
    std::vector<rect_pose> poses;
    std::vector<pair_index> pairs;
    /// The distinct tags, in order of first use: "near"; "parallel" or "turned"
    /// (integer_contact: B's rotation A's, or its own); else the contact
    /// placement, e.g. "v:x+2:y-1": along A's axis v = (-s, c) (or u = (c, s)),
    /// then B's center moved +2 float steps in x and -1 in y.
    std::vector<std::string> tag_names;
    std::vector<std::uint16_t> tags;  ///< per pair, an index into tag_names

    /// The tag of pair `index`.
    const std::string& tag_of(std::size_t index) const { return tag_names[tags[index]]; }
};

/// Exactly `pairs` pairs of family `f`, built from `seed`.
pose_suite make_pose_family(pose_family f, std::uint64_t seed, std::size_t pairs);

/// Poses a[i] and b[i] form pair i.
struct pose_pairs {
    std::vector<rect_pose> a;
    std::vector<rect_pose> b;
};

/// One pair of family `f`, drawn from `random` (the draw make_pose_family repeats).
void random_pose_pair(seeded_random& random, pose_family f, rect_pose& a, rect_pose& b);

/// `count` pairs from one stream, pair i of family all_pose_families()[i % 10]:
/// every kind of hard case mixed, for tests and golden digests.
pose_pairs random_pose_pairs(seeded_random& random, std::size_t count);

}  // namespace obbsat::suites
