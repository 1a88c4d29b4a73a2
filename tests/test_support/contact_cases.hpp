// The float pose pairs the contact tests draw: plain random pairs and the
// hard cases of contacts themselves (test_contact_backends.cpp runs every
// backend on them; test_contact64.cpp widens them to double).
#pragma once

#include <obbsat/ref/contact.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace obbsat::test {

struct pose_pairs {
    std::vector<rect_pose> a, b;
};

/// Only the pairs whose poses contacts accept (obbsat/ref/contact.hpp).
inline pose_pairs poses_accepted(const pose_pairs& in) {
    pose_pairs out;
    for (std::size_t i = 0; i < in.a.size(); ++i) {
        if (ref::pose_accepted(in.a[i]) && ref::pose_accepted(in.b[i])) {
            out.a.push_back(in.a[i]);
            out.b.push_back(in.b[i]);
        }
    }
    return out;
}

/// Plain random pairs: sizes 0.1 to 4, centers within 8 of each other, any
/// rotation vector of length 0.5 to 1.5 (about half of them collide).
inline pose_pairs random_pairs(std::uint64_t seed, std::size_t count) {
    seeded_random random(seed);
    pose_pairs out;
    auto draw = [&](float cx, float cy) {
        float c = 0, s = 0;
        do {
            c = random.uniform(-1.5f, 1.5f);
            s = random.uniform(-1.5f, 1.5f);
        } while ((c * c) + (s * s) < 0.25f || (c * c) + (s * s) > 2.25f);
        return rect_pose{{cx, cy}, {random.uniform(0.1f, 4.0f), random.uniform(0.1f, 4.0f)}, {c, s}};
    };
    for (std::size_t i = 0; i < count; ++i) {
        const float x = random.uniform(-100.0f, 100.0f), y = random.uniform(-100.0f, 100.0f);
        out.a.push_back(draw(x, y));
        out.b.push_back(draw(x + random.uniform(-6.0f, 6.0f), y + random.uniform(-6.0f, 6.0f)));
    }
    return poses_accepted(out);
}

/// The hard cases of contacts themselves, at scale `scale` (2^-20, 1, 2^20)
/// and offset `far` from the origin: faces parallel or one float step off
/// (the reference face may flip on a step), separations that tie exactly,
/// corner against corner, one box deep inside the other, exact touching,
/// segments and points.
inline pose_pairs hard_pairs(std::uint64_t seed, std::size_t count, float scale, float far) {
    seeded_random random(seed);
    pose_pairs out;
    const float unit_rotations[][2] = {{1, 0}, {0, 1}, {0.6f, 0.8f}, {1, 1}, {3, 4}, {-5, 12}, {0.28f, -0.96f}};
    for (std::size_t i = 0; i < count; ++i) {
        const auto& r = unit_rotations[random.below(7)];
        float c = r[0], s = r[1];
        const float hx = std::ldexp(static_cast<float>(1 + random.below(8)), -2) * scale;
        const float hy = std::ldexp(static_cast<float>(random.below(8)), -2) * scale;  // 0 sometimes
        const rect_pose a{{far, far}, {hx, hy}, {c, s}};
        // B's rotation: A's, one float step off per component, or turned a quarter, or 45°.
        float cb = c, sb = s;
        switch (random.below(5)) {
        case 0: break;
        case 1: cb = std::nextafter(c, 2.0f * c + 1.0f); break;
        case 2: sb = std::nextafter(s, -2.0f); break;
        case 3: cb = -s, sb = c; break;
        default: cb = c - s, sb = c + s; break;
        }
        const float hxb = std::ldexp(static_cast<float>(random.below(9)), -2) * scale;
        const float hyb = std::ldexp(static_cast<float>(1 + random.below(8)), -2) * scale;
        // B's center: along A's axis u = (c, s) or v = (-s, c), at a multiple of
        // 1/8 of the scale (touching, overlapping, apart, deep inside), then
        // slid along the face and moved a few float steps.
        const bool along_u = random.below(2) == 0;
        const float ax = along_u ? c : -s, ay = along_u ? s : c;
        const float bx = along_u ? -s : c * 1.0f, by = along_u ? c : s;
        const float reach = std::ldexp(static_cast<float>(random.below(40)), -3) * scale;
        const float slide = std::ldexp(static_cast<float>(static_cast<int>(random.below(33)) - 16), -3) * scale;
        float x = far + ((reach * ax) + (slide * bx));
        float y = far + ((reach * ay) + (slide * by));
        for (auto k = random.below(4); k > 0; --k) {
            x = std::nextafter(x, random.below(2) == 0 ? -INFINITY : INFINITY);
        }
        for (auto k = random.below(4); k > 0; --k) {
            y = std::nextafter(y, random.below(2) == 0 ? -INFINITY : INFINITY);
        }
        out.a.push_back(a);
        out.b.push_back(rect_pose{{x, y}, {hxb, hyb}, {cb, sb}});
    }
    return poses_accepted(out);
}

}  // namespace obbsat::test
