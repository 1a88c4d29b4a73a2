// Not a test: `double_gmp_soak PAIRS [SEED]` runs PAIRS pairs of every double
// family (tests/test_support/pose_cases64.hpp), as poses and as corners,
// through methods exact and conservative on doubles and compares them with the
// GMP model of rational_model.hpp (the exact corners, compared by segment
// intersection, ray crossing and clipped area): exact must agree on every pair,
// conservative must never miss a collision. Prints one line per family and
// exits 1 at the first disagreement, printing the pair in hex.
#include "rational_model.hpp"

#include "test_support/pose_cases64.hpp"

#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/exact64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using obbsat::point64;
using obbsat::rect64;
using obbsat::rect_pose64;
using obbsat::test::pose_pair64;
using obbsat::test::rational_point;

obbsat::test::rational_corners exact_corners(const rect_pose64& p) {
    const mpq_class cx(p.center.x), cy(p.center.y), hx(p.half_extents.x), hy(p.half_extents.y);
    const mpq_class c(p.rotation.x), s(p.rotation.y);
    const mpq_class ux = hx * c, uy = hx * s, vx = -hy * s, vy = hy * c;
    return {rational_point{cx - ux + vx, cy - uy + vy}, rational_point{cx + ux + vx, cy + uy + vy},
            rational_point{cx + ux - vx, cy + uy - vy}, rational_point{cx - ux - vx, cy - uy - vy}};
}

obbsat::test::rational_corners exact_corners(const rect64& r) {
    auto at = [](point64 p) { return rational_point{mpq_class(p.x), mpq_class(p.y)}; };
    return {at(r.ul), at(r.ur), at(r.lr), at(r.ll)};
}

template <class Item>
bool model_intersects(const Item& a, const Item& b) {
    return obbsat::test::rational_contact(obbsat::test::rational_region_of(exact_corners(a)),
                                          obbsat::test::rational_region_of(exact_corners(b))) != 'S';
}

void show(const char* what, const rect_pose64& a, const rect_pose64& b) {
    std::printf("%s\nA {c %a,%a h %a,%a r %a,%a}\nB {c %a,%a h %a,%a r %a,%a}\n", what, a.center.x, a.center.y,
                a.half_extents.x, a.half_extents.y, a.rotation.x, a.rotation.y, b.center.x, b.center.y,
                b.half_extents.x, b.half_extents.y, b.rotation.x, b.rotation.y);
}

void show(const char* what, const rect64& a, const rect64& b) {
    std::printf("%s\nA {%a,%a %a,%a %a,%a %a,%a}\nB {%a,%a %a,%a %a,%a %a,%a}\n", what, a.ul.x, a.ul.y, a.ur.x,
                a.ur.y, a.lr.x, a.lr.y, a.ll.x, a.ll.y, b.ul.x, b.ul.y, b.ur.x, b.ur.y, b.lr.x, b.lr.y, b.ll.x,
                b.ll.y);
}

template <class Item>
bool check(const Item& a, const Item& b, long& hits) {
    const bool truth = model_intersects(a, b);
    hits += truth ? 1 : 0;
    if (obbsat::ref::exact(a, b) != truth) {
        show(truth ? "exact says apart, the GMP model intersecting" : "exact says intersecting, the GMP model apart",
             a, b);
        return false;
    }
    if (truth && !obbsat::ref::conservative(a, b)) {
        show("conservative missed a collision", a, b);
        return false;
    }
    return true;
}

struct family {
    const char* name;
    pose_pair64 (*make)(obbsat::seeded_random&);
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: double_gmp_soak PAIRS [SEED]\n");
        return 2;
    }
    const long pairs = std::atol(argv[1]);
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    const family families[] = {
        {"UTM random", obbsat::test::utm_random_pair},
        {"UTM contacts 500000.125", obbsat::test::utm_contact_pair},
        {"UTM contacts 6e6", obbsat::test::utm_northing_contact_pair},
        {"contacts 1e9..1e15", obbsat::test::far_contact_pair},
        {"random 1e9..1e15", obbsat::test::far_random_pair},
        {"slivers", obbsat::test::sliver_pair},
        {"near parallel", obbsat::test::near_parallel_pair},
        {"scaled rotations", obbsat::test::scaled_rotation_pair},
    };
    long total = 0;
    for (const family& f : families) {
        obbsat::seeded_random random(seed);
        long pose_hits = 0;
        long corner_hits = 0;
        const auto start = std::chrono::steady_clock::now();
        for (long i = 0; i < pairs; ++i) {
            const pose_pair64 pair = f.make(random);
            if (!check(pair.a, pair.b, pose_hits) ||
                !check(obbsat::test::corners64(pair.a), obbsat::test::corners64(pair.b), corner_hits)) {
                std::printf("family %s, pair %ld, seed %llu\n", f.name, i, static_cast<unsigned long long>(seed));
                return 1;
            }
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%-26s %8ld pose pairs (%8ld hit) and as many corner pairs (%8ld hit): no disagreement, %.0f s\n",
                    f.name, pairs, pose_hits, corner_hits, seconds);
        total += 2 * pairs;
    }
    std::printf("%ld pairs in all, exact equal to the GMP model on each, conservative never missing\n", total);
    return 0;
}
