// double_backend_soak PAIRS [SEED [poses|corners|both]]: runs every method on
// double stores (exact, conservative and local on pose_records64; exact and
// conservative on rect_records64) through the public collide_pairs
// (obbsat/collide64.hpp) on every backend this CPU runs, on one thread and on
// two, over PAIRS pairs per store drawn from the families of
// tests/test_support/soak_pairs64.hpp (the hard double families, uniformly
// random pairs at many scales, ulp- and bit-fuzzed pairs), and checks pair by
// pair:
//   - exact equals the exact oracle (obbsat/oracle/pose_contact64.hpp,
//     contact64.hpp: wide integers, no tolerance), which runs once per pair;
//   - conservative is never false where the oracle says the pair collides;
//   - every method's verdict on every backend and thread count equals its
//     scalar reference (obbsat/ref/*64.hpp), and the number of pairs exact
//     sends to its slow path equals the pairs the reference's certified path
//     leaves undecided.
// Double corners have SIMD lanes only once the kernel has them: a backend that
// collide_pairs refuses for a store (invalid_input) is reported as such and the
// others still run. Prints one row per store, method and run (the reference or
// a backend and thread count): pairs checked, disagreements, slow-path pairs,
// seconds; then the pairs and collisions of each family. Stops after the batch
// with the first disagreement and exits 1, printing the first few pairs that
// disagree in hex floats.
#include "test_support/double_references.hpp"
#include "test_support/soak_pairs64.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/error.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/certified64.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect64;
using obbsat::rect_pose64;
using obbsat::test::pose_pair64;
using obbsat::test::rect_pair64;
using steady = std::chrono::steady_clock;

constexpr std::size_t batch_pairs = 1u << 16;
constexpr std::size_t failures_shown = 5;

double seconds_since(steady::time_point start) {
    return std::chrono::duration<double>(steady::now() - start).count();
}

/// True iff the certified fast path of exact leaves the pair to the oracle.
template <class Item>
bool undecided(const Item& a, const Item& b) {
    const obbsat::ref::certified_verdict fast = obbsat::ref::certify(a, b);
    return !fast.separated && !fast.intersecting;
}

std::string describe(const rect_pose64& p) {
    char text[256];
    std::snprintf(text, sizeof text, "{center %a, %a half %a, %a rotation %a, %a}", p.center.x, p.center.y,
                  p.half_extents.x, p.half_extents.y, p.rotation.x, p.rotation.y);
    return text;
}

std::string describe(const rect64& r) {
    char text[320];
    std::snprintf(text, sizeof text, "{UL %a, %a UR %a, %a LR %a, %a LL %a, %a}", r.ul.x, r.ul.y, r.ur.x, r.ur.y,
                  r.lr.x, r.lr.y, r.ll.x, r.ll.y);
    return text;
}

/// What one run (the scalar reference, or a backend on a thread count) did
/// with one method on one store.
struct run_row {
    std::string store;
    method test;
    std::string run;  ///< "reference" or "<backend> x<threads>"
    long pairs = 0;
    long oracle_disagreements = 0;     ///< exact != oracle, or conservative false on a colliding pair
    long reference_disagreements = 0;  ///< verdict != the scalar reference (backends only)
    long slow = 0;                     ///< pairs exact sent to its slow path
    double seconds = 0;
    bool refused = false;  ///< collide_pairs refused this backend for this store
};

struct family_row {
    std::string store;
    const char* name;
    long pairs = 0;
    long colliding = 0;
    long undecided = 0;  ///< left to the oracle by exact's certified path
};

struct soak_report {
    std::deque<run_row> runs;  // a deque: rows handed out stay where they are
    std::vector<family_row> families;
    std::vector<std::string> failures;  ///< the first few, described
    long failure_count = 0;
    double oracle_seconds = 0;

    run_row& row(const std::string& store, method m, const std::string& run) {
        for (run_row& r : runs) {
            if (r.store == store && r.test == m && r.run == run) return r;
        }
        runs.push_back(run_row{store, m, run});
        return runs.back();
    }

    template <class Item>
    void fail(const std::string& what, const Item& a, const Item& b) {
        if (++failure_count <= static_cast<long>(failures_shown)) {
            failures.push_back(what + "\n    A " + describe(a) + "\n    B " + describe(b));
        }
    }
};

/// The soak of one store kind: PAIRS pairs in batches, each pair drawn from a
/// family chosen at random, checked as the header says.
template <class Item, class Store, class Pair, std::size_t family_count>
bool soak_store(const char* store_name, const obbsat::test::soak_family64<Pair> (&families)[family_count],
                obbsat::store_kind kind, long pairs, std::uint64_t seed, soak_report& report) {
    obbsat::seeded_random random(seed);
    const std::vector<method> methods = obbsat::methods_on_doubles(kind);
    const std::vector<backend> backends = obbsat::runnable_backends();
    const std::size_t first_family = report.families.size();
    for (const auto& f : families) {
        report.families.push_back(family_row{store_name, f.name});
    }

    std::vector<Item> items(2 * batch_pairs);
    std::vector<pair_index> index(batch_pairs);
    std::vector<std::size_t> family_of(batch_pairs);
    auto family_row_of = [&](std::size_t i) -> family_row& { return report.families[first_family + family_of[i]]; };
    std::vector<std::uint8_t> truth(batch_pairs), expected(batch_pairs), verdicts(batch_pairs);
    for (std::size_t i = 0; i < batch_pairs; ++i) {
        index[i] = pair_index{static_cast<std::uint32_t>(2 * i), static_cast<std::uint32_t>(2 * i + 1)};
    }
    const long failures_before = report.failure_count;
    for (long done = 0; done < pairs && report.failure_count == failures_before;) {
        const std::size_t n = static_cast<std::size_t>(std::min<long>(static_cast<long>(batch_pairs), pairs - done));
        for (std::size_t i = 0; i < n; ++i) {
            family_of[i] = static_cast<std::size_t>(random.below(family_count));
            const Pair p = families[family_of[i]].make(random);
            items[2 * i] = p.a;
            items[2 * i + 1] = p.b;
        }
        const Store store(items.data(), 2 * n);

        const steady::time_point oracle_start = steady::now();
        for (std::size_t i = 0; i < n; ++i) {
            truth[i] = obbsat::oracle::intersects(items[2 * i], items[2 * i + 1]) ? 1 : 0;
        }
        report.oracle_seconds += seconds_since(oracle_start);
        for (std::size_t i = 0; i < n; ++i) {
            family_row& f = family_row_of(i);
            ++f.pairs;
            f.colliding += truth[i];
        }

        for (const method m : methods) {
            // The scalar reference, checked against the oracle.
            run_row& ref_row = report.row(store_name, m, "reference");
            long expected_slow = 0;
            const steady::time_point ref_start = steady::now();
            for (std::size_t i = 0; i < n; ++i) {
                expected[i] = obbsat::test::double_reference(m, items[2 * i], items[2 * i + 1]) ? 1 : 0;
            }
            ref_row.seconds += seconds_since(ref_start);
            for (std::size_t i = 0; i < n; ++i) {
                const bool wrong = m == method::exact          ? expected[i] != truth[i]
                                   : m == method::conservative ? truth[i] != 0 && expected[i] == 0
                                                               : false;
                if (m == method::exact && undecided(items[2 * i], items[2 * i + 1])) {
                    ++expected_slow;
                    ++family_row_of(i).undecided;
                }
                if (wrong) {
                    ++ref_row.oracle_disagreements;
                    report.fail(std::string(store_name) + " " + obbsat::method_name(m) + " reference says " +
                                    std::to_string(expected[i]) + ", oracle " + std::to_string(truth[i]) +
                                    " (family " + families[family_of[i]].name + ")",
                                items[2 * i], items[2 * i + 1]);
                }
            }
            ref_row.pairs += static_cast<long>(n);
            ref_row.slow += expected_slow;

            // Every backend on one thread and two, against the reference (and so the oracle).
            for (const backend b : backends) {
                for (const unsigned threads : {1u, 2u}) {
                    run_row& row =
                        report.row(store_name, m, std::string(obbsat::backend_name(b)) + " x" + std::to_string(threads));
                    obbsat::collide_options options;
                    options.test = m;
                    options.use = b;
                    options.threads = threads;
                    std::size_t slow = 0;
                    options.slow_path_pairs = &slow;
                    std::fill(verdicts.begin(), verdicts.end(), std::uint8_t{9});
                    const steady::time_point start = steady::now();
                    try {
                        obbsat::collide_pairs(store, index.data(), n, verdicts.data(), options);
                    } catch (const obbsat::invalid_input&) {
                        if (b == backend::scalar) throw;  // the scalar backend runs every store
                        row.refused = true;
                        continue;
                    }
                    row.seconds += seconds_since(start);
                    row.pairs += static_cast<long>(n);
                    row.slow += static_cast<long>(slow);
                    for (std::size_t i = 0; i < n; ++i) {
                        if (verdicts[i] != expected[i]) {
                            ++row.reference_disagreements;
                            report.fail(std::string(store_name) + " " + obbsat::method_name(m) + " on " + row.run +
                                            " says " + std::to_string(verdicts[i]) + ", reference " +
                                            std::to_string(expected[i]) + ", oracle " + std::to_string(truth[i]) +
                                            " (family " + families[family_of[i]].name + ")",
                                        items[2 * i], items[2 * i + 1]);
                        }
                        const bool wrong = m == method::exact          ? verdicts[i] != truth[i]
                                           : m == method::conservative ? truth[i] != 0 && verdicts[i] == 0
                                                                       : false;
                        row.oracle_disagreements += wrong ? 1 : 0;
                    }
                    if (m == method::exact && static_cast<long>(slow) != expected_slow) {
                        ++row.reference_disagreements;
                        ++report.failure_count;
                        report.failures.push_back(std::string(store_name) + " exact on " + row.run + ": " +
                                                  std::to_string(slow) + " slow-path pairs in a batch, the reference " +
                                                  std::to_string(expected_slow));
                    }
                }
            }
        }
        done += static_cast<long>(n);
        if (done % (long{1} << 24) < static_cast<long>(n)) {
            std::printf("%s: %ld pairs checked\n", store_name, done);
            std::fflush(stdout);
        }
    }
    return report.failure_count == failures_before;
}

void print(const soak_report& report) {
    std::printf("\n%-8s %-13s %-12s %12s %10s %10s %12s %9s\n", "store", "method", "run", "pairs", "vs oracle",
                "vs ref", "slow path", "seconds");
    for (const run_row& r : report.runs) {
        if (r.refused && r.pairs == 0) {
            std::printf("%-8s %-13s %-12s   refused for this store (scalar only)\n", r.store.c_str(),
                        obbsat::method_name(r.test), r.run.c_str());
            continue;
        }
        const bool checked_by_oracle = r.test == method::exact || r.test == method::conservative;
        std::printf("%-8s %-13s %-12s %12ld %10s %10s %12ld %9.1f\n", r.store.c_str(), obbsat::method_name(r.test),
                    r.run.c_str(), r.pairs, checked_by_oracle ? std::to_string(r.oracle_disagreements).c_str() : "-",
                    r.run == "reference" ? "-" : std::to_string(r.reference_disagreements).c_str(), r.slow,
                    r.seconds);
    }
    std::printf("\n%-8s %-26s %12s %12s %12s\n", "store", "family", "pairs", "colliding", "undecided");
    for (const family_row& f : report.families) {
        std::printf("%-8s %-26s %12ld %12ld %12ld\n", f.store.c_str(), f.name, f.pairs, f.colliding, f.undecided);
    }
    std::printf("\noracle: %.1f s\n", report.oracle_seconds);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::fprintf(stderr, "usage: double_backend_soak PAIRS [SEED [poses|corners|both]]\n");
        return 2;
    }
    const long pairs = std::atol(argv[1]);
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    const std::string stores = argc > 3 ? argv[3] : "both";
    if (pairs <= 0 || (stores != "poses" && stores != "corners" && stores != "both")) {
        std::fprintf(stderr, "usage: double_backend_soak PAIRS [SEED [poses|corners|both]]\n");
        return 2;
    }
    std::printf("double_backend_soak: %ld pairs per store, seed %llu, backends", pairs,
                static_cast<unsigned long long>(seed));
    for (const backend b : obbsat::runnable_backends()) {
        std::printf(" %s", obbsat::backend_name(b));
    }
    std::printf("\n");
    std::fflush(stdout);

    soak_report report;
    const steady::time_point start = steady::now();
    bool ok = true;
    if (stores != "corners") {
        ok = soak_store<rect_pose64, obbsat::pose_records64>("poses", obbsat::test::pose_soak_families,
                                                             obbsat::store_kind::poses, pairs, seed, report);
    }
    if (ok && stores != "poses") {
        ok = soak_store<rect64, obbsat::rect_records64>("corners", obbsat::test::corner_soak_families,
                                                        obbsat::store_kind::corners, pairs, seed, report);
    }
    print(report);
    std::printf("%.1f s in all\n", seconds_since(start));
    if (!ok) {
        std::printf("\n%ld disagreements; the first:\n", report.failure_count);
        for (const std::string& f : report.failures) {
            std::printf("  %s\n", f.c_str());
        }
        return 1;
    }
    std::printf("no disagreement: exact equals the oracle, conservative never misses, every backend and thread "
                "count equals the reference\n");
    return 0;
}
