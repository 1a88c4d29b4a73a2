// How a peer library is benchmarked: single-threaded, over the indexed_sorted
// pair list of the typical scene of each grid size, writing one verdict byte
// per pair like collide_pairs does. Before timing, the peer's verdicts are
// compared once with the scalar reference of sat4; the counters say how often
// they agree and, when not, which side reported the collision.
#pragma once

#include "bench_registry.hpp"
#include "bench_workload.hpp"

#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace obbsat_bench {

/// Shares of the pairs (0..1): verdict equal to sat4's reference, peer alone
/// says collide, reference alone says collide.
struct peer_agreement {
    double agreement = 0.0;
    double peer_only = 0.0;
    double reference_only = 0.0;
};

template <class Decide>
void decide_all_pairs(const std::vector<obbsat::pair_index>& pairs, const Decide& decide,
                      std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        verdicts[i] = decide(pairs[i].a, pairs[i].b) ? 1 : 0;
    }
}

inline peer_agreement compare_with_reference(const std::vector<std::uint8_t>& peer,
                                             const std::vector<std::uint8_t>& reference) {
    std::size_t same = 0, peer_only = 0, reference_only = 0;
    for (std::size_t i = 0; i < peer.size(); ++i) {
        same += peer[i] == reference[i] ? 1u : 0u;
        peer_only += (peer[i] != 0 && reference[i] == 0) ? 1u : 0u;
        reference_only += (peer[i] == 0 && reference[i] != 0) ? 1u : 0u;
    }
    const double n = peer.empty() ? 1.0 : static_cast<double>(peer.size());
    return {static_cast<double>(same) / n, static_cast<double>(peer_only) / n,
            static_cast<double>(reference_only) / n};
}

/// Registers peer/<peer>/pairs:<N> for every grid size. `prepare(workload&)`
/// builds (or fetches) the peer's own shapes for that scene and returns a
/// callable decide(index_a, index_b) -> bool.
template <class Prepare>
void register_peer(const std::string& peer, Prepare prepare) {
    for (const std::size_t pairs : grid_sizes) {
        auto measured = std::make_shared<std::unique_ptr<peer_agreement>>();
        const std::string name = "peer/" + peer + "/pairs:" + std::to_string(pairs);
        benchmark::RegisterBenchmark(
            name.c_str(),
            [pairs, prepare, measured](benchmark::State& state) {
                try {
                    workload& w = workload_for(pairs, obbsat::scene_density::typical);
                    const auto decide = prepare(w);
                    std::vector<std::uint8_t> verdicts(pairs);
                    if (!*measured) {
                        decide_all_pairs(w.sorted_pairs(), decide, verdicts.data());
                        *measured = std::make_unique<peer_agreement>(compare_with_reference(
                            verdicts, w.sorted_reference(obbsat::method::sat4)));
                    }
                    for (auto _ : state) {
                        decide_all_pairs(w.sorted_pairs(), decide, verdicts.data());
                        benchmark::DoNotOptimize(verdicts.data());
                        benchmark::ClobberMemory();
                    }
                } catch (const std::exception& e) {
                    state.SkipWithError(e.what());
                    return;
                }
                set_pair_rate_counters(state, pairs);
                state.counters["agreement"] = (*measured)->agreement;
                state.counters["peer_only"] = (*measured)->peer_only;
                state.counters["reference_only"] = (*measured)->reference_only;
            })
            ->UseRealTime()
            ->Unit(benchmark::kMicrosecond);
    }
}

}  // namespace obbsat_bench
