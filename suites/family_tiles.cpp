// Family tiles: tile maps whose neighbours share edges. Every grid point is
// rounded to float once and shared by the tiles that meet there, so grid
// neighbours share their edges exactly (touching). In brick bonds each row is
// shifted by half a tile: a tile's corner then sits on the neighbouring row's
// edge, exactly when the map is axis-aligned, and within rounding of it when
// the map is rotated. Pairs are all tiles within two tiles of each other.
#include "draws.hpp"
#include "families.hpp"
#include "geometry.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace obbsat::suites::detail {

namespace {

struct map_style {
    const char* name;
    bool rotated;
    bool brick;
    bool far;
    bool dyadic;  // tile sizes in eighths, so axis-aligned corners need no rounding
};

constexpr map_style styles[] = {
    {"aa_grid", false, false, false, false},    {"aa_brick", false, true, false, false},
    {"aa_dyadic", false, false, false, true},   {"aa_far", false, true, true, false},
    {"rot_grid", true, false, false, false},    {"rot_brick", true, true, false, false},
    {"rot_far", true, false, true, false},      {"rot_far_brick", true, true, true, false},
};

void build_map(suite_builder& out, seeded_random& random, const map_style& style) {
    const auto columns = static_cast<std::int64_t>(integer(random, 4, 12));
    const auto rows = static_cast<std::int64_t>(integer(random, 4, 12));
    double width = uniform(random, 0.5, 4.0);
    double height = uniform(random, 0.5, 4.0);
    if (style.dyadic) {
        width = static_cast<double>(integer(random, 4, 32)) / 8.0;
        height = static_cast<double>(integer(random, 4, 32)) / 8.0;
    }
    const vec axis = style.rotated ? random_axis(random) : vec{1.0, 0.0};
    const vec step_x = width * axis;          // one tile along a row
    const vec step_y = height * perp(axis);   // one row up
    vec origin{uniform(random, -100.0, 100.0), uniform(random, -100.0, 100.0)};
    if (style.far) {
        const double sign_x = random_sign(random);
        const double far_x = binary_log_uniform(random, 13, 19);
        const double sign_y = random_sign(random);
        const double far_y = binary_log_uniform(random, 13, 19);
        origin = vec{sign_x * far_x, sign_y * far_y};
    }

    // Grid points in half-tile units along the row, rounded once and shared.
    std::map<std::pair<std::int64_t, std::int64_t>, point> grid;
    auto grid_point = [&](std::int64_t half_steps, std::int64_t row) {
        const auto key = std::make_pair(half_steps, row);
        const auto found = grid.find(key);
        if (found != grid.end()) {
            return found->second;
        }
        const vec v = origin + (0.5 * static_cast<double>(half_steps)) * step_x +
                      static_cast<double>(row) * step_y;
        const point p{static_cast<float>(v.x), static_cast<float>(v.y)};
        grid.emplace(key, p);
        return p;
    };

    // Tile (i, j): row j, half-step start 2i (+1 on odd rows of a brick bond).
    std::vector<std::uint32_t> tile(static_cast<std::size_t>(columns * rows));
    for (std::int64_t j = 0; j < rows; ++j) {
        for (std::int64_t i = 0; i < columns; ++i) {
            const std::int64_t start = 2 * i + (style.brick ? (j & 1) : 0);
            tile[static_cast<std::size_t>(j * columns + i)] = out.add_rect(
                rect{grid_point(start, j + 1), grid_point(start + 2, j + 1), grid_point(start + 2, j),
                     grid_point(start, j)});
        }
    }
    for (std::int64_t j = 0; j < rows; ++j) {
        for (std::int64_t i = 0; i < columns; ++i) {
            for (std::int64_t dj = 0; dj <= 2; ++dj) {
                for (std::int64_t di = -2; di <= 2; ++di) {
                    const std::int64_t ni = i + di, nj = j + dj;
                    if ((dj == 0 && di <= 0) || ni < 0 || ni >= columns || nj >= rows) {
                        continue;
                    }
                    out.add_pair(tile[static_cast<std::size_t>(j * columns + i)],
                                 tile[static_cast<std::size_t>(nj * columns + ni)], style.name);
                }
            }
        }
    }
}

}  // namespace

void build_tiles(suite_builder& out, seeded_random& random) {
    constexpr std::size_t style_count = sizeof(styles) / sizeof(styles[0]);
    for (std::size_t map = 0; !out.full(); ++map) {
        build_map(out, random, styles[map % style_count]);
    }
}

}  // namespace obbsat::suites::detail
