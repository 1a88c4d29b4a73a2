#include "sort/radix_sort.hpp"

#include "support/work_shares.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>

namespace obbsat::detail {

namespace {

constexpr unsigned digit_bits = 8;
constexpr std::size_t digit_values = std::size_t{1} << digit_bits;

// Keys below which a second thread costs more than it saves, and the fewest
// keys a unit of a pass takes: below that its 256 counts and write streams
// cost more than its keys.
constexpr std::size_t min_per_part = 32768;
constexpr std::size_t min_per_unit = 8192;

}  // namespace

void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, radix_buffer& packed,
                radix_buffer& spare, std::size_t parts) {
    if (n < 2) {
        return;
    }
    if (packed.size() < n) {
        packed.resize(n);
    }
    if (spare.size() < n) {
        spare.resize(n);
    }
    radix_sort(keys, values, n, key_bits, packed.data(), spare.data(), parts);
}

void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, std::uint64_t* packed,
                std::uint64_t* spare, std::size_t parts) {
    if (n < 2) {
        return;
    }
    // The passes are cut into units taken as they come (work_shares.hpp): a
    // thread slowed by other work on its core takes fewer of them. Each unit
    // counts and scatters its own slice, after the same digit of the slices
    // before it, so the sort stays stable however the units are taken.
    const std::size_t threads = std::max<std::size_t>(1, std::min(parts, n / min_per_part));
    const std::size_t units = units_for(n, threads, min_per_unit);
    key_bits = std::min(key_bits, 32u);  // the keys have no more
    std::uint64_t* from = packed;
    std::uint64_t* to = spare;
    const auto run = [units, threads](const std::function<void(std::size_t)>& task) {
        if (units == 1) {
            task(0);
        } else {
            run_units(units, threads, task);
        }
    };
    const auto begin_of = [n, units](std::size_t unit) { return n * unit / units; };
    // On one thread the counts of every digit are taken as the keys are
    // packed: a digit's count over all keys does not depend on their order,
    // so no pass needs a read of its own to count. With several units each
    // unit counts the slice it holds at the start of each pass.
    constexpr unsigned max_passes = 32 / digit_bits;
    const unsigned passes = std::min(max_passes, (key_bits + digit_bits - 1) / digit_bits);
    std::array<std::array<std::size_t, digit_values>, max_passes> counted{};
    if (units == 1) {
        std::uint64_t* const out = from;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t key = keys[i];
            out[i] = (std::uint64_t{key} << 32) | values[i];
            for (unsigned d = 0; d < passes; ++d) {
                ++counted[d][(key >> (d * digit_bits)) & (digit_values - 1)];
            }
        }
    } else {
        run([&](std::size_t unit) {
            for (std::size_t i = begin_of(unit); i < begin_of(unit + 1); ++i) {
                from[i] = (std::uint64_t{keys[i]} << 32) | values[i];
            }
        });
    }
    // count[unit][digit]: each unit counts its own slice, then scatters it to
    // the slots after every lower digit and after the same digit of lower
    // units, which keeps the sort stable.
    std::vector<std::array<std::size_t, digit_values>> count(units);
    for (unsigned shift = 32; shift < 32 + key_bits; shift += digit_bits) {
        if (units == 1) {
            count[0] = counted[(shift - 32) / digit_bits];
        } else {
            run([&](std::size_t unit) {
                std::array<std::size_t, digit_values>& c = count[unit];
                c.fill(0);
                for (std::size_t i = begin_of(unit); i < begin_of(unit + 1); ++i) {
                    ++c[(from[i] >> shift) & (digit_values - 1)];
                }
            });
        }
        std::size_t sum = 0;
        bool one_digit = false;
        for (std::size_t d = 0; d < digit_values; ++d) {
            std::size_t of_digit = 0;
            for (std::size_t unit = 0; unit < units; ++unit) {
                const std::size_t here = count[unit][d];
                count[unit][d] = sum;
                sum += here;
                of_digit += here;
            }
            one_digit = one_digit || of_digit == n;
        }
        if (one_digit) {
            continue;  // every key has this digit: the pass would move nothing
        }
        run([&](std::size_t unit) {
            std::array<std::size_t, digit_values>& c = count[unit];
            for (std::size_t i = begin_of(unit); i < begin_of(unit + 1); ++i) {
                to[c[(from[i] >> shift) & (digit_values - 1)]++] = from[i];
            }
        });
        std::swap(from, to);
    }
    run([&](std::size_t unit) {
        for (std::size_t i = begin_of(unit); i < begin_of(unit + 1); ++i) {
            keys[i] = static_cast<std::uint32_t>(from[i] >> 32);
            values[i] = static_cast<std::uint32_t>(from[i]);
        }
    });
}

void bucket_starts(const std::uint32_t* keys, std::size_t n, unsigned shift, std::size_t buckets, std::size_t begin,
                   std::size_t end, std::uint32_t* starts) {
    // Index i starts the buckets after the one of i - 1, up to its own.
    std::size_t next = begin == 0 ? 0 : (keys[begin - 1] >> shift) + 1;
    for (std::size_t i = begin; i < end; ++i) {
        const std::size_t bucket = keys[i] >> shift;
        for (; next <= bucket; ++next) {
            starts[next] = static_cast<std::uint32_t>(i);
        }
    }
    if (end == n) {
        for (; next <= buckets; ++next) {
            starts[next] = static_cast<std::uint32_t>(n);
        }
    }
}

void merge_by_key(const std::uint32_t* a_keys, const std::uint32_t* a_values, std::size_t a_n,
                  const std::uint32_t* b_keys, const std::uint32_t* b_values, std::size_t b_n,
                  std::uint32_t* out_keys, std::uint32_t* out_values, std::size_t parts) {
    // Share s takes the entries of both runs whose keys lie from its split
    // key up to the next one, and writes them after the entries of both runs
    // before its split key: the shares write apart and at the same time.
    // The split keys are taken from the longer run, at equal steps. The
    // shares are units taken as they come (work_shares.hpp), a few a thread.
    constexpr std::size_t least_share = 16384;
    const std::size_t threads = std::max<std::size_t>(1, std::min(parts, (a_n + b_n) / least_share));
    const std::size_t shares = units_for(a_n + b_n, threads, least_share / 2);
    std::vector<std::size_t> a_at(shares + 1), b_at(shares + 1);
    a_at[0] = b_at[0] = 0;
    a_at[shares] = a_n;
    b_at[shares] = b_n;
    for (std::size_t s = 1; s < shares; ++s) {
        const std::uint32_t split = a_n >= b_n ? a_keys[a_n * s / shares] : b_keys[b_n * s / shares];
        a_at[s] = static_cast<std::size_t>(std::lower_bound(a_keys, a_keys + a_n, split) - a_keys);
        b_at[s] = static_cast<std::size_t>(std::lower_bound(b_keys, b_keys + b_n, split) - b_keys);
    }
    const auto merge_share = [&](std::size_t share) {
        std::size_t i = a_at[share];
        std::size_t j = b_at[share];
        const std::size_t i_end = a_at[share + 1];
        const std::size_t j_end = b_at[share + 1];
        std::size_t out = i + j;
        while (i < i_end && j < j_end) {
            const bool from_a = a_keys[i] < b_keys[j] || (a_keys[i] == b_keys[j] && a_values[i] <= b_values[j]);
            out_keys[out] = from_a ? a_keys[i] : b_keys[j];
            out_values[out] = from_a ? a_values[i] : b_values[j];
            i += from_a ? 1 : 0;
            j += from_a ? 0 : 1;
            ++out;
        }
        std::copy(a_keys + i, a_keys + i_end, out_keys + out);
        std::copy(a_values + i, a_values + i_end, out_values + out);
        out += i_end - i;
        std::copy(b_keys + j, b_keys + j_end, out_keys + out);
        std::copy(b_values + j, b_values + j_end, out_values + out);
    };
    run_units(shares, threads, merge_share);  // on this thread alone for one share
}

bool repair_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, std::size_t move_budget,
                 std::size_t* moved_out) {
    std::size_t moved = 0;
    for (std::size_t i = 1; i < n; ++i) {
        const std::uint32_t key = keys[i];
        if (keys[i - 1] <= key) {
            continue;
        }
        // The first of the sorted prefix greater than key: the insertion
        // point that keeps equal keys in their order. The block after it
        // moves up by one in one memmove each, cheap even when a rectangle
        // that changed strips crosses a whole strip.
        const std::size_t j = static_cast<std::size_t>(std::upper_bound(keys, keys + i, key) - keys);
        moved += i - j;
        if (moved > move_budget) {
            if (moved_out != nullptr) {
                *moved_out = moved;
            }
            return false;
        }
        const std::uint32_t value = values[i];
        std::memmove(keys + j + 1, keys + j, (i - j) * sizeof(std::uint32_t));
        std::memmove(values + j + 1, values + j, (i - j) * sizeof(std::uint32_t));
        keys[j] = key;
        values[j] = value;
    }
    if (moved_out != nullptr) {
        *moved_out = moved;
    }
    return true;
}

}  // namespace obbsat::detail
