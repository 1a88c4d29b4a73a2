// The checked batch entry points: errors name what is wrong and leave the
// verdicts untouched; colliding_pairs filters in order; empty batches work;
// method and backend names round-trip.
#include "test_support/rect_shapes.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_records;
using obbsat::rect_soa;

constexpr std::uint8_t canary = 0xa5;


obbsat::collide_options options_for(backend use, unsigned threads) {
    obbsat::collide_options options;
    options.use = use;
    options.threads = threads;
    return options;
}

bool untouched(const std::vector<std::uint8_t>& buffer) {
    return std::all_of(buffer.begin(), buffer.end(), [](std::uint8_t v) { return v == canary; });
}

/// Rectangles 1.5 by 0.5 on a unit grid, 100 per row: each overlaps its right neighbour.
std::vector<rect> grid_rects(std::size_t count) {
    std::vector<rect> rects;
    for (std::size_t i = 0; i < count; ++i) {
        const float x = static_cast<float>(i % 100);
        const float y = static_cast<float>(i / 100);
        rects.push_back(obbsat::test_support::axis_aligned(x, y, x + 1.5f, y + 0.5f));
    }
    return rects;
}

rect_soa grid_of_squares(std::size_t count) { return rect_soa(grid_rects(count)); }

std::string message_of(const std::function<void()>& call) {
    try {
        call();
    } catch (const obbsat::invalid_input& e) {
        return e.what();
    }
    return "(no invalid_input thrown)";
}

TEST(collide_api, default_options_are_sat4_automatic_one_thread) {
    const obbsat::collide_options options;
    EXPECT_EQ(options.test, obbsat::method::sat4);
    EXPECT_EQ(options.use, backend::automatic);
    EXPECT_EQ(options.threads, 1u);
}

// A bad index anywhere in a batch large enough to be split over threads: the
// error names the first bad pair and its bad index, and no verdict is written.
TEST(collide_api, out_of_range_index_names_pair_and_index_and_writes_nothing) {
    const rect_soa rects = grid_of_squares(10);
    const rect_records records(grid_rects(10));
    struct bad_case {
        std::size_t pair;
        pair_index value;
        std::string index_text;
    };
    const bad_case cases[] = {
        {5, {2, 17}, "index 17"},  // b out of range
        {3, {10, 0}, "index 10"},  // a equal to the size
        {0, {0xffffffffu, 1}, "index 4294967295"},
        {39999, {4, 10}, "index 10"},  // the very last pair
    };
    for (const backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 0u}) {
            for (const bad_case& c : cases) {
                SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " +
                             std::to_string(threads) + " threads, pair " + std::to_string(c.pair));
                std::vector<pair_index> pairs(40000);
                for (std::size_t i = 0; i < pairs.size(); ++i) {
                    pairs[i] = pair_index{static_cast<std::uint32_t>(i % 10),
                                          static_cast<std::uint32_t>((i * 7) % 10)};
                }
                pairs[c.pair] = c.value;
                // A later bad pair must not be the one named.
                if (c.pair + 1 < pairs.size()) {
                    pairs.back() = pair_index{99, 98};
                }
                const auto options = options_for(use, threads);
                std::vector<std::uint8_t> verdicts(pairs.size(), canary);
                const std::string over_soa = message_of([&] {
                    obbsat::collide_pairs(rects, pairs.data(), pairs.size(), verdicts.data(),
                                          options);
                });
                const std::string over_records = message_of([&] {
                    obbsat::collide_pairs(records, pairs.data(), pairs.size(), verdicts.data(),
                                          options);
                });
                for (const std::string& what : {over_soa, over_records}) {
                    EXPECT_NE(what.find("pair " + std::to_string(c.pair) + ":"), std::string::npos)
                        << what;
                    EXPECT_NE(what.find(c.index_text), std::string::npos) << what;
                    EXPECT_NE(what.find("10 rectangles"), std::string::npos) << what;
                }
                EXPECT_TRUE(untouched(verdicts)) << "verdicts were written before the error";

                EXPECT_THROW((void)obbsat::collide_pairs(rects, pairs, options),
                             obbsat::invalid_input);
                EXPECT_THROW((void)obbsat::colliding_pairs(rects, pairs, options),
                             obbsat::invalid_input);
                EXPECT_THROW((void)obbsat::collide_pairs(records, pairs, options),
                             obbsat::invalid_input);
                EXPECT_THROW((void)obbsat::colliding_pairs(records, pairs, options),
                             obbsat::invalid_input);
            }
        }
    }
}

TEST(collide_api, pairs_into_an_empty_set_of_rectangles_are_out_of_range) {
    const std::vector<pair_index> pairs = {{0, 0}};
    const std::string over_soa =
        message_of([&] { (void)obbsat::collide_pairs(rect_soa(), pairs); });
    const std::string over_records =
        message_of([&] { (void)obbsat::collide_pairs(rect_records(), pairs); });
    for (const std::string& what : {over_soa, over_records}) {
        EXPECT_NE(what.find("pair 0:"), std::string::npos) << what;
        EXPECT_NE(what.find("index 0"), std::string::npos) << what;
    }
}

TEST(collide_api, unequal_stream_lengths_are_refused_and_nothing_is_written) {
    const rect_soa five = grid_of_squares(5);
    const rect_soa six = grid_of_squares(6);
    for (const backend use : obbsat::runnable_backends()) {
        SCOPED_TRACE(obbsat::backend_name(use));
        std::vector<std::uint8_t> verdicts(6, canary);
        const std::string what = message_of(
            [&] { obbsat::collide_stream(five, six, verdicts.data(), options_for(use, 1)); });
        EXPECT_NE(what.find("5 rectangles in A"), std::string::npos) << what;
        EXPECT_NE(what.find("6 in B"), std::string::npos) << what;
        EXPECT_TRUE(untouched(verdicts));
        EXPECT_THROW(obbsat::collide_stream(six, five, verdicts.data(), options_for(use, 1)),
                     obbsat::invalid_input);
        EXPECT_TRUE(untouched(verdicts));
        EXPECT_THROW((void)obbsat::collide_stream(five, rect_soa(), options_for(use, 1)),
                     obbsat::invalid_input);
    }
}

TEST(collide_api, a_backend_this_cpu_lacks_is_refused_and_nothing_is_written) {
    std::vector<backend> missing;
    for (const backend b : {backend::sse2, backend::avx2, backend::avx512}) {
        if (!obbsat::cpu_supports(b)) {
            missing.push_back(b);
        }
    }
    if (missing.empty()) {
        GTEST_SKIP() << "this CPU runs every backend of the enum, so none can be refused here";
    }
    const rect_soa rects = grid_of_squares(20);
    const rect_records records(grid_rects(20));
    const std::vector<pair_index> pairs = {{0, 1}, {2, 3}};
    for (const backend b : missing) {
        SCOPED_TRACE(obbsat::backend_name(b));
        std::vector<std::uint8_t> verdicts(pairs.size(), canary);
        EXPECT_THROW(obbsat::collide_pairs(rects, pairs.data(), pairs.size(), verdicts.data(),
                                           options_for(b, 1)),
                     obbsat::unsupported_backend);
        EXPECT_THROW(obbsat::collide_pairs(records, pairs.data(), pairs.size(), verdicts.data(),
                                           options_for(b, 1)),
                     obbsat::unsupported_backend);
        EXPECT_THROW(obbsat::collide_stream(rects, rects, verdicts.data(), options_for(b, 1)),
                     obbsat::unsupported_backend);
        EXPECT_THROW((void)obbsat::resolve_backend(b), obbsat::unsupported_backend);
        EXPECT_TRUE(untouched(verdicts));
    }
}

TEST(collide_api, a_test_value_that_names_no_method_is_refused_and_nothing_is_written) {
    const rect_soa rects = grid_of_squares(20);
    const rect_records records(grid_rects(20));
    const std::vector<pair_index> pairs = {{0, 1}, {2, 3}};
    for (const unsigned bad : {obbsat::method_count, obbsat::method_count + 1, 255u, 0xffffffffu}) {
        for (const backend use : obbsat::runnable_backends()) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", test " + std::to_string(bad));
            obbsat::collide_options options = options_for(use, 1);
            options.test = static_cast<obbsat::method>(bad);
            std::vector<std::uint8_t> verdicts(pairs.size(), canary);
            const std::string what = message_of(
                [&] { obbsat::collide_pairs(rects, pairs.data(), pairs.size(), verdicts.data(), options); });
            EXPECT_NE(what.find("collide_options::test holds " + std::to_string(bad) + ", which names no method"),
                      std::string::npos)
                << what;
            EXPECT_THROW(obbsat::collide_pairs(records, pairs.data(), pairs.size(), verdicts.data(), options),
                         obbsat::invalid_input);
            EXPECT_THROW(obbsat::collide_pairs(records.data(), records.size(), pairs.data(), pairs.size(),
                                               verdicts.data(), options),
                         obbsat::invalid_input);
            EXPECT_THROW(obbsat::collide_stream(rects, rects, verdicts.data(), options), obbsat::invalid_input);
            EXPECT_THROW((void)obbsat::colliding_pairs(records, pairs, options), obbsat::invalid_input);
            EXPECT_TRUE(untouched(verdicts));
        }
        EXPECT_FALSE(obbsat::is_method(static_cast<obbsat::method>(bad)));
        EXPECT_STREQ(obbsat::method_name(static_cast<obbsat::method>(bad)), "unknown");
        EXPECT_EQ(obbsat::method_reference(static_cast<obbsat::method>(bad)), nullptr);
    }
}

TEST(collide_api, method_guarantees_are_stated_per_method) {
    EXPECT_EQ(obbsat::guarantee_of(obbsat::method::exact), obbsat::method_guarantee::exact);
    EXPECT_EQ(obbsat::guarantee_of(obbsat::method::conservative), obbsat::method_guarantee::no_false_negatives);
    for (const obbsat::method m : {obbsat::method::sat4, obbsat::method::sat4_centered, obbsat::method::sat4_double}) {
        EXPECT_EQ(obbsat::guarantee_of(m), obbsat::method_guarantee::none) << obbsat::method_name(m);
    }
}

TEST(collide_api, colliding_pairs_are_exactly_the_hits_in_input_order) {
    obbsat::scene s =
        obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::typical, 3000, 30000, 3));
    // Broadphase order is sorted; shuffle so that "in input order" means something.
    obbsat::seeded_random random(4);
    for (std::size_t i = s.pairs.size(); i > 1; --i) {
        std::swap(s.pairs[i - 1], s.pairs[random.below(i)]);
    }
    std::vector<rect> all(s.rects.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = s.rects[i];
    }
    const rect_records records(all);
    std::vector<pair_index> expected;
    for (const pair_index& p : s.pairs) {
        if (obbsat::ref::sat4(s.rects[p.a], s.rects[p.b])) {
            expected.push_back(p);
        }
    }
    ASSERT_GT(expected.size(), 0u);
    ASSERT_LT(expected.size(), s.pairs.size());
    auto expect_expected = [&](const std::vector<pair_index>& hits) {
        ASSERT_EQ(hits.size(), expected.size());
        for (std::size_t i = 0; i < hits.size(); ++i) {
            ASSERT_EQ(hits[i].a, expected[i].a) << "hit " << i;
            ASSERT_EQ(hits[i].b, expected[i].b) << "hit " << i;
        }
    };
    for (const backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 2u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + std::to_string(threads) +
                         " threads");
            expect_expected(obbsat::colliding_pairs(s.rects, s.pairs, options_for(use, threads)));
            expect_expected(obbsat::colliding_pairs(records, s.pairs, options_for(use, threads)));
        }
    }
}

TEST(collide_api, vector_forms_match_the_pointer_forms_with_bytes_zero_or_one) {
    const obbsat::scene s =
        obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::dense, 2000, 20000, 5));
    std::vector<rect> a, b;
    for (const pair_index& p : s.pairs) {
        a.push_back(s.rects[p.a]);
        b.push_back(s.rects[p.b]);
    }
    const rect_soa sa(a), sb(b);
    std::vector<rect> all(s.rects.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = s.rects[i];
    }
    const rect_records records(all);
    for (const backend use : obbsat::runnable_backends()) {
        SCOPED_TRACE(obbsat::backend_name(use));
        const auto options = options_for(use, 1);
        const std::vector<std::uint8_t> indexed = obbsat::collide_pairs(s.rects, s.pairs, options);
        const std::vector<std::uint8_t> from_records =
            obbsat::collide_pairs(records, s.pairs, options);
        const std::vector<std::uint8_t> stream = obbsat::collide_stream(sa, sb, options);
        std::vector<std::uint8_t> by_pointer(s.pairs.size(), canary);
        obbsat::collide_pairs(s.rects, s.pairs.data(), s.pairs.size(), by_pointer.data(), options);
        EXPECT_EQ(indexed, by_pointer);
        EXPECT_EQ(from_records, by_pointer);
        EXPECT_EQ(stream, by_pointer);
        EXPECT_TRUE(
            std::all_of(indexed.begin(), indexed.end(), [](std::uint8_t v) { return v <= 1; }));
    }
}

TEST(collide_api, empty_batches_are_answered_with_nothing) {
    const rect_soa rects = grid_of_squares(3);
    const rect_soa none;
    const rect_records no_records;
    const rect_records records(grid_rects(3));
    const std::vector<pair_index> no_pairs;
    for (const backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 0u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + std::to_string(threads) +
                         " threads");
            const auto options = options_for(use, threads);
            EXPECT_EQ(obbsat::collide_pairs(rects, nullptr, 0, nullptr, options), use);
            EXPECT_EQ(obbsat::collide_pairs(none, nullptr, 0, nullptr, options), use);
            EXPECT_TRUE(obbsat::collide_pairs(rects, no_pairs, options).empty());
            EXPECT_TRUE(obbsat::colliding_pairs(none, no_pairs, options).empty());
            EXPECT_EQ(obbsat::collide_pairs(records, nullptr, 0, nullptr, options), use);
            EXPECT_EQ(obbsat::collide_pairs(no_records, nullptr, 0, nullptr, options), use);
            EXPECT_TRUE(obbsat::collide_pairs(records, no_pairs, options).empty());
            EXPECT_TRUE(obbsat::colliding_pairs(no_records, no_pairs, options).empty());
            EXPECT_EQ(obbsat::collide_stream(none, none, nullptr, options), use);
            EXPECT_TRUE(obbsat::collide_stream(none, none, options).empty());
        }
    }
}

TEST(collide_api, method_names_round_trip) {
    const std::vector<obbsat::method> methods = obbsat::all_methods();
    EXPECT_EQ(methods.size(), obbsat::method_count);
    for (const obbsat::method m : methods) {
        const auto parsed = obbsat::parse_method(obbsat::method_name(m));
        ASSERT_TRUE(parsed.has_value()) << obbsat::method_name(m);
        EXPECT_EQ(*parsed, m);
    }
    EXPECT_STREQ(obbsat::method_name(obbsat::method::sat4), "sat4");
    EXPECT_STREQ(obbsat::method_name(obbsat::method::sat4_centered), "sat4_centered");
    EXPECT_STREQ(obbsat::method_name(obbsat::method::sat4_double), "sat4_double");
    for (const char* unknown : {"", "sat", "sat5", "SAT4", " sat4", "sat4 "}) {
        EXPECT_FALSE(obbsat::parse_method(unknown).has_value()) << '"' << unknown << '"';
    }
}

TEST(collide_api, backend_names_round_trip_and_auto_is_automatic) {
    std::vector<backend> named = obbsat::compiled_backends();
    named.push_back(backend::automatic);
    for (const backend b : named) {
        const auto parsed = obbsat::parse_backend(obbsat::backend_name(b));
        ASSERT_TRUE(parsed.has_value()) << obbsat::backend_name(b);
        EXPECT_EQ(*parsed, b);
    }
    EXPECT_STREQ(obbsat::backend_name(backend::automatic), "auto");
    EXPECT_EQ(obbsat::parse_backend("auto"), backend::automatic);
    const std::pair<const char*, backend> spelled[] = {{"scalar", backend::scalar},
                                                       {"sse2", backend::sse2},
                                                       {"avx2", backend::avx2},
                                                       {"avx512", backend::avx512}};
    for (const auto& [name, b] : spelled) {
        EXPECT_STREQ(obbsat::backend_name(b), name);
    }
    for (const char* unknown : {"", "automatic", "avx", "sse", "AVX2", "avx-512", "neon"}) {
        EXPECT_FALSE(obbsat::parse_backend(unknown).has_value()) << '"' << unknown << '"';
    }
}

TEST(collide_api, backend_table_is_ordered_best_first_ending_at_scalar) {
    const std::vector<backend> compiled = obbsat::compiled_backends();
    ASSERT_FALSE(compiled.empty());
    EXPECT_EQ(compiled.back(), backend::scalar);
    EXPECT_TRUE(obbsat::cpu_supports(backend::scalar));
    EXPECT_FALSE(obbsat::cpu_supports(backend::automatic));
    unsigned previous_lanes = 64;
    for (const backend b : compiled) {
        EXPECT_LT(obbsat::backend_lanes(b), previous_lanes) << obbsat::backend_name(b);
        previous_lanes = obbsat::backend_lanes(b);
    }
    EXPECT_EQ(obbsat::backend_lanes(backend::scalar), 1u);
    EXPECT_EQ(obbsat::backend_lanes(backend::sse2), 4u);
    EXPECT_EQ(obbsat::backend_lanes(backend::avx2), 8u);
    EXPECT_EQ(obbsat::backend_lanes(backend::avx512), 16u);
    // The best supported backend is the first runnable one of the table.
    const std::vector<backend> runnable = obbsat::runnable_backends();
    ASSERT_FALSE(runnable.empty());
    EXPECT_EQ(obbsat::best_supported_backend(), runnable.front());
}

TEST(collide_api, the_registry_compiles_exactly_the_backends_the_build_asked_for) {
    // OBBSAT_ISA_KERNELS, as tests/api/CMakeLists.txt passes it: "sse2,avx2,avx512" by default.
    const std::string requested = std::string(",") + OBBSAT_TEST_ISA_KERNELS + ",";
    std::vector<backend> expected;
    for (const backend b : {backend::avx512, backend::avx2, backend::sse2}) {
        if (requested.find(std::string(",") + obbsat::backend_name(b) + ",") != std::string::npos) {
            expected.push_back(b);
        }
    }
    expected.push_back(backend::scalar);
    EXPECT_EQ(obbsat::compiled_backends(), expected);
    for (const backend b : {backend::avx512, backend::avx2, backend::sse2}) {
        if (std::find(expected.begin(), expected.end(), b) != expected.end()) {
            continue;
        }
        // A backend left out of the build: its name parses, it never runs, and
        // asking for it says so.
        EXPECT_EQ(obbsat::parse_backend(obbsat::backend_name(b)), b);
        EXPECT_FALSE(obbsat::cpu_supports(b)) << obbsat::backend_name(b);
        const std::vector<backend> runnable = obbsat::runnable_backends();
        EXPECT_EQ(std::find(runnable.begin(), runnable.end(), b), runnable.end()) << obbsat::backend_name(b);
        try {
            (void)obbsat::resolve_backend(b);
            ADD_FAILURE() << obbsat::backend_name(b) << " resolved although it is not compiled";
        } catch (const obbsat::unsupported_backend& e) {
            EXPECT_NE(std::string(e.what()).find("is not compiled into this build"), std::string::npos) << e.what();
        }
    }
}

TEST(collide_api, automatic_resolves_to_the_best_backend_when_not_forced) {
    const char* forced = std::getenv("OBBSAT_BACKEND");
    if (forced != nullptr && *forced != '\0') {
        GTEST_SKIP() << "OBBSAT_BACKEND=" << forced << " is set: automatic follows it";
    }
    EXPECT_FALSE(obbsat::forced_backend().has_value());
    EXPECT_EQ(obbsat::resolve_backend(backend::automatic), obbsat::best_supported_backend());
    const rect_soa rects = grid_of_squares(4);
    const std::vector<pair_index> pairs = {{0, 1}};
    std::uint8_t verdict = canary;
    EXPECT_EQ(obbsat::collide_pairs(rects, pairs.data(), 1, &verdict),
              obbsat::best_supported_backend());
    EXPECT_EQ(verdict, 1);  // squares 1.5 wide on a unit grid overlap their neighbour
}

// slow_path_pairs reports how many pairs the exact method settled on its slow
// path: at most all of them, and 0 for every other method and for an empty batch.
TEST(collide_api, slow_path_pairs_is_reported_for_exact_and_zero_otherwise) {
    const obbsat::scene s =
        obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::typical, 3000, 30000, 9));
    const rect_records records(s.rects);
    std::vector<std::uint8_t> verdicts(s.pairs.size());
    for (const backend use : obbsat::runnable_backends()) {
        for (const obbsat::method m : obbsat::methods_on(obbsat::store_kind::corners)) {
            for (const unsigned threads : {1u, 0u}) {
                SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " +
                             obbsat::method_name(m) + ", " + std::to_string(threads) + " threads");
                auto options = options_for(use, threads);
                options.test = m;
                std::size_t settled = 123456789;
                options.slow_path_pairs = &settled;
                obbsat::collide_pairs(s.rects, s.pairs.data(), s.pairs.size(), verdicts.data(),
                                      options);
                if (m == obbsat::method::exact) {
                    EXPECT_LE(settled, s.pairs.size());
                } else {
                    EXPECT_EQ(settled, 0u);
                }
                settled = 123456789;
                obbsat::collide_pairs(records, s.pairs.data(), s.pairs.size(), verdicts.data(),
                                      options);
                EXPECT_LE(settled, s.pairs.size());
                settled = 123456789;
                obbsat::collide_pairs(records, nullptr, 0, nullptr, options);
                EXPECT_EQ(settled, 0u) << "empty batch";
            }
        }
    }
}

// OBBSAT_BACKEND is read once per process, so each case runs in a fresh
// process: a death test in the "threadsafe" style re-runs this binary for it.
void exit_with_resolved_backend(const char* environment_value, backend requested = backend::automatic) {
    setenv("OBBSAT_BACKEND", environment_value, 1);
    try {
        const rect_soa rects = grid_of_squares(4);
        const std::vector<pair_index> pairs = {{0, 1}};
        std::uint8_t verdict = canary;
        obbsat::collide_options options;
        options.use = requested;
        // The call comes first: the variable must be checked by the entry
        // point itself, not only by forced_backend().
        const backend ran = obbsat::collide_pairs(rects, pairs.data(), 1, &verdict, options);
        const auto forced = obbsat::forced_backend();
        std::fprintf(stderr, "forced %s\n", forced ? obbsat::backend_name(*forced) : "nothing");
        std::fprintf(stderr, "ran %s\n", obbsat::backend_name(ran));
        std::exit(verdict == 1 ? 0 : 2);
    } catch (const obbsat::unsupported_backend& e) {
        std::fprintf(stderr, "unsupported_backend: %s\n", e.what());
        std::exit(3);
    }
}

TEST(backends, the_runnable_ones_run_best_first_and_end_with_scalar) {
    const std::vector<backend> runnable = obbsat::runnable_backends();
    ASSERT_FALSE(runnable.empty());
    EXPECT_EQ(runnable.front(), obbsat::best_supported_backend());
    EXPECT_EQ(runnable.back(), backend::scalar);
    const std::vector<rect> one{rect{{0, 1}, {1, 1}, {1, 0}, {0, 0}}};
    const rect_records records(one);
    const std::vector<obbsat::pair_index> pairs{{0, 0}};
    std::uint8_t verdict = 0;
    for (const backend b : obbsat::compiled_backends()) {
        const bool listed = std::find(runnable.begin(), runnable.end(), b) != runnable.end();
        EXPECT_EQ(listed, obbsat::cpu_supports(b)) << obbsat::backend_name(b);
        if (listed) {
            obbsat::collide_options options;
            options.use = b;
            EXPECT_EQ(obbsat::collide_pairs(records, pairs.data(), 1, &verdict, options), b);
            EXPECT_EQ(verdict, 1);
        }
    }
}

TEST(backend_environment, obbsat_backend_forces_the_automatic_choice) {
    testing::FLAGS_gtest_death_test_style = "threadsafe";
    for (const backend b : obbsat::runnable_backends()) {
        const std::string name = obbsat::backend_name(b);
        EXPECT_EXIT(exit_with_resolved_backend(name.c_str()), testing::ExitedWithCode(0),
                    "forced " + name + "\nran " + name + "\n");
    }
    const std::string best = obbsat::backend_name(obbsat::best_supported_backend());
    EXPECT_EXIT(exit_with_resolved_backend("auto"), testing::ExitedWithCode(0),
                "forced auto\nran " + best + "\n");
    // Empty is the same as unset.
    EXPECT_EXIT(exit_with_resolved_backend(""), testing::ExitedWithCode(0),
                "forced nothing\nran " + best + "\n");
}

TEST(backend_environment, an_unknown_obbsat_backend_is_refused_naming_it) {
    testing::FLAGS_gtest_death_test_style = "threadsafe";
    EXPECT_EXIT(exit_with_resolved_backend("avx1024"), testing::ExitedWithCode(3),
                "unsupported_backend: OBBSAT_BACKEND=avx1024 names no backend");
}

TEST(backend_environment, an_unknown_obbsat_backend_is_refused_when_a_backend_is_named_too) {
    testing::FLAGS_gtest_death_test_style = "threadsafe";
    for (const backend b : obbsat::runnable_backends()) {
        EXPECT_EXIT(exit_with_resolved_backend("avx1024", b), testing::ExitedWithCode(3),
                    "unsupported_backend: OBBSAT_BACKEND=avx1024 names no backend \\(expected auto, scalar, "
                    "sse2, avx2 or avx512\\)");
    }
}

TEST(backend_environment, a_named_backend_wins_over_a_valid_obbsat_backend) {
    testing::FLAGS_gtest_death_test_style = "threadsafe";
    for (const backend b : obbsat::runnable_backends()) {
        const std::string name = obbsat::backend_name(b);
        EXPECT_EXIT(exit_with_resolved_backend("scalar", b), testing::ExitedWithCode(0),
                    "forced scalar\nran " + name + "\n");
    }
}

TEST(backend_environment, an_obbsat_backend_this_cpu_lacks_is_refused) {
    testing::FLAGS_gtest_death_test_style = "threadsafe";
    std::vector<backend> missing;
    for (const backend b : {backend::sse2, backend::avx2, backend::avx512}) {
        if (!obbsat::cpu_supports(b)) {
            missing.push_back(b);
        }
    }
    if (missing.empty()) {
        GTEST_SKIP() << "this CPU runs every backend of the enum, so none can be refused here";
    }
    for (const backend b : missing) {
        const std::string name = obbsat::backend_name(b);
        EXPECT_EXIT(exit_with_resolved_backend(name.c_str()), testing::ExitedWithCode(3),
                    "unsupported_backend: OBBSAT_BACKEND=" + name);
    }
}

}  // namespace
