#include "radix_sort.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace obbsat::detail {

namespace {

constexpr unsigned digit_bits = 11;
constexpr std::size_t digit_values = std::size_t{1} << digit_bits;

}  // namespace

void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits,
                std::vector<std::uint32_t>& spare_keys, std::vector<std::uint32_t>& spare_values) {
    if (n < 2) {
        return;
    }
    if (spare_keys.size() < n) {
        spare_keys.resize(n);
    }
    if (spare_values.size() < n) {
        spare_values.resize(n);
    }
    std::uint32_t* from_keys = keys;
    std::uint32_t* from_values = values;
    std::uint32_t* to_keys = spare_keys.data();
    std::uint32_t* to_values = spare_values.data();
    std::array<std::size_t, digit_values> count{};
    for (unsigned shift = 0; shift < key_bits; shift += digit_bits) {
        count.fill(0);
        for (std::size_t i = 0; i < n; ++i) {
            ++count[(from_keys[i] >> shift) & (digit_values - 1)];
        }
        if (count[(from_keys[0] >> shift) & (digit_values - 1)] == n) {
            continue;  // every key has this digit: the pass would move nothing
        }
        std::size_t sum = 0;
        for (std::size_t& c : count) {
            const std::size_t here = c;
            c = sum;
            sum += here;
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t slot = count[(from_keys[i] >> shift) & (digit_values - 1)]++;
            to_keys[slot] = from_keys[i];
            to_values[slot] = from_values[i];
        }
        std::swap(from_keys, to_keys);
        std::swap(from_values, to_values);
    }
    if (from_keys != keys) {
        std::memcpy(keys, from_keys, n * sizeof(std::uint32_t));
        std::memcpy(values, from_values, n * sizeof(std::uint32_t));
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
