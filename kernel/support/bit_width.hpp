// Counting bits: the bits an unsigned value needs, the bits set in a word.
// Internal to the library.
#pragma once

#include <cstdint>

namespace obbsat::detail {

/// The bits `largest` needs: 0 for 0, 1 for 1, 2 for 2 and 3, and so on.
inline unsigned bits_for(std::uint64_t largest) {
    unsigned bits = 0;
    while (bits < 64 && (largest >> bits) != 0) {
        ++bits;
    }
    return bits;
}

/// The bits set in `word`, in a few shifts and adds: the library's baseline
/// ISA has no population count instruction, and the compiler's builtin is
/// then a call.
inline unsigned bits_set(std::uint64_t word) {
    word = word - ((word >> 1) & 0x5555555555555555ull);
    word = (word & 0x3333333333333333ull) + ((word >> 2) & 0x3333333333333333ull);
    word = (word + (word >> 4)) & 0x0f0f0f0f0f0f0f0full;
    return static_cast<unsigned>((word * 0x0101010101010101ull) >> 56);
}

}  // namespace obbsat::detail
