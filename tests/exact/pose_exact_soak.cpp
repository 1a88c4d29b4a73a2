// pose_exact_soak PAIRS [SEED]: runs methods exact and conservative on poses
// over PAIRS pairs on every backend this CPU runs, and counts disagreements
// with the exact pose oracle (exact must agree on every pair, conservative
// must never call a colliding pair apart). Half the pairs come from the pose
// families of suites/, a quarter are bit-fuzzed poses (every field
// a random finite float, half extents made non-negative), a quarter are hard
// pairs with their low mantissa bits fuzzed. Exit 1 on any disagreement.
#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/suites/pose_suite.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

float fuzzed_float(obbsat::seeded_random& random) {
    for (;;) {
        const auto bits = static_cast<std::uint32_t>(random.next());
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (std::isfinite(f)) {
            return f;
        }
    }
}

/// `value` with its low `bits` mantissa bits replaced at random (finite stays finite).
float low_bits_fuzzed(float value, obbsat::seeded_random& random, unsigned bits) {
    std::uint32_t word;
    std::memcpy(&word, &value, sizeof word);
    const std::uint32_t mask = (1u << bits) - 1u;
    word = (word & ~mask) | (static_cast<std::uint32_t>(random.next()) & mask);
    float out;
    std::memcpy(&out, &word, sizeof out);
    return std::isfinite(out) ? out : value;
}

obbsat::rect_pose valid(obbsat::rect_pose p) {
    p.half_extents = obbsat::point{std::fabs(p.half_extents.x), std::fabs(p.half_extents.y)};
    if (p.rotation.x == 0.0f && p.rotation.y == 0.0f) {
        p.rotation.x = 1.0f;
    }
    return p;
}

obbsat::rect_pose fuzzed_pose(obbsat::seeded_random& random) {
    return valid(obbsat::rect_pose{{fuzzed_float(random), fuzzed_float(random)},
                                   {fuzzed_float(random), fuzzed_float(random)},
                                   {fuzzed_float(random), fuzzed_float(random)}});
}

obbsat::rect_pose nudged(obbsat::rect_pose p, obbsat::seeded_random& random) {
    const unsigned bits = 1 + static_cast<unsigned>(random.below(8));
    float* fields[] = {&p.center.x, &p.center.y, &p.half_extents.x, &p.half_extents.y, &p.rotation.x, &p.rotation.y};
    for (float* f : fields) {
        *f = low_bits_fuzzed(*f, random, bits);
    }
    return valid(p);
}

obbsat::suites::pose_family any_family(obbsat::seeded_random& random) {
    const auto& all = obbsat::suites::all_pose_families();
    return all[random.below(all.size())];
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: pose_exact_soak PAIRS [SEED]\n");
        return 2;
    }
    const std::size_t total = std::strtoull(argv[1], nullptr, 10);
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    obbsat::seeded_random random(seed);
    constexpr std::size_t chunk = 1000000;
    std::size_t exact_wrong = 0, conservative_missed = 0, colliding = 0, slow = 0, done = 0;
    const auto start = std::chrono::steady_clock::now();
    while (done < total) {
        const std::size_t n = std::min(chunk, total - done);
        std::vector<obbsat::rect_pose> a(n), b(n);
        for (std::size_t i = 0; i < n; ++i) {
            switch (i % 4) {
                case 0:
                case 1:
                    obbsat::suites::random_pose_pair(random, any_family(random), a[i], b[i]);
                    break;
                case 2:
                    a[i] = fuzzed_pose(random);
                    b[i] = fuzzed_pose(random);
                    break;
                default:
                    obbsat::suites::random_pose_pair(random, any_family(random), a[i], b[i]);
                    a[i] = nudged(a[i], random);
                    b[i] = nudged(b[i], random);
                    break;
            }
        }
        std::vector<std::uint8_t> truth(n);
        for (std::size_t i = 0; i < n; ++i) {
            truth[i] = obbsat::oracle::intersects(a[i], b[i]) ? 1 : 0;
            colliding += truth[i];
        }
        const obbsat::pose_records ra(a), rb(b);
        for (const obbsat::backend use : obbsat::compiled_backends()) {
            if (!obbsat::cpu_supports(use)) {
                continue;
            }
            obbsat::collide_options options;
            options.use = use;
            options.test = obbsat::method::exact;
            std::size_t slow_here = 0;
            options.slow_path_pairs = &slow_here;
            const std::vector<std::uint8_t> exact = obbsat::collide_stream(ra, rb, options);
            options.slow_path_pairs = nullptr;
            options.test = obbsat::method::conservative;
            const std::vector<std::uint8_t> conservative = obbsat::collide_stream(ra, rb, options);
            for (std::size_t i = 0; i < n; ++i) {
                if (exact[i] != truth[i] && ++exact_wrong <= 5) {
                    std::printf("exact disagrees (%s), pair %zu\n", obbsat::backend_name(use), done + i);
                }
                if (truth[i] != 0 && conservative[i] == 0 && ++conservative_missed <= 5) {
                    std::printf("conservative missed (%s), pair %zu\n", obbsat::backend_name(use), done + i);
                }
            }
            if (use == obbsat::best_supported_backend()) {
                slow += slow_here;
            }
        }
        done += n;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%zu pose pairs per backend (%zu colliding), exact wrong %zu, conservative missed %zu, "
                "slow path on the best backend %zu pairs, %.1f s\n",
                done, colliding, exact_wrong, conservative_missed, slow, seconds);
    return exact_wrong == 0 && conservative_missed == 0 ? 0 : 1;
}
