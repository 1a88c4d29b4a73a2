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
constexpr unsigned max_passes = 32 / digit_bits;

// Keys below which a second thread costs more than it saves, and the fewest
// keys a unit of the first pass takes.
constexpr std::size_t min_per_part = 32768;
constexpr std::size_t min_per_unit = 8192;

// Keys a fill writes at once: few enough to be read again from the caches.
constexpr std::size_t fill_slice = 4096;

// The most keys a bucket of the split on several threads may hold to be
// sorted in buffers of its own (two words a key, in a core's L2 cache).
constexpr std::size_t cached_bucket = 16384;

using digit_counts = std::array<std::size_t, digit_values>;
using all_digit_counts = std::array<digit_counts, max_passes>;

/// Digit `d` of a packed word: the key's bits [8d, 8d + 8).
inline std::size_t digit_of(std::uint64_t word, unsigned d) {
    return static_cast<std::size_t>(word >> (32 + d * digit_bits)) & (digit_values - 1);
}

/// Counts digits [0, digits) of words[0, n) into `counts` (added to it).
void count_digits(const std::uint64_t* words, std::size_t n, unsigned digits, all_digit_counts& counts) {
    for (std::size_t i = 0; i < n; ++i) {
        for (unsigned d = 0; d < digits; ++d) {
            ++counts[d][digit_of(words[i], d)];
        }
    }
}

/// The values of a sort: the caller's, values[i] with key i...
struct given_values {
    const std::uint32_t* values;

    std::uint32_t operator[](std::size_t i) const { return values[i]; }
    given_values from(std::size_t offset) const { return {values + offset}; }
};

/// ... or, in a sort of indices, i itself (counted from `first`): nothing to read.
struct index_values {
    std::size_t first;

    std::uint32_t operator[](std::size_t i) const { return static_cast<std::uint32_t>(first + i); }
    index_values from(std::size_t offset) const { return {first + offset}; }
};

/// Packs keys[i] and values[i] into words[i], key in the high half, and
/// counts digits [0, digits) of the keys into `counts` (added to it) on the way.
template <class Values>
void pack_and_count(const std::uint32_t* keys, Values values, std::size_t n, unsigned digits, std::uint64_t* words,
                    all_digit_counts& counts) {
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t key = keys[i];
        words[i] = (std::uint64_t{key} << 32) | values[i];
        for (unsigned d = 0; d < digits; ++d) {
            ++counts[d][(key >> (d * digit_bits)) & (digit_values - 1)];
        }
    }
}

/// Sorts the packed words source[0, n) stably by digits [0, digits) of their
/// keys, one pass a digit into `first` and back and forth between `second`
/// and `first` (n words each; `second` may be `source`, which is otherwise
/// only read), skipping a digit all of them share; `counts` holds each
/// digit's counts over them. Then writes the keys and values back, in their order.
void sort_words(const std::uint64_t* source, std::uint64_t* first, std::uint64_t* second, std::size_t n,
                unsigned digits, all_digit_counts& counts, std::uint32_t* keys, std::uint32_t* values) {
    const std::uint64_t* from = source;
    std::uint64_t* to = first;
    std::uint64_t* other = second;
    for (unsigned d = 0; d < digits; ++d) {
        // A copy of its own, which the scatter's stores cannot alias: the
        // compiler then keeps no reload of a slot after each store.
        digit_counts next = counts[d];
        std::size_t sum = 0;
        bool one_digit = false;
        for (std::size_t& slot : next) {
            const std::size_t here = slot;
            one_digit = one_digit || here == n;
            slot = sum;
            sum += here;
        }
        if (one_digit) {
            continue;  // every key has this digit: the pass would move nothing
        }
        for (std::size_t i = 0; i < n; ++i) {
            to[next[digit_of(from[i], d)]++] = from[i];
        }
        from = to;
        std::swap(to, other);
    }
    for (std::size_t i = 0; i < n; ++i) {
        keys[i] = static_cast<std::uint32_t>(from[i] >> 32);
        values[i] = static_cast<std::uint32_t>(from[i]);
    }
}

}  // namespace

namespace {

/// What a unit of the keys holds, for the split of a sort on several threads:
/// the counts of one digit, and the bits that some keys have and all have.
struct unit_survey {
    digit_counts counts;
    std::uint32_t any_bits;
    std::uint32_t all_bits;
};

/// Counts digit `d` of keys[0, n) into `survey` (added to it) and takes
/// their bits into its any_bits and all_bits.
void survey_keys(const std::uint32_t* keys, std::size_t n, unsigned d, unit_survey& survey) {
    std::uint32_t any = survey.any_bits;
    std::uint32_t all = survey.all_bits;
    digit_counts& counts = survey.counts;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t key = keys[i];
        ++counts[(key >> (d * digit_bits)) & (digit_values - 1)];
        any |= key;
        all &= key;
    }
    survey.any_bits = any;
    survey.all_bits = all;
}

/// radix_sort and radix_sort_indices (`fill` nullptr for the first) in lent memory.
template <class Values>
void sort_lent(std::uint32_t* keys, Values given, std::uint32_t* values, std::size_t n, unsigned key_bits,
               std::uint64_t* packed, std::uint64_t* spare, std::size_t parts, const radix_fill* fill,
               radix_bucket_buffers* buckets) {
    if (n < 2) {
        if (fill != nullptr) {
            (*fill)(0, n);
        }
        for (std::size_t i = 0; i < n; ++i) {
            values[i] = given[i];
        }
        return;
    }
    key_bits = std::min(key_bits, 32u);  // the keys have no more
    const unsigned digits = (key_bits + digit_bits - 1) / digit_bits;
    const std::size_t threads = std::max<std::size_t>(1, std::min(parts, n / min_per_part));
    if (threads == 1) {
        // Every digit is counted as the keys are packed: a digit's count over
        // all keys does not depend on their order, so no pass needs a read
        // of its own to count. Each slice the fill writes is packed while it
        // is still in the caches.
        all_digit_counts counts{};
        for (std::size_t begin = 0; begin < n; begin += fill_slice) {
            const std::size_t end = std::min(n, begin + fill_slice);
            if (fill != nullptr) {
                (*fill)(begin, end);
            }
            pack_and_count(keys + begin, given.from(begin), end - begin, digits, packed + begin, counts);
        }
        sort_words(packed, spare, packed, n, digits, counts, keys, values);
        return;
    }
    // On several threads the highest digit that varies goes first (most
    // significant digit first): units of the keys, taken as they come
    // (work_shares.hpp), count that digit over their slice (filling it
    // first), then pack their slice and scatter it by that digit after the
    // same digit of the slices before it. Each of the 256 buckets this
    // leaves, small enough for the caches, is then a unit of its own, sorted
    // by the lower digits (least significant first, its counts taken in one
    // read) and written back. Every step is stable, so the order does not
    // depend on the units or on who took them; no step makes both threads
    // wait for equal shares. The keys are packed as they are scattered, not
    // in a pass of their own, so the words go to memory once, not twice; and
    // only the one digit the scatter needs is counted before it. (The order
    // of a 1M-box query on two threads took 6.2-6.4 ms of thread time this
    // way, against 8.2-8.6 with a packing pass and the buckets sorted in the
    // lent memory; 6.2-6.5 on one thread. A loaded machine.)
    const std::size_t units = units_for(n, threads, min_per_unit);
    const auto begin_of = [n, units](std::size_t unit) { return n * unit / units; };
    // Each unit clears its own counts: cleared here, the cache lines of the
    // units the other thread takes would each have to leave this core first.
    scratch_vector<unit_survey> surveys(units);
    const unsigned top = digits - 1;
    run_units(units, threads, [&](std::size_t unit) {
        const std::size_t end = begin_of(unit + 1);
        unit_survey survey{{}, 0, ~std::uint32_t{0}};
        for (std::size_t begin = begin_of(unit); begin < end; begin += fill_slice) {
            const std::size_t slice_end = std::min(end, begin + fill_slice);
            if (fill != nullptr) {
                (*fill)(begin, slice_end);
            }
            survey_keys(keys + begin, slice_end - begin, top, survey);
        }
        surveys[unit] = survey;
    });
    // The highest digit whose keys differ: those above it are the same for every key.
    std::uint32_t any_bits = 0;
    std::uint32_t all_bits = ~std::uint32_t{0};
    for (const unit_survey& survey : surveys) {
        any_bits |= survey.any_bits;
        all_bits &= survey.all_bits;
    }
    // Only the digits the keys may have count (key_bits).
    const std::uint32_t digit_mask =
        digits * digit_bits >= 32 ? ~std::uint32_t{0} : (std::uint32_t{1} << (digits * digit_bits)) - 1;
    const std::uint32_t varying = any_bits & ~all_bits & digit_mask;
    if (varying == 0) {
        // Every key the same: the input is its own stable order.
        run_units(units, threads, [&](std::size_t unit) {
            for (std::size_t i = begin_of(unit); i < begin_of(unit + 1); ++i) {
                values[i] = given[i];
            }
        });
        return;
    }
    unsigned first = top;
    while (((varying >> (first * digit_bits)) & (digit_values - 1)) == 0) {
        --first;
    }
    if (first != top) {
        // Keys whose highest digits are all the same: the digit to split by
        // was not the one counted, and is counted now.
        run_units(units, threads, [&](std::size_t unit) {
            unit_survey survey{{}, 0, ~std::uint32_t{0}};
            survey_keys(keys + begin_of(unit), begin_of(unit + 1) - begin_of(unit), first, survey);
            surveys[unit].counts = survey.counts;
        });
    }
    // bucket_begin[v]: the first slot of the keys whose first digit is v;
    // slots[unit][v]: the first slot of the unit's keys whose first digit is
    // v. The slots go to a table of their own rather than over the counts:
    // half of these were written by the other thread, and writing over each
    // of its cache lines would wait for the line to leave the other core
    // (this step took 0.10 ms between the passes of a 1M-box query on two
    // threads, 0.04 ms with the table).
    std::vector<std::size_t> bucket_begin(digit_values + 1, 0);
    std::vector<digit_counts> slots(units);
    std::size_t sum = 0;
    for (std::size_t v = 0; v < digit_values; ++v) {
        bucket_begin[v] = sum;
        for (std::size_t unit = 0; unit < units; ++unit) {
            slots[unit][v] = sum;
            sum += surveys[unit].counts[v];
        }
    }
    bucket_begin[digit_values] = n;
    if (buckets != nullptr) {
        buckets->reserve_units(threads);
    }
    run_units(units, threads, [&](std::size_t unit) {
        digit_counts next = slots[unit];  // a copy of its own, as in sort_words
        std::uint64_t* const to = spare;
        const std::uint32_t* const from = keys;
        const Values with = given;
        const unsigned shift = first * digit_bits;
        const std::size_t end = begin_of(unit + 1);  // read once: the stores might alias what it reads
        for (std::size_t i = begin_of(unit); i < end; ++i) {
            const std::uint32_t key = from[i];
            to[next[(key >> shift) & (digit_values - 1)]++] = (std::uint64_t{key} << 32) | with[i];
        }
    });
    run_units(digit_values, threads, [&](std::size_t bucket) {
        const std::size_t begin = bucket_begin[bucket];
        const std::size_t size = bucket_begin[bucket + 1] - begin;
        all_digit_counts lower{};
        count_digits(spare + begin, size, first, lower);
        if (size > cached_bucket) {
            sort_words(spare + begin, packed + begin, spare + begin, size, first, lower, keys + begin,
                       values + begin);
            return;
        }
        // The passes go between two buffers of the unit's own, which stay in
        // the caches, rather than through the lent memory: the bucket is only
        // read there, so none of its lines is fetched to be written over, or
        // written back. They are the caller's, kept between calls, when it
        // lends them (radix_bucket_buffers).
        const radix_bucket_buffers::lease passes(buckets, 2 * size);
        sort_words(spare + begin, passes.data(), passes.data() + size, size, first, lower, keys + begin,
                   values + begin);
    });
}

/// Grows the caller's buffers to n words.
void grow_buffers(std::size_t n, radix_buffer& packed, radix_buffer& spare) {
    if (packed.size() < n) {
        packed.resize(n);
    }
    if (spare.size() < n) {
        spare.resize(n);
    }
}

}  // namespace

void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, radix_buffer& packed,
                radix_buffer& spare, std::size_t parts, radix_bucket_buffers* buckets) {
    if (n < 2) {
        return;
    }
    grow_buffers(n, packed, spare);
    sort_lent(keys, given_values{values}, values, n, key_bits, packed.data(), spare.data(), parts, nullptr, buckets);
}

void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, std::uint64_t* packed,
                std::uint64_t* spare, std::size_t parts) {
    sort_lent(keys, given_values{values}, values, n, key_bits, packed, spare, parts, nullptr, nullptr);
}

void radix_sort_indices(std::uint32_t* keys, std::uint32_t* indices, std::size_t n, unsigned key_bits,
                        radix_buffer& packed, radix_buffer& spare, std::size_t parts, const radix_fill& fill,
                        radix_bucket_buffers* buckets) {
    grow_buffers(n, packed, spare);
    sort_lent(keys, index_values{0}, indices, n, key_bits, packed.data(), spare.data(), parts, &fill, buckets);
}

void radix_sort_indices(std::uint32_t* keys, std::uint32_t* indices, std::size_t n, unsigned key_bits,
                        std::uint64_t* packed, std::uint64_t* spare, std::size_t parts, const radix_fill& fill,
                        radix_bucket_buffers* buckets) {
    sort_lent(keys, index_values{0}, indices, n, key_bits, packed, spare, parts, &fill, buckets);
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
