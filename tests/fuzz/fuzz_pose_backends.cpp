// Fuzz target: every backend this CPU runs, for every method on poses and
// through every pose entry point (collide_pairs over pose_records,
// collide_stream over pose_records and over pose_soa), must give exactly the
// verdicts of the method's scalar reference on any valid pose (for exact: the
// exact pose oracle); conservative must never miss a collision; the scene
// query with method exact must report exactly the pairs the pose oracle calls
// colliding, fresh and from a pair_finder's kept candidates; the conversion to
// corners must equal its reference byte for byte. The first difference is
// printed with the two poses in hex floats and stops the run.
//
// Input format: one byte for the number of poses, then each pose as a kind
// byte and its payload; the bytes left over are pairs of indices (each taken
// modulo the number of poses).
#include "fuzz_bytes.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/ref/pose_corners.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat::fuzz::byte_source;
using obbsat::fuzz::finite_from_bits;

constexpr std::size_t max_poses = 48;

rect_pose made_valid(rect_pose p) {
    p.half_extents = {std::fabs(p.half_extents.x), std::fabs(p.half_extents.y)};
    if (p.rotation.x == 0.0f && p.rotation.y == 0.0f) {
        p.rotation.x = 1.0f;
    }
    return p;
}

// Six raw 32-bit patterns: every scale, subnormals, the largest floats.
rect_pose raw_pose(byte_source& in) {
    float v[6];
    for (float& f : v) {
        f = finite_from_bits(in.u32());
    }
    return made_valid(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}});
}

// Small integers times a power of two, with integer rotation vectors:
// exact contacts at every scale.
rect_pose integer_pose(byte_source& in) {
    const int exponent = static_cast<int>(in.byte() % 64) - 32;
    auto small = [&](int range) { return std::ldexp(static_cast<float>(static_cast<int>(in.byte() % range) - range / 2), exponent); };
    static const float rotations[][2] = {{1, 0}, {0, 1}, {3, 4}, {-4, 3}, {5, 12}, {-12, -5}, {1, 1}, {2, -1}};
    const auto& r = rotations[in.byte() % 8];
    return made_valid(rect_pose{{small(64), small(64)}, {small(16), small(16)}, {r[0], r[1]}});
}

// A pose near an earlier one: each field moved by a few representable floats.
rect_pose near_pose(byte_source& in, const std::vector<rect_pose>& earlier) {
    rect_pose p = earlier.empty() ? rect_pose{{0, 0}, {1, 1}, {1, 0}} : earlier[in.byte() % earlier.size()];
    float* fields[] = {&p.center.x, &p.center.y, &p.half_extents.x, &p.half_extents.y, &p.rotation.x, &p.rotation.y};
    for (float* f : fields) {
        *f = obbsat::fuzz::nudged(*f, static_cast<int>(in.byte() % 9) - 4);
    }
    return made_valid(p);
}

rect_pose decode_pose(byte_source& in, const std::vector<rect_pose>& earlier) {
    switch (in.byte() % 3) {
        case 0: return raw_pose(in);
        case 1: return integer_pose(in);
        default: return near_pose(in, earlier);
    }
}

std::string hex(float f) {
    char text[32];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(f));
    return text;
}

std::string text_of(const rect_pose& p) {
    return "(" + hex(p.center.x) + ", " + hex(p.center.y) + ") half (" + hex(p.half_extents.x) + ", " +
           hex(p.half_extents.y) + ") rotation (" + hex(p.rotation.x) + ", " + hex(p.rotation.y) + ")";
}

[[noreturn]] void stop(const std::string& what) {
    std::fprintf(stderr, "fuzz_pose_backends: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    byte_source in(data, size);
    const std::size_t count = 1 + in.byte() % max_poses;
    std::vector<rect_pose> poses;
    for (std::size_t i = 0; i < count; ++i) {
        poses.push_back(decode_pose(in, poses));
    }
    std::vector<pair_index> pairs;
    while (!in.empty()) {
        const auto a = static_cast<std::uint32_t>(in.byte() % count);
        const auto b = static_cast<std::uint32_t>(in.byte() % count);
        pairs.push_back(pair_index{a, b});
    }
    if (pairs.empty()) {
        for (std::uint32_t a = 0; a < count; ++a) {
            pairs.push_back(pair_index{a, static_cast<std::uint32_t>((a + 1) % count)});
        }
    }
    const obbsat::pose_records records(poses);
    std::vector<rect_pose> side_a, side_b;
    for (const pair_index& p : pairs) {
        side_a.push_back(poses[p.a]);
        side_b.push_back(poses[p.b]);
    }
    const obbsat::pose_records stream_a(side_a), stream_b(side_b);
    const obbsat::pose_soa soa_a(side_a), soa_b(side_b);
    const std::size_t n = pairs.size();

    std::vector<std::uint8_t> truth(n);
    std::vector<std::uint8_t> got(n);
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        const obbsat::pose_reference_fn reference = obbsat::pose_method_reference(m);
        std::vector<std::uint8_t> expected(n);
        for (std::size_t i = 0; i < n; ++i) {
            expected[i] = reference(side_a[i], side_b[i]) ? 1 : 0;
        }
        if (m == method::exact) {
            truth = expected;
        }
        for (const backend b : obbsat::compiled_backends()) {
            if (!obbsat::cpu_supports(b)) {
                continue;
            }
            obbsat::collide_options options;
            options.test = m;
            options.use = b;
            const char* paths[] = {"collide_pairs over pose_records", "collide_stream over pose_records",
                                   "collide_stream over pose_soa"};
            for (int path = 0; path < 3; ++path) {
                got.assign(n, 0xee);
                if (path == 0) {
                    obbsat::collide_pairs(records, pairs.data(), n, got.data(), options);
                } else if (path == 1) {
                    obbsat::collide_stream(stream_a, stream_b, got.data(), options);
                } else {
                    obbsat::collide_stream(soa_a, soa_b, got.data(), options);
                }
                for (std::size_t i = 0; i < n; ++i) {
                    if (got[i] != expected[i]) {
                        stop(std::string(obbsat::method_name(m)) + " on " + obbsat::backend_name(b) + ", " +
                             paths[path] + ", pair " + std::to_string(i) + ": backend " + std::to_string(got[i]) +
                             ", reference " + std::to_string(expected[i]) + "\n  A " + text_of(side_a[i]) +
                             "\n  B " + text_of(side_b[i]));
                    }
                }
            }
        }
    }
    if (obbsat::runs_on(method::conservative, obbsat::store_kind::poses)) {
        obbsat::collide_options options;
        options.test = method::conservative;
        const std::vector<std::uint8_t> conservative = obbsat::collide_stream(stream_a, stream_b, options);
        for (std::size_t i = 0; i < n; ++i) {
            if (truth[i] == 1 && conservative[i] == 0) {
                stop("conservative says apart where the pose oracle says they collide\n  A " + text_of(side_a[i]) +
                     "\n  B " + text_of(side_b[i]));
            }
        }
    }
    // The scene query with method exact, over the poses read in place, on
    // every backend: exactly the pairs i < j the pose oracle calls colliding.
    std::vector<pair_index> colliding;
    for (std::uint32_t i = 0; i < count; ++i) {
        for (std::uint32_t j = i + 1; j < count; ++j) {
            if (obbsat::oracle::intersects(poses[i], poses[j])) {
                colliding.push_back(pair_index{i, j});
            }
        }
    }
    const auto expect_oracle_pairs = [&](const std::vector<pair_index>& found, const std::string& what) {
        bool same = found.size() == colliding.size();
        for (std::size_t k = 0; same && k < found.size(); ++k) {
            same = found[k].a == colliding[k].a && found[k].b == colliding[k].b;
        }
        if (same) {
            return;
        }
        std::string detail;
        const auto has = [](const std::vector<pair_index>& list, const pair_index& p) {
            return std::any_of(list.begin(), list.end(), [&](const pair_index& q) { return q.a == p.a && q.b == p.b; });
        };
        int shown = 0;
        for (const pair_index& p : found) {
            if (!has(colliding, p) && shown++ < 3) {
                detail += "\n  only the query: (" + std::to_string(p.a) + ", " + std::to_string(p.b) + ")\n    A " +
                          text_of(poses[p.a]) + "\n    B " + text_of(poses[p.b]);
            }
        }
        for (const pair_index& p : colliding) {
            if (!has(found, p) && shown++ < 6) {
                detail += "\n  only the oracle: (" + std::to_string(p.a) + ", " + std::to_string(p.b) + ")\n    A " +
                          text_of(poses[p.a]) + "\n    B " + text_of(poses[p.b]);
            }
        }
        stop(what + " reports " + std::to_string(found.size()) + " pairs, the pose oracle " +
             std::to_string(colliding.size()) + detail);
    };
    // A persistent query that saw the poses nudged by one ulp, then sees them
    // again: answered from the candidates it kept when they still fit, and
    // exactly the oracle's pairs either way.
    std::vector<rect_pose> nudged = poses;
    for (rect_pose& p : nudged) {
        const float x = std::nextafter(p.center.x, 0.0f);
        p.center.x = std::isfinite(x) ? x : p.center.x;
    }
    for (const backend b : obbsat::compiled_backends()) {
        if (!obbsat::cpu_supports(b)) {
            continue;
        }
        obbsat::collide_options options;
        options.test = method::exact;
        options.use = b;
        const std::string on = std::string(" on ") + obbsat::backend_name(b);
        expect_oracle_pairs(obbsat::find_pairs(poses, options), "find_pairs(exact)" + on);
        obbsat::pair_finder finder(options);
        finder.find(poses);
        finder.find(nudged);
        const std::vector<pair_index>& again = finder.find(poses);
        expect_oracle_pairs(again, "pair_finder(exact)" + on + " after a nudge, " +
                                       (finder.stats().reused_candidates ? "from kept candidates," : "full query,"));
    }
    std::vector<obbsat::rect> corners(count);
    for (const backend b : obbsat::compiled_backends()) {
        if (!obbsat::cpu_supports(b)) {
            continue;
        }
        obbsat::convert_to_corners(records, corners.data(), b);
        for (std::size_t i = 0; i < count; ++i) {
            const obbsat::rect expected = obbsat::ref::corners_of(poses[i]);
            if (std::memcmp(&expected, &corners[i], sizeof expected) != 0) {
                stop(std::string("corners of pose ") + std::to_string(i) + " differ on " + obbsat::backend_name(b) +
                     ": " + text_of(poses[i]));
            }
        }
    }
    return 0;
}
