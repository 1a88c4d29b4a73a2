#include "demo/demo_scene.hpp"

#include "demo/demo_scene_box2d.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <string>
#include <vector>

namespace obbsat::cli {

namespace {

using clock = std::chrono::steady_clock;

double seconds_since(clock::time_point start) { return std::chrono::duration<double>(clock::now() - start).count(); }

std::uint64_t digest_of(const std::vector<pair_index>& pairs) {
    return verdict_digest(reinterpret_cast<const std::uint8_t*>(pairs.data()), pairs.size() * sizeof(pair_index));
}

bool same(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

/// The scene moved a little: every center by up to 0.05 along each axis.
std::vector<rect_pose> moved(std::vector<rect_pose> poses, std::uint64_t seed) {
    seeded_random random(seed ^ 0x5eedf00dull);
    for (rect_pose& p : poses) {
        p.center.x += random.uniform(-0.05f, 0.05f);
        p.center.y += random.uniform(-0.05f, 0.05f);
    }
    return poses;
}

struct timed_query {
    double seconds;          // the median
    find_pairs_stats stats;  // of the median run
};

/// The median run of `reps` after one warm-up, by total time.
template <class Run>
timed_query median_of(unsigned reps, const Run& run) {
    run();
    std::vector<timed_query> runs;
    for (unsigned r = 0; r < reps; ++r) {
        runs.push_back(run());
    }
    std::sort(runs.begin(), runs.end(), [](const timed_query& x, const timed_query& y) { return x.seconds < y.seconds; });
    return runs[runs.size() / 2];
}

void print_row(const char* sizes, unsigned threads, const char* query, const timed_query& t, std::size_t boxes,
               std::size_t pairs, std::uint64_t digest) {
    const double n = static_cast<double>(boxes);
    std::printf("  %-7s  %7u  %-5s  %7.1f  %7.1f  %7.1f  %7.1f  %8.1f  %7.1f  %9.2f  %016" PRIx64 "\n", sizes, threads,
                query, t.stats.bounds_seconds * 1e3, t.stats.order_seconds * 1e3, t.stats.sweep_seconds * 1e3,
                t.stats.output_seconds * 1e3, t.seconds * 1e3, t.seconds / n * 1e9,
                static_cast<double>(pairs) / n, digest);
    std::fflush(stdout);
}

}  // namespace

bool print_scene_queries(const scene_demo_settings& settings) {
    const backend best = best_supported_backend();
    std::printf("\nscene query: %zu poses to every colliding pair, sorted (find_pairs, method exact, %s); each row\n"
                "the median of %u runs after one warm-up, stages in ms as the query reports them (bounds: bounds\n"
                "and sort keys; order: sorting and copying the records; sweep: broadphase and exact narrowphase;\n"
                "output: caller's indices, sorted). cold: a new query each run; frame: one pair_finder, every\n"
                "box moved up to 0.05 between runs, answered from the pairs of widened bounds it kept (bounds:\n"
                "the records refreshed and checked; sweep: the kept pairs filtered and tested; output: the\n"
                "answer read in the kept order)\n",
                settings.boxes, backend_name(best), settings.reps);
    if (settings.boxes < 2) {
        std::printf("a scene of one box has no pairs: every row finds none, timed all the same\n");
    }
    std::printf("  %-7s  %7s  %-5s  %7s  %7s  %7s  %7s  %8s  %7s  %9s  %-16s\n", "sizes", "threads", "query", "bounds",
                "order", "sweep", "output", "total", "ns/box", "pairs/box", "digest");
    double uniform_cold_one = 0;
    for (const scene_sizes sizes : {scene_sizes::uniform, scene_sizes::mixed}) {
        pose_scene_spec spec;
        spec.seed = settings.seed;
        spec.boxes = settings.boxes;
        spec.sizes = sizes;
        const std::vector<rect_pose> poses = make_pose_scene(spec);
        const pose_records start(poses);
        const pose_records shifted(moved(poses, settings.seed));
        std::vector<pair_index> expected[2];  // of start and shifted, at 1 thread
        for (const unsigned threads : {1u, 2u}) {
            collide_options options;
            options.test = method::exact;
            options.threads = threads;
            std::vector<pair_index> cold_pairs;
            const timed_query cold = median_of(settings.reps, [&] {
                pair_finder finder(options);
                const auto t0 = clock::now();
                cold_pairs = finder.find(start);
                return timed_query{seconds_since(t0), finder.stats()};
            });
            pair_finder finder(options);
            finder.find(start);
            std::vector<pair_index> frame_pairs[2];
            bool frame_is_shifted = false;
            const timed_query frame = median_of(settings.reps, [&] {
                frame_is_shifted = !frame_is_shifted;
                const auto t0 = clock::now();
                const std::vector<pair_index>& found = finder.find(frame_is_shifted ? shifted : start);
                const double seconds = seconds_since(t0);
                frame_pairs[frame_is_shifted ? 1 : 0] = found;
                return timed_query{seconds, finder.stats()};
            });
            if (threads == 1) {
                expected[0] = cold_pairs;
                expected[1] = find_pairs(shifted, options);
            }
            if (!same(cold_pairs, expected[0]) || !same(frame_pairs[0], expected[0]) ||
                !same(frame_pairs[1], expected[1])) {
                std::fprintf(stderr, "obbsat: demo: the scene query on %s sizes at %u threads gave other pairs than "
                                     "the same query at 1 thread\n",
                             scene_sizes_name(sizes), threads);
                return false;
            }
            if (sizes == scene_sizes::uniform && threads == 1) {
                uniform_cold_one = cold.seconds / static_cast<double>(settings.boxes);
            }
            print_row(scene_sizes_name(sizes), threads, "cold", cold, settings.boxes, cold_pairs.size(),
                      digest_of(cold_pairs));
            print_row(scene_sizes_name(sizes), threads, "frame", frame, settings.boxes, expected[1].size(),
                      digest_of(expected[1]));
        }
    }
    std::printf("every row gave the same pairs as the cold query at 1 thread on the same poses (the frame rows'\n"
                "digest is of the moved scene); tests/scene checks the query against brute force and the exact oracle\n");

    // Box2D on a smaller scene of the same kind: its tree, filled in the
    // scene's random order, slows down as it grows (seconds per box at 1M).
    pose_scene_spec peer_spec;
    peer_spec.seed = settings.seed;
    peer_spec.boxes = std::min(settings.peer_boxes, settings.boxes);
    const std::vector<rect_pose> peer_poses = make_pose_scene(peer_spec);
    const pose_records peer_store(peer_poses);
    collide_options options;
    options.test = method::exact;
    const std::vector<pair_index> exact = find_pairs(peer_store, options);
    const std::optional<scene_peer_timing> box2d = time_box2d_scene(peer_poses, exact);
    if (!box2d) {
        std::printf("Box2D: not found when this program was built (Debian: libbox2d-dev); no scene peer\n");
        return true;
    }
    const timed_query ours = median_of(settings.reps, [&] {
        pair_finder finder(options);
        const auto t0 = clock::now();
        finder.find(peer_store);
        return timed_query{seconds_since(t0), finder.stats()};
    });
    const double n = static_cast<double>(peer_spec.boxes);
    std::printf("Box2D 2.4 b2BroadPhase + b2CollidePolygons, %zu uniform boxes, 1 thread, one cold query: %.0f ns/box\n"
                "  (%zu pairs, %zu of them not touching: Box2D's 0.01 skin; %zu exact pairs missed)\n"
                "  obbsat find_pairs exact on the same scene, 1 thread, cold: %.1f ns/box, %.1fx Box2D",
                peer_spec.boxes, box2d->seconds / n * 1e9, box2d->pairs, box2d->extra, box2d->missed,
                ours.seconds / n * 1e9, box2d->seconds / ours.seconds);
    if (uniform_cold_one > 0) {
        std::printf(" (%.1f ns/box at %zu boxes)", uniform_cold_one * 1e9, settings.boxes);
    }
    std::printf("\n");
    return true;
}

}  // namespace obbsat::cli
