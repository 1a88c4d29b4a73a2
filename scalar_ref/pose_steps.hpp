// The steps of the methods on poses, written once over the pose type: local
// (obbsat/ref/local.hpp, local64.hpp) and the pose margins of conservative and
// of exact's certified fast path (obbsat/ref/pose_conservative.hpp,
// pose_conservative64.hpp). obbsat::rect_pose runs them in float,
// obbsat::rect_pose64 in double; the headers state the operations and their
// order, and only the margins' constants differ between the two, given by
// the caller.
#pragma once

#include <obbsat/ref/certified.hpp>

#include <cmath>
#include <limits>

namespace obbsat::ref::pose_steps {

/// Steps 1 to 4 of local: the center offset and the reach on each axis, in
/// the order A.x, A.y, B.x, B.y.
template <class Axes, class Pose>
Axes axes_of(const Pose& a, const Pose& b) {
    const auto ca = a.rotation.x, sa = a.rotation.y;
    const auto cb = b.rotation.x, sb = b.rotation.y;
    const auto hxa = a.half_extents.x, hya = a.half_extents.y;
    const auto hxb = b.half_extents.x, hyb = b.half_extents.y;

    const auto dx = b.center.x - a.center.x;
    const auto dy = b.center.y - a.center.y;

    const auto P = std::fabs((ca * cb) + (sa * sb));
    const auto Q = std::fabs((ca * sb) - (sa * cb));
    const auto na = (ca * ca) + (sa * sa);
    const auto nb = (cb * cb) + (sb * sb);

    Axes out;
    out.offset[0] = (dx * ca) + (dy * sa);
    out.reach[0] = ((hxa * na) + (hxb * P)) + (hyb * Q);
    out.offset[1] = (dy * ca) - (dx * sa);
    out.reach[1] = ((hya * na) + (hxb * Q)) + (hyb * P);
    out.offset[2] = (dx * cb) + (dy * sb);
    out.reach[2] = ((hxb * nb) + (hxa * P)) + (hya * Q);
    out.offset[3] = (dy * cb) - (dx * sb);
    out.reach[3] = ((hyb * nb) + (hxa * Q)) + (hya * P);
    out.dx = dx;
    out.dy = dy;
    return out;
}

/// Step 5 of local for axis k: |offset| <= reach.
template <class Axes>
bool shows_overlap(const Axes& axes, int k) {
    return std::fabs(axes.offset[k]) <= axes.reach[k];
}

/// Method local: all four axes show overlap, tested in order.
template <class Axes>
bool all_show_overlap(const Axes& axes) {
    for (int k = 0; k < 4; ++k) {
        if (!shows_overlap(axes, k)) {
            return false;
        }
    }
    return true;
}

/// The gap on each axis: |offset| − reach.
template <class Axes, class Real>
void gaps_of(const Axes& axes, Real gap[4]) {
    for (int k = 0; k < 4; ++k) {
        gap[k] = std::fabs(axes.offset[k]) - axes.reach[k];
    }
}

/// The constants of one precision's margins: margins are proven only while
/// min_rotation <= Ra, Rb <= max_rotation and Sa, Sb <= max_scaled; each
/// margin is (relative · S) + absolute.
template <class Real>
struct margin_limits {
    Real min_rotation;
    Real max_rotation;
    Real max_scaled;
    Real relative;
    Real absolute;
};

/// A's margin (axes A.x, A.y) and B's (B.x, B.y); +inf where the pair lies
/// outside the limits, so that no gap is taken as proof.
template <class Margins, class Pose, class Axes, class Real>
Margins margins_of(const Pose& a, const Pose& b, const Axes& axes, const margin_limits<Real>& limits) {
    const Real D = std::fabs(axes.dx) + std::fabs(axes.dy);
    const Real Ra = std::fmax(std::fabs(a.rotation.x), std::fabs(a.rotation.y));
    const Real Rb = std::fmax(std::fabs(b.rotation.x), std::fabs(b.rotation.y));
    const Real Ha = a.half_extents.x + a.half_extents.y;
    const Real Hb = b.half_extents.x + b.half_extents.y;
    const Real T = (D + (Ra * Ha)) + (Rb * Hb);
    const Real Sa = Ra * T;
    const Real Sb = Rb * T;
    const bool in_range = Ra >= limits.min_rotation && Ra <= limits.max_rotation && Rb >= limits.min_rotation &&
                          Rb <= limits.max_rotation;
    if (Sa <= limits.max_scaled && Sb <= limits.max_scaled && in_range) {
        return Margins{(limits.relative * Sa) + limits.absolute, (limits.relative * Sb) + limits.absolute};
    }
    const Real none = std::numeric_limits<Real>::infinity();
    return Margins{none, none};
}

/// The margin of axis k: A's for axes 0 and 1, B's for 2 and 3.
template <class Margins>
auto margin_of_axis(const Margins& m, int k) {
    return k < 2 ? m.a : m.b;
}

/// Method conservative: no axis's gap exceeds its margin.
template <class Real, class Axes, class Margins>
bool none_apart(const Axes& axes, const Margins& margins) {
    Real gap[4];
    gaps_of(axes, gap);
    for (int k = 0; k < 4; ++k) {
        if (gap[k] > margin_of_axis(margins, k)) {
            return false;
        }
    }
    return true;
}

/// The certified verdict: apart if some gap exceeds its margin, overlapping
/// if every gap is below minus its margin, otherwise undecided.
template <class Real, class Axes, class Margins>
certified_verdict certify_from(const Axes& axes, const Margins& margins) {
    Real gap[4];
    gaps_of(axes, gap);
    bool apart = false;
    bool overlapping = true;
    for (int k = 0; k < 4; ++k) {
        const Real margin = margin_of_axis(margins, k);
        apart = apart || gap[k] > margin;
        overlapping = overlapping && gap[k] < -margin;
    }
    return certified_verdict{apart, overlapping && !apart};
}

}  // namespace obbsat::ref::pose_steps
