#include <obbsat/scene.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace obbsat {

std::uint64_t seeded_random::next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

float seeded_random::uniform(float lo, float hi) {
    const float unit = static_cast<float>(next() >> 40) * 0x1p-24f;
    return lo + (hi - lo) * unit;
}

std::uint64_t seeded_random::below(std::uint64_t bound) {
    // The modulo bias (below 2^-40 for bounds under 2^24) is irrelevant here.
    return next() % bound;
}

float candidate_radius_for(scene_density density) {
    // Measured on make_scene with 100k rectangles and 1M pairs, method sat4.
    switch (density) {
        case scene_density::sparse: return 30.0f;  // 4.9% collide
        case scene_density::dense: return 6.3f;    // 80%
        case scene_density::typical: break;
    }
    return 12.0f;  // 30.5%
}

scene_spec scene_spec_for(scene_density density, std::size_t rects, std::size_t pairs,
                          std::uint64_t seed) {
    scene_spec spec;
    spec.seed = seed;
    spec.rects = rects;
    spec.pairs = pairs;
    spec.candidate_radius = candidate_radius_for(density);
    return spec;
}

namespace {

// Corners of a rectangle centered at c with half extents h, rotated by the
// unit vector ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)), t in [-1, 1].
rect rotated_rect(double cx, double cy, double hx, double hy, double t) {
    const double c = (1.0 - t * t) / (1.0 + t * t);
    const double s = (2.0 * t) / (1.0 + t * t);
    auto corner = [&](double lx, double ly) {
        return point{static_cast<float>(cx + (c * lx - s * ly)),
                     static_cast<float>(cy + (s * lx + c * ly))};
    };
    return rect{corner(-hx, hy), corner(hx, hy), corner(hx, -hy), corner(-hx, -hy)};
}

}  // namespace

scene make_scene(const scene_spec& spec) {
    scene out;
    if (spec.rects == 0) {
        return out;
    }
    seeded_random random(spec.seed);
    const double n = static_cast<double>(spec.rects);
    const double r = spec.candidate_radius;
    // Side of the square domain such that about 1.1 * pairs centers lie
    // within r of each other: n^2 / 2 * pi r^2 / side^2 pairs.
    const double wanted = std::max<double>(1.0, 1.1 * static_cast<double>(spec.pairs));
    const double side = std::max(r, std::sqrt(n * n * 3.141592653589793 * r * r / (2.0 * wanted)));

    std::vector<point> centers(spec.rects);
    out.rects.reserve(spec.rects);
    for (std::size_t i = 0; i < spec.rects; ++i) {
        const double cx = static_cast<double>(random.uniform(0.0f, 1.0f)) * side;
        const double cy = static_cast<double>(random.uniform(0.0f, 1.0f)) * side;
        const double hx = static_cast<double>(random.uniform(0.5f, 5.0f));
        const double hy = static_cast<double>(random.uniform(0.5f, 5.0f));
        const double t = static_cast<double>(random.uniform(-1.0f, 1.0f));
        centers[i] = point{static_cast<float>(cx), static_cast<float>(cy)};
        out.rects.push_back(rotated_rect(cx, cy, hx, hy, t));
    }

    // Uniform grid of cell size r: candidates are in the same or adjacent cells.
    const auto cells_per_side = static_cast<std::int64_t>(std::max(1.0, std::floor(side / r)));
    auto cell_of = [&](float v) {
        const auto k = static_cast<std::int64_t>(static_cast<double>(v) / side *
                                                 static_cast<double>(cells_per_side));
        return std::min<std::int64_t>(std::max<std::int64_t>(k, 0), cells_per_side - 1);
    };
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid;
    for (std::size_t i = 0; i < spec.rects; ++i) {
        grid[cell_of(centers[i].x) * cells_per_side + cell_of(centers[i].y)].push_back(
            static_cast<std::uint32_t>(i));
    }
    const float r2 = spec.candidate_radius * spec.candidate_radius;
    std::vector<pair_index> candidates;
    for (std::size_t i = 0; i < spec.rects; ++i) {
        const std::int64_t gx = cell_of(centers[i].x);
        const std::int64_t gy = cell_of(centers[i].y);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                const std::int64_t x = gx + dx, y = gy + dy;
                if (x < 0 || y < 0 || x >= cells_per_side || y >= cells_per_side) {
                    continue;
                }
                const auto cell = grid.find(x * cells_per_side + y);
                if (cell == grid.end()) {
                    continue;
                }
                for (const std::uint32_t j : cell->second) {
                    if (j <= i) {
                        continue;
                    }
                    const float ddx = centers[i].x - centers[j].x;
                    const float ddy = centers[i].y - centers[j].y;
                    if (ddx * ddx + ddy * ddy < r2) {
                        candidates.push_back(pair_index{static_cast<std::uint32_t>(i), j});
                    }
                }
            }
        }
    }
    // Keep exactly spec.pairs of them (a seeded sample), in broadphase order.
    if (candidates.size() > spec.pairs) {
        for (std::size_t i = 0; i < spec.pairs; ++i) {
            const std::size_t k = i + static_cast<std::size_t>(random.below(candidates.size() - i));
            std::swap(candidates[i], candidates[k]);
        }
        candidates.resize(spec.pairs);
    }
    std::sort(candidates.begin(), candidates.end(), [](const pair_index& p, const pair_index& q) {
        return p.a != q.a ? p.a < q.a : p.b < q.b;
    });
    out.pairs = std::move(candidates);
    return out;
}

}  // namespace obbsat
