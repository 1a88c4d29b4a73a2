// Sorting (key, value) pairs of 32-bit integers by key, stably: a least
// significant digit radix sort, 11 bits per pass, skipping passes whose digit
// is the same for every key. Internal to the library.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Sorts keys[0, n) and values[0, n) together by key, stably; `key_bits` is
/// the number of low bits that can be non-zero. spare_keys and spare_values
/// are grown to n and used as the other half of each pass.
void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits,
                std::vector<std::uint32_t>& spare_keys, std::vector<std::uint32_t>& spare_values);

/// Sorts keys[0, n) and values[0, n) by key, stably, when they are nearly
/// sorted already: an insertion sort that gives up (returning false, with the
/// arrays still a permutation of the input) once it has moved more than
/// `move_budget` elements.
bool repair_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, std::size_t move_budget);

}  // namespace obbsat::detail
