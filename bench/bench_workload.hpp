// The workloads every benchmark of obbsat_bench runs on: one seeded scene per
// size and density in both stores (rect_soa as generated, rect_records for
// pair lists), its pair list as the generator emits it (sorted by first index)
// and the same list shuffled, the reference verdicts of each, and on demand
// the two streams A[i] = rects[pairs[i].a], B[i] = rects[pairs[i].b].
//
// A workload is built the first time a benchmark asks for it and kept for the
// rest of the run, so each scene is generated once however many benchmarks use
// it. The benchmarks run one at a time, so the cache needs no lock.
#pragma once

#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>
#include <obbsat/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace obbsat_bench {

/// The batch sizes of the benchmark grid: ~4K (cache), ~256K (L2/L3), ~4M (DRAM).
inline constexpr std::size_t grid_sizes[] = {4096, 262144, 4194304};

/// The size at which the sparse and dense scenes are benchmarked.
inline constexpr std::size_t density_variant_size = 262144;

/// "sparse", "typical" or "dense".
const char* density_name(obbsat::scene_density density);

/// Verdicts (one byte, 0 or 1, per pair) of the scalar reference of `test`,
/// evaluated pair by pair, directly from the reference functions.
std::vector<std::uint8_t> reference_verdicts(obbsat::method test, const obbsat::rect_soa& rects,
                                             const std::vector<obbsat::pair_index>& pairs);

class workload {
public:
    /// The scene of `pairs` candidate pairs over pairs / 2 rectangles at `density`, seed 1.
    workload(std::size_t pairs, obbsat::scene_density density);

    /// The scene's rectangles as eight coordinate arrays.
    const obbsat::rect_soa& rects() const { return scene_.rects; }
    /// The same rectangles as packed 32-byte records.
    const obbsat::rect_records& records() const { return records_; }
    /// The pairs in the generator's order: sorted by first index, then second.
    const std::vector<obbsat::pair_index>& sorted_pairs() const { return scene_.pairs; }
    /// The sorted pairs after a seeded Fisher-Yates shuffle.
    const std::vector<obbsat::pair_index>& shuffled_pairs() const { return shuffled_pairs_; }

    /// Reference verdicts of `test` for sorted_pairs() (and for the streams, which follow it).
    const std::vector<std::uint8_t>& sorted_reference(obbsat::method test);
    /// Reference verdicts of `test` for shuffled_pairs().
    const std::vector<std::uint8_t>& shuffled_reference(obbsat::method test);

    /// The scene's rectangles as poses (pose_records::from_corners); built on first use.
    const obbsat::pose_records& poses();
    /// The same poses as rows in the caller's memory (24 bytes each); built on first use.
    const std::vector<obbsat::rect_pose>& pose_rows();
    /// Reference verdicts of pose method `test` for sorted_pairs() over poses().
    const std::vector<std::uint8_t>& pose_sorted_reference(obbsat::method test);
    /// Reference verdicts of pose method `test` for shuffled_pairs() over poses().
    const std::vector<std::uint8_t>& pose_shuffled_reference(obbsat::method test);
    /// A[i] = poses()[sorted_pairs()[i].a]; built on first use.
    const obbsat::pose_records& pose_stream_a();
    /// B[i] = poses()[sorted_pairs()[i].b]; built on first use.
    const obbsat::pose_records& pose_stream_b();

    /// pose_stream_a() as a pose_soa; built on first use.
    const obbsat::pose_soa& pose_soa_stream_a();
    /// pose_stream_b() as a pose_soa; built on first use.
    const obbsat::pose_soa& pose_soa_stream_b();

    /// A[i] = rects[sorted_pairs()[i].a]; built on first use.
    const obbsat::rect_soa& stream_a();
    /// B[i] = rects[sorted_pairs()[i].b]; built on first use.
    const obbsat::rect_soa& stream_b();

private:
    void build_streams();
    void build_pose_streams();

    obbsat::scene scene_;
    obbsat::rect_records records_;
    std::vector<obbsat::pair_index> shuffled_pairs_;
    std::map<obbsat::method, std::vector<std::uint8_t>> sorted_reference_;
    std::map<obbsat::method, std::vector<std::uint8_t>> shuffled_reference_;
    std::unique_ptr<obbsat::rect_soa> stream_a_;
    std::unique_ptr<obbsat::rect_soa> stream_b_;
    std::unique_ptr<obbsat::pose_records> poses_;
    std::vector<obbsat::rect_pose> pose_rows_;
    std::map<obbsat::method, std::vector<std::uint8_t>> pose_sorted_reference_;
    std::map<obbsat::method, std::vector<std::uint8_t>> pose_shuffled_reference_;
    std::unique_ptr<obbsat::pose_records> pose_stream_a_;
    std::unique_ptr<obbsat::pose_records> pose_stream_b_;
    std::unique_ptr<obbsat::pose_soa> pose_soa_stream_a_;
    std::unique_ptr<obbsat::pose_soa> pose_soa_stream_b_;
};

/// The shared workload of that size and density, built on first request.
/// Throws std::runtime_error when the generator yields another number of pairs.
workload& workload_for(std::size_t pairs, obbsat::scene_density density);

}  // namespace obbsat_bench
