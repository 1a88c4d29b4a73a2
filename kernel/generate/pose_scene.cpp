#include <obbsat/error.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace obbsat {

namespace {

constexpr double pi = 3.141592653589793;

/// 100^u for u in [0, 1] with basic arithmetic only (a library's pow may
/// round differently elsewhere): e^(u ln 100) as (e^(u ln 100 / 256))^256,
/// the inner power by its Taylor series to the 9th term.
double hundred_to_the(double u) {
    const double y = u * 4.605170185988092 / 256.0;  // ln 100 = 4.60517018598809136...
    double term = 1.0;
    double sum = 1.0;
    for (int k = 1; k <= 9; ++k) {
        term = term * y / k;
        sum = sum + term;
    }
    for (int k = 0; k < 8; ++k) {
        sum = sum * sum;
    }
    return sum;
}

struct sized {
    float hx, hy;
};

/// The half extents of every rectangle of `spec`, drawn first so that the
/// side can follow from their mean Minkowski sum.
std::vector<sized> sizes_of(const pose_scene_spec& spec, seeded_random& random) {
    std::vector<sized> out(spec.boxes);
    for (sized& s : out) {
        if (spec.sizes == scene_sizes::uniform) {
            s.hx = random.uniform(0.5f, 1.5f);
            s.hy = random.uniform(0.5f, 1.5f);
        } else {
            const double size = 0.2 * hundred_to_the(static_cast<double>(random.uniform(0.0f, 1.0f)));
            const double aspect = static_cast<double>(random.uniform(0.3f, 1.0f));
            const bool wide = (random.next() & 1u) != 0;
            s.hx = static_cast<float>(wide ? size : size * aspect);
            s.hy = static_cast<float>(wide ? size * aspect : size);
        }
    }
    return out;
}

double side_for(const pose_scene_spec& spec, const std::vector<sized>& sizes) {
    if (sizes.size() < 2 || !(spec.pairs_per_box > 0)) {
        return 1.0;
    }
    double area = 0;
    double perimeter = 0;
    for (const sized& s : sizes) {
        area += 4.0 * static_cast<double>(s.hx) * static_cast<double>(s.hy);
        perimeter += 4.0 * (static_cast<double>(s.hx) + static_cast<double>(s.hy));
    }
    const double n = static_cast<double>(sizes.size());
    area /= n;
    perimeter /= n;
    const double minkowski = 2.0 * area + perimeter * perimeter / (2.0 * pi);
    return std::sqrt((n - 1.0) * minkowski / (2.0 * spec.pairs_per_box));
}

}  // namespace

const char* scene_sizes_name(scene_sizes sizes) {
    return sizes == scene_sizes::mixed ? "mixed" : "uniform";
}

std::optional<scene_sizes> parse_scene_sizes(std::string_view name) {
    if (name == "uniform") {
        return scene_sizes::uniform;
    }
    if (name == "mixed") {
        return scene_sizes::mixed;
    }
    return std::nullopt;
}

double pose_scene_side(const pose_scene_spec& spec) {
    seeded_random random(spec.seed);
    return side_for(spec, sizes_of(spec, random));
}

std::vector<rect_pose> make_pose_scene(const pose_scene_spec& spec) {
    seeded_random random(spec.seed);
    const std::vector<sized> sizes = sizes_of(spec, random);
    const double side = side_for(spec, sizes);
    std::vector<rect_pose> out(spec.boxes);
    for (std::size_t i = 0; i < spec.boxes; ++i) {
        const double x = spec.origin_x + static_cast<double>(random.uniform(0.0f, 1.0f)) * side;
        const double y = spec.origin_y + static_cast<double>(random.uniform(0.0f, 1.0f)) * side;
        const double t = static_cast<double>(random.uniform(-1.0f, 1.0f));
        const double c = (1.0 - t * t) / (1.0 + t * t);
        const double s = (2.0 * t) / (1.0 + t * t);
        out[i] = rect_pose{{static_cast<float>(x), static_cast<float>(y)},
                           {sizes[i].hx, sizes[i].hy},
                           {static_cast<float>(c), static_cast<float>(s)}};
    }
    return out;
}

}  // namespace obbsat
