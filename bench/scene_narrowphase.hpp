// The narrowphase of the grid and R-tree peers: their candidate pairs handed
// to obbsat::collide_pairs on the scene's poses with method exact, one core
// per part (scene_parts.hpp), and the colliding ones kept in candidate order.
// What a developer who brings their own broadphase would write.
#pragma once

#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat_bench {

/// One part's buffers, kept from one query to the next.
struct part_pairs {
    std::vector<obbsat::pair_index> candidates;
    std::vector<std::uint8_t> verdicts;
    std::vector<obbsat::pair_index> colliding;
};

/// part.colliding = the candidates of `part` whose poses collide exactly.
inline void decide_exact(const obbsat::pose_records& poses, part_pairs& part) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.threads = 1;
    part.verdicts.resize(part.candidates.size());
    obbsat::collide_pairs(poses, part.candidates.data(), part.candidates.size(), part.verdicts.data(), options);
    part.colliding.clear();
    for (std::size_t k = 0; k < part.candidates.size(); ++k) {
        if (part.verdicts[k] != 0) {
            part.colliding.push_back(part.candidates[k]);
        }
    }
}

/// The parts' colliding pairs one after another in `out`; their candidate count.
inline std::size_t join_parts(const std::vector<part_pairs>& parts, std::vector<obbsat::pair_index>& out) {
    out.clear();
    std::size_t candidates = 0;
    for (const part_pairs& part : parts) {
        out.insert(out.end(), part.colliding.begin(), part.colliding.end());
        candidates += part.candidates.size();
    }
    return candidates;
}

}  // namespace obbsat_bench
