// Every backend's sweep of one strip (the kernel table's strip_sweep, written
// once over the lanes in lanes/strip_sweep_lanes.hpp, one pair at a time for
// scalar) against its plain definition (dispatch/strip_view.hpp): every entry
// pair e < f whose closed bounds overlap, that is not two visitors and, in a
// query across two stores, mixes them, written as (id[e], id[f]) in entry
// order, e then f; never a sentinel, whatever its bounds; the same pairs when
// the output is cut short by its capacity and the sweep resumed, with nothing
// written past the capacity. On random strips (quantized coarsely, so that
// many entries share a position, and finely), on strips of a few small
// integers where bounds touch and are equal, with zeros of both signs and
// infinite bounds, and on hand-worked strips.
#include "backends/backend_cases.hpp"
#include "dispatch/strip_view.hpp"
#include "scene/strip_grid.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace obbsat {
// For readable failures.
inline bool operator==(const pair_index& x, const pair_index& y) { return x.a == y.a && x.b == y.b; }
inline std::ostream& operator<<(std::ostream& os, const pair_index& p) { return os << "(" << p.a << ", " << p.b << ")"; }
}  // namespace obbsat

namespace {

using obbsat::pair_index;
using obbsat::detail::strip_padding;
using obbsat::detail::strip_view;
using obbsat::detail::sweep_cursor;

constexpr float inf = std::numeric_limits<float>::infinity();
/// The id every sentinel carries: a pair naming it was read past the end.
constexpr std::int32_t sentinel_id = 0x7ffffff0;

struct entry {
    float lo_x, lo_y, hi_x, hi_y;
    bool starts;  // its lowest strip is this one (else a visitor from below)
    int store;    // 0 or 1
    std::int32_t id;
};

/// A strip as the sweep reads it: entries sorted by quantized lo_x, then the
/// sentinels, whose q_lo and lo_x are +inf and starts -1, as strip_view.hpp
/// asks; every other field of a sentinel is chosen so that only those keep it
/// out (its bounds overlap everything, its store differs from both).
struct strip {
    std::vector<float> q_lo, q_hi, starts, store, lo_x, lo_y, hi_x, hi_y;
    std::vector<std::int32_t> id;
    std::size_t size = 0;
    bool cross = false;

    strip_view view() const {
        return {q_lo.data(), q_hi.data(), id.data(), starts.data(), store.data(), lo_x.data(), lo_y.data(),
                hi_x.data(), hi_y.data(), size, cross};
    }
};

/// Sorts `entries` by quantized lo_x (stable: the order among equal positions
/// is whatever the caller shuffled in) and lays them out with the sentinels.
strip make_strip(std::vector<entry> entries, const obbsat::detail::strip_grid& grid, bool cross) {
    std::stable_sort(entries.begin(), entries.end(),
                     [&](const entry& x, const entry& y) { return grid.q_of(x.lo_x) < grid.q_of(y.lo_x); });
    strip s;
    s.size = entries.size();
    s.cross = cross;
    for (const entry& e : entries) {
        s.q_lo.push_back(static_cast<float>(grid.q_of(e.lo_x)));
        s.q_hi.push_back(static_cast<float>(grid.q_of(e.hi_x)));
        s.starts.push_back(e.starts ? 1.0f : 0.0f);
        s.store.push_back(static_cast<float>(e.store));
        s.lo_x.push_back(e.lo_x);
        s.lo_y.push_back(e.lo_y);
        s.hi_x.push_back(e.hi_x);
        s.hi_y.push_back(e.hi_y);
        s.id.push_back(e.id);
    }
    for (std::size_t k = 0; k < strip_padding; ++k) {
        s.q_lo.push_back(inf);
        s.q_hi.push_back(inf);
        s.starts.push_back(-1.0f);
        s.store.push_back(0.5f);
        s.lo_x.push_back(inf);
        s.lo_y.push_back(-inf);
        s.hi_x.push_back(inf);
        s.hi_y.push_back(inf);
        s.id.push_back(sentinel_id);
    }
    return s;
}

/// What the sweep must write, from its definition alone.
std::vector<pair_index> expected_pairs(const strip& s) {
    std::vector<pair_index> out;
    for (std::size_t e = 0; e < s.size; ++e) {
        for (std::size_t f = e + 1; f < s.size; ++f) {
            const bool overlap = s.lo_x[f] <= s.hi_x[e] && s.lo_x[e] <= s.hi_x[f] && s.lo_y[f] <= s.hi_y[e] &&
                                 s.lo_y[e] <= s.hi_y[f];
            const bool not_two_visitors = s.starts[e] == 1.0f || s.starts[f] == 1.0f;
            const bool mixes = !s.cross || s.store[e] != s.store[f];
            if (overlap && not_two_visitors && mixes) {
                out.push_back({static_cast<std::uint32_t>(s.id[e]), static_cast<std::uint32_t>(s.id[f])});
            }
        }
    }
    return out;
}

/// Runs the sweep as the scene query does, call after call until the strip
/// is done, each call given `capacity` slots, and returns every pair written.
/// Checks that nothing lands past the capacity and that every call moves on.
std::vector<pair_index> swept_pairs(obbsat::detail::strip_sweep_fn sweep, const strip& s, std::size_t capacity,
                                    const std::string& what) {
    constexpr pair_index guard{0xdeadbeefu, 0xfeedfaceu};
    const strip_view view = s.view();
    std::vector<pair_index> out;
    std::vector<pair_index> buffer(capacity + strip_padding, guard);
    sweep_cursor cursor;
    std::size_t calls = 0;
    do {
        const sweep_cursor before = cursor;
        std::fill(buffer.begin(), buffer.end(), guard);
        const std::size_t written = sweep(view, cursor, buffer.data(), capacity);
        EXPECT_LE(written, capacity) << what;
        for (std::size_t i = capacity; i < buffer.size(); ++i) {
            if (!(buffer[i] == guard)) {
                ADD_FAILURE() << what << ": slot " << i << " past the capacity " << capacity << " written";
                return out;
            }
        }
        out.insert(out.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(std::min(written, capacity)));
        const bool done = cursor.e + 1 >= s.size;
        const bool moved = cursor.e > before.e || (cursor.e == before.e && cursor.f > before.f);
        if (!(done || moved) || ++calls > 1'000'000) {
            ADD_FAILURE() << what << ": the sweep stopped moving at entry " << cursor.e << ", " << cursor.f;
            return out;
        }
    } while (cursor.e + 1 < s.size);
    EXPECT_GE(cursor.e + 1, s.size) << what;
    return out;
}

void expect_sweep_matches(obbsat::detail::strip_sweep_fn sweep, const strip& s, const std::string& what) {
    const std::vector<pair_index> want = expected_pairs(s);
    for (const std::size_t capacity :
         {want.size() + strip_padding, strip_padding, strip_padding + 1, 2 * strip_padding + 3, std::size_t{100}}) {
        const std::string case_name = what + ", capacity " + std::to_string(capacity);
        const std::vector<pair_index> got = swept_pairs(sweep, s, capacity, case_name);
        if (got == want) {
            continue;
        }
        std::size_t first = 0;
        while (first < got.size() && first < want.size() && got[first] == want[first]) {
            ++first;
        }
        ADD_FAILURE() << case_name << ": " << got.size() << " pairs, want " << want.size() << "; first difference at "
                      << first << ": "
                      << (first < got.size() ? ::testing::PrintToString(got[first]) : std::string("nothing"))
                      << ", want "
                      << (first < want.size() ? ::testing::PrintToString(want[first]) : std::string("nothing"));
        return;
    }
}

/// A grid over [x_low, x_high] in `positions` steps: coarse grids put many
/// entries at one position.
obbsat::detail::strip_grid grid_over(double x_low, double x_high, std::uint32_t positions) {
    obbsat::detail::strip_grid grid;
    grid.x_low = x_low;
    grid.x_high = x_high;
    grid.q_max = positions - 1;
    grid.x_scale = static_cast<double>(grid.q_max) / (x_high - x_low);
    return grid;
}

/// Random entries over [0, width] x [0, height], up to `size` wide and tall;
/// `visitors` and `infinite` are shares in 1/1000.
std::vector<entry> random_entries(obbsat::seeded_random& random, std::size_t count, float width, float height,
                                  float size, std::uint32_t visitors, std::uint32_t infinite) {
    std::vector<entry> out;
    for (std::size_t i = 0; i < count; ++i) {
        entry e{};
        if (random.below(1000) < infinite) {
            e.lo_x = -inf;
            e.lo_y = -inf;
            e.hi_x = inf;
            e.hi_y = inf;
        } else {
            e.lo_x = random.uniform(0.0f, width);
            e.lo_y = random.uniform(0.0f, height);
            e.hi_x = e.lo_x + random.uniform(0.0f, size);
            e.hi_y = e.lo_y + random.uniform(0.0f, size);
        }
        e.starts = random.below(1000) >= visitors;
        e.store = static_cast<int>(random.below(2));
        e.id = static_cast<std::int32_t>(random.below(0x7fff0000u));
        out.push_back(e);
    }
    return out;
}

/// Entries whose coordinates are a few small integers and zeros of both
/// signs: bounds that touch, are equal, or are points and segments.
std::vector<entry> touching_entries(obbsat::seeded_random& random, std::size_t count) {
    const float at[] = {-2.0f, -1.0f, -0.0f, 0.0f, 1.0f, 2.0f};
    std::vector<entry> out;
    for (std::size_t i = 0; i < count; ++i) {
        entry e{};
        e.lo_x = at[random.below(6)];
        e.lo_y = at[random.below(6)];
        e.hi_x = std::max(e.lo_x, at[random.below(6)]);
        e.hi_y = std::max(e.lo_y, at[random.below(6)]);
        e.starts = random.below(4) != 0;
        e.store = static_cast<int>(random.below(2));
        e.id = static_cast<std::int32_t>(i);
        out.push_back(e);
    }
    return out;
}

class strip_sweep_lanes : public ::testing::TestWithParam<obbsat_test::backend_case> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam().id)) {
            GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(GetParam().id);
        }
        sweep_ = GetParam().table->strip_sweep;
        ASSERT_NE(sweep_, nullptr);
    }
    obbsat::detail::strip_sweep_fn sweep_ = nullptr;
};

TEST_P(strip_sweep_lanes, random_strips_give_the_defined_pairs_in_entry_order) {
    obbsat::seeded_random random(20261126);
    std::size_t pairs = 0;
    for (const bool cross : {false, true}) {
        for (std::size_t m = 0; m <= 70; ++m) {
            for (const std::uint32_t positions : {4u, 1u << 16}) {
                const strip s = make_strip(random_entries(random, m, 100.0f, 100.0f, 30.0f, 300, 20),
                                           grid_over(0, 100, positions), cross);
                pairs += expected_pairs(s).size();
                expect_sweep_matches(sweep_, s,
                                     "size " + std::to_string(m) + (cross ? ", across stores" : ", one store") +
                                         ", " + std::to_string(positions) + " positions");
                if (HasFailure()) {
                    return;
                }
            }
        }
        // A long strip of small entries, as a scene gives.
        const strip s = make_strip(random_entries(random, 3000, 1000.0f, 20.0f, 8.0f, 200, 1),
                                   grid_over(0, 1000, 1u << 16), cross);
        pairs += expected_pairs(s).size();
        expect_sweep_matches(sweep_, s, std::string("3000 entries") + (cross ? ", across stores" : ", one store"));
    }
    EXPECT_GT(pairs, 20000u);  // the strips are not empty of pairs
}

TEST_P(strip_sweep_lanes, touching_and_equal_bounds_are_pairs_and_two_visitors_are_not) {
    obbsat::seeded_random random(7);
    for (const bool cross : {false, true}) {
        for (std::size_t m = 2; m <= 60; m += 3) {
            for (int round = 0; round < 4; ++round) {
                // Two positions to the unit: -2, -1.5, ... 2 (both zeros at one).
                const strip s = make_strip(touching_entries(random, m), grid_over(-2, 2, 9), cross);
                expect_sweep_matches(sweep_, s,
                                     "touching, size " + std::to_string(m) + (cross ? ", across stores" : ""));
                if (HasFailure()) {
                    return;
                }
            }
        }
    }
}

TEST_P(strip_sweep_lanes, equal_bounds_give_every_pair_in_order) {
    for (const std::size_t m : {std::size_t{2}, std::size_t{17}, std::size_t{40}}) {
        std::vector<entry> entries;
        for (std::size_t i = 0; i < m; ++i) {
            entries.push_back({1.0f, 1.0f, 3.0f, 3.0f, true, 0, static_cast<std::int32_t>(100 + i)});
        }
        const strip s = make_strip(entries, grid_over(0, 4, 256), false);
        std::vector<pair_index> want;
        for (std::uint32_t e = 0; e < m; ++e) {
            for (std::uint32_t f = e + 1; f < m; ++f) {
                want.push_back({100 + e, 100 + f});
            }
        }
        const auto got = swept_pairs(sweep_, s, m * m + strip_padding, "equal bounds");
        EXPECT_EQ(got.size(), m * (m - 1) / 2);
        EXPECT_EQ(got, want) << m << " equal entries";
    }
}

TEST_P(strip_sweep_lanes, hand_worked_strip) {
    // x:  A [0, 2]   C [1, 1]   B [2, 3]   D [2.5, 4]   E [5, 6]
    // y:  A [0, 1]   C [0, 0]   B [1, 2]   D [3, 4]     E [0, 9]
    // D is a visitor; D and E are of the second store. A and C overlap (C is
    // a point on A's edge), A and B touch at a corner; B and D overlap in x
    // only, A and D not at all, E is clear of all.
    const std::vector<entry> entries = {
        {0.0f, 0.0f, 2.0f, 1.0f, true, 0, 10},   // A
        {1.0f, 0.0f, 1.0f, 0.0f, true, 0, 30},   // C
        {2.0f, 1.0f, 3.0f, 2.0f, true, 0, 20},   // B
        {2.5f, 3.0f, 4.0f, 4.0f, false, 1, 40},  // D, a visitor
        {5.0f, 0.0f, 6.0f, 9.0f, true, 1, 50},   // E
    };
    const auto grid = grid_over(0, 8, 9);  // one position per unit
    const strip one_store = make_strip(entries, grid, false);
    EXPECT_EQ(swept_pairs(sweep_, one_store, 64, "one store"),
              (std::vector<pair_index>{{10, 30}, {10, 20}}));
    // A visitor that reaches a visitor is no pair; one that reaches an entry
    // that starts here is: A and C are made visitors, and D reaches B.
    std::vector<entry> visitors = entries;
    visitors[0].starts = false;  // A
    visitors[1].starts = false;  // C
    visitors[3] = {2.5f, 1.5f, 4.0f, 4.0f, false, 1, 40};  // D now reaches B
    const strip with_visitors = make_strip(visitors, grid, false);
    EXPECT_EQ(swept_pairs(sweep_, with_visitors, 64, "visitors"),
              (std::vector<pair_index>{{10, 20}, {20, 40}}));
    const strip across = make_strip(visitors, grid, true);
    EXPECT_EQ(swept_pairs(sweep_, across, 64, "across stores"), (std::vector<pair_index>{{20, 40}}));
}

TEST_P(strip_sweep_lanes, infinite_bounds_reach_every_entry_but_no_sentinel) {
    for (const std::size_t m : {std::size_t{1}, std::size_t{2}, std::size_t{5}, std::size_t{16}, std::size_t{33}}) {
        std::vector<entry> entries;
        for (std::size_t i = 0; i < m; ++i) {
            const float x = static_cast<float>(i + 1) * 10.0f;  // clear of each other and of position 0
            entries.push_back({x, 0.0f, x + 1.0f, 1.0f, true, 0, static_cast<std::int32_t>(i)});
        }
        entries.back() = {-inf, -inf, inf, inf, true, 0, 999};  // sorts first
        const strip s = make_strip(entries, grid_over(0, 1000, 1024), false);
        std::vector<pair_index> want;
        for (std::uint32_t f = 0; f + 1 < m; ++f) {
            want.push_back({999, f});
        }
        EXPECT_EQ(swept_pairs(sweep_, s, 4 * strip_padding, "infinite first"), want) << m << " entries";
        // Next to last, with one entry and then the sentinels in its reach.
        std::vector<entry> near_end(entries.begin(), entries.end() - 1);
        const float far = static_cast<float>(m + 1) * 10.0f;
        near_end.push_back({far, -inf, inf, inf, true, 0, 999});
        near_end.push_back({far + 10.0f, 0.0f, far + 11.0f, 1.0f, true, 0, 500});
        const strip t = make_strip(near_end, grid_over(0, 1000, 1024), false);
        EXPECT_EQ(swept_pairs(sweep_, t, 4 * strip_padding, "infinite next to last"),
                  (std::vector<pair_index>{{999, 500}}))
            << m << " entries";
    }
}

TEST_P(strip_sweep_lanes, strips_of_no_entry_or_one_write_nothing) {
    for (const std::size_t m : {std::size_t{0}, std::size_t{1}}) {
        const strip s = make_strip(std::vector<entry>(m, entry{0, 0, 1, 1, true, 0, 3}), grid_over(0, 1, 2), false);
        std::vector<pair_index> out(strip_padding, pair_index{7, 7});
        sweep_cursor cursor;
        const strip_view view = s.view();
        EXPECT_EQ(sweep_(view, cursor, out.data(), out.size()), 0u) << m;
        EXPECT_GE(cursor.e + 1, m + 1) << m;
        EXPECT_EQ(out[0].a, 7u) << m;
    }
}

TEST(strip_sweep_lanes_cases, the_random_strips_hold_visitors_infinite_bounds_and_shared_positions) {
    // The inputs must exercise what the sweep could get wrong.
    obbsat::seeded_random random(20261126);
    const std::vector<entry> entries = random_entries(random, 20000, 100.0f, 100.0f, 30.0f, 300, 20);
    const auto grid = grid_over(0, 100, 4);
    std::size_t visitors = 0;
    std::size_t infinite = 0;
    for (const entry& e : entries) {
        visitors += e.starts ? 0u : 1u;
        infinite += std::isinf(e.hi_x) ? 1u : 0u;
    }
    EXPECT_GT(visitors, 5000u);
    EXPECT_GT(infinite, 200u);
    // On the coarse grid 60 entries share at most four positions.
    const strip s = make_strip(std::vector<entry>(entries.begin(), entries.begin() + 60), grid, true);
    std::vector<float> q(s.q_lo.begin(), s.q_lo.begin() + 60);
    EXPECT_LE(static_cast<std::size_t>(std::unique(q.begin(), q.end()) - q.begin()), 4u);
}

INSTANTIATE_TEST_SUITE_P(backends, strip_sweep_lanes, ::testing::ValuesIn(obbsat_test::backends_here()),
                         obbsat_test::backend_case_name);

}  // namespace
