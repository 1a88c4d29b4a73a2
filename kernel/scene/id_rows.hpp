// The rows of a pair_finder's last call by the caller's ids
// (box_view::with_ids), and the match of a call's ids against them: which
// rows are the same boxes as before (and where they were), which are new,
// which are gone. One set of rows per id_rows; a query across two sets has
// one for each. Internal to the library.
//
// The match walks this call's ids and the last call's side by side: equal
// ids are the same row; at a difference a short look-ahead on either side
// tells a removed row (the last call's id shows up a few rows later) from an
// inserted one (this call's id shows up a few rows later), so rows that
// shift after a removal or an insertion cost one comparison each. The few
// rows left over (a swap-remove's moved row, new rows, gone rows) are matched
// through a small table of the left-over last ids. Duplicate ids are found
// on the way, with a set of the last call's ids (the last ids are unique, so
// a duplicate involves a row that is new or left over): see match().
//
// Memory: 8 bytes per row for the last ids and 18 to 36 for the set (9
// bytes a place, at a load between a quarter and a half), 4 for the match.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// A row of no match: a new row has no last row, a gone row no row now.
constexpr std::uint32_t no_row = 0xffffffffu;

/// How one call's rows relate to the last call's (id_rows::match).
struct row_match {
    /// For each row of the last call, its row now, or no_row when its id is gone.
    std::vector<std::uint32_t> now_of_last;
    /// Rows now whose id the last call did not have, in increasing order.
    std::vector<std::uint32_t> fresh;
    /// Rows of the last call whose id is not here now, in increasing order.
    std::vector<std::uint32_t> gone;
    /// Rows now outside the runs of rows with the last call's ids (new rows,
    /// and rows matched through the left-over ids), in increasing order.
    std::vector<std::uint32_t> off_runs;
    /// Every run of rows with the last call's ids kept its rows (no row
    /// shifted): only the rows off_runs hold ids other than the last call's
    /// at the same row, so commit() writes those alone.
    bool runs_in_place = false;
    std::size_t last_count = 0;  ///< rows of the last call
    std::size_t count = 0;       ///< rows now
    bool same_rows = false;      ///< every row is the last call's row at the same position
    /// No left-over row was matched (rows only removed, inserted or appended,
    /// or taken as new): now_of_last increases past its no_row entries.
    bool in_order = true;

    bool unchanged() const { return same_rows; }
};

/// Takes the last call's rows `last_rows` (increasing, each matched to a row
/// now) as gone and their rows now as fresh, with the same ids: a row whose
/// pair filters changed is carried over as a new row (kept_filters.hpp).
void rematch_as_new(row_match& m, const std::vector<std::uint32_t>& last_rows);

/// The ids of the last call's rows, and where each one was.
class id_rows {
public:
    /// Whether a last call's ids are held.
    bool ready() const { return ready_; }
    /// The last call's ids, one per row.
    const std::vector<std::uint64_t>& ids() const { return ids_; }

    /// Matches `ids` (one per row now) against the last call's (against none
    /// when not ready or not `follow`: every row is fresh) into `out`;
    /// changes nothing here.
    /// Throws invalid_input when two rows share an id, naming both rows and
    /// the id, `label` in front ("a: " or "b: " in a query across two sets).
    void match(const std::uint64_t* ids, std::size_t count, bool follow, const char* label, row_match& out) const;

    /// Makes `ids` the last call's, as matched by match() into `m` (matched
    /// against none when m.last_count is 0).
    void commit(const std::uint64_t* ids, const row_match& m);

    /// Forgets the last call's ids (a call without ids, or one that failed).
    void clear();

private:
    /// The place of `id` in the set, or the empty place where it would go.
    std::size_t find_place(std::uint64_t id) const;
    bool contains(std::uint64_t id) const;
    void insert(std::uint64_t id);
    void erase(std::uint64_t id);
    void grow_for(std::size_t count);

    bool ready_ = false;
    std::vector<std::uint64_t> ids_;  ///< the last call's, by row
    // The set of the last ids: open addressing with linear probing; deletion
    // shifts the entries after a freed place back, so no tombstones pile up
    // over many calls.
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint8_t> used_places_;  ///< 1 where keys_ holds an id
    std::size_t used_ = 0;
    std::size_t mask_ = 0;
    /// At least the largest id in the set (ids counted up as boxes are
    /// created make every new one larger): a larger id is not in the set,
    /// with no read of it.
    std::uint64_t id_bound_ = 0;
};

}  // namespace obbsat::detail
