// The C++ side of python/bench/bench_collide.py: the same seeded scene the
// Python script builds (obbsat::make_scene), the same calls with the
// generator's sorted pair list, timed the same way (best of --repeats
// wall-clock runs): collide_pairs over rect_records (what obbsat.collide on a
// RectRecords store calls) and over a plain rect array (what obbsat.collide
// on a float32 array calls: the coordinates are checked on every call).
// Prints one line per call and thread count:
//   call=C threads=T backend=B seconds=S mpairs_per_s=R hits=H
#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::size_t pairs = 1000000;
    int repeats = 20;
    std::string method = "sat4";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--pairs") {
            pairs = std::strtoull(argv[i + 1], nullptr, 10);
        } else if (flag == "--repeats") {
            repeats = std::atoi(argv[i + 1]);
        } else if (flag == "--method") {
            method = argv[i + 1];
        } else {
            std::fprintf(stderr, "usage: %s [--pairs M] [--repeats K] [--method NAME]\n", argv[0]);
            return 2;
        }
    }
    const auto test = obbsat::parse_method(method);
    if (!test || repeats < 1) {
        std::fprintf(stderr, "bad --method or --repeats\n");
        return 2;
    }
    const obbsat::scene s =
        obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::typical, pairs / 2, pairs, 1));
    const obbsat::rect_records records(s.rects);
    std::vector<std::uint8_t> verdicts(s.pairs.size());
    for (const unsigned threads : {1u, 2u}) {
        for (const char* call : {"records", "array"}) {
            obbsat::collide_options options;
            options.test = *test;
            options.threads = threads;
            const bool array = std::strcmp(call, "array") == 0;
            double best = 1e30;
            obbsat::backend ran = obbsat::backend::automatic;
            for (int r = 0; r < repeats; ++r) {
                const auto start = std::chrono::steady_clock::now();
                ran = array ? obbsat::collide_pairs(records.data(), records.size(), s.pairs.data(), s.pairs.size(),
                                                    verdicts.data(), options)
                            : obbsat::collide_pairs(records, s.pairs.data(), s.pairs.size(), verdicts.data(), options);
                const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
                best = std::min(best, took.count());
            }
            const std::size_t hits = static_cast<std::size_t>(std::count(verdicts.begin(), verdicts.end(), 1));
            std::printf("call=%s threads=%u backend=%s seconds=%.6f mpairs_per_s=%.1f hits=%zu\n", call, threads,
                        obbsat::backend_name(ran), best, static_cast<double>(s.pairs.size()) / best / 1e6, hits);
        }
    }
    return 0;
}
