// find_contacts: the scene query's pairs sorted into the answer, then their
// contacts on the caller's rows (query_contacts.hpp); with a margin, the
// pairs of widened stand-ins kept when their contacts have points
// (obbsat/find_contacts.hpp says why the stand-ins lose none); pair_finder's
// frames with contacts.
#include "dispatch/backend_registry.hpp"
#include "dispatch/contact_kernel_table.hpp"
#include "methods/method_check.hpp"
#include "scene/pair_search.hpp"
#include "scene/query_contacts.hpp"
#include "scene/query_input.hpp"
#include "scene/search_common.hpp"
#include "scene/spare_search.hpp"
#include "support/executor_scope.hpp"

#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/ref/contact.hpp>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace obbsat {

namespace detail {

void pair_search::collect_into(const query_input& input, std::vector<pair_index>& out) {
    run(input, pair_chunk_sink{});
    // The sort writes into out's memory: a caller's answer kept between
    // calls takes no fresh page.
    pairs_.swap(out);
    sort_found();
    pairs_.swap(out);
}

}  // namespace detail

namespace {

constexpr std::size_t no_row = std::numeric_limits<std::size_t>::max();

/// The contact kernel of `boxes`' kind on `use`; invalid_input for double rows.
detail::contact_fn contact_kernel_of(const box_view& boxes, backend use, const char* call) {
    if (boxes.precision() != precision::float32) {
        throw invalid_input(std::string(call) +
                            ": contacts are computed on float rows; these are double (round them to float first)");
    }
    const detail::contact_kernel_table& table = detail::contact_kernels_for(resolve_backend(use));
    return boxes.kind() == store_kind::poses ? table.poses : table.corners;
}

/// The first row of `boxes` that contacts do not accept (obbsat/contact.hpp),
/// or no_row. One branch-free pass over poses when all are accepted.
std::size_t first_unaccepted(const box_view& boxes) {
    const float* v = boxes.floats();
    const std::size_t stride = boxes.stride();
    if (boxes.kind() == store_kind::poses) {
        bool all = true;
        for (std::size_t row = 0; row < boxes.size(); ++row) {
            const float c = v[stride * row + 4], s = v[stride * row + 5];
            const float q = (c * c) + (s * s);
            all &= (q >= FLT_MIN) & (q <= FLT_MAX);
        }
        if (all) {
            return no_row;
        }
    }
    for (std::size_t row = 0; row < boxes.size(); ++row) {
        const float* r = v + stride * row;
        const bool accepted = boxes.kind() == store_kind::poses
                                  ? ref::pose_accepted(rect_pose{{r[0], r[1]}, {r[2], r[3]}, {r[4], r[5]}})
                                  : ref::corners_accepted(rect{{r[0], r[1]}, {r[2], r[3]}, {r[4], r[5]}, {r[6], r[7]}});
        if (!accepted) {
            return row;
        }
    }
    return no_row;
}

/// Throws invalid_input, as contact_pairs does, for the first row of `boxes`
/// that contacts do not accept, unless some row is not a valid box at all:
/// the query then refuses that one first (as when find_pairs ran first).
void require_accepted(const box_view& boxes) {
    const std::size_t row = first_unaccepted(boxes);
    if (row == no_row) {
        return;
    }
    for (std::size_t r = 0; r < boxes.size(); ++r) {
        if (!detail::valid_row(boxes.kind(), boxes.floats() + boxes.stride() * r)) {
            return;
        }
    }
    const float* v = boxes.floats() + boxes.stride() * row;
    if (boxes.kind() == store_kind::poses) {
        throw invalid_input("pose " + std::to_string(row) + ": rotation (" + std::to_string(v[4]) + ", " +
                            std::to_string(v[5]) +
                            ") is too short or too long for contacts (c*c + s*s must be a normal float)");
    }
    throw invalid_input("rectangle " + std::to_string(row) +
                        ": corners are not a strictly convex quadrilateral (self-intersecting, degenerate or "
                        "with a reflex corner), which contacts do not accept");
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

/// The checks find_contacts makes before any work: the margin, the rows'
/// precision, the method on their kind, and that contacts accept every row
/// (the query checks the rows themselves). Returns the contact kernel.
detail::contact_fn checked_kernel(const box_view& boxes, const collide_options& options, const char* call) {
    const detail::contact_fn kernel = contact_kernel_of(boxes, options.use, call);
    detail::require_method_on(options, boxes.kind());
    require_accepted(boxes);
    return kernel;
}

/// The contact rows of one box set: both boxes of a pair read from `boxes`.
detail::contact_rows rows_of(detail::contact_fn kernel, const box_view& boxes, float margin) {
    return detail::contact_rows{kernel, boxes.floats(), boxes.stride(), boxes.floats(), boxes.stride(), margin};
}

/// What find_contacts with a margin keeps, kept between calls. A call that
/// finds it taken (another thread's call running) makes its own, which it
/// drops.
class kept_near_contacts {
public:
    kept_near_contacts() {
        const std::lock_guard<std::mutex> lock(mutex());
        held_ = std::move(spare());
        if (!held_) {
            held_ = std::make_unique<detail::near_contacts>();
        }
    }
    ~kept_near_contacts() {
        const std::lock_guard<std::mutex> lock(mutex());
        if (!spare()) {
            spare() = std::move(held_);
        }
    }
    kept_near_contacts(const kept_near_contacts&) = delete;
    kept_near_contacts& operator=(const kept_near_contacts&) = delete;

    detail::near_contacts& get() { return *held_; }
    /// Frees the memory kept for the next call.
    static void release() {
        std::unique_ptr<detail::near_contacts> released;
        const std::lock_guard<std::mutex> lock(mutex());
        released = std::move(spare());
    }

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    static std::unique_ptr<detail::near_contacts>& spare() {
        static std::unique_ptr<detail::near_contacts> kept;
        return kept;
    }
    std::unique_ptr<detail::near_contacts> held_;
};

/// find_contacts once its checks have passed, margin 0: the method's pairs
/// sorted straight into found.pairs, then their contacts into found.contacts.
void touching_contacts(const box_view& boxes, const collide_options& options, detail::contact_fn kernel,
                       scene_contacts& found) {
    detail::spare_search spare(options);
    detail::pair_search& search = spare.get();
    search.collect_into(search.bound_doubles(detail::input_of(boxes, nullptr)), found.pairs);
    detail::contacts_of_answer(rows_of(kernel, boxes, 0.0f), found.pairs, found.contacts, options.threads);
}

/// find_contacts once its checks have passed, with a margin: the method's
/// pairs, then the pairs of widened stand-ins (obbsat/find_contacts.hpp says
/// why they lose none), each kept when the method reported it or its contact
/// at the margin has a point.
void near_contacts_of(const box_view& boxes, const collide_options& options, detail::contact_fn kernel, float margin,
                      scene_contacts& found) {
    kept_near_contacts kept;
    detail::near_contacts& near = kept.get();
    // The method's pairs first: this query also checks every box.
    {
        detail::spare_search spare(options);
        detail::pair_search& search = spare.get();
        search.collect_into(search.bound_doubles(detail::input_of(boxes, nullptr)), near.reported);
    }
    near.stand_ins.resize(boxes.size());
    for (std::size_t i = 0; i < near.stand_ins.size(); ++i) {
        near.stand_ins[i] = stand_in_of(bounds_of_row(boxes, i), margin);
    }
    collide_options near_options = options;
    near_options.test = method::exact;
    {
        detail::spare_search spare(near_options);
        detail::pair_search& search = spare.get();
        search.collect_into(
            search.bound_doubles(detail::input_of(box_view(near.stand_ins).with_filters(boxes.filters()), nullptr)),
            near.candidates);
    }
    near.answer(rows_of(kernel, boxes, margin), options.threads, found);
}

}  // namespace

void detail::release_kept_contacts() { kept_near_contacts::release(); }

scene_contacts find_contacts(box_view boxes, const collide_options& options, float margin) {
    scene_contacts found;
    find_contacts(boxes, options, margin, found);
    return found;
}

void find_contacts(box_view boxes, const collide_options& options, float margin, scene_contacts& found) {
    if (!(margin >= 0.0f) || !std::isfinite(margin)) {
        throw invalid_input("margin must be finite and >= 0");
    }
    const detail::executor_scope scope(options.executor);
    const detail::contact_fn kernel = checked_kernel(boxes, options, "find_contacts");
    try {
        if (margin == 0.0f) {
            touching_contacts(boxes, options, kernel, found);
        } else {
            near_contacts_of(boxes, options, kernel, margin, found);
        }
    } catch (const invalid_input&) {
        throw;  // a box the query refused: found is as it was
    } catch (...) {
        // Out of memory once found may be partly written: never half an answer.
        found.pairs.clear();
        found.contacts.clear();
        throw;
    }
}

const scene_contacts& pair_finder::find_contacts(box_view boxes) {
    return frame_contacts(boxes, nullptr);
}

const scene_contacts& pair_finder::find_contacts(box_view a, box_view b) {
    return frame_contacts(a, &b);
}

const scene_contacts& pair_finder::frame_contacts(const box_view& a, const box_view* b) {
    if (!search_) {
        throw invalid_input(
            "pair_finder::find_contacts on a moved-from pair_finder: assign it a pair_finder before calling it again");
    }
    const collide_options& options = search_->options();
    const detail::executor_scope scope(options.executor);
    // Every check before the frame, so that a refused call changes nothing.
    const detail::contact_fn kernel = checked_kernel(a, options, "pair_finder::find_contacts");
    if (b != nullptr) {
        checked_kernel(*b, options, "pair_finder::find_contacts");
    }
    const std::vector<pair_index>& pairs = b == nullptr ? find(a) : find(a, *b);
    if (!contacts_) {
        contacts_ = std::make_unique<scene_contacts>();
    }
    contacts_->pairs.assign(pairs.begin(), pairs.end());
    const box_view& rows_b = b == nullptr ? a : *b;
    detail::contacts_of_answer(detail::contact_rows{kernel, a.floats(), a.stride(), rows_b.floats(), rows_b.stride(), 0.0f},
                               contacts_->pairs, contacts_->contacts, options.threads);
    return *contacts_;
}

}  // namespace obbsat
