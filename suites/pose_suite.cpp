// The constructions of the pose families, written once for make_pose_family
// and for the mixed stream of random_pose_pairs.
//
// Each draw is a statement of its own or an element of a braced list (which
// is evaluated in order): the order in which a function's arguments, or the
// operands of an operator, are evaluated is unspecified, and so would the
// suites be.
#include <obbsat/suites/pose_suite.hpp>

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace obbsat::suites {

namespace {

/// How a pair was built: what its tag says.
struct placement {
    enum class kind : std::uint8_t { drawn, integer_parallel, integer_turned, on_contact };
    kind how = kind::drawn;
    bool along_v = false;  ///< on_contact: along A's axis v = (-s, c), else u = (c, s)
    int steps_x = 0;       ///< on_contact: float steps B's center moved in x after rounding
    int steps_y = 0;       ///< and in y
};

/// A rotation vector of unit length within rounding: a random direction normalised in float.
point unit_rotation(seeded_random& random) {
    for (;;) {
        const float x = random.uniform(-1.0f, 1.0f);
        const float y = random.uniform(-1.0f, 1.0f);
        const float n = std::sqrt(x * x + y * y);
        if (n > 0.1f && n <= 1.0f) {
            return point{x / n, y / n};
        }
    }
}

/// A rotation vector with integer components and an integer length: (3, 4),
/// (5, 12), (8, 15), (7, 24), the axes, and their quarter turns.
point integer_rotation(seeded_random& random) {
    static const point triples[] = {{3, 4}, {4, 3}, {5, 12}, {12, 5}, {8, 15}, {1, 0}, {0, 1}, {7, 24}};
    const point r = triples[random.below(8)];
    switch (random.below(4)) {
        case 0: return r;
        case 1: return point{-r.y, r.x};
        case 2: return point{-r.x, -r.y};
        default: return point{r.y, -r.x};
    }
}

float float_steps_away(float value, int steps) {
    for (; steps > 0; --steps) value = std::nextafter(value, INFINITY);
    for (; steps < 0; ++steps) value = std::nextafter(value, -INFINITY);
    return value;
}

/// The reach of pose p along the unit direction (ux, uy), in double.
double reach_along(const rect_pose& p, double ux, double uy) {
    const double c = p.rotation.x, s = p.rotation.y;
    return p.half_extents.x * std::fabs(c * ux + s * uy) + p.half_extents.y * std::fabs(-s * ux + c * uy);
}

/// Moves b's center to where, along a's own u or v axis, the two just touch
/// (at a random slide across that axis), rounds it to float and moves it -4..4
/// float steps in x and in y.
placement place_on_contact(seeded_random& random, const rect_pose& a, rect_pose& b) {
    placement out;
    out.how = placement::kind::on_contact;
    const double c = a.rotation.x, s = a.rotation.y;
    const double n = std::sqrt(c * c + s * s);
    double ux = c / n, uy = s / n;
    if (random.below(2) == 1) {
        out.along_v = true;
        const double t = ux;
        ux = -uy;
        uy = t;
    }
    const double side = random.below(2) == 0 ? 1.0 : -1.0;
    const double distance = reach_along(a, ux, uy) + reach_along(b, ux, uy);
    const double slide = (random.uniform(-1.0f, 1.0f)) * 0.5 * distance;
    const double dx = side * distance * ux - slide * uy;
    const double dy = side * distance * uy + slide * ux;
    out.steps_x = static_cast<int>(random.below(9)) - 4;
    out.steps_y = static_cast<int>(random.below(9)) - 4;
    b.center = point{float_steps_away(static_cast<float>(a.center.x + dx), out.steps_x),
                     float_steps_away(static_cast<float>(a.center.y + dy), out.steps_y)};
    return out;
}

/// (1 + u) * 2^e, u in [0, 1) and e uniform in [lo_exponent, hi_exponent].
float log_uniform(seeded_random& random, int lo_exponent, int hi_exponent) {
    const int e = lo_exponent + static_cast<int>(random.below(static_cast<std::uint64_t>(hi_exponent - lo_exponent + 1)));
    return std::ldexp(random.uniform(1.0f, 2.0f), e);
}

rect_pose random_pose(seeded_random& random, point center, float size) {
    return rect_pose{center, {size * random.uniform(0.05f, 1.0f), size * random.uniform(0.05f, 1.0f)},
                     unit_rotation(random)};
}

rect_pose scaled(const rect_pose& p, float scale) {
    return rect_pose{{p.center.x * scale, p.center.y * scale},
                     {p.half_extents.x * scale, p.half_extents.y * scale},
                     p.rotation};
}

placement build_pair(seeded_random& random, pose_family f, rect_pose& a, rect_pose& b) {
    // Every family starts from the same draws: two poses about one origin.
    const point origin{random.uniform(-1000.0f, 1000.0f), random.uniform(-1000.0f, 1000.0f)};
    const float size_a = log_uniform(random, -3, 4);
    const float size_b = log_uniform(random, -3, 4);
    a = random_pose(random, origin, size_a);
    b = random_pose(random, origin, size_b);
    switch (f) {
        case pose_family::near: {
            const float spread = 1.5f * (size_a + size_b);
            b.center = point{origin.x + random.uniform(-spread, spread), origin.y + random.uniform(-spread, spread)};
            return placement{};
        }
        case pose_family::contact:
            return place_on_contact(random, a, b);
        case pose_family::integer_contact: {
            // Every product and sum of the four-axis test is exact in float here.
            a = rect_pose{{static_cast<float>(random.below(41)) - 20.0f, static_cast<float>(random.below(41)) - 20.0f},
                          {static_cast<float>(random.below(6)), static_cast<float>(random.below(6))},
                          integer_rotation(random)};
            b = rect_pose{{static_cast<float>(random.below(41)) - 20.0f, static_cast<float>(random.below(41)) - 20.0f},
                          {static_cast<float>(random.below(6)), static_cast<float>(random.below(6))},
                          integer_rotation(random)};
            placement out;
            out.how = placement::kind::integer_turned;
            if (random.below(2) == 0) {
                b.rotation = a.rotation;  // parallel frames: edge-to-edge contacts
                out.how = placement::kind::integer_parallel;
            }
            return out;
        }
        case pose_family::far: {
            const float far = log_uniform(random, 13, 24);
            a.center = point{a.center.x + far, a.center.y - far * random.uniform(0.0f, 1.0f)};
            return place_on_contact(random, a, b);
        }
        case pose_family::rotation_scale: {
            // The boxes keep their size: the rotation's length scales them back.
            const float scale_a = log_uniform(random, -30, 30);
            const float scale_b = log_uniform(random, -30, 30);
            a.rotation = point{a.rotation.x * scale_a, a.rotation.y * scale_a};
            b.rotation = point{b.rotation.x * scale_b, b.rotation.y * scale_b};
            a.half_extents = point{a.half_extents.x / scale_a, a.half_extents.y / scale_a};
            b.half_extents = point{b.half_extents.x / scale_b, b.half_extents.y / scale_b};
            return place_on_contact(random, a, b);
        }
        case pose_family::zero_extents:
            if (random.below(2) == 0) a.half_extents.x = 0.0f;
            if (random.below(2) == 0) a.half_extents.y = 0.0f;
            if (random.below(2) == 0) b.half_extents.x = 0.0f;
            if (random.below(2) == 0) b.half_extents.y = 0.0f;
            return place_on_contact(random, a, b);
        case pose_family::slivers:
            a.half_extents.y = a.half_extents.x * log_uniform(random, -24, -10);
            b.half_extents.x = b.half_extents.y * log_uniform(random, -24, -10);
            return place_on_contact(random, a, b);
        case pose_family::near_parallel:
            b.rotation = point{float_steps_away(a.rotation.x, static_cast<int>(random.below(9)) - 4),
                               float_steps_away(a.rotation.y, static_cast<int>(random.below(9)) - 4)};
            return place_on_contact(random, a, b);
        case pose_family::tiny: {
            const float tiny = log_uniform(random, -60, -40);
            a = scaled(a, tiny);
            b = scaled(b, tiny);
            return place_on_contact(random, a, b);
        }
        case pose_family::huge: {
            const float huge = log_uniform(random, 40, 60);
            a = scaled(a, huge);
            b = scaled(b, huge);
            return place_on_contact(random, a, b);
        }
    }
    throw std::invalid_argument("obbsat::suites: not a pose family");
}

std::string signed_steps(int steps) {
    return (steps < 0 ? "-" : "+") + std::to_string(steps < 0 ? -steps : steps);
}

std::string tag_text(const placement& p) {
    switch (p.how) {
        case placement::kind::drawn: return "near";
        case placement::kind::integer_parallel: return "parallel";
        case placement::kind::integer_turned: return "turned";
        case placement::kind::on_contact: break;
    }
    return std::string(p.along_v ? "v" : "u") + ":x" + signed_steps(p.steps_x) + ":y" + signed_steps(p.steps_y);
}

}  // namespace

void random_pose_pair(seeded_random& random, pose_family f, rect_pose& a, rect_pose& b) {
    build_pair(random, f, a, b);
}

pose_pairs random_pose_pairs(seeded_random& random, std::size_t count) {
    const std::vector<pose_family>& families = all_pose_families();
    pose_pairs out;
    out.a.resize(count);
    out.b.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        build_pair(random, families[i % families.size()], out.a[i], out.b[i]);
    }
    return out;
}

pose_suite make_pose_family(pose_family f, std::uint64_t seed, std::size_t pairs) {
    if (pairs > 0x7fffffffu) {
        throw std::length_error("obbsat::suites: more poses than a pair_index can address");
    }
    pose_suite out;
    out.source = f;
    out.seed = seed;
    out.poses.reserve(2 * pairs);
    out.pairs.reserve(pairs);
    out.tags.reserve(pairs);
    // Each family draws from its own stream, unrelated to the corner
    // families' streams of the same seed.
    seeded_random random(seed ^ (0xd1b54a32d192ed03ull * (static_cast<std::uint64_t>(f) + 1)));
    std::unordered_map<std::string, std::uint16_t> tag_index;
    for (std::size_t i = 0; i < pairs; ++i) {
        rect_pose a, b;
        const std::string tag = tag_text(build_pair(random, f, a, b));
        auto found = tag_index.find(tag);
        if (found == tag_index.end()) {
            if (out.tag_names.size() > 0xffffu) {
                throw std::length_error("obbsat::suites: too many distinct tags");
            }
            found = tag_index.emplace(tag, static_cast<std::uint16_t>(out.tag_names.size())).first;
            out.tag_names.push_back(tag);
        }
        const auto first = static_cast<std::uint32_t>(out.poses.size());
        out.poses.push_back(a);
        out.poses.push_back(b);
        out.pairs.push_back(pair_index{first, first + 1});
        out.tags.push_back(found->second);
    }
    return out;
}

}  // namespace obbsat::suites
