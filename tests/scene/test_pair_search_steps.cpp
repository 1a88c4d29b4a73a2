// The scene query's engine (kernel/scene/pair_search.hpp) taken one step at
// a time: rows that change between its passes, which the caller must not do
// (find_pairs.hpp) but which must never make a count underflow into an absurd
// allocation; and the candidate buffer of a crowded strip, which stays one
// block however many pairs the strip holds.
#include "scene/pair_search.hpp"
#include "test_support/pose_query_rows.hpp"

#include "test_support/sanitizers.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>

#include <gtest/gtest.h>

#if defined(__linux__)
#include <sys/resource.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace obbsat::detail {

struct pair_search_test_access {
    /// The steps of pair_search::run on one thread, with `change` called
    /// after the order is made and before the records are copied: what a
    /// caller writing into the rows from another thread could do.
    static void run_with_rows_changed_after_order(pair_search& search, const query_input& input,
                                                  const std::function<void()>& change, const pair_chunk_sink& emit) {
        search.set_query(input);
        constexpr std::size_t parts = 1;
        search.used_parts_ = parts;
        search.measure_extent(input, parts, search.same_scene_as_last());
        search.order_boxes(input, parts);
        change();
        search.copy_records(input, parts);
        search.collect_visits(parts);
        search.sweep(parts, &emit);
    }

    static std::size_t strips(const pair_search& search) { return search.grid_.strips; }

    /// The typical extent the extent pass of `input` measures (one thread),
    /// which the next query that keeps candidates widens by.
    static float measured_typical_extent(pair_search& search, const query_input& input) {
        search.set_query(input);
        search.measure_extent(input, 1, false);
        return search.kept_.measured_typical_extent;
    }

    /// The largest candidate buffer of any part, in pairs.
    static std::size_t largest_candidate_buffer(const pair_search& search) {
        std::size_t largest = 0;
        for (const auto& p : search.parts_) {
            largest = std::max(largest, p.candidates.capacity());
        }
        return largest;
    }
};

}  // namespace obbsat::detail

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat::detail::pair_search;
using obbsat::detail::pair_search_test_access;
using obbsat::detail::query_input;

/// Rows of poses in the caller's memory, checked by the query.
query_input rows_of(const std::vector<rect_pose>& a, const std::vector<rect_pose>* b = nullptr) {
    return obbsat::test_support::pose_query_rows(a, b);
}

/// While it lives, this process may map at most `extra` bytes more than it
/// has now (Linux; not under the sanitizers, whose shadow memory it would
/// refuse): an absurd allocation then fails at once instead of taking the
/// machine's memory.
class address_space_limit {
public:
    explicit address_space_limit(std::size_t extra) {
#if defined(__linux__)
        if (obbsat::test_support::under_sanitizers || getrlimit(RLIMIT_AS, &old_) != 0) {
            return;
        }
        std::ifstream status("/proc/self/status");
        std::string word;
        std::size_t kib = 0;
        while (status >> word) {
            if (word == "VmSize:") {
                status >> kib;
                break;
            }
        }
        if (kib == 0) {
            return;
        }
        rlimit limited = old_;
        const rlim_t wanted = static_cast<rlim_t>(kib * 1024 + extra);
        limited.rlim_cur = old_.rlim_max == RLIM_INFINITY || wanted < old_.rlim_max ? wanted : old_.rlim_max;
        active_ = setrlimit(RLIMIT_AS, &limited) == 0;
#else
        (void)extra;
#endif
    }
    ~address_space_limit() {
#if defined(__linux__)
        if (active_) {
            setrlimit(RLIMIT_AS, &old_);
        }
#endif
    }
    address_space_limit(const address_space_limit&) = delete;
    address_space_limit& operator=(const address_space_limit&) = delete;

private:
#if defined(__linux__)
    rlimit old_{};
#endif
    bool active_ = false;
};

/// A column of boxes one above the other, `count` of them, 0.5 apart: each
/// meets its neighbours, and the scene spans many strips.
std::vector<rect_pose> column(std::size_t count) {
    std::vector<rect_pose> out;
    for (std::size_t i = 0; i < count; ++i) {
        out.push_back(rect_pose{{0.0f, 0.5f * static_cast<float>(i)}, {0.5f, 0.5f}, {1.0f, 0.0f}});
    }
    return out;
}

TEST(pair_search, the_typical_extent_counts_every_box_wherever_it_lies_in_a_run) {
    // The larger extent of each box's bounds, axis-aligned: 3 for five boxes
    // (exponent 1), 40 for four (exponent 5); the median is 3, the typical
    // extent the power of two below it. The small boxes sit at positions of
    // every remainder modulo 2, 3 and 4, so a count that missed the boxes of
    // some positions would find no median (or the large one).
    std::vector<rect_pose> poses;
    for (const float half : {20.0f, 1.5f, 20.0f, 1.5f, 1.5f, 20.0f, 1.5f, 20.0f, 1.5f}) {
        const float x = static_cast<float>(poses.size()) * 50.0f;
        poses.push_back(rect_pose{{x, 0.0f}, {half, half}, {1.0f, 0.0f}});
    }
    collide_options options;
    options.test = method::exact;
    pair_search search(options);
    EXPECT_EQ(pair_search_test_access::measured_typical_extent(search, rows_of(poses)), 2.0f);
    // Past one run of bounds (256 boxes): 300 boxes, two of every three of extent 6 (typical 4).
    std::vector<rect_pose> many;
    for (std::size_t i = 0; i < 300; ++i) {
        const float half = i % 3 == 0 ? 20.0f : 3.0f;
        many.push_back(rect_pose{{static_cast<float>(i) * 50.0f, 0.0f}, {half, half}, {1.0f, 0.0f}});
    }
    EXPECT_EQ(pair_search_test_access::measured_typical_extent(search, rows_of(many)), 4.0f);
}

TEST(pair_search, rows_moved_down_between_passes_make_no_count_underflow) {
    auto poses = column(2000);
    const query_input input = rows_of(poses);
    collide_options options;
    options.test = method::exact;
    options.threads = 1;
    pair_search search(options);
    std::size_t found = 0;
    {
        const address_space_limit limit(std::size_t{2} << 30);
        // The top boxes drop to the bottom after the order put them in the top
        // strips: their highest strip is now below their lowest.
        EXPECT_NO_THROW(pair_search_test_access::run_with_rows_changed_after_order(
            search, input,
            [&] {
                for (std::size_t i = poses.size() - 10; i < poses.size(); ++i) {
                    poses[i].center.y = -100.0f;
                }
            },
            [&](const pair_index*, std::size_t count) { found += count; }));
    }
    ASSERT_GT(pair_search_test_access::strips(search), 100u);
    // A wrong answer is allowed, an absurd one is not: visits at most one per strip and box.
    EXPECT_LE(search.stats().visits, poses.size() * pair_search_test_access::strips(search));
    EXPECT_LE(found, poses.size() * (poses.size() - 1) / 2);
    // The same engine answers the rows as they are now like a fresh query.
    std::size_t again = 0;
    search.run(input, [&](const pair_index*, std::size_t count) { again += count; });
    EXPECT_EQ(again, obbsat::find_pairs(poses, options).size());
}

TEST(pair_search, rows_made_invalid_between_passes_give_an_answer_or_an_error) {
    // NaNs, infinities and negative extents after the check: whatever the
    // answer, no crash and no absurd allocation.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const rect_pose bad : {rect_pose{{nan, nan}, {nan, nan}, {nan, nan}},
                                rect_pose{{0, -inf}, {inf, inf}, {1, 0}},
                                rect_pose{{0, 1e30f}, {-1, -1}, {1, 0}}}) {
        const std::vector<rect_pose> fresh = column(2000);
        std::vector<rect_pose> poses = fresh;
        const query_input input = rows_of(poses);
        for (const method m : {method::exact, method::local, method::conservative}) {
            collide_options options;
            options.test = m;
            options.threads = 1;
            pair_search search(options);
            const address_space_limit limit(std::size_t{2} << 30);
            std::copy(fresh.begin(), fresh.end(), poses.begin());
            try {
                pair_search_test_access::run_with_rows_changed_after_order(
                    search, input, [&] { poses[1000] = bad; poses[1999] = bad; },
                    [](const pair_index*, std::size_t) {});
            } catch (const std::bad_alloc&) {
                ADD_FAILURE() << "an allocation failed";
            } catch (const std::length_error&) {
                ADD_FAILURE() << "an allocation failed";
            } catch (const std::exception&) {
                // A clear error is an answer too.
            }
            EXPECT_LE(search.stats().visits, poses.size() * pair_search_test_access::strips(search));
        }
    }
}

TEST(pair_search, a_crowded_strip_tests_its_candidates_in_blocks) {
    // 3000 boxes in one place: 4.5 million candidates, all in one strip.
    const std::vector<rect_pose> stack(3000, rect_pose{{0, 0}, {1, 1}, {1, 0}});
    collide_options options;
    options.test = method::exact;
    options.threads = 1;
    pair_search search(options);
    std::size_t found = 0;
    search.run(rows_of(stack), [&](const pair_index*, std::size_t count) { found += count; });
    EXPECT_EQ(found, stack.size() * (stack.size() - 1) / 2);
    EXPECT_EQ(search.stats().candidates, found);
    EXPECT_LE(pair_search_test_access::largest_candidate_buffer(search), std::size_t{2048});
}

}  // namespace
