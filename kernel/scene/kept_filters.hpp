// The pair filters pair_finder's kept candidates were built with
// (kept_pairs.hpp). The sweep drops a filtered pair before it is kept, so
// the kept candidates hold only pairs that the filters of the full query
// that kept them let through, and a kept pair stays right as long as both
// of its rows keep their filters. A copy of the last call's filters, in its
// rows (20 bytes per rectangle at most), is compared with each call's:
//   - rows matched by position (no ids): value for value; any change makes
//     the call a full query that keeps anew;
//   - rows matched by id (box_view::with_ids; id_rows.hpp): each row with
//     the values its id had in the last call; a row whose filters changed is
//     taken as a row gone and a new one with the same id (its kept pairs
//     dropped, its candidates found anew with the filters, kept_changes.cpp),
//     so rows that come, go, move and change filters are all absorbed.
// Filters given or taken away (an array present in one call and not in the
// other) make a full query either way. Keeping the candidates unfiltered
// instead would keep and refresh pairs that no call reports (a compound
// body's own pairs, which always overlap) and gather every rectangle's
// filters on each call. Internal to the library.
#pragma once

#include "scene/id_rows.hpp"
#include "scene/query_input.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

class kept_filters {
public:
    /// True iff `input` carries the filters take() last copied: the same
    /// arrays given, holding the same values (same counts assumed checked).
    bool same_as(const query_input& input) const;
    /// Rows matched by id (`a`, and `b` across two sets, else nullptr): false
    /// when an array was given or taken away since take(), or the copy is not
    /// of the matched rows; else appends to `changed_a` (`changed_b`) each last
    /// row, in increasing order, whose row now holds other filter values.
    bool changed_rows(const query_input& input, const row_match& a, const row_match* b,
                      std::vector<std::uint32_t>& changed_a, std::vector<std::uint32_t>& changed_b) const;
    /// Copies the filters of `input`, those the kept candidates now hold.
    void take(const query_input& input);

private:
    /// The filters of one set; an array not given is empty and not `has_`.
    struct side_copy {
        bool has_categories = false;
        bool has_masks = false;
        bool has_groups = false;
        std::vector<std::uint64_t> categories, masks;
        std::vector<std::int32_t> groups;

        bool same_as(const pair_filters& f, std::size_t count) const;
        bool same_arrays(const pair_filters& f) const;
        bool changed_rows(const pair_filters& f, const row_match& m, std::vector<std::uint32_t>& changed) const;
        void take(const pair_filters& f, std::size_t count);
    };
    side_copy a_, b_;
};

}  // namespace obbsat::detail
