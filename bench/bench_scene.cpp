// Benchmarks of obbsat's scene queries (obbsat/find_pairs.hpp): from a
// scene's poses, or corner records converted from them, to the list of its
// colliding pairs, with no pair list to bring.
//
//   scene/<method>/<store>/...  obbsat::find_pairs, a fresh query each time
//   frame/<method>/<store>/...  one obbsat::pair_finder across the frames
//   drift/<method>/poses/...    one obbsat::pair_finder over a scene in steady
//       motion: each box at its own velocity (up to ±frame_step in x and y per
//       frame) and turning rate (up to ±0.005 rad per frame), reversing every
//       drift_half_period frames, so that boxes keep leaving the widened
//       bounds the finder kept and the workload stays the same however many
//       iterations run. One period untimed, then one timed (64 frames).
//       The motion itself is not timed. Counter
//       reused_candidates: the share of frames answered from kept candidates.
//
//   filters/exact/poses/.../filtered:<0|1>  obbsat::find_pairs on the
//       as-generated uniform scene, without pair filters (0) and with them (1):
//       about 71% of the boxes are "debris" (category 2) that collide only
//       with "solid" boxes (mask 1), so about half the overlapping pairs, the
//       debris-debris ones, are dropped before the method. Both rows check
//       their answer against the unfiltered one filtered afterwards (up to
//       check_limit boxes). Counters: pairs_per_box, candidates_per_box,
//       filtered_share (of the unfiltered pairs).
//
//   precision/exact/poses/.../float64 and .../float32  obbsat::find_pairs on
//       one thread over the as-generated uniform scene moved to UTM-like
//       coordinates (500000.125, 5712345.5), first as double poses, then as
//       those poses rounded to float32, in the same run. Both rows first check
//       their answer against brute force over the pairs of a plain sweep of
//       the same query's bounds (up to check_limit boxes): the double one
//       against the double oracle. Counter pairs_per_box.
//
//   find_pairs/exact/poses/..., find_contacts/exact/poses/... and
//       find_contacts_into/exact/poses/...  the scene query on one thread
//       over the as-generated uniform scene, without and with contacts
//       (obbsat::find_contacts at margin 0; _into: into one scene_contacts
//       filled once before the timed loop and kept between iterations, so
//       no fresh memory), in the same run.
//       Each checks that find_contacts's pairs are find_pairs's (up to
//       check_limit boxes). Counters pairs_per_box, points_per_pair.
//
//   find_pairs64/exact/poses/..., find_contacts64/exact/poses/... and
//       find_contacts64_into/exact/poses/...  the same three on the double
//       poses of the precision rows (the uniform scene at UTM-like
//       coordinates, rect_pose64 rows read in place): obbsat::find_pairs and
//       obbsat::find_contacts64 at margin 0, the contacts in double. Each
//       checks that find_contacts64's pairs are find_pairs's (up to
//       check_limit boxes).
//
// The peers' rows (peer_scene/, peer_frame/) answer the same question on the
// same scenes; scene_harness.hpp says how every row is timed and checked.
#include "bench_registry.hpp"
#include "scene_harness.hpp"
#include "scene_workload.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/bounds64.hpp>

#include <benchmark/benchmark.h>

#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace obbsat_bench {

namespace {

/// A method on one store: the one list of what the scene rows measure.
struct scene_method {
    obbsat::store_kind store;
    obbsat::method test;
};

constexpr scene_method scene_methods[] = {
    {obbsat::store_kind::poses, obbsat::method::exact},
    {obbsat::store_kind::poses, obbsat::method::local},
    {obbsat::store_kind::corners, obbsat::method::sat4},
    {obbsat::store_kind::corners, obbsat::method::exact},
};

/// The store of one kind for both frames of a scene.
template <class Store>
struct frame_stores {
    const Store* as_generated;
    const Store* moved;

    const Store& operator[](scene_frame f) const { return f == scene_frame::as_generated ? *as_generated : *moved; }
};

frame_stores<obbsat::pose_records> pose_frames(scene_workload& w) {
    return {&w.poses(scene_frame::as_generated), &w.poses(scene_frame::moved)};
}

frame_stores<obbsat::rect_records> corner_frames(scene_workload& w) {
    return {&w.corners(scene_frame::as_generated), &w.corners(scene_frame::moved)};
}

/// A fresh find_pairs per call. find_pairs says nothing of its candidates, so
/// their count comes from one pair_finder on the same frame, before timing.
template <class Store>
class cold_query final : public scene_query {
public:
    cold_query(frame_stores<Store> stores, const obbsat::collide_options& options, std::size_t candidates)
        : stores_(stores), options_(options), candidates_(candidates) {}

    const std::vector<obbsat::pair_index>& find(scene_frame f) override {
        pairs_ = obbsat::find_pairs(stores_[f], options_);
        return pairs_;
    }
    std::size_t candidates() const override { return candidates_; }

private:
    frame_stores<Store> stores_;
    obbsat::collide_options options_;
    std::size_t candidates_;
    std::vector<obbsat::pair_index> pairs_;
};

/// One pair_finder kept across calls.
template <class Store>
class frame_query final : public scene_query {
public:
    frame_query(frame_stores<Store> stores, const obbsat::collide_options& options)
        : stores_(stores), finder_(options) {}

    const std::vector<obbsat::pair_index>& find(scene_frame f) override { return finder_.find(stores_[f]); }
    std::size_t candidates() const override { return finder_.stats().candidates; }
    std::optional<bool> reused_order() const override { return finder_.stats().reused_order; }
    std::optional<double> kernel_seconds() const override { return finder_.stats().kernel_seconds; }

private:
    frame_stores<Store> stores_;
    obbsat::pair_finder finder_;
};

obbsat::collide_options options_for(obbsat::method test, unsigned threads) {
    obbsat::collide_options options;
    options.test = test;
    options.threads = threads;
    return options;
}

/// The candidates of the as-generated frame, counted once per store and method.
template <class Store>
std::size_t cold_candidates(const frame_stores<Store>& stores, obbsat::method test) {
    static std::map<std::tuple<const Store*, obbsat::method>, std::size_t> counted;
    const auto key = std::make_tuple(stores.as_generated, test);
    auto found = counted.find(key);
    if (found == counted.end()) {
        obbsat::pair_finder finder(options_for(test, 0));
        finder.find(stores[scene_frame::as_generated]);
        found = counted.emplace(key, finder.stats().candidates).first;
    }
    return found->second;
}

template <class Store>
scene_query_prepare prepare_for(scene_method m, frame_stores<Store> (*stores_of)(scene_workload&)) {
    return [m, stores_of](scene_workload& w, scene_row_kind kind) -> scene_query_factory {
        const frame_stores<Store> stores = stores_of(w);
        if (kind == scene_row_kind::frame) {
            return [stores, m](unsigned threads) -> std::unique_ptr<scene_query> {
                return std::make_unique<frame_query<Store>>(stores, options_for(m.test, threads));
            };
        }
        const std::size_t candidates = cold_candidates(stores, m.test);
        return [stores, m, candidates](unsigned threads) -> std::unique_ptr<scene_query> {
            return std::make_unique<cold_query<Store>>(stores, options_for(m.test, threads), candidates);
        };
    };
}

/// Frames a drift row moves one way before it turns back.
constexpr int drift_half_period = 32;

/// The poses of a scene in steady motion (see the top of this file).
class drifting_scene {
public:
    explicit drifting_scene(const obbsat::pose_records& start) : current_(start) {
        obbsat::seeded_random random(4242);
        for (std::size_t i = 0; i < start.size(); ++i) {
            start_.push_back(start[i]);
            velocity_.push_back({random.uniform(-frame_step, frame_step), random.uniform(-frame_step, frame_step)});
            turn_.push_back(random.uniform(-0.005f, 0.005f));
        }
    }

    /// Moves every box to frame `t`.
    void go_to(int t) {
        const int phase = t % (2 * drift_half_period);
        const auto k = static_cast<float>(phase <= drift_half_period ? phase : 2 * drift_half_period - phase);
        for (std::size_t i = 0; i < start_.size(); ++i) {
            obbsat::rect_pose p = start_[i];
            p.center = {p.center.x + velocity_[i].x * k, p.center.y + velocity_[i].y * k};
            const float c = std::cos(turn_[i] * k), s = std::sin(turn_[i] * k);
            p.rotation = {p.rotation.x * c - p.rotation.y * s, p.rotation.x * s + p.rotation.y * c};
            current_.set(i, p);
        }
    }

    const obbsat::pose_records& poses() const { return current_; }

private:
    std::vector<obbsat::rect_pose> start_;
    std::vector<obbsat::point> velocity_;
    std::vector<float> turn_;
    obbsat::pose_records current_;
};

void run_drift_row(benchmark::State& state, obbsat::method test, std::size_t boxes, obbsat::scene_sizes sizes,
                   unsigned threads) {
    try {
        scene_workload& w = scene_workload_for(boxes, sizes);
        drifting_scene scene(w.poses(scene_frame::as_generated));
        obbsat::pair_finder finder(options_for(test, threads));
        int t = 0;
        if (boxes <= check_limit) {
            // Every frame of one period equals a fresh query before anything is timed.
            for (; t < 2 * drift_half_period; ++t) {
                scene.go_to(t);
                const std::vector<obbsat::pair_index>& got = finder.find(scene.poses());
                const std::vector<obbsat::pair_index> fresh = obbsat::find_pairs(scene.poses(), options_for(test, 1));
                const auto same = [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
                    return x.a == y.a && x.b == y.b;
                };
                if (got.size() != fresh.size() || !std::equal(got.begin(), got.end(), fresh.begin(), same)) {
                    state.SkipWithError(("frame " + std::to_string(t) + " differs from a fresh query").c_str());
                    return;
                }
            }
        } else {
            // One period untimed, so that the timed frames see the margin the motion settled.
            for (; t < 2 * drift_half_period; ++t) {
                scene.go_to(t);
                finder.find(scene.poses());
            }
        }
        double pairs = 0, candidates = 0, from_kept = 0;
        for (auto _ : state) {
            state.PauseTiming();
            scene.go_to(++t);
            state.ResumeTiming();
            const std::vector<obbsat::pair_index>& found = finder.find(scene.poses());
            benchmark::DoNotOptimize(found.data());
            pairs += static_cast<double>(found.size());
            candidates += static_cast<double>(finder.stats().candidates);
            from_kept += finder.stats().reused_candidates ? 1.0 : 0.0;
        }
        const auto n = static_cast<double>(boxes);
        state.counters["ns_per_box"] =
            benchmark::Counter(n * 1e-9, static_cast<benchmark::Counter::Flags>(
                                             benchmark::Counter::kIsIterationInvariantRate |
                                             benchmark::Counter::kInvert));
        state.counters["pairs_per_box"] = benchmark::Counter(pairs / n, benchmark::Counter::kAvgIterations);
        state.counters["candidates_per_box"] = benchmark::Counter(candidates / n, benchmark::Counter::kAvgIterations);
        state.counters["reused_candidates"] = benchmark::Counter(from_kept, benchmark::Counter::kAvgIterations);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}

/// The filters of the filters/ rows for a scene of `boxes`: each box debris
/// (category 2, colliding with category 1 only) with probability 1/sqrt(2),
/// else solid (category 1, colliding with everything); no groups.
struct debris_filters {
    std::vector<std::uint64_t> categories, masks;

    explicit debris_filters(std::size_t boxes) {
        obbsat::seeded_random random(777);
        for (std::size_t i = 0; i < boxes; ++i) {
            const bool debris = random.uniform(0.0f, 1.0f) < 0.70710678f;
            categories.push_back(debris ? 2u : 1u);
            masks.push_back(debris ? 1u : ~std::uint64_t{0});
        }
    }
    obbsat::pair_filters view() const {
        obbsat::pair_filters f;
        f.categories = categories.data();
        f.masks = masks.data();
        return f;
    }
    bool passes(const obbsat::pair_index& p) const {
        return (categories[p.a] & masks[p.b]) != 0 && (categories[p.b] & masks[p.a]) != 0;
    }
};

void run_filter_row(benchmark::State& state, std::size_t boxes, bool filtered) {
    try {
        scene_workload& w = scene_workload_for(boxes, obbsat::scene_sizes::uniform);
        const obbsat::pose_records& poses = w.poses(scene_frame::as_generated);
        const debris_filters filters(boxes);
        const obbsat::box_view view =
            filtered ? obbsat::box_view(poses).with_filters(filters.view()) : obbsat::box_view(poses);
        const obbsat::collide_options options = options_for(obbsat::method::exact, 1);
        // Candidates from a pair_finder's first call, which answers as find_pairs does.
        obbsat::pair_finder counter(options);
        const std::vector<obbsat::pair_index> got = counter.find(view);
        const std::size_t candidates = counter.stats().candidates;
        const std::vector<obbsat::pair_index> all = obbsat::find_pairs(poses, options);
        std::size_t passing = 0;
        for (const obbsat::pair_index& p : all) {
            passing += filters.passes(p) ? 1u : 0u;
        }
        if (boxes <= check_limit) {
            std::vector<obbsat::pair_index> want;
            for (const obbsat::pair_index& p : all) {
                if (!filtered || filters.passes(p)) {
                    want.push_back(p);
                }
            }
            const auto same = [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
                return x.a == y.a && x.b == y.b;
            };
            if (got.size() != want.size() || !std::equal(got.begin(), got.end(), want.begin(), same)) {
                state.SkipWithError("the filtered pairs differ from the unfiltered ones filtered afterwards");
                return;
            }
        }
        double pairs = 0;
        for (auto _ : state) {
            const std::vector<obbsat::pair_index> found = obbsat::find_pairs(view, options);
            benchmark::DoNotOptimize(found.data());
            pairs += static_cast<double>(found.size());
        }
        const auto n = static_cast<double>(boxes);
        state.counters["ns_per_box"] =
            benchmark::Counter(n * 1e-9, static_cast<benchmark::Counter::Flags>(
                                             benchmark::Counter::kIsIterationInvariantRate |
                                             benchmark::Counter::kInvert));
        state.counters["pairs_per_box"] = benchmark::Counter(pairs / n, benchmark::Counter::kAvgIterations);
        state.counters["candidates_per_box"] = static_cast<double>(candidates) / n;
        state.counters["filtered_share"] =
            all.empty() ? 0.0 : 1.0 - static_cast<double>(passing) / static_cast<double>(all.size());
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}

/// The as-generated uniform scene at UTM-like coordinates: its poses in double, and rounded to float32.
struct utm_scene {
    std::vector<obbsat::rect_pose64> wide;
    std::vector<obbsat::rect_pose> rounded;
};

const utm_scene& utm_scene_for(std::size_t boxes) {
    static std::map<std::size_t, std::unique_ptr<utm_scene>> built;
    std::unique_ptr<utm_scene>& scene = built[boxes];
    if (!scene) {
        scene = std::make_unique<utm_scene>();
        const obbsat::pose_records& poses =
            scene_workload_for(boxes, obbsat::scene_sizes::uniform).poses(scene_frame::as_generated);
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const obbsat::rect_pose p = poses[i];
            const obbsat::rect_pose64 q{{500000.125 + p.center.x, 5712345.5 + p.center.y},
                                        {p.half_extents.x, p.half_extents.y},
                                        {p.rotation.x, p.rotation.y}};
            scene->wide.push_back(q);
            scene->rounded.push_back({{static_cast<float>(q.center.x), static_cast<float>(q.center.y)},
                                      {p.half_extents.x, p.half_extents.y},
                                      {p.rotation.x, p.rotation.y}});
        }
    }
    return *scene;
}

/// The double answer by the double oracle over the pairs whose outward float
/// bounds overlap, found by a plain sort on lo_x (no find_pairs).
std::vector<obbsat::pair_index> brute_force64(const std::vector<obbsat::rect_pose64>& poses) {
    std::vector<obbsat::ref::box_bounds> b;
    std::vector<std::uint32_t> by_lo(poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        b.push_back(obbsat::ref::bounds_of(poses[i]));
        by_lo[i] = static_cast<std::uint32_t>(i);
    }
    std::sort(by_lo.begin(), by_lo.end(), [&](std::uint32_t x, std::uint32_t y) { return b[x].lo_x < b[y].lo_x; });
    std::vector<obbsat::pair_index> out;
    for (std::size_t k = 0; k < by_lo.size(); ++k) {
        for (std::size_t l = k + 1; l < by_lo.size() && b[by_lo[l]].lo_x <= b[by_lo[k]].hi_x; ++l) {
            const std::uint32_t i = std::min(by_lo[k], by_lo[l]), j = std::max(by_lo[k], by_lo[l]);
            if (obbsat::ref::bounds_overlap(b[i], b[j]) && obbsat::oracle::intersects(poses[i], poses[j])) {
                out.push_back({i, j});
            }
        }
    }
    std::sort(out.begin(), out.end(), [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
        return x.a < y.a || (x.a == y.a && x.b < y.b);
    });
    return out;
}

void run_precision_row(benchmark::State& state, std::size_t boxes, bool doubles) {
    try {
        const utm_scene& scene = utm_scene_for(boxes);
        const obbsat::box_view view = doubles ? obbsat::box_view(scene.wide) : obbsat::box_view(scene.rounded);
        const obbsat::collide_options options = options_for(obbsat::method::exact, 1);
        if (doubles && boxes <= check_limit) {
            const std::vector<obbsat::pair_index> got = obbsat::find_pairs(view, options);
            const std::vector<obbsat::pair_index> want = brute_force64(scene.wide);
            const auto same = [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
                return x.a == y.a && x.b == y.b;
            };
            if (got.size() != want.size() || !std::equal(got.begin(), got.end(), want.begin(), same)) {
                state.SkipWithError("the double query differs from the double oracle");
                return;
            }
        }
        double pairs = 0;
        for (auto _ : state) {
            const std::vector<obbsat::pair_index> found = obbsat::find_pairs(view, options);
            benchmark::DoNotOptimize(found.data());
            pairs += static_cast<double>(found.size());
        }
        const auto n = static_cast<double>(boxes);
        state.counters["ns_per_box"] =
            benchmark::Counter(n * 1e-9, static_cast<benchmark::Counter::Flags>(
                                             benchmark::Counter::kIsIterationInvariantRate |
                                             benchmark::Counter::kInvert));
        state.counters["pairs_per_box"] = benchmark::Counter(pairs / n, benchmark::Counter::kAvgIterations);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}


/// What a row of the contacts rows times.
enum class contacts_row { pairs, contacts, contacts_into };

/// The rows and answer type of the float contacts rows (the as-generated
/// uniform scene) or the double ones (the same at UTM-like coordinates).
template <class Answer>
obbsat::box_view contacts_scene(std::size_t boxes);
template <>
obbsat::box_view contacts_scene<obbsat::scene_contacts>(std::size_t boxes) {
    return obbsat::box_view(scene_workload_for(boxes, obbsat::scene_sizes::uniform).poses(scene_frame::as_generated));
}
template <>
obbsat::box_view contacts_scene<obbsat::scene_contacts64>(std::size_t boxes) {
    return obbsat::box_view(utm_scene_for(boxes).wide);
}

/// find_contacts at margin 0 into `found`: float contacts of float rows, double ones of double rows.
void find_contacts_into(const obbsat::box_view& view, const obbsat::collide_options& options,
                        obbsat::scene_contacts& found) {
    obbsat::find_contacts(view, options, 0.0f, found);
}
void find_contacts_into(const obbsat::box_view& view, const obbsat::collide_options& options,
                        obbsat::scene_contacts64& found) {
    obbsat::find_contacts(view, options, 0.0, found);
}

/// One row of the three: find_pairs, find_contacts at margin 0, or
/// find_contacts into one answer kept from one iteration to the next, with
/// method exact on one thread, over the as-generated uniform scene (Answer
/// scene_contacts) or its double poses at UTM-like coordinates (Answer
/// scene_contacts64). Each first checks that find_contacts's pairs are
/// find_pairs's (up to check_limit boxes).
template <class Answer>
void run_contacts_row(benchmark::State& state, std::size_t boxes, contacts_row row) {
    const bool contacts = row != contacts_row::pairs;
    try {
        const obbsat::box_view view = contacts_scene<Answer>(boxes);
        const obbsat::collide_options options = options_for(obbsat::method::exact, 1);
        if (boxes <= check_limit) {
            const std::vector<obbsat::pair_index> want = obbsat::find_pairs(view, options);
            Answer got;
            find_contacts_into(view, options, got);
            const auto same = [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
                return x.a == y.a && x.b == y.b;
            };
            if (got.pairs.size() != want.size() || got.contacts.size() != want.size() ||
                !std::equal(want.begin(), want.end(), got.pairs.begin(), same)) {
                state.SkipWithError("find_contacts's pairs differ from find_pairs's");
                return;
            }
        }
        // Nothing but the call is timed: the contacts' points are counted
        // after the loop, on the last answer (pausing the timer in the loop
        // costs time of its own). The row that returns an answer frees the
        // last one before the next call, as a caller's answer going out of
        // scope each step would (freed after, the OS would map the next one
        // in other pages, which costs more).
        double pairs = 0;
        Answer found;
        if (row == contacts_row::contacts_into) {
            // A caller's answer kept from step to step holds the last
            // answer before every call, the first timed one too: otherwise
            // each run's first iteration would pay a fresh answer's pages.
            find_contacts_into(view, options, found);
        }
        for (auto _ : state) {
            if (!contacts) {
                const std::vector<obbsat::pair_index> only_pairs = obbsat::find_pairs(view, options);
                benchmark::DoNotOptimize(only_pairs.data());
                pairs += static_cast<double>(only_pairs.size());
            } else {
                if (row == contacts_row::contacts_into) {
                    find_contacts_into(view, options, found);
                } else {
                    found = Answer();
                    Answer fresh;
                    find_contacts_into(view, options, fresh);
                    found = std::move(fresh);
                }
                benchmark::DoNotOptimize(found.contacts.data());
                pairs += static_cast<double>(found.pairs.size());
            }
        }
        double points = 0;
        for (const auto& c : found.contacts) {
            points += static_cast<double>(c.point_count);
        }
        const auto n = static_cast<double>(boxes);
        state.counters["ns_per_box"] =
            benchmark::Counter(n * 1e-9, static_cast<benchmark::Counter::Flags>(
                                             benchmark::Counter::kIsIterationInvariantRate |
                                             benchmark::Counter::kInvert));
        state.counters["pairs_per_box"] = benchmark::Counter(pairs / n, benchmark::Counter::kAvgIterations);
        if (contacts) {
            state.counters["points_per_pair"] =
                benchmark::Counter(found.pairs.empty() ? 0.0 : points / static_cast<double>(found.pairs.size()));
        }
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}

/// Registers the three contacts rows of one precision, side by side on one scene: `suffix` "" or "64".
template <class Answer>
void register_contacts_rows(const char* suffix) {
    for (const std::size_t boxes : scene_box_counts_to_register()) {
        for (const contacts_row row : {contacts_row::pairs, contacts_row::contacts, contacts_row::contacts_into}) {
            const char* call = row == contacts_row::pairs      ? "find_pairs"
                               : row == contacts_row::contacts ? "find_contacts"
                                                               : "find_contacts_into";
            std::string name = std::string(call) + suffix;
            if (row == contacts_row::contacts_into && *suffix != 0) {
                name = std::string("find_contacts") + suffix + "_into";
            }
            name += "/exact/poses/" + scene_name_tail(boxes, obbsat::scene_sizes::uniform, 1);
            benchmark::RegisterBenchmark(name.c_str(),
                                         [boxes, row](benchmark::State& state) {
                                             run_contacts_row<Answer>(state, boxes, row);
                                         })
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
}

}  // namespace

void register_scene_benchmarks() {
    for (const scene_method m : scene_methods) {
        const std::string label = std::string(obbsat::method_name(m.test)) + "/" + obbsat::store_name(m.store);
        scene_rows rows;
        rows.cold_prefix = "scene/" + label;
        rows.frame_prefix = "frame/" + label;
        rows.thread_counts = {1, 2};
        rows.expected = {m.store, m.test, true};
        rows.prepare = m.store == obbsat::store_kind::poses ? prepare_for(m, pose_frames)
                                                            : prepare_for(m, corner_frames);
        register_scene_rows(rows);
    }
    for (const obbsat::method test : {obbsat::method::exact, obbsat::method::local}) {
        for (const std::size_t boxes : scene_box_counts_to_register()) {
            for (const obbsat::scene_sizes sizes : scene_size_spreads) {
                for (const unsigned threads : {1u, 2u}) {
                    const std::string name = std::string("drift/") + obbsat::method_name(test) + "/poses/" +
                                             scene_name_tail(boxes, sizes, threads);
                    benchmark::RegisterBenchmark(name.c_str(),
                                                 [test, boxes, sizes, threads](benchmark::State& state) {
                                                     run_drift_row(state, test, boxes, sizes, threads);
                                                 })
                        ->UseRealTime()
                        ->Iterations(2 * drift_half_period)
                        ->Unit(benchmark::kMillisecond);
                }
            }
        }
    }
    // Double poses and the same poses rounded to float32, side by side on one scene.
    for (const std::size_t boxes : scene_box_counts_to_register()) {
        for (const bool doubles : {true, false}) {
            const std::string name = "precision/exact/poses/" +
                                     scene_name_tail(boxes, obbsat::scene_sizes::uniform, 1) +
                                     (doubles ? "/float64" : "/float32");
            benchmark::RegisterBenchmark(name.c_str(),
                                         [boxes, doubles](benchmark::State& state) {
                                             run_precision_row(state, boxes, doubles);
                                         })
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
    // With and without pair filters, side by side on one scene.
    for (const std::size_t boxes : scene_box_counts_to_register()) {
        for (const bool filtered : {false, true}) {
            const std::string name = "filters/exact/poses/" + scene_name_tail(boxes, obbsat::scene_sizes::uniform, 1) +
                                     "/filtered:" + (filtered ? "1" : "0");
            benchmark::RegisterBenchmark(name.c_str(),
                                         [boxes, filtered](benchmark::State& state) {
                                             run_filter_row(state, boxes, filtered);
                                         })
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
    // The scene query with and without contacts, side by side on one scene; then on double poses.
    register_contacts_rows<obbsat::scene_contacts>("");
    register_contacts_rows<obbsat::scene_contacts64>("64");
}

}  // namespace obbsat_bench
