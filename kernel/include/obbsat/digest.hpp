// A fingerprint of a verdict array, to compare runs across backends, thread
// counts and machines at a glance.
#pragma once

#include <cstddef>
#include <cstdint>

namespace obbsat {

/// FNV-1a (64-bit) over the verdict bytes.
inline std::uint64_t verdict_digest(const std::uint8_t* verdicts, std::size_t count) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 0; i < count; ++i) {
        h = (h ^ verdicts[i]) * 0x100000001b3ull;
    }
    return h;
}

}  // namespace obbsat
