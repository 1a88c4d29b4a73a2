// The contacts of a scene query's sorted pairs, on the caller's rows (query_contacts.hpp).
#include "scene/query_contacts.hpp"

#include "store/contact_acceptance.hpp"
#include "support/fetch_ahead.hpp"
#include "support/huge_pages.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace obbsat::detail {

namespace {

// A contact costs a few nanoseconds: below this many pairs a part, waking
// another core costs more than it saves. Parts start on multiples of the
// widest backend's vector.
constexpr std::size_t min_pairs_per_part = 2048;
constexpr std::size_t part_alignment = 64;

/// Contacts appended a block at a time go through a buffer of this many
/// (96 KiB, which L2 holds and the allocator serves from its heap).
constexpr std::size_t appended_block = 2048;

/// Double pose rows copied into records by one thread at least this many a part.
constexpr std::size_t min_rows_per_copy = 16384;

/// Records checked for contacts' acceptance right after each run of this
/// many is copied (16 KiB, which L1 holds).
constexpr std::size_t rows_per_checked_run = 256;

/// Makes room in `out` for `count` elements without keeping its old ones
/// (all are about to be overwritten): fresh memory, in huge pages for a
/// large answer, only when its capacity is short.
template <class T>
void make_room(std::vector<T>& out, std::size_t count) {
    if (out.capacity() < count) {
        out.clear();
        out.reserve(count);
        advise_huge_pages(out.data(), count * sizeof(T));
    }
}

}  // namespace

template <class Real>
void contacts_of_pairs(const contact_rows_of<Real>& rows, const pair_index* pairs, std::size_t count,
                       contact_of_rows<Real>* out, unsigned threads) {
    const std::size_t parts = parts_for(count, threads, min_pairs_per_part);
    run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = aligned_share_of(count, part, parts, part_alignment);
        if (begin < end) {
            rows.kernel(rows.a, rows.a_stride, rows.b, rows.b_stride, pairs + begin, end - begin, rows.margin,
                        out + begin);
        }
    });
}

template <class Real>
void contacts_of_answer(const contact_rows_of<Real>& rows, const std::vector<pair_index>& pairs,
                        std::vector<contact_of_rows<Real>>& out, unsigned threads) {
    const std::size_t n = pairs.size();
    make_room(out, n);
    if (out.size() >= n || parts_for(n, threads, min_pairs_per_part) > 1) {
        // Kept elements enough (a caller's answer kept between calls), or
        // several threads, which write their shares in place: the new
        // elements zeroed once by resize, a cost only while the answer grows.
        out.resize(n);
        contacts_of_pairs(rows, pairs.data(), n, out.data(), threads);
        return;
    }
    // One thread: the kept elements in place, then the rest appended.
    const std::size_t kept = out.size();
    contacts_of_pairs(rows, pairs.data(), kept, out.data(), 1);
    scratch_vector<contact_of_rows<Real>> block(std::min(appended_block, n - kept));
    for (std::size_t begin = kept; begin < n; begin += appended_block) {
        const std::size_t count = std::min(appended_block, n - begin);
        // The kernel fetches the rows of the pairs ahead only within one
        // call: the next block's first ones are asked for here.
        const std::size_t next_end = std::min(n, begin + count + random_rows_ahead);
        for (std::size_t k = begin + count; k < next_end; ++k) {
            fetch_into_l2(rows.a + rows.a_stride * pairs[k].a);
            fetch_into_l2(rows.b + rows.b_stride * pairs[k].b);
        }
        rows.kernel(rows.a, rows.a_stride, rows.b, rows.b_stride, pairs.data() + begin, count, rows.margin,
                    block.data());
        out.insert(out.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(count));
    }
}

template void contacts_of_pairs(const contact_rows&, const pair_index*, std::size_t, contact*, unsigned);
template void contacts_of_pairs(const contact_rows64&, const pair_index*, std::size_t, contact64*, unsigned);
template void contacts_of_answer(const contact_rows&, const std::vector<pair_index>&, std::vector<contact>&, unsigned);
template void contacts_of_answer(const contact_rows64&, const std::vector<pair_index>&, std::vector<contact64>&,
                                 unsigned);

bool double_pose_records::copy_accepted(const double* rows, std::size_t count, unsigned threads) {
    if (records_.size() < 8 * count) {
        records_ = scratch_records<double>(8 * count);  // unwritten until the copy writes it
    }
    double* out = records_.data();
    const std::size_t parts = parts_for(count, threads, min_rows_per_copy);
    std::vector<std::uint8_t> part_accepted(parts, 1);
    run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = share_of(count, part, parts);
        bool accepted = true;
        for (std::size_t run_begin = begin; run_begin < end; run_begin += rows_per_checked_run) {
            const std::size_t run_end = std::min(end, run_begin + rows_per_checked_run);
            for (std::size_t row = run_begin; row < run_end; ++row) {
                std::memcpy(out + 8 * row, rows + 6 * row, 6 * sizeof(double));
                out[8 * row + 6] = 0.0;
                out[8 * row + 7] = 0.0;
            }
            accepted &= poses_all_accepted(out + 8 * run_begin, 8, run_end - run_begin);
        }
        part_accepted[part] = accepted ? 1 : 0;
    });
    return std::all_of(part_accepted.begin(), part_accepted.end(), [](std::uint8_t a) { return a != 0; });
}

void near_contacts::answer(const contact_rows& rows, unsigned threads, scene_contacts& found) {
    answer_of(rows, threads, contacts_, found);
}

void near_contacts::answer(const contact_rows64& rows, unsigned threads, scene_contacts64& found) {
    answer_of(rows, threads, contacts64_, found);
}

template <class Real, class Found>
void near_contacts::answer_of(const contact_rows_of<Real>& rows, unsigned threads,
                              scratch_records<contact_of_rows<Real>>& contacts, Found& found) {
    const std::size_t n = candidates.size();
    if (contacts.size() < n) {
        contacts = scratch_records<contact_of_rows<Real>>(n);  // unwritten until the kernel writes; huge pages from 4 MiB
    }
    contacts_of_pairs(rows, candidates.data(), n, contacts.data(), threads);
    // Both lists are sorted; a candidate stays when the method reported it
    // or its contact has a point. At most every candidate stays: room for
    // all of them costs no page the answer does not write.
    make_room(found.pairs, n);
    make_room(found.contacts, n);
    found.pairs.clear();
    found.contacts.clear();
    const auto precedes = [](const pair_index& x, const pair_index& y) {
        return x.a < y.a || (x.a == y.a && x.b < y.b);
    };
    std::size_t next = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const pair_index& candidate = candidates[k];
        while (next < reported.size() && precedes(reported[next], candidate)) {
            ++next;
        }
        const bool is_reported =
            next < reported.size() && reported[next].a == candidate.a && reported[next].b == candidate.b;
        if (is_reported || contacts[k].point_count > 0) {
            found.pairs.push_back(candidate);
            found.contacts.push_back(contacts[k]);
        }
    }
}

}  // namespace obbsat::detail
