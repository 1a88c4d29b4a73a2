// pair_finder's frames whose rows come and go by id, carried over in units
// (kernel/scene/kept_carry.cpp) and with the new rows' candidates found in
// units (kept_changes.cpp): on one to three threads and on the caller's
// executor, every frame equals a fresh find_pairs and every finder keeps the
// same candidates, through spawn frames, frames with no change (the answer
// read in shares past the gaps) and a swap-remove (pairs of moved rows sorted
// apart past the gaps). Inside the engine: the gaps the units leave in the
// kept list are listed and skipped, the rest of the list stays sorted, and
// gaps do not pile up from frame to frame.
#include "scene/pair_search.hpp"
#include "spawning_world.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/executor.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace obbsat::detail {

struct pair_search_test_access {
    static const kept_pairs& kept(const pair_search& search) { return search.kept_; }
};

}  // namespace obbsat::detail

namespace {

using obbsat_test::spawning_world;

using obbsat::collide_options;
using obbsat::pair_index;
using obbsat::rect_pose;

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

collide_options options_for(unsigned threads, const obbsat::executor* given = nullptr) {
    collide_options o;
    o.test = obbsat::method::exact;
    o.threads = threads;
    o.executor = given;
    return o;
}

/// Every item a range of its own, run in reverse order before enqueue returns.
void* enqueue_reversed(obbsat::executor_task task, std::size_t count, std::size_t, void* task_context, void* user) {
    for (std::size_t i = count; i-- > 0;) {
        task(i, i + 1, task_context);
        static_cast<std::atomic<std::size_t>*>(user)->fetch_add(1);
    }
    return nullptr;
}
void finish_nothing(void*, void*) {}

/// What happens before frame f (frames 0 and 1 make the finders keep candidates).
enum class change { none, spawn, swap_remove_and_spawn };
const std::vector<change> plan = {change::none,  change::none,  change::spawn, change::spawn,
                                  change::none,  change::spawn, change::swap_remove_and_spawn,
                                  change::spawn, change::none,  change::spawn};

void apply(spawning_world& w, change c) {
    if (c == change::swap_remove_and_spawn) {
        w.swap_remove(w.boxes.size() / 3);
    }
    if (c == change::none) {
        w.drift();
    } else {
        w.spawn_frame(0.01);
    }
}

TEST(kept_carry, spawn_frames_equal_fresh_queries_and_keep_the_same_candidates_on_1_to_3_threads_and_an_executor) {
    // Enough boxes for three shares of work.
    spawning_world w(60000, 21);
    std::atomic<std::size_t> executor_ranges{0};
    const obbsat::executor reversed{&enqueue_reversed, &finish_nothing, &executor_ranges};
    struct finder_of {
        std::string name;
        obbsat::pair_finder finder;
    };
    std::vector<finder_of> finders;
    for (unsigned threads = 1; threads <= 3; ++threads) {
        finders.push_back({std::to_string(threads) + " threads", obbsat::pair_finder(options_for(threads))});
    }
    finders.push_back({"executor, 2 units a step", obbsat::pair_finder(options_for(2, &reversed))});
    finders.push_back({"executor, 3 units a step", obbsat::pair_finder(options_for(3, &reversed))});
    std::size_t changed_frames = 0;
    std::size_t reused = 0;
    for (std::size_t f = 0; f < plan.size(); ++f) {
        apply(w, plan[f]);
        const obbsat::box_view view(w.boxes);
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(1));
        ASSERT_FALSE(want.empty());
        for (finder_of& named : finders) {
            const std::vector<pair_index>& got = named.finder.find(view.with_ids(w.ids));
            ASSERT_TRUE(same_pairs(got, want)) << named.name << ", frame " << f << ": " << got.size()
                                               << " pairs, want " << want.size();
            // The candidates kept for the next frame do not depend on the threads either.
            EXPECT_EQ(named.finder.stats().kept_candidates, finders[0].finder.stats().kept_candidates)
                << named.name << ", frame " << f;
            if (plan[f] != change::none) {
                ++changed_frames;
                reused += named.finder.stats().reused_candidates ? 1u : 0u;
            }
        }
    }
    // The frames of rows that came and went are answered from kept candidates, not by a full query.
    EXPECT_GE(reused + finders.size(), changed_frames);
    EXPECT_GT(executor_ranges.load(), 0u);
}

TEST(kept_carry, edits_that_keep_or_break_the_rows_order_equal_fresh_queries_on_1_to_3_threads_and_an_executor) {
    // Each frame drifts and makes one edit: those that keep the order of the
    // rows that stay (removals anywhere, the first and last rows included,
    // appends) and those that break it (swaps, a block moved, rows reversed),
    // then everything removed and the scene filled again.
    spawning_world w(40000, 23);
    std::atomic<std::size_t> executor_ranges{0};
    const obbsat::executor reversed{&enqueue_reversed, &finish_nothing, &executor_ranges};
    std::vector<obbsat::pair_finder> finders;
    for (unsigned threads = 1; threads <= 3; ++threads) {
        finders.emplace_back(options_for(threads));
    }
    finders.emplace_back(options_for(3, &reversed));
    const auto erase = [&](std::size_t at) {
        w.boxes.erase(w.boxes.begin() + static_cast<std::ptrdiff_t>(at));
        w.ids.erase(w.ids.begin() + static_cast<std::ptrdiff_t>(at));
    };
    const auto swap_rows = [&](std::size_t i, std::size_t j) {
        std::swap(w.boxes[i], w.boxes[j]);
        std::swap(w.ids[i], w.ids[j]);
    };
    const std::vector<std::pair<std::string, std::function<void()>>> edits = {
        {"none", [] {}},
        {"none", [] {}},
        {"the first row removed", [&] { erase(0); }},
        {"the last row removed, one appended", [&] { erase(w.boxes.size() - 1); w.spawn(); }},
        {"1% removed in order, as many appended", [&] { w.spawn_frame(0.01); }},
        {"the first and last rows removed, 1% appended", [&] {
             erase(w.boxes.size() - 1);
             erase(0);
             for (int c = 0; c < 400; ++c) {
                 w.spawn();
             }
         }},
        {"two rows swapped", [&] { swap_rows(5, w.boxes.size() - 7); }},
        {"the first and last rows swapped, 1% spawned", [&] {
             swap_rows(0, w.boxes.size() - 1);
             w.spawn_frame(0.01);
         }},
        {"a swap-remove", [&] { w.swap_remove(w.boxes.size() / 2); }},
        {"a block moved to the front", [&] {
             std::rotate(w.boxes.begin(), w.boxes.begin() + 300, w.boxes.begin() + 800);
             std::rotate(w.ids.begin(), w.ids.begin() + 300, w.ids.begin() + 800);
         }},
        {"rows reversed", [&] {
             std::reverse(w.boxes.begin() + 1000, w.boxes.begin() + 1400);
             std::reverse(w.ids.begin() + 1000, w.ids.begin() + 1400);
         }},
        {"1% removed in order, as many appended", [&] { w.spawn_frame(0.01); }},
        {"everything removed", [&] {
             w.boxes.clear();
             w.ids.clear();
         }},
        {"the scene filled again", [&] {
             while (w.boxes.size() < 40000) {
                 w.spawn();
             }
         }},
        {"none", [] {}},
        {"1% removed in order, as many appended", [&] { w.spawn_frame(0.01); }},
    };
    std::size_t reused = 0;
    for (std::size_t f = 0; f < edits.size(); ++f) {
        w.drift();
        edits[f].second();
        const obbsat::box_view view(w.boxes);
        const std::vector<pair_index> want = obbsat::find_pairs(view, options_for(1));
        for (std::size_t i = 0; i < finders.size(); ++i) {
            const std::vector<pair_index>& got = finders[i].find(view.with_ids(w.ids));
            ASSERT_TRUE(same_pairs(got, want)) << "finder " << i << ", frame " << f << " (" << edits[f].first
                                               << "): " << got.size() << " pairs, want " << want.size();
            EXPECT_EQ(finders[i].stats().kept_candidates, finders[0].stats().kept_candidates)
                << "finder " << i << ", frame " << f;
            reused += finders[i].stats().reused_candidates ? 1u : 0u;
        }
    }
    // Most frames are answered from kept candidates carried over the edits.
    EXPECT_GE(reused, 8 * finders.size());
    EXPECT_GT(executor_ranges.load(), 0u);
}

/// The engine of a pair_finder over `w`'s frames, inside: each call as pair_finder::find makes it.
const std::vector<pair_index>& find_by_id(obbsat::detail::pair_search& search, const spawning_world& w) {
    const obbsat::box_view view(w.boxes);
    return search.collect(search.bound_doubles(obbsat::detail::input_of(view.with_ids(w.ids), nullptr, true)));
}

bool key_less(const obbsat::detail::tagged_pair& x, const obbsat::detail::tagged_pair& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
}

TEST(kept_carry, gaps_the_units_leave_are_listed_skipped_and_do_not_pile_up) {
    // Spawn frames, and now and then a swap-remove: a row changes places, and its pairs are sorted apart.
    spawning_world w(60000, 22);
    obbsat::detail::pair_search search(options_for(2));
    std::size_t frames_with_gaps = 0;
    for (std::size_t f = 0; f < 14; ++f) {
        if (f >= 2) {
            if (f % 4 == 0) {
                w.swap_remove(w.random.below(w.boxes.size() / 2));
            }
            w.spawn_frame(0.01);
        }
        const std::vector<pair_index>& got = find_by_id(search, w);
        ASSERT_TRUE(same_pairs(got, obbsat::find_pairs(obbsat::box_view(w.boxes), options_for(1)))) << "frame " << f;
        const obbsat::detail::kept_pairs& kept = obbsat::detail::pair_search_test_access::kept(search);
        // Gap entries lie in the listed runs and nowhere else; the others are sorted.
        std::size_t gaps = 0;
        const obbsat::detail::tagged_pair* last = nullptr;
        for (std::size_t j = 0; j < kept.by_caller.size(); ++j) {
            const obbsat::detail::tagged_pair& p = kept.by_caller[j];
            const bool listed = std::any_of(kept.gaps.begin(), kept.gaps.end(),
                                            [&](const auto& run) { return run.first <= j && j < run.second; });
            ASSERT_EQ(obbsat::detail::kept_pairs::is_gap(p), listed) << "frame " << f << ", entry " << j;
            if (listed) {
                ++gaps;
                continue;
            }
            if (last != nullptr) {
                ASSERT_TRUE(key_less(*last, p)) << "frame " << f << ", entry " << j;
            }
            last = &p;
        }
        std::size_t in_runs = 0;
        for (const auto& run : kept.gaps) {
            in_runs += run.second - run.first;
        }
        EXPECT_EQ(gaps, kept.gap_entries);
        EXPECT_EQ(in_runs, kept.gap_entries);
        EXPECT_EQ(search.stats().kept_candidates, kept.by_caller.size() - kept.gap_entries) << "frame " << f;
        frames_with_gaps += kept.gap_entries > 0 ? 1u : 0u;
        // A frame drops the pairs of 1% of the rows, some 2% of the kept
        // pairs: its gaps hold about as many. Gaps kept from frame to frame
        // would pass a twentieth after three frames.
        EXPECT_LE(20 * kept.gap_entries, kept.by_caller.size()) << "frame " << f;
    }
    // The units' gaps were made, so the kept list was carried in units.
    EXPECT_GT(frames_with_gaps, 4u);
}

}  // namespace
