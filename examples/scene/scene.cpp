// A game-like loop: a few thousand boxes move, spin and bounce off the walls of
// a square world. Each box is a pose (center, half extents, rotation vector),
// as a physics engine keeps it; no corners are ever computed. Each frame a
// uniform-grid broadphase lists the pairs whose bounding boxes overlap, and
// obbsat decides on the poses which of those really collide (method local).
//
//   scene [SECONDS [BOXES]]     simulated seconds (default 10), boxes (default 4000)
//
// Motion is seeded, so every run is the same. The digest printed at the end is
// a fingerprint of every verdict of every frame; it does not depend on the
// backend (compare with OBBSAT_BACKEND=scalar).
#include <obbsat/obbsat.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

constexpr float world_size = 400.0f;
constexpr std::size_t frames_per_second = 60;
constexpr float frame_seconds = 1.0f / static_cast<float>(frames_per_second);
constexpr float two_pi = 6.2831853f;

struct body {
    obbsat::rect_pose pose;
    obbsat::point velocity;  // world units per second
    obbsat::point turn;      // the rotation of one frame, as (cos, sin) of its angle
    float reach;             // distance from the center to a corner
};

struct bounds {
    float min_x, min_y, max_x, max_y;
};

std::vector<body> spawn_bodies(std::size_t count, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<body> bodies(count);
    for (body& b : bodies) {
        const float hx = random.uniform(0.5f, 2.5f);
        const float hy = random.uniform(0.5f, 2.5f);
        b.reach = std::sqrt(hx * hx + hy * hy);
        b.pose.half_extents = {hx, hy};
        b.pose.center = {random.uniform(b.reach, world_size - b.reach),
                         random.uniform(b.reach, world_size - b.reach)};
        const float angle = random.uniform(0.0f, two_pi);
        b.pose.rotation = {std::cos(angle), std::sin(angle)};
        b.velocity = {random.uniform(-20.0f, 20.0f), random.uniform(-20.0f, 20.0f)};
        const float spin = random.uniform(-3.0f, 3.0f) * frame_seconds;  // radians per frame
        b.turn = {std::cos(spin), std::sin(spin)};
    }
    return bodies;
}

// A wall reverses the velocity component that points into it; a box never
// tunnels out because it moves far less than its own size per frame.
void bounce(float& position, float& velocity, float reach) {
    if ((position - reach < 0.0f && velocity < 0.0f) ||
        (position + reach > world_size && velocity > 0.0f)) {
        velocity = -velocity;
    }
}

// One frame of motion. The rotation vector turns by the frame's rotation and
// is renormalised, so that its length (which scales the box) stays 1 within
// rounding however many frames pass.
void advance(std::vector<body>& bodies, float seconds) {
    for (body& b : bodies) {
        b.pose.center.x += b.velocity.x * seconds;
        b.pose.center.y += b.velocity.y * seconds;
        const obbsat::point r = b.pose.rotation;
        const float c = r.x * b.turn.x - r.y * b.turn.y;
        const float s = r.y * b.turn.x + r.x * b.turn.y;
        const float length = std::sqrt(c * c + s * s);
        b.pose.rotation = {c / length, s / length};
        bounce(b.pose.center.x, b.velocity.x, b.reach);
        bounce(b.pose.center.y, b.velocity.y, b.reach);
    }
}

// The axis-aligned bounds of a pose, from its center and the reach of its
// half extents along x and y, widened by a relative 2^-20 so that rounding
// never makes them smaller than the exact box.
bounds bounds_of(const obbsat::rect_pose& p) {
    const float c = std::fabs(p.rotation.x);
    const float s = std::fabs(p.rotation.y);
    const float ex = p.half_extents.x * c + p.half_extents.y * s;
    const float ey = p.half_extents.x * s + p.half_extents.y * c;
    const float wx = ex + 0x1p-20f * (ex + std::fabs(p.center.x));
    const float wy = ey + 0x1p-20f * (ey + std::fabs(p.center.y));
    return {p.center.x - wx, p.center.y - wy, p.center.x + wx, p.center.y + wy};
}

// Closed intervals: boxes whose bounds merely touch are candidates, because
// touching rectangles collide.
bool overlap(const bounds& a, const bounds& b) {
    return a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
}

// The broadphase: each box is filed under the grid cell of its center. A cell
// is as wide as the largest box could reach across two centers, so boxes whose
// bounds overlap sit in the same or in neighbouring cells.
class uniform_grid {
public:
    // The margin covers rounding in the bounds, so that two boxes whose bounds
    // overlap are never two cells apart.
    uniform_grid(float world, float largest_reach)
        : cell_size_(2.0f * largest_reach + 0.25f),
          columns_(std::max(1, static_cast<int>(std::ceil(world / cell_size_)))) {}

    void find_candidates(const obbsat::pose_records& boxes, std::vector<obbsat::pair_index>& pairs) {
        file_boxes(boxes);
        pairs.clear();
        // Each unordered pair of cells is visited once: the cell itself, then
        // the neighbours to the right and in the row above.
        constexpr int forward[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
        for (int row = 0; row < columns_; ++row) {
            for (int column = 0; column < columns_; ++column) {
                const std::size_t cell = cell_index(column, row);
                for (std::size_t p = cell_start_[cell]; p < cell_start_[cell + 1]; ++p) {
                    const std::uint32_t i = filed_[p];
                    for (std::size_t q = p + 1; q < cell_start_[cell + 1]; ++q) {
                        add_if_overlapping(i, filed_[q], pairs);
                    }
                    for (const auto& step : forward) {
                        const int c = column + step[0];
                        const int r = row + step[1];
                        if (c < 0 || c >= columns_ || r >= columns_) {
                            continue;
                        }
                        const std::size_t other = cell_index(c, r);
                        for (std::size_t q = cell_start_[other]; q < cell_start_[other + 1]; ++q) {
                            add_if_overlapping(i, filed_[q], pairs);
                        }
                    }
                }
            }
        }
    }

private:
    std::size_t cell_index(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
               static_cast<std::size_t>(column);
    }

    int coordinate_cell(float v) const {
        // Clamping keeps neighbours neighbours when a box pokes past a wall.
        const int cell = static_cast<int>(std::floor(v / cell_size_));
        return std::clamp(cell, 0, columns_ - 1);
    }

    // A counting sort of the boxes by cell: no allocation after the first frame.
    void file_boxes(const obbsat::pose_records& boxes) {
        const std::size_t cells = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(columns_);
        bounds_.resize(boxes.size());
        cell_of_.resize(boxes.size());
        filed_.resize(boxes.size());
        cell_start_.assign(cells + 1, 0);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            bounds_[i] = bounds_of(boxes[i]);
            const float cx = 0.5f * (bounds_[i].min_x + bounds_[i].max_x);
            const float cy = 0.5f * (bounds_[i].min_y + bounds_[i].max_y);
            cell_of_[i] = cell_index(coordinate_cell(cx), coordinate_cell(cy));
            ++cell_start_[cell_of_[i] + 1];
        }
        for (std::size_t c = 0; c < cells; ++c) {
            cell_start_[c + 1] += cell_start_[c];
        }
        fill_position_.assign(cell_start_.begin(), cell_start_.end() - 1);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            filed_[fill_position_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
        }
    }

    void add_if_overlapping(std::uint32_t i, std::uint32_t j, std::vector<obbsat::pair_index>& pairs) const {
        if (overlap(bounds_[i], bounds_[j])) {
            pairs.push_back({i, j});
        }
    }

    float cell_size_;
    int columns_;
    std::vector<bounds> bounds_;
    std::vector<std::size_t> cell_of_;
    std::vector<std::uint32_t> filed_;
    std::vector<std::size_t> cell_start_;
    std::vector<std::size_t> fill_position_;
};

bool parse_count(const char* text, unsigned long low, unsigned long high, unsigned long& out) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text, &end, 10);
    if (end == text || *end != '\0' || text[0] == '-' || value < low || value > high) {
        return false;
    }
    out = value;
    return true;
}

using clock_type = std::chrono::steady_clock;

double milliseconds_between(clock_type::time_point from, clock_type::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

int run(unsigned long seconds, std::size_t box_count) {
    std::vector<body> bodies = spawn_bodies(box_count, 2024);
    float largest_reach = 0.0f;
    obbsat::pose_records boxes;
    for (const body& b : bodies) {
        largest_reach = std::max(largest_reach, b.reach);
        boxes.push_back(b.pose);
    }
    uniform_grid grid(world_size, largest_reach);
    std::vector<obbsat::pair_index> pairs;
    std::vector<std::uint8_t> verdicts;

    obbsat::collide_options options;  // best backend, one thread: a frame is small
    options.test = obbsat::method::local;
    std::printf("%zu boxes in a %.0f x %.0f world, %zu frames per second, backend %s\n", box_count,
                static_cast<double>(world_size), static_cast<double>(world_size), frames_per_second,
                obbsat::backend_name(obbsat::resolve_backend(options.use)));

    std::uint64_t digest = 0;
    for (unsigned long second = 1; second <= seconds; ++second) {
        double motion_ms = 0;
        double broadphase_ms = 0;
        double narrowphase_ms = 0;
        double slowest_frame_ms = 0;
        std::size_t candidates = 0;
        std::size_t collisions = 0;
        for (std::size_t frame = 0; frame < frames_per_second; ++frame) {
            const clock_type::time_point start = clock_type::now();
            advance(bodies, frame_seconds);
            for (std::size_t i = 0; i < bodies.size(); ++i) {
                boxes.set(i, bodies[i].pose);
            }
            const clock_type::time_point moved = clock_type::now();
            grid.find_candidates(boxes, pairs);
            const clock_type::time_point listed = clock_type::now();

            verdicts.resize(pairs.size());
            obbsat::collide_pairs(boxes, pairs.data(), pairs.size(), verdicts.data(), options);
            const clock_type::time_point decided = clock_type::now();

            candidates += pairs.size();
            collisions += static_cast<std::size_t>(std::count(verdicts.begin(), verdicts.end(), 1));
            // Folds the frame's FNV-1a digest into the run's, in frame order.
            digest = (digest ^ obbsat::verdict_digest(verdicts.data(), verdicts.size())) * 0x100000001b3ull;
            motion_ms += milliseconds_between(start, moved);
            broadphase_ms += milliseconds_between(moved, listed);
            narrowphase_ms += milliseconds_between(listed, decided);
            slowest_frame_ms = std::max(slowest_frame_ms, milliseconds_between(start, decided));
        }
        const double frames = static_cast<double>(frames_per_second);
        std::printf("t=%3lus  candidates %6zu/frame  collisions %6zu/frame  frame %.3f ms (motion %.3f, "
                    "broadphase %.3f, obbsat %.3f, slowest %.3f)\n",
                    second, candidates / frames_per_second, collisions / frames_per_second,
                    (motion_ms + broadphase_ms + narrowphase_ms) / frames, motion_ms / frames,
                    broadphase_ms / frames, narrowphase_ms / frames, slowest_frame_ms);
    }
    std::printf("verdict digest %016llx\n", static_cast<unsigned long long>(digest));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    unsigned long seconds = 10;
    unsigned long box_count = 4000;
    if (argc > 3 || (argc > 1 && !parse_count(argv[1], 1, 3600, seconds)) ||
        (argc > 2 && !parse_count(argv[2], 2, 1000000, box_count))) {
        std::fprintf(stderr,
                     "usage: scene [SECONDS [BOXES]]\n"
                     "  SECONDS  simulated seconds, 1 to 3600 (default 10)\n"
                     "  BOXES    number of boxes, 2 to 1000000 (default 4000)\n");
        return 2;
    }
    try {
        return run(seconds, box_count);
    } catch (const obbsat::unsupported_backend& e) {
        std::fprintf(stderr, "scene: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scene: %s\n", e.what());
        return 1;
    }
}
