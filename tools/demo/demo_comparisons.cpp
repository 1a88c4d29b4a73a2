#include "demo/demo_comparisons.hpp"

#include "demo/demo_box2d.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/pose_corners.hpp>

#include <cstdio>
#include <cstring>
#include <optional>

namespace obbsat::cli {

void print_pose_ratios(const std::vector<measured_row>& rows, double pairs) {
    const char* best = backend_name(best_supported_backend());
    bool first = true;
    for (const measured_row& row : rows) {
        if (row.store != "poses" || row.runner != best || row.threads != 1) {
            continue;
        }
        const method counterpart = corner_counterpart(row.test);
        const measured_row* corners = find_row(rows, counterpart, "records", best, 1);
        if (corners == nullptr) {
            continue;
        }
        if (first) {
            std::printf("poses against corners (%s, 1 thread, the same pairs):\n", best);
            first = false;
        }
        std::printf("  %s on poses: %.1f Mpairs/s, %.2fx %s on records (%.1f Mpairs/s)\n",
                    method_name(row.test), pairs / row.seconds / 1e6, corners->seconds / row.seconds,
                    method_name(counterpart), pairs / corners->seconds / 1e6);
    }
}

void print_box2d_comparison(const scene& world, unsigned reps, const std::vector<std::uint8_t>& sat4,
                            const double sat4_seconds[2]) {
    if (sat4.empty()) {
        return;
    }
    const std::optional<peer_timing> box2d = time_box2d(world.rects, world.pairs, reps, sat4);
    if (!box2d) {
        std::printf("Box2D: not found when this program was built (Debian: libbox2d-dev); no peer comparison\n");
        return;
    }
    const double pairs = static_cast<double>(world.pairs.size());
    std::printf("Box2D 2.4 b2CollidePolygons, 1 thread: %.1f Mpairs/s (%.2f ns/pair), same verdict as sat4 "
                "on %.2f%% of pairs\n",
                pairs / box2d->median_seconds / 1e6, box2d->median_seconds / pairs * 1e9,
                100.0 * box2d->agreement);
    for (unsigned t = 0; t < 2; ++t) {
        if (sat4_seconds[t] > 0.0) {
            std::printf("  sat4 %s records, %u thread%s: %.1fx Box2D\n", backend_name(best_supported_backend()),
                        t + 1, t == 0 ? "" : "s", box2d->median_seconds / sat4_seconds[t]);
        }
    }
}

bool print_conversions(const demo_scene& demo, unsigned reps) {
    const pose_records& poses = demo.poses;
    const std::size_t count = poses.size();
    std::vector<rect> want(count);
    for (std::size_t i = 0; i < count; ++i) {
        want[i] = ref::corners_of(poses[i]);
    }
    std::vector<pose> angles(count);
    for (std::size_t i = 0; i < count; ++i) {
        angles[i] = pose_of(demo.records[i]);
    }
    const double boxes = static_cast<double>(count);
    const std::optional<double> from_angles = timed_median(
        reps, [] {}, [&angles] { rect_records built = rect_records::from_poses(angles); (void)built; },
        [] { return true; });
    std::printf("\nposes to corners, %zu boxes, median of %u runs after one warm-up:\n", count, reps);
    std::printf("  %-16s  %-24s  %-8s  %8s  %9s\n", "pose", "conversion", "backend", "ns/box", "speedup");
    std::printf("  %-16s  %-24s  %-8s  %8.2f  %8.2fx\n", "angle", "rect_records::from_poses", "-",
                *from_angles / boxes * 1e9, 1.0);
    // Filled with NaN bytes before each run, so that a corner a run did not
    // write cannot pass for the reference's.
    std::vector<rect> got(count);
    const auto poison = [&got] { std::memset(static_cast<void*>(got.data()), 0xff, got.size() * sizeof(rect)); };
    for (const backend b : runnable_backends()) {
        std::size_t differs = count;
        const std::optional<double> seconds = timed_median(
            reps, poison, [&] { convert_to_corners(poses, got.data(), b); },
            [&] {
                for (std::size_t i = 0; i < count; ++i) {
                    if (std::memcmp(&got[i], &want[i], sizeof(rect)) != 0) {
                        differs = i;
                        return false;
                    }
                }
                return true;
            });
        if (!seconds) {
            std::fprintf(stderr,
                         "obbsat: demo: convert_to_corners on %s gives other corners than ref::corners_of "
                         "for pose %zu\n",
                         backend_name(b), differs);
            return false;
        }
        std::printf("  %-16s  %-24s  %-8s  %8.2f  %8.2fx\n", "rotation vector", "convert_to_corners",
                    backend_name(b), *seconds / boxes * 1e9, *from_angles / *seconds);
    }
    std::printf("every convert_to_corners run gave the corners of ref::corners_of, byte for byte; speedup\n"
                "against corners built from angles (cos and sin in double per box, into a new checked store)\n\n");
    return true;
}

}  // namespace obbsat::cli
