// The number of bits an unsigned value needs. Internal to the library.
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

}  // namespace obbsat::detail
