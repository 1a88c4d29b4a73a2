// find_contacts: the scene query's pairs sorted into the answer, then their
// contacts on the caller's rows (query_contacts.hpp); with a margin, the
// pairs of widened stand-ins kept when their contacts have points
// (obbsat/find_contacts.hpp says why the stand-ins lose none); pair_finder's
// frames with contacts. Float rows give float contacts, double rows double
// ones (find_contacts64), by the same steps templated on the precision.
#include "dispatch/backend_registry.hpp"
#include "dispatch/contact_kernel_table.hpp"
#include "methods/method_check.hpp"
#include "scene/pair_search.hpp"
#include "scene/query_contacts.hpp"
#include "scene/query_input.hpp"
#include "scene/search_common.hpp"
#include "scene/spare_search.hpp"
#include "store/contact_acceptance.hpp"
#include "support/executor_scope.hpp"
#include "support/fetch_ahead.hpp"

#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/ref/bounds64.hpp>
#include <obbsat/ref/contact.hpp>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
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

/// The values of a view's rows in their own precision.
template <class Real>
const Real* values_of(const box_view& boxes);
template <>
const float* values_of<float>(const box_view& boxes) {
    return boxes.floats();
}
template <>
const double* values_of<double>(const box_view& boxes) {
    return boxes.doubles();
}

rect_pose pose_at(const float* v) { return rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}; }
rect_pose64 pose_at(const double* v) { return rect_pose64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}; }
rect corners_at(const float* v) { return rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}; }
rect64 corners_at(const double* v) { return rect64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}; }

/// A value as the messages show it: a float as std::to_string does, a
/// double with the digits that read back to it.
std::string shown(float value) { return std::to_string(value); }
std::string shown(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

/// Throws invalid_input unless `boxes` hold `Real` rows: a float call
/// (scene_contacts) refuses double rows and a double one float rows, so that
/// no contact is rounded on the way.
template <class Real>
void require_precision(const box_view& boxes, const char* call) {
    constexpr bool doubles = std::is_same<Real, double>::value;
    if ((boxes.precision() == precision::float64) == doubles) {
        return;
    }
    if (doubles) {
        throw invalid_input(std::string(call) +
                            ": these rows are float; their contacts are float (find_contacts, scene_contacts)");
    }
    throw invalid_input(std::string(call) +
                        ": these rows are double, whose contacts are double: find_contacts64 (a scene_contacts64) "
                        "computes them without rounding");
}

/// The first row of `boxes` that contacts do not accept (obbsat/contact.hpp),
/// or no_row. One branch-free pass over poses when all are accepted.
template <class Real>
std::size_t first_unaccepted(const box_view& boxes) {
    const Real* v = values_of<Real>(boxes);
    const std::size_t stride = boxes.stride();
    if (boxes.kind() == store_kind::poses && detail::poses_all_accepted(v, stride, boxes.size())) {
        return no_row;
    }
    for (std::size_t row = 0; row < boxes.size(); ++row) {
        const Real* r = v + stride * row;
        const bool accepted = boxes.kind() == store_kind::poses ? ref::pose_accepted(pose_at(r))
                                                                : ref::corners_accepted(corners_at(r));
        if (!accepted) {
            return row;
        }
    }
    return no_row;
}

/// Throws invalid_input, as contact_pairs does, for the first row of `boxes`
/// that contacts do not accept, unless some row is not a valid box at all:
/// the query then refuses that one first (as when find_pairs ran first).
template <class Real>
void require_accepted(const box_view& boxes) {
    const std::size_t row = first_unaccepted<Real>(boxes);
    if (row == no_row) {
        return;
    }
    const Real* values = values_of<Real>(boxes);
    for (std::size_t r = 0; r < boxes.size(); ++r) {
        if (!detail::valid_row(boxes.kind(), values + boxes.stride() * r)) {
            return;
        }
    }
    const Real* v = values + boxes.stride() * row;
    if (boxes.kind() == store_kind::poses) {
        throw invalid_input("pose " + std::to_string(row) + ": rotation (" + shown(v[4]) + ", " + shown(v[5]) +
                            ") is too short or too long for contacts (c*c + s*s must be a normal " +
                            (std::is_same<Real, double>::value ? "double" : "float") + ")");
    }
    throw invalid_input("rectangle " + std::to_string(row) +
                        ": corners are not a strictly convex quadrilateral (self-intersecting, degenerate or "
                        "with a reflex corner), which contacts do not accept");
}

/// The float bounds of row `row` of a view whose rows were checked (by the
/// query that ran first), whatever their store and precision: for double
/// rows their double bounds rounded outward (obbsat/ref/bounds64.hpp).
ref::box_bounds bounds_of_row(const box_view& boxes, std::size_t row) {
    if (boxes.precision() == precision::float64) {
        const double* v = boxes.doubles() + row * boxes.stride();
        return boxes.kind() == store_kind::poses ? ref::bounds_of(pose_at(v)) : ref::bounds_of(corners_at(v));
    }
    const float* v = boxes.floats() + row * boxes.stride();
    return boxes.kind() == store_kind::poses ? ref::bounds_of(pose_at(v)) : ref::bounds_of(corners_at(v));
}

/// An axis-aligned pose that contains [lo - margin, hi + margin] on one axis
/// pair. Computed in double and rounded outward by a float ulp of the
/// larger of the center and the half extent, so it holds the widened bounds
/// despite its own rounding; a half extent beyond float range is the
/// largest float (the pose then reaches every box it could pair with).
rect_pose stand_in_of(const ref::box_bounds& b, double margin) {
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

/// The contact kernel of `boxes`' kind and precision in `table`: for double
/// poses whose `rows_read` records L2 holds, the one that fetches nothing
/// ahead (as contact_pairs chooses; the bits are the same).
detail::contact_fn contact_kernel_of(const detail::contact_kernel_table& table, const box_view& boxes, std::size_t,
                                     float) {
    return boxes.kind() == store_kind::poses ? table.poses : table.corners;
}
detail::contact64_fn contact_kernel_of(const detail::contact_kernel_table& table, const box_view& boxes,
                                       std::size_t rows_read, double) {
    if (boxes.kind() == store_kind::corners) {
        return table.corners64;
    }
    const bool in_l2 = rows_read * 8 * sizeof(double) <= detail::store_bytes_in_l2;
    return in_l2 ? table.poses64_in_l2 : table.poses64;
}

/// The checks find_contacts makes before any work: the rows' precision and
/// the method on their kind (the query checks the rows themselves, and
/// kernel_rows_of or require_accepted that contacts accept every one).
/// Returns the contact kernel.
template <class Real>
typename detail::contact_types<Real>::kernel checked_kernel(const box_view& boxes, const collide_options& options,
                                                            const char* call, std::size_t rows_read) {
    require_precision<Real>(boxes, call);
    const detail::contact_kernel_table& table = detail::contact_kernels_for(resolve_backend(options.use));
    if constexpr (std::is_same<Real, double>::value) {
        detail::require_method_on_double_rows(options, boxes.kind());
    } else {
        detail::require_method_on(options, boxes.kind());
    }
    return contact_kernel_of(table, boxes, rows_read, Real(0));
}

/// The rows of one box set as the contact kernels read them.
template <class Real>
struct kernel_rows {
    const Real* values;
    std::size_t stride;  ///< in values
};

/// Whether kernel_rows_of is still to check that contacts accept every row
/// (require_accepted), or a check before it did.
enum class acceptance { to_check, checked };

/// The rows of `boxes` as the contact kernels read them: float rows and
/// 8-double records in place; rect_pose64 rows (six doubles) copied into
/// `records` (the double kernels read whole records only). Called after the
/// query, so that the cache still holds the last records when the kernel
/// starts (copied before the query instead, the contacts of 1M boxes took
/// some 3 ms more), and the rows checked as they are copied rather than in a
/// pass of their own. Throws invalid_input for a row contacts refuse when
/// `check` is to_check.
template <class Real>
kernel_rows<Real> kernel_rows_of(const box_view& boxes, detail::double_pose_records* records, unsigned threads,
                                 acceptance check) {
    bool accepted = check == acceptance::checked;
    kernel_rows<Real> rows{values_of<Real>(boxes), boxes.stride()};
    if constexpr (std::is_same<Real, double>::value) {
        if (boxes.stride() != 8 && boxes.size() != 0) {
            accepted |= records->copy_accepted(boxes.doubles(), boxes.size(), threads);
            rows = {records->data(), 8};
        }
    }
    if (!accepted) {
        require_accepted<Real>(boxes);
    }
    return rows;
}

/// The contact rows of a pair's sets a and b (the same set within one).
template <class Real>
detail::contact_rows_of<Real> contact_rows_for(typename detail::contact_types<Real>::kernel kernel,
                                               const kernel_rows<Real>& a, const kernel_rows<Real>& b, Real margin) {
    return detail::contact_rows_of<Real>{kernel, a.values, a.stride, b.values, b.stride, margin};
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
    /// Bytes of double pose records kept for the next call.
    static std::size_t record_bytes() {
        const std::lock_guard<std::mutex> lock(mutex());
        return spare() ? spare()->records64.bytes() : 0;
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
/// sorted straight into near.reported, which becomes found.pairs once
/// contacts are found to accept every row (found is as it was until then),
/// then their contacts into found.contacts. found.pairs' old memory is kept
/// as near.reported for the next call: an answer kept by the caller between
/// calls and this one take turns, and neither takes fresh pages.
template <class Real, class Found>
void touching_contacts(const box_view& boxes, const collide_options& options,
                       typename detail::contact_types<Real>::kernel kernel, detail::near_contacts& near,
                       Found& found) {
    {
        detail::spare_search spare(options);
        detail::pair_search& search = spare.get();
        search.collect_into(search.bound_doubles(detail::input_of(boxes, nullptr)), near.reported);
    }
    const kernel_rows<Real> rows = kernel_rows_of<Real>(boxes, &near.records64, options.threads, acceptance::to_check);
    found.pairs.swap(near.reported);
    detail::contacts_of_answer(contact_rows_for(kernel, rows, rows, Real(0)), found.pairs, found.contacts,
                               options.threads);
}

/// find_contacts once its checks have passed, with a margin: the method's
/// pairs, then the pairs of widened stand-ins (obbsat/find_contacts.hpp says
/// why they lose none), each kept when the method reported it or its contact
/// at the margin has a point.
template <class Real, class Found>
void near_contacts_of(const box_view& boxes, const collide_options& options,
                      typename detail::contact_types<Real>::kernel kernel, Real margin, detail::near_contacts& near,
                      Found& found) {
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
    const kernel_rows<Real> rows = kernel_rows_of<Real>(boxes, &near.records64, options.threads, acceptance::to_check);
    near.answer(contact_rows_for(kernel, rows, rows, margin), options.threads, found);
}

/// find_contacts into `found` on `Real` rows (scene_contacts or scene_contacts64).
template <class Real, class Found>
void find_contacts_into(const box_view& boxes, const collide_options& options, Real margin, Found& found,
                        const char* call) {
    if (!(margin >= Real(0)) || !std::isfinite(margin)) {
        throw invalid_input(std::string(call) + ": margin is " + shown(margin) + ": it must be finite and >= 0");
    }
    const detail::executor_scope scope(options.executor);
    const auto kernel = checked_kernel<Real>(boxes, options, call, boxes.size());
    kept_near_contacts kept;
    try {
        if (margin == Real(0)) {
            touching_contacts<Real>(boxes, options, kernel, kept.get(), found);
        } else {
            near_contacts_of<Real>(boxes, options, kernel, margin, kept.get(), found);
        }
    } catch (const invalid_input&) {
        throw;  // a box the query or contacts refused: found is as it was
    } catch (...) {
        // Out of memory once found may be partly written: never half an answer.
        found.pairs.clear();
        found.contacts.clear();
        throw;
    }
}

/// A pair_finder frame with contacts on `Real` rows into `answer`: every
/// check first (so that a refused call changes nothing), then the frame's
/// pairs, then their contacts on this frame's rows. `records_a` and
/// `records_b` hold rect_pose64 rows as records (unused for float rows).
template <class Real, class Found>
void frame_contacts_of(pair_finder& finder, const collide_options& options, const box_view& a, const box_view* b,
                       const char* call, detail::double_pose_records* records_a,
                       detail::double_pose_records* records_b, Found& answer) {
    const detail::executor_scope scope(options.executor);
    const std::size_t rows_read = a.size() + (b == nullptr ? 0 : b->size());
    const auto kernel = checked_kernel<Real>(a, options, call, rows_read);
    require_accepted<Real>(a);
    if (b != nullptr) {
        checked_kernel<Real>(*b, options, call, rows_read);
        require_accepted<Real>(*b);
    }
    const std::vector<pair_index>& pairs = b == nullptr ? finder.find(a) : finder.find(a, *b);
    answer.pairs.assign(pairs.begin(), pairs.end());
    const kernel_rows<Real> rows_a = kernel_rows_of<Real>(a, records_a, options.threads, acceptance::checked);
    const kernel_rows<Real> rows_b =
        b == nullptr ? rows_a : kernel_rows_of<Real>(*b, records_b, options.threads, acceptance::checked);
    detail::contacts_of_answer(contact_rows_for(kernel, rows_a, rows_b, Real(0)), answer.pairs, answer.contacts,
                               options.threads);
}

}  // namespace

void detail::release_kept_contacts() { kept_near_contacts::release(); }

std::size_t detail::kept_contacts_record_bytes() { return kept_near_contacts::record_bytes(); }

scene_contacts find_contacts(box_view boxes, const collide_options& options, float margin) {
    scene_contacts found;
    find_contacts(boxes, options, margin, found);
    return found;
}

void find_contacts(box_view boxes, const collide_options& options, float margin, scene_contacts& found) {
    find_contacts_into(boxes, options, margin, found, "find_contacts");
}

scene_contacts64 find_contacts64(box_view boxes, const collide_options& options, double margin) {
    scene_contacts64 found;
    find_contacts_into(boxes, options, margin, found, "find_contacts64");
    return found;
}

void find_contacts(box_view boxes, const collide_options& options, double margin, scene_contacts64& found) {
    find_contacts_into(boxes, options, margin, found, "find_contacts64");
}

const scene_contacts& pair_finder::find_contacts(box_view boxes) {
    return frame_contacts(boxes, nullptr);
}

const scene_contacts& pair_finder::find_contacts(box_view a, box_view b) {
    return frame_contacts(a, &b);
}

const scene_contacts64& pair_finder::find_contacts64(box_view boxes) {
    return frame_contacts64(boxes, nullptr);
}

const scene_contacts64& pair_finder::find_contacts64(box_view a, box_view b) {
    return frame_contacts64(a, &b);
}

const scene_contacts& pair_finder::frame_contacts(const box_view& a, const box_view* b) {
    if (!search_) {
        throw invalid_input(
            "pair_finder::find_contacts on a moved-from pair_finder: assign it a pair_finder before calling it again");
    }
    if (!contacts_) {
        contacts_ = std::make_unique<scene_contacts>();
    }
    frame_contacts_of<float>(*this, search_->options(), a, b, "pair_finder::find_contacts", nullptr, nullptr,
                             *contacts_);
    return *contacts_;
}

const scene_contacts64& pair_finder::frame_contacts64(const box_view& a, const box_view* b) {
    if (!search_) {
        throw invalid_input(
            "pair_finder::find_contacts64 on a moved-from pair_finder: assign it a pair_finder before calling it "
            "again");
    }
    if (!contacts64_) {
        contacts64_ = std::make_unique<detail::frame_contacts64>();
    }
    detail::frame_contacts64& frame = *contacts64_;
    frame_contacts_of<double>(*this, search_->options(), a, b, "pair_finder::find_contacts64", &frame.a_records,
                              &frame.b_records, frame.answer);
    return frame.answer;
}

}  // namespace obbsat
