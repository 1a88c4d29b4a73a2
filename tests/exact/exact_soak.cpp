// exact_soak PAIRS [SEED]: runs methods exact and conservative on PAIRS pairs
// of random rectangles and of bit-fuzzed quads (random finite float bit
// patterns, including subnormals and extremes) on every backend this CPU
// runs, and counts disagreements with the exact oracle. Exit 1 on any.
#include <obbsat/collide.hpp>
#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/scene.hpp>

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

// Quads built to sit near each other at random scales and offsets, half of
// them exact rectangles' float corners, half arbitrary bit patterns nearby.
std::vector<obbsat::rect> make_rects(std::size_t count, obbsat::seeded_random& random) {
    std::vector<obbsat::rect> out(count);
    for (auto& r : out) {
        const int kind = static_cast<int>(random.below(4));
        if (kind == 0) {
            obbsat::point* c = &r.ul;
            for (int k = 0; k < 4; ++k) {
                c[k] = obbsat::point{fuzzed_float(random), fuzzed_float(random)};
            }
            continue;
        }
        const float scale = std::ldexp(1.0f, static_cast<int>(random.below(120)) - 60);
        const float ox = random.uniform(-1, 1) * scale * (kind == 1 ? 1.0f : 4096.0f);
        const float oy = random.uniform(-1, 1) * scale * (kind == 1 ? 1.0f : 4096.0f);
        const double t = random.uniform(-1, 1);
        const double c = (1 - t * t) / (1 + t * t), s = 2 * t / (1 + t * t);
        const double hx = random.uniform(0.05f, 1) * scale, hy = random.uniform(0.05f, 1) * scale;
        auto corner = [&](double lx, double ly) {
            return obbsat::point{static_cast<float>(ox + c * lx - s * ly), static_cast<float>(oy + s * lx + c * ly)};
        };
        r = obbsat::rect{corner(-hx, hy), corner(hx, hy), corner(hx, -hy), corner(-hx, -hy)};
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: exact_soak PAIRS [SEED]\n");
        return 2;
    }
    const std::size_t total = std::strtoull(argv[1], nullptr, 10);
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    obbsat::seeded_random random(seed);
    const std::size_t chunk = 1u << 20;
    std::size_t done = 0, wrong_exact = 0, missed = 0, slow_total = 0;
    const auto start = std::chrono::steady_clock::now();
    while (done < total) {
        const std::size_t n = std::min(chunk, total - done);
        const std::vector<obbsat::rect> rects = make_rects(n / 2 + 2, random);
        std::vector<obbsat::pair_index> pairs(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto a = static_cast<std::uint32_t>(random.below(rects.size()));
            const auto b = static_cast<std::uint32_t>(random.below(4) == 0 ? random.below(rects.size())
                                                                               : (a + 1) % rects.size());
            pairs[i] = {a, b};
        }
        const auto contacts = obbsat::oracle::classify_pairs(rects, pairs, 0);
        const obbsat::rect_records records(rects);
        for (const obbsat::backend b : obbsat::compiled_backends()) {
            if (!obbsat::cpu_supports(b)) {
                continue;
            }
            obbsat::collide_options options;
            options.use = b;
            options.threads = 0;
            std::size_t slow = 0;
            options.slow_path_pairs = &slow;
            options.test = obbsat::method::exact;
            const auto exact = obbsat::collide_pairs(records, pairs, options);
            if (b == obbsat::best_supported_backend()) {
                slow_total += slow;
            }
            options.test = obbsat::method::conservative;
            options.slow_path_pairs = nullptr;
            const auto loose = obbsat::collide_pairs(records, pairs, options);
            for (std::size_t i = 0; i < n; ++i) {
                const bool truth = contacts[i] != obbsat::oracle::contact::separated;
                wrong_exact += ((exact[i] != 0) != truth) ? 1u : 0u;
                missed += (truth && loose[i] == 0) ? 1u : 0u;
            }
        }
        done += n;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%zu pairs per backend, seed %llu: exact disagreements %zu, conservative misses %zu, "
                "slow path on the best backend %.2f%%, %.1f s\n",
                done, static_cast<unsigned long long>(seed), wrong_exact, missed,
                100.0 * static_cast<double>(slow_total) / static_cast<double>(done), seconds);
    return (wrong_exact == 0 && missed == 0) ? 0 : 1;
}
