// Whether pair_finder's kept candidates pay (kernel/scene/kept_costs.hpp):
// the policy fed given costs (a cycle that clearly pays, one weighed against
// a plain query, rests that double and end, a first call's and a first
// cycle's costs), and an engine over a swap-remove sequence whose calls are
// costed by a model of their counts, not timed: where keeping costs more
// than plain queries it rests, answering by plain queries, and keeps again
// after the rest; where keeping pays it never rests. Every frame equals a
// fresh find_pairs and its begin/end events by id the differences of
// consecutive answers, whichever path answers.
#include "pair_finder_id_pairs.hpp"
#include "spawning_world.hpp"
#include "scene/kept_costs.hpp"
#include "scene/pair_events.hpp"
#include "scene/pair_search.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace obbsat::detail {

struct pair_search_test_access {
    using call_cost = pair_search::call_cost;
    static void cost_calls_by(pair_search& search, call_cost model) { search.call_cost_ = model; }
};

}  // namespace obbsat::detail

namespace {

using obbsat::pair_index;
using obbsat::detail::keep_costs;
using obbsat::detail::pair_search;
using obbsat::detail::pair_search_test_access;

// ---- The policy, fed given costs ----

/// A scene's first call of 3 (counted as 1 plain query), a full query of
/// `full`, and `calls` carried calls of `carried` each.
keep_costs one_cycle(double full, std::size_t calls, double carried) {
    keep_costs costs;
    costs.new_scene(3.0);
    costs.kept(full);
    for (std::size_t i = 0; i < calls; ++i) {
        costs.carried(carried);
    }
    return costs;
}

/// The plain queries that weigh a cycle, each `plain`; whether a rest began.
bool weigh(keep_costs& costs, double plain) {
    costs.start_judging();
    bool rest = false;
    for (std::size_t i = 0; i < keep_costs::judge_calls; ++i) {
        EXPECT_TRUE(costs.judging());
        EXPECT_FALSE(rest) << "only the last plain query weighing a cycle decides";
        rest = costs.judge(plain);
    }
    EXPECT_FALSE(costs.judging());
    return rest;
}

TEST(kept_costs, a_cycle_whose_calls_cost_a_fraction_of_a_plain_query_clearly_pays) {
    keep_costs costs = one_cycle(2.0, 12, 0.2);
    // (2 + 12 * 0.2) / 13 per call against a plain query of 1 (the first call's 3 counted as 1).
    EXPECT_DOUBLE_EQ(costs.cycle_cost(), (2.0 + 12 * 0.2) / 13);
    EXPECT_TRUE(costs.clearly_pays());
    EXPECT_FALSE(costs.rest_call());
    EXPECT_EQ(costs.rests(), 0u);
}

TEST(kept_costs, a_cycle_that_costs_more_than_a_plain_query_starts_a_rest_that_ends_and_doubles) {
    keep_costs costs = one_cycle(2.0, 12, 1.0);
    ASSERT_FALSE(costs.clearly_pays());
    // The plain queries that weigh the cycle: cheaper than (2 + 12) / 13.
    EXPECT_TRUE(weigh(costs, 0.9));
    EXPECT_EQ(costs.rests(), 1u);
    EXPECT_EQ(costs.rest_left(), keep_costs::first_rest);
    for (std::size_t i = 0; i < keep_costs::first_rest; ++i) {
        EXPECT_TRUE(costs.rest_call()) << "call " << i << " of the rest";
        costs.plain(0.9);
    }
    EXPECT_FALSE(costs.rest_call());
    EXPECT_EQ(costs.next_rest(), 2 * keep_costs::first_rest);
    // Another cycle that does not pay: twice the rest.
    costs.kept(2.0);
    for (int i = 0; i < 12; ++i) {
        costs.carried(1.0);
    }
    EXPECT_FALSE(costs.clearly_pays());
    EXPECT_TRUE(weigh(costs, 0.9));
    EXPECT_EQ(costs.rest_left(), 2 * keep_costs::first_rest);
}

TEST(kept_costs, a_cycle_weighed_cheaper_than_a_plain_query_keeps_and_shortens_the_next_rest) {
    keep_costs costs = one_cycle(2.0, 12, 1.0);
    ASSERT_FALSE(costs.clearly_pays());
    EXPECT_TRUE(weigh(costs, 0.9));
    while (costs.rest_call()) {
    }
    // Now the carried calls got cheap: 0.6 against plain 0.9 is not clear, but pays.
    costs.kept(2.0);
    for (int i = 0; i < 12; ++i) {
        costs.carried(0.6);
    }
    ASSERT_FALSE(costs.clearly_pays());
    EXPECT_FALSE(weigh(costs, 0.9));
    EXPECT_EQ(costs.rest_left(), 0u);
    EXPECT_EQ(costs.rests(), 1u);
    EXPECT_EQ(costs.next_rest(), keep_costs::first_rest);
}

TEST(kept_costs, a_cycle_that_costs_about_a_plain_query_keeps_and_one_clearly_dearer_rests) {
    // Carried calls of 0.8, well under a plain query of 1: a full query of f
    // (at most full_query_cap plain queries, counted whole) makes
    // (f + 4 * 0.8) / 5 per call.
    const auto full_for = [](double per_call) { return 5 * per_call - 4 * 0.8; };
    ASSERT_LE(full_for(1.05), keep_costs::full_query_cap);
    keep_costs about = one_cycle(full_for(1.02), 4, 0.8);
    ASSERT_FALSE(about.clearly_pays());
    EXPECT_FALSE(weigh(about, 1.0));
    keep_costs dearer = one_cycle(full_for(1.05), 4, 0.8);
    ASSERT_FALSE(dearer.clearly_pays());
    EXPECT_TRUE(weigh(dearer, 1.0));
}

TEST(kept_costs, a_long_cycle_whose_carried_calls_cost_nearly_a_plain_query_rests) {
    // 60 carried calls of 0.95 after a full query of 2: (2 + 60 * 0.95) / 61,
    // under a plain query of 1 per call, yet each call saves only 5%.
    keep_costs near = one_cycle(2.0, 60, 0.95);
    ASSERT_LT(near.cycle_cost(), 1.0);
    ASSERT_FALSE(near.clearly_pays());
    EXPECT_TRUE(weigh(near, 1.0));
    EXPECT_EQ(near.rest_left(), keep_costs::first_rest);
    // The same with carried calls clearly cheaper than a plain query keeps.
    const double cheaper = 0.95 * keep_costs::carried_share;
    keep_costs clear = one_cycle(2.0, 60, cheaper);
    ASSERT_FALSE(clear.clearly_pays());
    EXPECT_FALSE(weigh(clear, 1.0));
    EXPECT_EQ(clear.rest_left(), 0u);
}

TEST(kept_costs, rests_double_up_to_the_longest) {
    keep_costs costs = one_cycle(2.0, 4, 1.0);
    for (int cycle = 0; cycle < 12; ++cycle) {
        EXPECT_TRUE(weigh(costs, 0.5));
        EXPECT_LE(costs.rest_left(), keep_costs::longest_rest);
        while (costs.rest_call()) {
        }
        costs.kept(2.0);
        for (int i = 0; i < 4; ++i) {
            costs.carried(1.0);
        }
    }
    EXPECT_EQ(costs.next_rest(), keep_costs::longest_rest);
}

TEST(kept_costs, a_delayed_carried_call_counts_as_a_typical_one) {
    keep_costs calm = one_cycle(2.0, 12, 0.2);
    keep_costs delayed = one_cycle(2.0, 11, 0.2);
    delayed.carried(50.0);
    EXPECT_DOUBLE_EQ(delayed.cycle_cost(), calm.cycle_cost());
    EXPECT_TRUE(delayed.clearly_pays());
}

TEST(kept_costs, the_first_cycles_full_query_counts_as_at_most_a_few_plain_queries) {
    // Its memory faulted in, the first full query took 40; counted as 3 plain queries of 1.
    keep_costs costs = one_cycle(40.0, 12, 0.2);
    EXPECT_DOUBLE_EQ(costs.cycle_cost(), (keep_costs::full_query_cap * 1.0 + 12 * 0.2) / 13);
    // A later cycle counts its full query whole.
    costs.kept(40.0);
    for (int i = 0; i < 12; ++i) {
        costs.carried(0.2);
    }
    EXPECT_DOUBLE_EQ(costs.cycle_cost(), (40.0 + 12 * 0.2) / 13);
}

TEST(kept_costs, a_first_calls_time_stands_for_a_plain_query_for_the_first_cycles_only) {
    keep_costs costs = one_cycle(2.0, 12, 0.2);
    for (std::size_t cycle = 0; cycle < keep_costs::first_call_cycles; ++cycle) {
        EXPECT_TRUE(costs.clearly_pays()) << "cycle " << cycle;
        costs.kept(2.0);
        for (int i = 0; i < 12; ++i) {
            costs.carried(0.2);
        }
    }
    // No plain query timed since the first call: this cycle is weighed against one.
    EXPECT_FALSE(costs.clearly_pays());
    EXPECT_FALSE(weigh(costs, 1.0));
    EXPECT_EQ(costs.rests(), 0u);
    costs.kept(2.0);
    for (int i = 0; i < 12; ++i) {
        costs.carried(0.2);
    }
    EXPECT_TRUE(costs.clearly_pays());
}

// ---- An engine over a swap-remove sequence, its calls costed by counts ----

/// Kept candidates answer a call for `carried_cost`, a full query that keeps
/// costs 3 and a plain query 1: the count that says which path answered is
/// what the cost model reads (find_pairs_stats).
template <int carried_tenths>
double cost_by_path(const obbsat::find_pairs_stats& stats, double) {
    if (stats.reused_candidates) {
        return carried_tenths / 10.0;
    }
    return stats.kept_candidates > 0 ? 3.0 : 1.0;
}

/// What answered each frame: 'p' a first or plain query, 'F' a full query
/// that kept candidates, 'k' kept candidates, 'R' a plain query while resting.
struct run_record {
    std::string paths;
    std::size_t frames_checked = 0;
};

/// `frames` frames of the swap-remove world through an engine costed by
/// `model` (threads as given), each checked against a fresh find_pairs and
/// its events against the differences of consecutive answers.
run_record run_swap_removes(pair_search_test_access::call_cost model, unsigned threads, std::size_t frames) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.threads = threads;
    pair_search search(options);
    pair_search_test_access::cost_calls_by(search, model);
    obbsat::detail::pair_events events;
    // Each frame removes 2% of the rows by swap-remove (the last row takes
    // the removed one's place) and appends as many new ones.
    obbsat_test::spawning_world w(6000, 29);
    std::vector<obbsat::id_pair> last;
    run_record record;
    for (std::size_t f = 0; f < frames; ++f, w.swap_remove_frame(0.02)) {
        const obbsat::box_view view(w.boxes);
        const obbsat::detail::query_input input =
            search.bound_doubles(obbsat::detail::input_of(view.with_ids(w.ids), nullptr, true));
        const std::vector<pair_index>& got = search.collect(input);
        events.update(got, false, input.a_ids, nullptr, input.a_count, 0);
        const obbsat::find_pairs_stats& stats = search.stats();
        record.paths += stats.kept_resting ? 'R' : stats.reused_candidates ? 'k' : stats.kept_candidates > 0 ? 'F' : 'p';
        const std::vector<pair_index> want = obbsat::find_pairs(view, options);
        EXPECT_TRUE(got.size() == want.size() &&
                    std::equal(got.begin(), got.end(), want.begin(),
                               [](const pair_index& x, const pair_index& y) { return x.a == y.a && x.b == y.b; }))
            << "frame " << f << " (" << record.paths.back() << "): " << got.size() << " pairs, want " << want.size();
        const std::vector<obbsat::id_pair> now = obbsat_test::by_id(want, w.ids, nullptr);
        if (f > 0) {
            const auto same = [](const std::vector<obbsat::id_pair>& x, const std::vector<obbsat::id_pair>& y) {
                return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(),
                                                          [](const obbsat::id_pair& p, const obbsat::id_pair& q) {
                                                              return p.a == q.a && p.b == q.b;
                                                          });
            };
            std::vector<obbsat::id_pair> began = events.began_ids();
            std::vector<obbsat::id_pair> ended = events.ended_ids();
            std::sort(began.begin(), began.end(), obbsat_test::id_less);
            std::sort(ended.begin(), ended.end(), obbsat_test::id_less);
            EXPECT_TRUE(same(began, obbsat_test::minus(now, last))) << "frame " << f << ": began";
            EXPECT_TRUE(same(ended, obbsat_test::minus(last, now))) << "frame " << f << ": ended";
        }
        last = now;
        ++record.frames_checked;
    }
    return record;
}

TEST(kept_costs, an_engine_whose_kept_calls_cost_a_plain_query_rests_then_keeps_again_with_every_frame_fresh) {
    for (const unsigned threads : {1u, 2u}) {
        // Carried calls cost 1, as a plain query: the full query is never paid back.
        const run_record r = run_swap_removes(&cost_by_path<10>, threads, 64);
        SCOPED_TRACE(std::to_string(threads) + " threads, paths " + r.paths);
        ASSERT_EQ(r.frames_checked, 64u);
        // The first cycle: a first call, a full query that keeps, calls answered from it.
        ASSERT_GE(r.paths.size(), 4u);
        EXPECT_EQ(r.paths.substr(0, 3), "pFk");
        // It ends when the kept candidates serve no more: the next calls are
        // the plain queries that weigh it, the last of which begins a rest
        // (kept_resting) for the first rest's calls, then a full query keeps again.
        const std::size_t weighed = r.paths.find_first_not_of('k', 2);
        ASSERT_NE(weighed, std::string::npos);
        const std::size_t first_rest = r.paths.find('R');
        ASSERT_NE(first_rest, std::string::npos);
        EXPECT_EQ(first_rest - weighed, keep_costs::judge_calls - 1);
        EXPECT_EQ(r.paths.substr(weighed, first_rest - weighed), std::string(keep_costs::judge_calls - 1, 'p'));
        const std::size_t rest_end = r.paths.find_first_not_of('R', first_rest);
        ASSERT_NE(rest_end, std::string::npos);
        EXPECT_EQ(rest_end - first_rest, 1 + keep_costs::first_rest);  // the last weighing call and the rest
        EXPECT_EQ(r.paths[rest_end], 'F');
        EXPECT_EQ(r.paths[rest_end + 1], 'k');
    }
}

TEST(kept_costs, an_engine_whose_kept_calls_are_cheap_never_rests_with_every_frame_fresh) {
    for (const unsigned threads : {1u, 2u}) {
        // Carried calls cost a tenth of a plain query: every cycle clearly pays.
        const run_record r = run_swap_removes(&cost_by_path<1>, threads, 40);
        SCOPED_TRACE(std::to_string(threads) + " threads, paths " + r.paths);
        EXPECT_EQ(r.paths.find('R'), std::string::npos);
        // Several cycles ended, each followed by a full query that keeps (at
        // most the plain queries weighing the cycle between).
        EXPECT_GE(std::count(r.paths.begin(), r.paths.end(), 'F'), 3);
        EXPECT_EQ(r.paths.find(std::string(keep_costs::judge_calls + 1, 'p'), 1), std::string::npos);
    }
}

}  // namespace
