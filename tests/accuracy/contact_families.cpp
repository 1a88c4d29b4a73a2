#include "contact_families.hpp"

#include <obbsat/ref/local.hpp>
#include <obbsat/ref/local64.hpp>

#include <cmath>

namespace obbsat::accuracy {

namespace {

constexpr double pi = 3.14159265358979323846;

/// A pose in double before it is rounded: center, half extents, angle.
struct placed {
    double cx, cy, hx, hy, angle;
};

class placer {
public:
    /// Parallel faces tilt by 10^e rad for e from `least_tilt_exponent` to -3.
    placer(std::uint64_t seed, double least_tilt_exponent) : random_(seed), least_tilt_(least_tilt_exponent) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random_); }
    /// A small integer (|v| < 2^24, exact) as a float.
    float small(int lo, int hi) { return static_cast<float>(integer(lo, hi)); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

    placed box_at_origin() { return placed{0.0, 0.0, uniform(0.25, 2.0), uniform(0.25, 2.0), uniform(0.0, 2 * pi)}; }

    /// B of half extents (hx, hy) and angle, pushed `depth` into face f of A
    /// (its reach along the face normal taken in double), slid along the face.
    placed against_face(const placed& a, double hx, double hy, double angle, double depth) {
        const int f = integer(0, 3);
        const double along = a.angle + f * (pi / 2);
        const double nx = std::cos(along), ny = std::sin(along);
        const double half_a = (f % 2 == 0) ? a.hx : a.hy;  // A's half extent along the normal
        const double side_a = (f % 2 == 0) ? a.hy : a.hx;  // and along the face
        const double reach_b = hx * std::fabs(std::cos(angle - along)) + hy * std::fabs(std::sin(angle - along));
        const double distance = half_a + reach_b - depth;
        const double slide = uniform(-1.0, 1.0) * side_a;
        return placed{a.cx + distance * nx - slide * ny, a.cy + distance * ny + slide * nx, hx, hy, angle};
    }

    placed face_parallel(const placed& a) {
        const double tilt = chance(0.2) ? 0.0 : (chance(0.5) ? -1 : 1) * std::pow(10.0, uniform(least_tilt_, -3.0));
        const double angle = a.angle + integer(0, 3) * (pi / 2) + tilt;
        return against_face(a, uniform(0.25, 2.0), uniform(0.25, 2.0), angle, uniform(0.0, 0.2) * a.hx);
    }

    placed corner_into_face(const placed& a) {
        const double angle = a.angle + uniform(0.15, pi / 2 - 0.15);
        return against_face(a, uniform(0.25, 2.0), uniform(0.25, 2.0), angle, uniform(0.0, 0.2) * a.hx);
    }

    placed corner_corner(const placed& a) {
        const double sx = chance(0.5) ? 1 : -1, sy = chance(0.5) ? 1 : -1;
        const double c = std::cos(a.angle), s = std::sin(a.angle);
        const double px = a.cx + sx * a.hx * c - sy * a.hy * s, py = a.cy + sx * a.hx * s + sy * a.hy * c;
        const double reach = std::hypot(px - a.cx, py - a.cy);
        const double dx = (px - a.cx) / reach, dy = (py - a.cy) / reach;
        const double hx = uniform(0.25, 2.0), hy = uniform(0.25, 2.0);
        // Turn B so that its corner (−hx, −hy) points back along the diagonal.
        const double angle = std::atan2(-dy, -dx) - std::atan2(-hy, -hx) + uniform(-0.3, 0.3);
        const double to_corner = std::hypot(hx, hy) - uniform(0.0, 0.1) * a.hx;
        return placed{px + dx * to_corner, py + dy * to_corner, hx, hy, angle};
    }

    placed deep_inside(const placed& a) {
        const double c = std::cos(a.angle), s = std::sin(a.angle);
        const double u = uniform(-0.6, 0.6) * a.hx, v = uniform(-0.6, 0.6) * a.hy;
        const double size = 0.3 * (a.hx < a.hy ? a.hx : a.hy);
        return placed{a.cx + u * c - v * s, a.cy + u * s + v * c, uniform(0.1, 1.0) * size, uniform(0.1, 1.0) * size,
                      uniform(0.0, 2 * pi)};
    }

    /// B on A's axes (up to quarter turns) with equal overlaps along A.x and
    /// A.y, its center then moved by up to 4 ulps: which of A's faces is the
    /// reference is a tie that the last bits of the center decide.
    placed axes_tie(const placed& a) {
        const double hx = uniform(0.25, 2.0), hy = uniform(0.25, 2.0);
        const int turns = integer(0, 3);
        const double reach_x = turns % 2 == 0 ? hx : hy, reach_y = turns % 2 == 0 ? hy : hx;
        const double overlap = uniform(0.0, 0.2) * (a.hx < a.hy ? a.hx : a.hy);
        const double u = (chance(0.5) ? 1 : -1) * (a.hx + reach_x - overlap);
        const double v = (chance(0.5) ? 1 : -1) * (a.hy + reach_y - overlap);
        const double c = std::cos(a.angle), s = std::sin(a.angle);
        const double nudge = integer(-4, 4) * 0x1p-52;
        return placed{(a.cx + u * c - v * s) * (1 + nudge), a.cy + u * s + v * c, hx, hy, a.angle + turns * (pi / 2)};
    }

    /// One of the four placements above, at random.
    placed mixed(const placed& a) {
        switch (integer(0, 3)) {
        case 0: return face_parallel(a);
        case 1: return corner_into_face(a);
        case 2: return corner_corner(a);
        default: return deep_inside(a);
        }
    }

private:
    std::mt19937_64 random_;
    double least_tilt_;
};

/// The pose of a placement, scaled and moved in double, then held as Pose:
/// rounded to float for rect_pose, kept as it is for rect_pose64.
template <class Pose>
Pose rounded(const placed& p, double scale, double shift_x, double shift_y) {
    using value = decltype(Pose{}.center.x);
    return Pose{{static_cast<value>(shift_x + p.cx * scale), static_cast<value>(shift_y + p.cy * scale)},
                {static_cast<value>(p.hx * scale), static_cast<value>(p.hy * scale)},
                {static_cast<value>(std::cos(p.angle)), static_cast<value>(std::sin(p.angle))}};
}

rect_pose64 widened(const rect_pose& p) {
    return rect_pose64{{p.center.x, p.center.y}, {p.half_extents.x, p.half_extents.y}, {p.rotation.x, p.rotation.y}};
}

/// A float pair as Pair: itself, or widened exactly to double.
pose_pair held_as(const pose_pair& p, const pose_pair*) { return p; }
pose_pair64 held_as(const pose_pair& p, const pose_pair64*) { return pose_pair64{widened(p.a), widened(p.b)}; }

/// Integer rotations, sizes and centers: every separation is exact in float.
pose_pair exactly_touching(placer& random) {
    static const float rotations[][2] = {{1, 0}, {0, 1}, {3, 4}, {4, 3}, {-3, 4}, {5, 12}, {-12, 5}, {8, -15}};
    const auto& rotation = rotations[random.integer(0, 7)];
    const float c = rotation[0], s = rotation[1];
    const float hxa = 0.5f * random.small(0, 6), hya = 0.5f * random.small(1, 6);
    const float hxb = 0.5f * random.small(1, 6), hyb = 0.5f * random.small(0, 6);
    const rect_pose a{{random.small(-8, 8), random.small(-8, 8)},
                      {hxa, hya}, {c, s}};
    // B shares A's rotation (or a quarter turn of it); its center is A's
    // plus whole multiples of A's axes, so its faces or corners lie exactly
    // on A's: along A.x by hxa + hxb, along A.y by a slide or by hya + hyb.
    const bool quarter = random.chance(0.3);
    const float bx = quarter ? hyb : hxb, by = quarter ? hxb : hyb;
    const float sign = random.chance(0.5) ? 1.0f : -1.0f;
    const float along_x = sign * (hxa + bx);
    const float along_y = random.chance(0.3) ? (hya + by) * (random.chance(0.5) ? 1.0f : -1.0f)
                                             : 0.5f * random.small(-4, 4);
    const rect_pose b{{a.center.x + along_x * c - along_y * s, a.center.y + along_x * s + along_y * c},
                      {hxb, hyb},
                      quarter ? point{-s, c} : point{c, s}};
    return random.chance(0.5) ? pose_pair{a, b} : pose_pair{b, a};
}

}  // namespace

const char* contact_family_name(contact_family family) {
    switch (family) {
    case contact_family::face_parallel: return "face_parallel";
    case contact_family::corner_into_face: return "corner_into_face";
    case contact_family::corner_corner: return "corner_corner";
    case contact_family::deep_inside: return "deep_inside";
    case contact_family::axes_tie: return "axes_tie";
    case contact_family::exact_touching: return "exact_touching";
    case contact_family::zero_extents: return "zero_extents";
    case contact_family::tiny: return "tiny_1e-6";
    case contact_family::huge: return "huge_1e6";
    case contact_family::far_1e6: return "far_1e6";
    case contact_family::far_1e7: return "far_1e7";
    case contact_family::random: return "random";
    case contact_family::far_utm: return "far_1e5_1e7";
    case contact_family::far_1e15: return "far_1e9_1e15";
    }
    return "?";
}

namespace {

/// The pairs of `family` as Pair (pose_pair or pose_pair64).
template <class Pair>
std::vector<Pair> make_pairs(contact_family family, std::size_t count, std::uint64_t seed,
                             double least_tilt_exponent) {
    using pose = decltype(Pair{}.a);
    placer random(seed * 1000003u + static_cast<std::uint64_t>(family), least_tilt_exponent);
    std::vector<Pair> out;
    out.reserve(count);
    while (out.size() < count) {
        const placed a = random.box_at_origin();
        double scale = 1.0, shift_x = 0.0, shift_y = 0.0;
        placed b = a;
        switch (family) {
        case contact_family::face_parallel: b = random.face_parallel(a); break;
        case contact_family::corner_into_face: b = random.corner_into_face(a); break;
        case contact_family::corner_corner: b = random.corner_corner(a); break;
        case contact_family::deep_inside: b = random.deep_inside(a); break;
        case contact_family::axes_tie: b = random.axes_tie(a); break;
        case contact_family::exact_touching:
            out.push_back(held_as(exactly_touching(random), static_cast<const Pair*>(nullptr)));
            continue;
        case contact_family::zero_extents: {
            placed flat = a;
            const int which = random.integer(0, 2);  // A's x, A's y, or both of A's
            flat.hx = which == 1 ? a.hx : 0.0;
            flat.hy = which == 0 ? a.hy : 0.0;
            b = random.mixed(a);
            if (random.chance(0.5)) {
                out.push_back(Pair{rounded<pose>(flat, 1, 0, 0), rounded<pose>(b, 1, 0, 0)});
            } else {
                out.push_back(Pair{rounded<pose>(b, 1, 0, 0), rounded<pose>(flat, 1, 0, 0)});
            }
            continue;
        }
        case contact_family::tiny: b = random.mixed(a); scale = 1e-6; break;
        case contact_family::huge: b = random.mixed(a); scale = 1e6; break;
        case contact_family::far_1e6:
        case contact_family::far_1e7: {
            b = random.mixed(a);
            const double far = family == contact_family::far_1e6 ? 1e6 : 1e7;
            shift_x = random.uniform(0.5, 1.0) * far * (random.chance(0.5) ? 1 : -1);
            shift_y = random.uniform(0.5, 1.0) * far * (random.chance(0.5) ? 1 : -1);
            break;
        }
        case contact_family::far_utm:
        case contact_family::far_1e15: {
            // Each coordinate's magnitude log-uniform over the range.
            b = random.mixed(a);
            const double lo = family == contact_family::far_utm ? 5.0 : 9.0;
            const double hi = family == contact_family::far_utm ? 7.0 : 15.0;
            shift_x = std::pow(10.0, random.uniform(lo, hi)) * (random.chance(0.5) ? 1 : -1);
            shift_y = std::pow(10.0, random.uniform(lo, hi)) * (random.chance(0.5) ? 1 : -1);
            break;
        }
        case contact_family::random: {
            placed p = random.box_at_origin(), q = random.box_at_origin();
            q.cx = random.uniform(-3.0, 3.0);
            q.cy = random.uniform(-3.0, 3.0);
            const Pair pair{rounded<pose>(p, 1, 0, 0), rounded<pose>(q, 1, 0, 0)};
            if (obbsat::ref::local(pair.a, pair.b)) {
                out.push_back(pair);
            }
            continue;
        }
        }
        out.push_back(Pair{rounded<pose>(a, scale, shift_x, shift_y), rounded<pose>(b, scale, shift_x, shift_y)});
    }
    return out;
}

}  // namespace

std::vector<pose_pair> make_contact_pairs(contact_family family, std::size_t count, std::uint64_t seed) {
    return make_pairs<pose_pair>(family, count, seed, -7.0);
}

// Parallel faces tilt down to 1e-16 rad, below an ulp of the angle itself:
// the two faces are parallel, or one ulp of a rotation component apart, where
// a tie of A's and B's separations decides the reference face.
std::vector<pose_pair64> make_contact_pairs64(contact_family family, std::size_t count, std::uint64_t seed) {
    return make_pairs<pose_pair64>(family, count, seed, -16.0);
}

namespace {

/// The corners of `p` computed in double, held as Quad (rounded to float for rect).
template <class Quad, class Pose>
Quad quad_of(const Pose& p) {
    using value = decltype(Quad{}.ul.x);
    const double cx = p.center.x, cy = p.center.y, c = p.rotation.x, s = p.rotation.y;
    const double ux = p.half_extents.x * c, uy = p.half_extents.x * s;
    const double wx = p.half_extents.y * s, wy = p.half_extents.y * c;
    auto at = [](double x, double y) { return decltype(Quad{}.ul){static_cast<value>(x), static_cast<value>(y)}; };
    return Quad{at(cx - ux - wx, cy - uy + wy), at(cx + ux - wx, cy + uy + wy), at(cx + ux + wx, cy + uy - wy),
                at(cx - ux + wx, cy - uy - wy)};
}

}  // namespace

rect corners_of(const rect_pose& p) { return quad_of<rect>(p); }
rect64 corners_of(const rect_pose64& p) { return quad_of<rect64>(p); }

}  // namespace obbsat::accuracy
