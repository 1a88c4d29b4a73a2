// Times the pose oracle on every make of pose_cases.hpp, single-threaded, in
// nanoseconds per pair (best of three runs): classify (the double filter,
// exact arithmetic only where it cannot decide) over all the pairs, streamed
// from memory, and over the first 16384, passed over 20 times from cache; and
// classify_exact (every slack exactly). The row "touching" holds only lattice
// pairs of two boxes with area that touch: each has a zero slack, which no
// double bound can decide, so it times the exact path as classify meets it.
//
// usage: pose_oracle_throughput [pairs per make = 200000] [seed = 1]
#include "pose_cases.hpp"

#include <obbsat/oracle/pose_contact.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using obbsat::oracle::contact;
using obbsat::test::pose_pair;

unsigned long parse_count(const char* text, const char* what) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text, &end, 10);
    if (*text == '\0' || *end != '\0') {
        std::fprintf(stderr, "pose_oracle_throughput: %s must be a non-negative integer, got '%s'\n", what,
                     text);
        std::exit(2);
    }
    return value;
}

using pose_classifier = contact (*)(const obbsat::rect_pose&, const obbsat::rect_pose&);

// Nanoseconds per pair of `classify` over the first `used` pairs, passed over
// `passes` times, the best of three runs (the machine may be shared); counts
// the classes of the last pass into `count`.
double nanoseconds_per_pair(const std::vector<pose_pair>& pairs, std::size_t used, int passes,
                            pose_classifier classify, std::size_t count[3]) {
    double best = 0.0;
    for (int run = 0; run < 3; ++run) {
        const auto start = std::chrono::steady_clock::now();
        for (int pass = 0; pass < passes; ++pass) {
            count[0] = count[1] = count[2] = 0;
            for (std::size_t i = 0; i < used; ++i) {
                ++count[static_cast<int>(classify(pairs[i].a, pairs[i].b))];
            }
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = run == 0 ? seconds : std::min(best, seconds);
    }
    return used == 0 ? 0.0 : 1e9 * best / (static_cast<double>(used) * passes);
}

// Pairs that fit in a core's L2 cache (48 bytes each), for the in-cache column.
constexpr std::size_t cached_pairs = 16384;

void print_row(const char* name, const std::vector<pose_pair>& pairs) {
    std::size_t count[3], exact_count[3], cached_count[3];
    const double filtered = nanoseconds_per_pair(pairs, pairs.size(), 1, obbsat::oracle::classify, count);
    const double exact = nanoseconds_per_pair(pairs, pairs.size(), 1, obbsat::oracle::classify_exact, exact_count);
    const std::size_t used = std::min(cached_pairs, pairs.size());
    const double cached = nanoseconds_per_pair(pairs, used, 20, obbsat::oracle::classify, cached_count);
    const bool same = count[0] == exact_count[0] && count[1] == exact_count[1] && count[2] == exact_count[2];
    std::printf("%-24s %8zu %8zu %8zu %8zu %12.1f %12.1f %12.1f%s\n", name, pairs.size(), count[0], count[1],
                count[2], filtered, cached, exact, same ? "" : "  CLASS COUNTS DIFFER");
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t pairs_per_make = argc > 1 ? parse_count(argv[1], "pairs") : 200000;
    const std::uint64_t seed = argc > 2 ? parse_count(argv[2], "seed") : 1;
    std::printf("%-24s %8s %8s %8s %8s %12s %12s %12s\n", "make", "pairs", "S", "T", "O", "classify ns",
                "in cache ns", "exact ns");
    for (const obbsat::test::pose_make& make : obbsat::test::pose_makes) {
        obbsat::seeded_random random(seed);
        std::vector<pose_pair> pairs(pairs_per_make);
        for (pose_pair& p : pairs) {
            p = make.make(random);
        }
        print_row(make.name, pairs);
    }
    obbsat::seeded_random random(seed);
    std::vector<pose_pair> touching;
    while (touching.size() < pairs_per_make) {
        const pose_pair p = obbsat::test::lattice_pair(random);
        const bool area = p.a.half_extents.x > 0 && p.a.half_extents.y > 0 && p.b.half_extents.x > 0 &&
                          p.b.half_extents.y > 0;
        if (area && obbsat::oracle::classify(p.a, p.b) == contact::touching) {
            touching.push_back(p);
        }
    }
    print_row("touching", touching);
    return 0;
}
