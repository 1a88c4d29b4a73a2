// The contacts of a scene query's pairs (find_contacts, obbsat/find_contacts.hpp),
// computed on the caller's rows once the pairs are sorted, each written once,
// straight into its place in the answer. Internal to the library, baseline ISA.
//
// Why after the sort: the answer is in the caller's order, (a, b), and the
// query finds its pairs in the plane's. Whichever way the contacts are
// computed, one of the two orders is read or written at random. Here it is
// the rows of the b boxes, read at random (the a rows in order, the kernel
// fetching the rows of the pairs ahead); the contacts themselves are written
// in order, once. Computing each contact in the sweep instead, on records the
// cache held, then reading it back through a tag in the answer's order cost
// more (1M boxes, one thread, a kept answer: 91-95 ms of CPU against 74-76,
// find_pairs 54-58, on a busy machine): it wrote every contact twice (a
// block, then the answer), read the blocks at random, 48 bytes a pair against
// a row's 24 or 32, and sorted 12-byte tagged pairs where the query sorts 8-byte
// ones.
#pragma once

#include "dispatch/contact_kernel_table.hpp"
#include "support/scratch_vector.hpp"

#include <obbsat/contact_manifold.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <vector>

namespace obbsat::detail {

/// The contact kernel and contact of one precision: float rows give
/// `contact`s (contact_fn), double rows `contact64`s (contact64_fn).
template <class Real>
struct contact_types;
template <>
struct contact_types<float> {
    using kernel = contact_fn;
    using value = contact;
};
template <>
struct contact_types<double> {
    using kernel = contact64_fn;
    using value = contact64;
};

/// The contact of a pair of `Real` rows.
template <class Real>
using contact_of_rows = typename contact_types<Real>::value;

/// The contact kernel on the caller's rows: box a of a pair is the row at
/// a + a_stride * pair.a (in floats or doubles), box b the row at
/// b + b_stride * pair.b. Double rows are whole 8-double records (the double
/// kernels read no other stride).
template <class Real>
struct contact_rows_of {
    typename contact_types<Real>::kernel kernel = nullptr;
    const Real* a = nullptr;
    std::size_t a_stride = 0;
    const Real* b = nullptr;
    std::size_t b_stride = 0;
    Real margin = 0;
};

using contact_rows = contact_rows_of<float>;
using contact_rows64 = contact_rows_of<double>;

/// out[k] = the contact of pairs[k] on `rows`, k < count, split over `threads`.
template <class Real>
void contacts_of_pairs(const contact_rows_of<Real>& rows, const pair_index* pairs, std::size_t count,
                       contact_of_rows<Real>* out, unsigned threads);

/// `out` = the contact of each of `pairs` on `rows`, each element written
/// once: `out` keeps its memory, its old elements are overwritten in place
/// and only what it grows by is new (appended by one thread a block at a
/// time; std::vector would zero it first, a second write of memory the
/// caches do not hold).
template <class Real>
void contacts_of_answer(const contact_rows_of<Real>& rows, const std::vector<pair_index>& pairs,
                        std::vector<contact_of_rows<Real>>& out, unsigned threads);

/// Double pose rows of the caller (rect_pose64, six doubles each) as the
/// 8-double records the double contact kernels read: `records` keeps its
/// memory from one call to the next.
class double_pose_records {
public:
    /// Copies `count` rows of six doubles from `rows`, split over `threads`,
    /// and tells whether contacts accept every one (obbsat/contact.hpp): the
    /// check reads each run of records just copied, which L1 still holds,
    /// rather than the caller's rows again (1M rows: 48 MB).
    bool copy_accepted(const double* rows, std::size_t count, unsigned threads);
    /// The records of the last copy_accepted.
    const double* data() const { return records_.data(); }
    /// Bytes of memory held.
    std::size_t bytes() const { return records_.capacity() * sizeof(double); }

private:
    scratch_records<double> records_;
};

/// What find_contacts keeps from one call to the next (a million boxes'
/// worth is some 200 MB, and fresh memory costs the OS a page fault and a
/// zeroing per page on every call), and the answer it makes of the
/// candidates at a margin.
class near_contacts {
public:
    /// The pairs the method reports, sorted by (a, b). At margin 0 they are
    /// the answer's pairs until contacts accept every row, then swapped with
    /// the caller's (find_contacts.cpp, touching_contacts).
    std::vector<pair_index> reported;
    std::vector<rect_pose> stand_ins;    ///< each box's widened stand-in
    std::vector<pair_index> candidates;  ///< the pairs of stand-ins, sorted by (a, b)
    double_pose_records records64;       ///< double pose rows as records (at every margin)

    /// `found` = the candidates the method reported or whose contact on
    /// `rows` has a point, each with its contact; every reported pair is a
    /// candidate.
    void answer(const contact_rows& rows, unsigned threads, scene_contacts& found);
    /// The same on double rows.
    void answer(const contact_rows64& rows, unsigned threads, scene_contacts64& found);

private:
    template <class Real, class Found>
    void answer_of(const contact_rows_of<Real>& rows, unsigned threads, scratch_records<contact_of_rows<Real>>& contacts,
                   Found& found);

    scratch_records<contact> contacts_;      ///< the candidates' contacts on float rows
    scratch_records<contact64> contacts64_;  ///< on double rows
};

/// What a pair_finder's frames with double contacts keep
/// (pair_finder::find_contacts64): the answer, and the double pose rows of
/// each set as records.
struct frame_contacts64 {
    scene_contacts64 answer;
    double_pose_records a_records;
    double_pose_records b_records;
};

/// Frees the near_contacts find_contacts keeps for its next call
/// (find_contacts.cpp); a call running now keeps its own until it ends.
void release_kept_contacts();

/// Bytes of memory the near_contacts kept for find_contacts' next call hold
/// in double pose records (0 when none is kept).
std::size_t kept_contacts_record_bytes();

}  // namespace obbsat::detail
