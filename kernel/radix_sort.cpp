#include "radix_sort.hpp"

#include <algorithm>
#include <array>

namespace obbsat::detail {

namespace {

constexpr unsigned digit_bits = 8;
constexpr std::size_t digit_values = std::size_t{1} << digit_bits;

}  // namespace

void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, radix_buffer& packed,
                radix_buffer& spare) {
    if (n < 2) {
        return;
    }
    if (packed.size() < n) {
        packed.resize(n);
    }
    if (spare.size() < n) {
        spare.resize(n);
    }
    std::uint64_t* from = packed.data();
    std::uint64_t* to = spare.data();
    for (std::size_t i = 0; i < n; ++i) {
        from[i] = (std::uint64_t{keys[i]} << 32) | values[i];
    }
    std::array<std::size_t, digit_values> count{};
    for (unsigned shift = 32; shift < 32 + key_bits; shift += digit_bits) {
        count.fill(0);
        for (std::size_t i = 0; i < n; ++i) {
            ++count[(from[i] >> shift) & (digit_values - 1)];
        }
        if (count[(from[0] >> shift) & (digit_values - 1)] == n) {
            continue;  // every key has this digit: the pass would move nothing
        }
        std::size_t sum = 0;
        for (std::size_t& c : count) {
            const std::size_t here = c;
            c = sum;
            sum += here;
        }
        for (std::size_t i = 0; i < n; ++i) {
            to[count[(from[i] >> shift) & (digit_values - 1)]++] = from[i];
        }
        std::swap(from, to);
    }
    for (std::size_t i = 0; i < n; ++i) {
        keys[i] = static_cast<std::uint32_t>(from[i] >> 32);
        values[i] = static_cast<std::uint32_t>(from[i]);
    }
}

bool repair_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, std::size_t move_budget) {
    std::size_t moved = 0;
    for (std::size_t i = 1; i < n; ++i) {
        const std::uint32_t key = keys[i];
        if (keys[i - 1] <= key) {
            continue;
        }
        const std::uint32_t value = values[i];
        std::size_t j = i;
        while (j > 0 && keys[j - 1] > key) {
            keys[j] = keys[j - 1];
            values[j] = values[j - 1];
            --j;
        }
        keys[j] = key;
        values[j] = value;
        moved += i - j;
        if (moved > move_budget) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::detail
