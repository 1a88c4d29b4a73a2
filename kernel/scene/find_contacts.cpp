// find_contacts: the scene query, then the contacts of its pairs, and with a
// margin the pairs of widened stand-ins kept when their contacts have points
// (obbsat/find_contacts.hpp says why the stand-ins lose none).
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/ref/bounds.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace obbsat {

namespace {

bool precedes(const pair_index& x, const pair_index& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
}

bool same_pair(const pair_index& x, const pair_index& y) {
    return x.a == y.a && x.b == y.b;
}

/// The bounds of row `row` of a view whose rows were checked (by the query
/// that ran first), whatever their store.
ref::box_bounds bounds_of_row(const box_view& boxes, std::size_t row) {
    const float* v = boxes.floats() + row * boxes.stride();
    if (boxes.kind() == store_kind::poses) {
        return ref::bounds_of(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}});
    }
    return ref::bounds_of(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
}

/// An axis-aligned pose that contains [lo - margin, hi + margin] on one axis
/// pair. Computed in double and rounded outward by a float ulp of the
/// larger of the center and the half extent, so it holds the widened bounds
/// despite its own rounding; a half extent beyond float range is the
/// largest float (the pose then reaches every box it could pair with).
rect_pose stand_in_of(const ref::box_bounds& b, float margin) {
    constexpr double largest = std::numeric_limits<float>::max();
    const auto axis = [&](float lo, float hi, float& center, float& half) {
        const double c = 0.5 * (static_cast<double>(lo) + static_cast<double>(hi));
        const double h = 0.5 * (static_cast<double>(hi) - static_cast<double>(lo)) + margin;
        center = static_cast<float>(c);
        const double slack = std::fabs(static_cast<double>(center)) * 0x1p-22 + h * 0x1p-22;
        half = static_cast<float>(std::fmin(h + slack, largest));
        if (!std::isfinite(center)) {  // bounds reaching infinity: one huge box at the origin
            center = 0.0f;
            half = static_cast<float>(largest);
        }
    };
    rect_pose p{};
    axis(b.lo_x, b.hi_x, p.center.x, p.half_extents.x);
    axis(b.lo_y, b.hi_y, p.center.y, p.half_extents.y);
    p.rotation = {1.0f, 0.0f};
    return p;
}

/// The contacts of `pairs` over the checked rows of `boxes`.
std::vector<contact> contacts_of(const box_view& boxes, const std::vector<pair_index>& pairs,
                                 const contact_options& options) {
    std::vector<contact> out(pairs.size());
    if (boxes.kind() == store_kind::corners) {
        contact_pairs(reinterpret_cast<const rect*>(boxes.floats()), boxes.size(), pairs.data(), pairs.size(),
                      out.data(), options);
    } else if (boxes.stride() == 6) {
        contact_pairs(reinterpret_cast<const rect_pose*>(boxes.floats()), boxes.size(), pairs.data(),
                      pairs.size(), out.data(), options);
    } else {  // a pose store: its records carry two floats of padding
        std::vector<rect_pose> rows(boxes.size());
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const float* v = boxes.floats() + i * boxes.stride();
            rows[i] = rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}};
        }
        contact_pairs(rows.data(), rows.size(), pairs.data(), pairs.size(), out.data(), options);
    }
    return out;
}

}  // namespace

scene_contacts find_contacts(box_view boxes, const collide_options& options, float margin) {
    if (!(margin >= 0.0f) || !std::isfinite(margin)) {
        throw invalid_input("margin must be finite and >= 0");
    }
    contact_options run;
    run.use = options.use;
    run.threads = options.threads;
    run.margin = margin;

    scene_contacts found;
    // The method's pairs first: this query also checks every box.
    found.pairs = find_pairs(boxes, options);
    if (margin == 0.0f) {
        found.contacts = contacts_of(boxes, found.pairs, run);
        return found;
    }

    std::vector<rect_pose> stand_ins(boxes.size());
    for (std::size_t i = 0; i < stand_ins.size(); ++i) {
        stand_ins[i] = stand_in_of(bounds_of_row(boxes, i), margin);
    }
    collide_options near_options = options;
    near_options.test = method::exact;
    const std::vector<pair_index> candidates =
        find_pairs(box_view(stand_ins).with_filters(boxes.filters()), near_options);
    stand_ins = {};
    const std::vector<contact> contacts = contacts_of(boxes, candidates, run);

    // Both lists are sorted; a candidate stays when the method reported it
    // or its contact has a point. Every reported pair is a candidate, as its
    // bounds overlap and the stand-ins contain them.
    std::vector<pair_index> colliding;
    colliding.swap(found.pairs);
    std::size_t next = 0;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        while (next < colliding.size() && precedes(colliding[next], candidates[k])) {
            ++next;
        }
        const bool reported = next < colliding.size() && same_pair(colliding[next], candidates[k]);
        if (reported || contacts[k].point_count > 0) {
            found.pairs.push_back(candidates[k]);
            found.contacts.push_back(contacts[k]);
        }
    }
    return found;
}

}  // namespace obbsat
