// The match of a call's ids against the last call's (kernel/scene/id_rows.hpp)
// against a plain one through a map of ids, over edits of every kind: rows
// removed with the others kept in order (the first, the last, runs of them,
// all of them), rows appended and inserted, swap-removes, swaps, blocks
// moved, reversed rows; with ids counted up as boxes are created (each new
// one larger than every id before, which the match uses) and with ids drawn
// at random; after each call the ids held must be that call's. Duplicate ids
// are refused in both, whether the duplicate is below or above the largest
// id held so far. A match says whether the rows it matched kept their order
// (in_order), and it is never wrong in saying so.
#include "scene/id_rows.hpp"

#include <obbsat/error.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace {

using obbsat::detail::id_rows;
using obbsat::detail::no_row;
using obbsat::detail::row_match;

/// The match of `now` against `last` through a map: what id_rows::match must give.
row_match plain_match(const std::vector<std::uint64_t>& last, const std::vector<std::uint64_t>& now) {
    row_match m;
    m.last_count = last.size();
    m.count = now.size();
    std::map<std::uint64_t, std::uint32_t> row_now;
    for (std::size_t r = 0; r < now.size(); ++r) {
        row_now[now[r]] = static_cast<std::uint32_t>(r);
    }
    std::map<std::uint64_t, std::uint32_t> row_last;
    for (std::size_t l = 0; l < last.size(); ++l) {
        row_last[last[l]] = static_cast<std::uint32_t>(l);
        const auto found = row_now.find(last[l]);
        m.now_of_last.push_back(found == row_now.end() ? no_row : found->second);
        if (found == row_now.end()) {
            m.gone.push_back(static_cast<std::uint32_t>(l));
        }
    }
    for (std::size_t r = 0; r < now.size(); ++r) {
        if (row_last.count(now[r]) == 0) {
            m.fresh.push_back(static_cast<std::uint32_t>(r));
        }
    }
    m.same_rows = last == now;
    return m;
}

void expect_match(const id_rows& rows, const std::vector<std::uint64_t>& last, const std::vector<std::uint64_t>& now,
                  const std::string& what, row_match& got) {
    rows.match(now.data(), now.size(), true, "", got);
    const row_match want = plain_match(last, now);
    EXPECT_EQ(got.last_count, want.last_count) << what;
    EXPECT_EQ(got.count, want.count) << what;
    EXPECT_EQ(got.now_of_last, want.now_of_last) << what;
    EXPECT_EQ(got.fresh, want.fresh) << what;
    EXPECT_EQ(got.gone, want.gone) << what;
    EXPECT_EQ(got.same_rows, want.same_rows) << what;
    // A match in order promises that the rows matched keep their order: the
    // carry of kept pairs then looks for no rows out of order.
    std::vector<std::uint32_t> matched;
    std::copy_if(want.now_of_last.begin(), want.now_of_last.end(), std::back_inserter(matched),
                 [](std::uint32_t r) { return r != no_row; });
    const bool increasing = std::is_sorted(matched.begin(), matched.end());
    EXPECT_TRUE(!got.in_order || increasing) << what << ": in order, but the rows matched do not increase";
}

/// Ids of boxes, edited as a scene's rows are, with new ids counted up or drawn at random.
struct id_list {
    std::vector<std::uint64_t> ids;
    std::uint64_t next = 1;
    bool counted_up = true;
    obbsat::seeded_random random{5};

    std::uint64_t new_id() {
        if (counted_up) {
            return next++;
        }
        // Random ids, apart from every id used before (the counter keeps them distinct).
        return (random.below(1u << 30) << 24) | (next++ & 0xffffffu);
    }
    void append(std::size_t count) {
        for (std::size_t c = 0; c < count; ++c) {
            ids.push_back(new_id());
        }
    }
    void erase(std::size_t at, std::size_t count = 1) {
        ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(at), ids.begin() + static_cast<std::ptrdiff_t>(at + count));
    }
};

TEST(id_rows, matches_equal_a_plain_match_over_edits_of_every_kind) {
    for (const bool counted_up : {true, false}) {
        id_list list;
        list.counted_up = counted_up;
        list.append(3000);
        id_rows rows;
        row_match m;
        rows.match(list.ids.data(), list.ids.size(), true, "", m);
        rows.commit(list.ids.data(), m);
        const auto edit = [&](const std::string& name, auto change) {
            const std::vector<std::uint64_t> last = list.ids;
            change();
            const std::string what = std::string(counted_up ? "counted up, " : "random, ") + name;
            expect_match(rows, last, list.ids, what, m);
            rows.commit(list.ids.data(), m);
            // The ids held are this call's, whether written whole or only where they changed.
            EXPECT_EQ(rows.ids(), list.ids) << what;
        };
        // Rows removed, appended or inserted are matched in order, with no pass that looks for moved ones.
        const auto expect_in_order = [&](const std::string& name) { EXPECT_TRUE(m.in_order) << name; };
        edit("no change", [] {});
        expect_in_order("no change");
        edit("the first row removed", [&] { list.erase(0); });
        edit("the last row removed", [&] { list.erase(list.ids.size() - 1); });
        expect_in_order("the last row removed");
        edit("1% removed in order, as many appended", [&] {
            for (std::size_t c = 0; c < 30; ++c) {
                list.erase(list.random.below(list.ids.size()));
            }
            list.append(30);
        });
        expect_in_order("1% removed in order, as many appended");
        edit("runs longer than the look-ahead removed", [&] {
            list.erase(100, 20);
            list.erase(1000, 9);
            list.erase(2000, 40);
        });
        // (Runs longer than the look-ahead are matched as left over, and may be called out of order.)
        edit("rows inserted among the others", [&] {
            for (std::size_t c = 0; c < 10; ++c) {
                list.ids.insert(list.ids.begin() + static_cast<std::ptrdiff_t>(list.random.below(list.ids.size())),
                                list.new_id());
            }
        });
        expect_in_order("rows inserted among the others");
        edit("swap-removes", [&] {
            for (std::size_t c = 0; c < 5; ++c) {
                const std::size_t at = list.random.below(list.ids.size() - 1);
                list.ids[at] = list.ids.back();
                list.ids.pop_back();
            }
        });
        EXPECT_FALSE(m.in_order) << "swap-removes";
        edit("swap-removes and rows appended", [&] {
            for (std::size_t c = 0; c < 20; ++c) {
                const std::size_t at = list.random.below(list.ids.size() - 1);
                list.ids[at] = list.ids.back();
                list.ids.pop_back();
            }
            list.append(25);
        });
        edit("the last rows removed", [&] { list.ids.resize(list.ids.size() - 7); });
        edit("two rows swapped, and the first and last", [&] {
            std::swap(list.ids[10], list.ids[2000]);
            std::swap(list.ids.front(), list.ids.back());
        });
        edit("a block moved to the front", [&] {
            std::rotate(list.ids.begin(), list.ids.begin() + 500, list.ids.begin() + 700);
        });
        edit("rows reversed", [&] { std::reverse(list.ids.begin() + 100, list.ids.begin() + 400); });
        edit("the largest id removed, a new one appended", [&] {
            const auto largest = std::max_element(list.ids.begin(), list.ids.end());
            list.ids.erase(largest);
            list.append(1);
        });
        edit("everything removed", [&] { list.ids.clear(); });
        edit("all new rows", [&] { list.append(500); });
        edit("all rows replaced", [&] {
            list.ids.clear();
            list.append(400);
        });
    }
}

/// Whether matching `now` against the rows is refused for a duplicate id, naming `first` and `second`.
void expect_refused(const id_rows& rows, const std::vector<std::uint64_t>& now, std::size_t first, std::size_t second,
                    const std::string& what) {
    row_match m;
    try {
        rows.match(now.data(), now.size(), true, "", m);
        ADD_FAILURE() << what << ": duplicate ids accepted";
    } catch (const obbsat::invalid_input& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("rows " + std::to_string(first) + " and " + std::to_string(second)), std::string::npos)
            << what << ": " << message;
    }
}

TEST(id_rows, duplicates_below_and_above_the_largest_id_are_refused) {
    id_list list;
    list.append(1000);
    id_rows rows;
    row_match m;
    rows.match(list.ids.data(), list.ids.size(), true, "", m);
    rows.commit(list.ids.data(), m);
    // A new row (appended) with the id of a row that stayed: below the largest id.
    std::vector<std::uint64_t> now = list.ids;
    now.push_back(now[40]);
    expect_refused(rows, now, 40, 1000, "an old id appended");
    // A row inserted in front with the id of the last row, which moved by one.
    now = list.ids;
    now.insert(now.begin(), now.back());
    expect_refused(rows, now, 0, 1000, "the last id inserted in front");
    // Two new rows with one id above every id so far.
    now = list.ids;
    now.push_back(5000);
    now.push_back(5000);
    expect_refused(rows, now, 1000, 1001, "a new id twice");
    // The largest id gone: an id below it that a row still holds, on a new row.
    const std::uint64_t largest = list.ids.back();
    list.ids.pop_back();
    rows.match(list.ids.data(), list.ids.size(), true, "", m);
    rows.commit(list.ids.data(), m);
    now = list.ids;
    now.push_back(largest);  // the gone id again: a new row, accepted
    now.push_back(now[7]);
    expect_refused(rows, now, 7, 1000, "an old id after the largest went");
    now.pop_back();
    expect_match(rows, list.ids, now, "the gone largest id back", m);
}

}  // namespace
