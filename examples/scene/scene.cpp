// A game-like loop: a few thousand boxes move, spin and bounce off the walls of
// a square world. Each box is a pose (center, half extents, rotation vector),
// as a physics engine keeps it; no corners are ever computed. Each frame one
// call of obbsat's scene query, a pair_finder kept across frames, lists every
// pair of boxes that collides (method local): its broadphase finds the pairs
// whose bounds overlap, its narrowphase decides them, and it starts from the
// order of the frame before, which a small motion barely changes.
//
//   scene [SECONDS [BOXES]]     simulated seconds (default 10), boxes (default 4000)
//
// The world grows with the box count (400 x 400 for 4000 boxes), so that every
// size is as crowded as the default. Each second prints the pairs per frame
// and per box, and the mean frame (in all and per box) split into the
// example's own motion and the query's stages as pair_finder::stats() times
// them (bounds: bounds and sort keys; order: sorting or repairing the order;
// sweep: the broadphase sweep and the narrowphase; output: the pairs in the
// caller's indices, sorted); then how many frames reused the previous order,
// and the slowest frame.
//
// Motion is seeded, so every run is the same. After the last frame its pairs
// are checked: each collides by collide_pairs, and for small scenes a brute
// force over all pairs finds the same ones. The digest printed at the end is a
// fingerprint of every frame's pairs; it does not depend on the backend
// (compare with OBBSAT_BACKEND=scalar).
#include <obbsat/obbsat.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

namespace {

constexpr std::size_t default_box_count = 4000;
constexpr float default_world_size = 400.0f;
constexpr std::size_t frames_per_second = 60;
constexpr float frame_seconds = 1.0f / static_cast<float>(frames_per_second);
constexpr float two_pi = 6.2831853f;
// The brute force decides N(N-1)/2 pairs: 8 million at this size, about a
// tenth of a second.
constexpr std::size_t brute_force_limit = 4000;

struct body {
    obbsat::rect_pose pose;
    obbsat::point velocity;  // world units per second
    obbsat::point turn;      // the rotation of one frame, as (cos, sin) of its angle
    float reach;             // distance from the center to a corner
};

std::vector<body> spawn_bodies(std::size_t count, float world_size, std::uint64_t seed) {
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
void bounce(float& position, float& velocity, float reach, float world_size) {
    if ((position - reach < 0.0f && velocity < 0.0f) ||
        (position + reach > world_size && velocity > 0.0f)) {
        velocity = -velocity;
    }
}

// One frame of motion. The rotation vector turns by the frame's rotation and
// is renormalised, so that its length (which scales the box) stays 1 within
// rounding however many frames pass.
void advance(std::vector<body>& bodies, float seconds, float world_size) {
    for (body& b : bodies) {
        b.pose.center.x += b.velocity.x * seconds;
        b.pose.center.y += b.velocity.y * seconds;
        const obbsat::point r = b.pose.rotation;
        const float c = r.x * b.turn.x - r.y * b.turn.y;
        const float s = r.y * b.turn.x + r.x * b.turn.y;
        const float length = std::sqrt(c * c + s * s);
        b.pose.rotation = {c / length, s / length};
        bounce(b.pose.center.x, b.velocity.x, b.reach, world_size);
        bounce(b.pose.center.y, b.velocity.y, b.reach, world_size);
    }
}

bool same_pairs(const std::vector<obbsat::pair_index>& x, const std::vector<obbsat::pair_index>& y) {
    return std::equal(x.begin(), x.end(), y.begin(), y.end(),
                      [](obbsat::pair_index p, obbsat::pair_index q) { return p.a == q.a && p.b == q.b; });
}

// Every pair (i, j), i < j, that collides, one row of i at a time; sorted as
// the query sorts its answer.
std::vector<obbsat::pair_index> brute_force_pairs(const obbsat::pose_records& boxes,
                                                  const obbsat::collide_options& options) {
    std::vector<obbsat::pair_index> colliding;
    std::vector<obbsat::pair_index> row;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        row.clear();
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
            row.push_back({i, j});
        }
        const std::vector<obbsat::pair_index> hits = obbsat::colliding_pairs(boxes, row, options);
        colliding.insert(colliding.end(), hits.begin(), hits.end());
    }
    return colliding;
}

// The query's answer, checked two ways: every pair it reports collides by
// collide_pairs on the same poses, and (small scenes) it is the brute force's.
bool check_pairs(const obbsat::pose_records& boxes, const std::vector<obbsat::pair_index>& pairs,
                 const obbsat::collide_options& options) {
    const std::vector<std::uint8_t> verdicts = obbsat::collide_pairs(boxes, pairs, options);
    if (std::count(verdicts.begin(), verdicts.end(), 1) != static_cast<std::ptrdiff_t>(pairs.size())) {
        std::fprintf(stderr, "scene: the query reported a pair that collide_pairs says is apart\n");
        return false;
    }
    if (boxes.size() > brute_force_limit) {
        std::printf("check: all %zu pairs of the last frame collide (no brute force above %zu boxes)\n",
                    pairs.size(), brute_force_limit);
        return true;
    }
    if (!same_pairs(pairs, brute_force_pairs(boxes, options))) {
        std::fprintf(stderr, "scene: the query and the brute force found different pairs\n");
        return false;
    }
    std::printf("check: all %zu pairs of the last frame collide, and a brute force over all %zu pairs finds "
                "the same\n",
                pairs.size(), boxes.size() * (boxes.size() - 1) / 2);
    return true;
}

// FNV-1a over a frame's pairs, folded into the run's digest in frame order.
std::uint64_t fold_digest(std::uint64_t digest, const std::vector<obbsat::pair_index>& pairs) {
    for (const obbsat::pair_index& p : pairs) {
        digest = (digest ^ p.a) * 0x100000001b3ull;
        digest = (digest ^ p.b) * 0x100000001b3ull;
    }
    return digest;
}

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

// Sums of one second's frames, in milliseconds.
struct second_totals {
    double motion = 0, query = 0, bounds = 0, order = 0, sweep = 0, output = 0, slowest_frame = 0;
    std::size_t pairs = 0, reused_order = 0, reused_candidates = 0;

    void add(const obbsat::find_pairs_stats& s) {
        bounds += 1e3 * s.bounds_seconds;
        order += 1e3 * s.order_seconds;
        sweep += 1e3 * s.sweep_seconds;
        output += 1e3 * s.output_seconds;
        pairs += s.pairs;
        reused_order += s.reused_order ? 1 : 0;
        reused_candidates += s.reused_candidates ? 1 : 0;
    }
};

int run(unsigned long seconds, std::size_t box_count) {
    const float world_size =
        default_world_size * std::sqrt(static_cast<float>(box_count) / static_cast<float>(default_box_count));
    std::vector<body> bodies = spawn_bodies(box_count, world_size, 2024);
    obbsat::pose_records boxes;
    for (const body& b : bodies) {
        boxes.push_back(b.pose);
    }

    obbsat::collide_options options;  // best backend, one thread
    options.test = obbsat::method::local;
    obbsat::pair_finder finder(options);  // kept across frames: its order and buffers are reused
    std::printf("%zu boxes in a %.0f x %.0f world, %zu frames per second, backend %s\n", box_count,
                static_cast<double>(world_size), static_cast<double>(world_size), frames_per_second,
                obbsat::backend_name(obbsat::resolve_backend(options.use)));

    std::uint64_t digest = 0xcbf29ce484222325ull;
    const std::vector<obbsat::pair_index>* pairs = nullptr;
    for (unsigned long second = 1; second <= seconds; ++second) {
        second_totals sum;
        for (std::size_t frame = 0; frame < frames_per_second; ++frame) {
            const clock_type::time_point start = clock_type::now();
            advance(bodies, frame_seconds, world_size);
            for (std::size_t i = 0; i < bodies.size(); ++i) {
                boxes.set(i, bodies[i].pose);
            }
            const clock_type::time_point moved = clock_type::now();
            pairs = &finder.find(boxes);
            const clock_type::time_point found = clock_type::now();

            digest = fold_digest(digest, *pairs);
            sum.add(finder.stats());
            sum.motion += milliseconds_between(start, moved);
            sum.query += milliseconds_between(moved, found);
            sum.slowest_frame = std::max(sum.slowest_frame, milliseconds_between(start, found));
        }
        const double frames = static_cast<double>(frames_per_second);
        const double frame_ms = (sum.motion + sum.query) / frames;
        std::printf("t=%3lus  pairs %.0f (%.2f/box)  frame %.3f ms, %.1f ns/box: motion %.3f, bounds %.3f, "
                    "order %.3f, sweep %.3f, output %.3f (candidates kept %zu/%zu, order reused %zu/%zu, slowest %.3f)\n",
                    second, static_cast<double>(sum.pairs) / frames,
                    static_cast<double>(sum.pairs) / frames / static_cast<double>(box_count), frame_ms,
                    1e6 * frame_ms / static_cast<double>(box_count), sum.motion / frames, sum.bounds / frames,
                    sum.order / frames, sum.sweep / frames, sum.output / frames, sum.reused_candidates,
                    frames_per_second, sum.reused_order, frames_per_second, sum.slowest_frame);
    }
    std::printf("pair digest %016llx\n", static_cast<unsigned long long>(digest));
    return check_pairs(boxes, *pairs, options) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    unsigned long seconds = 10;
    unsigned long box_count = default_box_count;
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
