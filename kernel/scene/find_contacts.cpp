// find_contacts: the scene query with each pair's contact computed as the
// pair is found (query_contacts.hpp), and with a margin the pairs of widened
// stand-ins kept when their contacts have points (obbsat/find_contacts.hpp
// says why the stand-ins lose none); pair_finder's frames with contacts.
#include "dispatch/backend_registry.hpp"
#include "dispatch/contact_kernel_table.hpp"
#include "methods/method_check.hpp"
#include "scene/pair_search.hpp"
#include "scene/query_contacts.hpp"
#include "scene/query_input.hpp"
#include "scene/search_common.hpp"
#include "scene/spare_search.hpp"
#include "support/executor_scope.hpp"
#include "support/huge_pages.hpp"
#include "support/work_shares.hpp"

#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/ref/contact.hpp>

#include <algorithm>

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

void pair_search::collect_with_contacts(const query_input& input, query_contacts& contacts) {
    static_assert(sizeof(record) == query_contacts::record_floats * sizeof(float),
                  "the contact kernel reads the query's records with this stride");
    contacts.start(input.a_count + (input.b == nullptr ? 0 : input.b_count));
    for (part& p : parts_) {
        p.contacts.clear();
    }
    struct handed {
        query_contacts*& to;
        ~handed() { to = nullptr; }
    } const hand{contacts_};
    contacts_ = &contacts;
    run(input, pair_chunk_sink{});
    std::vector<const unit_contacts*> units(used_parts_);
    for (std::size_t i = 0; i < used_parts_; ++i) {
        units[i] = &parts_[i].contacts;
    }
    // One group per thread of the output sort, as sort_found groups the units.
    const std::size_t groups = std::max<std::size_t>(
        1, std::min(std::max<std::size_t>(used_parts_, 1), parts_for(n_, options_.threads, min_boxes_per_part)));
    contacts.sort(units, groups, self_ ? n_ : a_count_);
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

/// The sorted pairs of `contacts` that `keep(pair, contact)` accepts, each
/// with its contact, into `found`. The contacts are read in the pairs'
/// order, at random in the blocks: each is fetched a few pairs ahead.
template <class Keep>
void answer_of(const detail::query_contacts& contacts, scene_contacts& found, const Keep& keep) {
    const std::vector<detail::tagged_pair>& sorted = contacts.sorted();
    const std::size_t n = sorted.size();
    found.pairs.clear();
    found.contacts.clear();
    found.pairs.reserve(n);
    found.contacts.reserve(n);
    // Fresh memory for a large answer: in huge pages, one fault per 2 MiB.
    detail::advise_huge_pages(found.pairs.data(), n * sizeof(pair_index));
    detail::advise_huge_pages(found.contacts.data(), n * sizeof(contact));
    constexpr std::size_t ahead = 48;
    for (std::size_t k = 0; k < n; ++k) {
        if (k + ahead < n) {
            contacts.fetch(sorted[k + ahead]);
        }
        const pair_index pair{sorted[k].a, sorted[k].b};
        const contact& c = contacts.contact_of(sorted[k]);
        if (keep(pair, c)) {
            found.pairs.push_back(pair);
            found.contacts.push_back(c);
        }
    }
}

bool precedes(const pair_index& x, const pair_index& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
}

bool same_pair(const pair_index& x, const pair_index& y) {
    return x.a == y.a && x.b == y.b;
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

/// out[k] = the contact of a's row pairs[k].a and b's row pairs[k].b, split over `threads`.
void contacts_of_rows(detail::contact_fn kernel, const box_view& a, const box_view& b,
                      const std::vector<pair_index>& pairs, contact* out, unsigned threads) {
    // A contact costs a few nanoseconds; parts start on multiples of the
    // widest backend's vector.
    constexpr std::size_t min_pairs_per_part = 2048;
    constexpr std::size_t part_alignment = 64;
    const std::size_t count = pairs.size();
    const std::size_t parts = detail::parts_for(count, threads, min_pairs_per_part);
    detail::run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = detail::aligned_share_of(count, part, parts, part_alignment);
        if (begin < end) {
            kernel(a.floats(), a.stride(), b.floats(), b.stride(), pairs.data() + begin, end - begin, 0.0f,
                   out + begin);
        }
    });
}

/// The contact blocks of find_contacts, kept between calls: a query of a
/// million boxes writes some 120 MB of them, and fresh memory costs a page
/// fault per page on every call. A call that finds them taken (another
/// thread's call running) makes its own, which it drops.
class kept_contacts {
public:
    kept_contacts() {
        const std::lock_guard<std::mutex> lock(mutex());
        held_ = std::move(spare());
        if (!held_) {
            held_ = std::make_unique<detail::query_contacts>();
        }
    }
    ~kept_contacts() {
        const std::lock_guard<std::mutex> lock(mutex());
        if (!spare()) {
            spare() = std::move(held_);
        }
    }
    kept_contacts(const kept_contacts&) = delete;
    kept_contacts& operator=(const kept_contacts&) = delete;

    detail::query_contacts& get() { return *held_; }
    /// Frees the blocks kept for the next call.
    static void release() {
        std::unique_ptr<detail::query_contacts> released;
        const std::lock_guard<std::mutex> lock(mutex());
        released = std::move(spare());
    }

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    static std::unique_ptr<detail::query_contacts>& spare() {
        static std::unique_ptr<detail::query_contacts> kept;
        return kept;
    }
    std::unique_ptr<detail::query_contacts> held_;
};

}  // namespace

void detail::release_kept_contacts() { kept_contacts::release(); }

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
    kept_contacts kept;
    detail::query_contacts& contacts = kept.get();
    if (margin == 0.0f) {
        // The method's pairs, each with its contact computed on the query's
        // own records as the pair is found.
        detail::pair_search search(options);
        contacts.read_records(kernel, 0.0f);
        search.collect_with_contacts(search.bound_doubles(detail::input_of(boxes, nullptr)), contacts);
        answer_of(contacts, found, [](const pair_index&, const contact&) { return true; });
        return;
    }

    // The method's pairs first: this query also checks every box.
    const std::vector<pair_index> colliding = find_pairs(boxes, options);
    std::vector<rect_pose> stand_ins(boxes.size());
    for (std::size_t i = 0; i < stand_ins.size(); ++i) {
        stand_ins[i] = stand_in_of(bounds_of_row(boxes, i), margin);
    }
    // The candidates are the pairs of stand-ins, their contacts computed on
    // the boxes' own rows as each is found.
    collide_options near_options = options;
    near_options.test = method::exact;
    detail::pair_search search(near_options);
    contacts.read_rows(kernel, margin, boxes.floats(), boxes.stride());
    search.collect_with_contacts(
        search.bound_doubles(detail::input_of(box_view(stand_ins).with_filters(boxes.filters()), nullptr)),
        contacts);

    // Both lists are sorted; a candidate stays when the method reported it
    // or its contact has a point. Every reported pair is a candidate, as its
    // bounds overlap and the stand-ins contain them.
    std::size_t next = 0;
    answer_of(contacts, found, [&](const pair_index& candidate, const contact& c) {
        while (next < colliding.size() && precedes(colliding[next], candidate)) {
            ++next;
        }
        const bool reported = next < colliding.size() && same_pair(colliding[next], candidate);
        return reported || c.point_count > 0;
    });
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
    contacts_->contacts.resize(pairs.size());
    contacts_of_rows(kernel, a, b == nullptr ? a : *b, pairs, contacts_->contacts.data(), options.threads);
    return *contacts_;
}

}  // namespace obbsat
