// The rows of a pair_finder's last call by id (id_rows.hpp).
#include "scene/id_rows.hpp"

#include <obbsat/error.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>

namespace obbsat::detail {

namespace {

/// How far the side-by-side walk looks ahead for a removed or inserted row.
constexpr std::size_t look_ahead = 8;

/// The place of `id` in a set of mask + 1 places: the high bits of a
/// multiplicative hash, so that ids counted up from 0 spread out.
std::size_t home_of(std::uint64_t id, std::size_t mask) {
    return static_cast<std::size_t>((id * 0x9e3779b97f4a7c15ull) >> 32) & mask;
}

[[noreturn]] void refuse_duplicate(const char* label, std::size_t first, std::size_t second, std::uint64_t id) {
    throw invalid_input(std::string(label) + "ids: rows " + std::to_string(std::min(first, second)) + " and " +
                        std::to_string(std::max(first, second)) + " share the id " + std::to_string(id) +
                        "; the ids of one call must be unique");
}

/// How many of a[0, n) and b[0, n), from the first on, are equal: eight
/// compared at a time with no branch between them, since rows that keep
/// their ids are most of a call's.
std::size_t equal_prefix(const std::uint64_t* a, const std::uint64_t* b, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t differ = 0;
        for (std::size_t k = 0; k < 8; ++k) {
            differ |= a[i + k] ^ b[i + k];
        }
        if (differ != 0) {
            break;
        }
    }
    while (i < n && a[i] == b[i]) {
        ++i;
    }
    return i;
}

/// The row other than `row` of `ids` that holds `id` (there is one: a duplicate was found).
std::size_t other_row_with(const std::uint64_t* ids, std::size_t count, std::size_t row, std::uint64_t id) {
    for (std::size_t r = 0; r < count; ++r) {
        if (r != row && ids[r] == id) {
            return r;
        }
    }
    return row;
}

/// A few ids, each with a row, in open addressing: the rows a match leaves
/// over (a swap-remove's moved rows, new rows, gone rows), looked up in a
/// step or two where a sort and a search by halving cost some 0.1 ms a call
/// for a thousand of each.
class left_over_ids {
public:
    explicit left_over_ids(std::size_t count) {
        std::size_t places = 16;
        while (places < 2 * count) {
            places *= 2;
        }
        keys_.resize(places);
        rows_.assign(places, no_row);
        mask_ = places - 1;
    }
    /// The row held for `id`, or no_row.
    std::uint32_t find(std::uint64_t id) const { return rows_[place_of(id)]; }
    /// Holds `row` for `id` unless a row is held for it already; returns that row, or no_row.
    std::uint32_t insert(std::uint64_t id, std::uint32_t row) {
        const std::size_t at = place_of(id);
        if (rows_[at] == no_row) {
            keys_[at] = id;
            rows_[at] = row;
            return no_row;
        }
        return rows_[at];
    }

private:
    std::size_t place_of(std::uint64_t id) const {
        std::size_t at = home_of(id, mask_);
        while (rows_[at] != no_row && keys_[at] != id) {
            at = (at + 1) & mask_;
        }
        return at;
    }
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> rows_;
    std::size_t mask_ = 0;
};

/// Fetches the place of `id` in a set of mask + 1 places into the cache.
void fetch_place(const std::vector<std::uint64_t>& keys, const std::vector<std::uint8_t>& used, std::uint64_t id,
                 std::size_t mask) {
    const std::size_t at = home_of(id, mask);
    __builtin_prefetch(keys.data() + at);
    __builtin_prefetch(used.data() + at);
}

/// Set operations a call takes on its gone and fresh rows are fetched this many ahead.
constexpr std::size_t places_ahead = 8;

}  // namespace

std::size_t id_rows::find_place(std::uint64_t id) const {
    std::size_t at = home_of(id, mask_);
    while (used_places_[at] != 0 && keys_[at] != id) {
        at = (at + 1) & mask_;
    }
    return at;
}

bool id_rows::contains(std::uint64_t id) const {
    return used_ != 0 && id <= id_bound_ && used_places_[find_place(id)] != 0;
}

void id_rows::grow_for(std::size_t count) {
    if (!keys_.empty() && 2 * count <= keys_.size()) {
        return;
    }
    std::size_t places = 16;
    while (places < 2 * count) {
        places *= 2;
    }
    std::vector<std::uint64_t> keys(places);
    std::vector<std::uint8_t> used(places, 0);
    keys.swap(keys_);
    used.swap(used_places_);
    mask_ = places - 1;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (used[i] != 0) {
            const std::size_t at = find_place(keys[i]);
            keys_[at] = keys[i];
            used_places_[at] = 1;
        }
    }
}

void id_rows::insert(std::uint64_t id) {
    id_bound_ = used_ == 0 ? id : std::max(id_bound_, id);
    const std::size_t at = find_place(id);
    used_ += used_places_[at] == 0 ? std::size_t{1} : std::size_t{0};
    keys_[at] = id;
    used_places_[at] = 1;
}

void id_rows::erase(std::uint64_t id) {
    std::size_t hole = find_place(id);
    if (used_places_[hole] == 0) {
        return;
    }
    --used_;
    used_places_[hole] = 0;
    // Backward shift: an entry after the hole whose home is not cyclically
    // between the hole and itself would no longer be found past the hole, so
    // it moves into it, and its place becomes the hole.
    std::size_t at = (hole + 1) & mask_;
    while (used_places_[at] != 0) {
        const std::size_t home = home_of(keys_[at], mask_);
        const bool stays = ((at - home) & mask_) < ((at - hole) & mask_);
        if (!stays) {
            keys_[hole] = keys_[at];
            used_places_[hole] = 1;
            used_places_[at] = 0;
            hole = at;
        }
        at = (at + 1) & mask_;
    }
}

void id_rows::match(const std::uint64_t* ids, std::size_t count, bool follow, const char* label,
                    row_match& out) const {
    const std::size_t last_count = ready_ && follow ? ids_.size() : 0;
    const std::uint64_t* const last = ids_.data();
    out.last_count = last_count;
    out.count = count;
    out.now_of_last.resize(last_count);
    out.fresh.clear();
    out.gone.clear();
    out.off_runs.clear();
    out.runs_in_place = true;
    out.in_order = true;
    // Side by side: equal ids are one row; a difference is a removed row when
    // this call's id comes a few rows later in the last call's, an inserted
    // one when the last call's id comes a few rows later in this call's, and
    // otherwise both rows are left over.
    std::vector<std::uint32_t>& left_now = out.off_runs;
    std::vector<std::uint32_t> left_last;
    std::size_t r = 0;
    std::size_t l = 0;
    while (r < count && l < last_count) {
        if (ids[r] == last[l]) {
            // A run of rows with the last call's ids, shifted by r - l.
            const std::size_t run = equal_prefix(ids + r, last + l, std::min(count - r, last_count - l));
            out.runs_in_place &= r == l;
            const auto first = out.now_of_last.begin() + static_cast<std::ptrdiff_t>(l);
            std::iota(first, first + static_cast<std::ptrdiff_t>(run), static_cast<std::uint32_t>(r));
            r += run;
            l += run;
            continue;
        }
        std::size_t skip_last = 0;
        for (std::size_t d = 1; d <= look_ahead && l + d < last_count; ++d) {
            if (last[l + d] == ids[r]) {
                skip_last = d;
                break;
            }
        }
        if (skip_last != 0) {
            for (std::size_t d = 0; d < skip_last; ++d) {
                out.now_of_last[l + d] = no_row;
                left_last.push_back(static_cast<std::uint32_t>(l + d));
            }
            l += skip_last;
            continue;
        }
        std::size_t skip_now = 0;
        for (std::size_t d = 1; d <= look_ahead && r + d < count; ++d) {
            if (ids[r + d] == last[l]) {
                skip_now = d;
                break;
            }
        }
        if (skip_now != 0) {
            for (std::size_t d = 0; d < skip_now; ++d) {
                left_now.push_back(static_cast<std::uint32_t>(r + d));
            }
            r += skip_now;
            continue;
        }
        out.now_of_last[l] = no_row;
        left_now.push_back(static_cast<std::uint32_t>(r));
        left_last.push_back(static_cast<std::uint32_t>(l));
        ++r;
        ++l;
    }
    for (; r < count; ++r) {
        left_now.push_back(static_cast<std::uint32_t>(r));
    }
    for (; l < last_count; ++l) {
        out.now_of_last[l] = no_row;
        left_last.push_back(static_cast<std::uint32_t>(l));
    }
    out.same_rows = left_now.empty() && left_last.empty() && count == last_count;
    // The left-over rows: a row now whose id a left-over last row had is
    // that row, moved; one whose id the last call had elsewhere shares it
    // with the row now matched there (the last ids are unique); any other is
    // fresh, and two fresh rows with one id are refused once every other
    // duplicate has been looked for, the smallest such id first.
    left_over_ids left_ids(left_last.size());
    for (const std::uint32_t row : left_last) {
        left_ids.insert(last[row], row);
    }
    left_over_ids fresh_ids(left_now.size());
    bool fresh_twice = false;
    std::uint64_t twice_id = 0;
    std::uint32_t twice_first = 0, twice_second = 0;
    for (const std::uint32_t row : left_now) {
        const std::uint64_t id = ids[row];
        const std::uint32_t last_row = left_ids.find(id);
        if (last_row != no_row) {
            std::uint32_t& now = out.now_of_last[last_row];
            if (now != no_row) {
                refuse_duplicate(label, now, row, id);
            }
            now = row;
            out.in_order = false;  // a moved row: its place against the others is not known
        } else if (last_count != 0 && contains(id)) {
            refuse_duplicate(label, other_row_with(ids, count, row, id), row, id);
        } else {
            const std::uint32_t first = fresh_ids.insert(id, row);
            if (first == no_row) {
                out.fresh.push_back(row);  // left_now is increasing, so fresh is too
            } else if (!fresh_twice || id < twice_id) {
                fresh_twice = true;
                twice_id = id;
                twice_first = first;
                twice_second = row;
            }
        }
    }
    if (fresh_twice) {
        refuse_duplicate(label, twice_first, twice_second, twice_id);
    }
    for (const std::uint32_t row : left_last) {
        if (out.now_of_last[row] == no_row) {
            out.gone.push_back(row);
        }
    }
}

void id_rows::commit(const std::uint64_t* ids, const row_match& m) {
    if (m.last_count == 0) {
        std::fill(used_places_.begin(), used_places_.end(), std::uint8_t{0});
        used_ = 0;
    } else {
        // Each erase and insert is a read at a random place of the set:
        // fetched ahead, several are under way at once.
        const std::vector<std::uint32_t>& gone = m.gone;
        for (std::size_t i = 0; i < gone.size(); ++i) {
            if (i + places_ahead < gone.size()) {
                fetch_place(keys_, used_places_, ids_[gone[i + places_ahead]], mask_);
            }
            erase(ids_[gone[i]]);
        }
    }
    grow_for(used_ + m.fresh.size());
    const std::vector<std::uint32_t>& fresh = m.fresh;
    for (std::size_t i = 0; i < fresh.size(); ++i) {
        if (i + places_ahead < fresh.size()) {
            fetch_place(keys_, used_places_, ids[fresh[i + places_ahead]], mask_);
        }
        insert(ids[fresh[i]]);
    }
    if (m.last_count == 0 || (!m.same_rows && !m.runs_in_place)) {
        ids_.assign(ids, ids + m.count);
    } else if (!m.same_rows) {
        // Rows removed by swapping the last row in, or appended: the other
        // rows hold their ids already, and a copy of every id (8 bytes a
        // row, out of the caches by now) is saved.
        ids_.resize(m.count);
        for (const std::uint32_t row : m.off_runs) {
            ids_[row] = ids[row];
        }
    }
    ready_ = true;
}

void rematch_as_new(row_match& m, const std::vector<std::uint32_t>& last_rows) {
    if (last_rows.empty()) {
        return;
    }
    std::vector<std::uint32_t> rows_now;
    rows_now.reserve(last_rows.size());
    for (const std::uint32_t l : last_rows) {
        rows_now.push_back(m.now_of_last[l]);
        m.now_of_last[l] = no_row;
    }
    std::sort(rows_now.begin(), rows_now.end());
    const auto merge_in = [](std::vector<std::uint32_t>& into, const std::vector<std::uint32_t>& more) {
        const auto middle = static_cast<std::ptrdiff_t>(into.size());
        into.insert(into.end(), more.begin(), more.end());
        std::inplace_merge(into.begin(), into.begin() + middle, into.end());
    };
    merge_in(m.gone, last_rows);
    merge_in(m.fresh, rows_now);
    m.same_rows = false;
}

void id_rows::clear() {
    ready_ = false;
    ids_.clear();
    std::fill(used_places_.begin(), used_places_.end(), std::uint8_t{0});
    used_ = 0;
}

}  // namespace obbsat::detail
