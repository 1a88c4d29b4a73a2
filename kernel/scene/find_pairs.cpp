#include "scene/pair_events.hpp"
#include "scene/pair_search.hpp"
#include "scene/query_contacts.hpp"
#include "scene/spare_search.hpp"
#include "support/executor_scope.hpp"

#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>

#include <string>

namespace obbsat {

static_assert(sizeof(rect_pose) == 6 * sizeof(float), "a rect_pose row is cx, cy, hx, hy, c, s");
static_assert(sizeof(rect) == 8 * sizeof(float), "a rect row is eight coordinates");

box_view::box_view(const pose_records& poses)
    : data_(poses.data()), count_(poses.size()), stride_(pose_records::record_floats), kind_(store_kind::poses),
      checked_(true) {}

box_view::box_view(const rect_records& rects)
    : data_(rects.empty() ? nullptr : &rects.data()->ul.x), count_(rects.size()), stride_(8),
      kind_(store_kind::corners), checked_(true) {}

box_view::box_view(const rect_pose* poses, std::size_t count)
    : data_(count == 0 ? nullptr : &poses->center.x), count_(count), stride_(6), kind_(store_kind::poses),
      checked_(false) {}

box_view::box_view(const rect* rects, std::size_t count)
    : data_(count == 0 ? nullptr : &rects->ul.x), count_(count), stride_(8), kind_(store_kind::corners),
      checked_(false) {}

box_view::box_view(const std::vector<rect_pose>& poses) : box_view(poses.data(), poses.size()) {}

box_view::box_view(const std::vector<rect>& rects) : box_view(rects.data(), rects.size()) {}

box_view box_view::with_ids(const std::uint64_t* ids, std::size_t count) const {
    if (count != count_) {
        throw invalid_input("box_view::with_ids: " + std::to_string(count) + " ids for " + std::to_string(count_) +
                            " rows; give one id per row");
    }
    if (ids == nullptr && count != 0) {
        throw invalid_input("box_view::with_ids: ids is nullptr for " + std::to_string(count) + " rows");
    }
    box_view view = *this;
    view.ids_ = ids;
    view.has_ids_ = true;
    return view;
}

box_view box_view::with_ids(const std::vector<std::uint64_t>& ids) const { return with_ids(ids.data(), ids.size()); }

static_assert(sizeof(rect_pose64) == 6 * sizeof(double), "a rect_pose64 row is cx, cy, hx, hy, c, s");
static_assert(sizeof(rect64) == 8 * sizeof(double), "a rect64 row is eight coordinates");

box_view::box_view(const pose_records64& poses)
    : data_(poses.data()), count_(poses.size()), stride_(pose_records64::record_doubles), kind_(store_kind::poses),
      precision_(precision::float64), checked_(true) {}

box_view::box_view(const rect_records64& rects)
    : data_(rects.empty() ? nullptr : &rects.data()->ul.x), count_(rects.size()), stride_(8),
      kind_(store_kind::corners), precision_(precision::float64), checked_(true) {}

box_view::box_view(const rect_pose64* poses, std::size_t count)
    : data_(count == 0 ? nullptr : &poses->center.x), count_(count), stride_(6), kind_(store_kind::poses),
      precision_(precision::float64), checked_(false) {}

box_view::box_view(const rect64* rects, std::size_t count)
    : data_(count == 0 ? nullptr : &rects->ul.x), count_(count), stride_(8), kind_(store_kind::corners),
      precision_(precision::float64), checked_(false) {}

box_view::box_view(const std::vector<rect_pose64>& poses) : box_view(poses.data(), poses.size()) {}

box_view::box_view(const std::vector<rect64>& rects) : box_view(rects.data(), rects.size()) {}

/// The query over `a`, and `b` when it is not nullptr. An empty set's
/// pointer may be nullptr, but the second set's must not be: nullptr there
/// means "a query within the first set". The rows' ids are taken only `with_ids`
/// (a pair_finder's calls); a query across two sets takes them from both or neither.
detail::query_input detail::input_of(const box_view& a, const box_view* b, bool with_ids) {
    static const float none[8] = {};
    static const double none64[8] = {};
    const bool doubles = a.precision() == precision::float64;
    detail::query_input in;
    in.kind = a.kind();
    in.doubles = doubles;
    in.double_kind = a.kind();
    // The float rows of a double query are made later (pair_search::bound_doubles).
    in.a = a.floats() != nullptr ? a.floats() : none;
    in.a_count = a.size();
    in.a_stride = doubles ? 8 : a.stride();
    in.a_checked = a.checked();
    in.a_filters = a.filters();
    if (doubles) {
        in.a64 = a.doubles() != nullptr ? a.doubles() : none64;
        in.a64_stride = a.stride();
        in.a64_checked = a.checked();
    }
    if (b != nullptr) {
        if (b->kind() != a.kind() || b->precision() != a.precision()) {
            const auto name = [](const box_view& v) {
                return std::string(v.precision() == precision::float64 ? "double " : "float ") +
                       (v.kind() == store_kind::poses ? "poses" : "corners");
            };
            throw invalid_input("a scene query compares one kind and precision of rectangle: a holds " + name(a) +
                                ", b holds " + name(*b));
        }
        in.b = b->floats() != nullptr ? b->floats() : none;
        in.b_count = b->size();
        in.b_stride = doubles ? 8 : b->stride();
        in.b_checked = b->checked();
        in.b_filters = b->filters();
        if (doubles) {
            in.b64 = b->doubles() != nullptr ? b->doubles() : none64;
            in.b64_stride = b->stride();
            in.b64_checked = b->checked();
        }
    }
    if (with_ids && (a.has_ids() || (b != nullptr && b->has_ids()))) {
        if (b != nullptr && a.has_ids() != b->has_ids()) {
            throw invalid_input(std::string("pair_finder::find: ") + (a.has_ids() ? "a" : "b") +
                                " has ids and " + (a.has_ids() ? "b" : "a") +
                                " has none; a query across two sets takes ids for both or for neither");
        }
        static const std::uint64_t no_ids[1] = {};
        in.with_ids = true;
        in.a_ids = a.ids() != nullptr ? a.ids() : no_ids;
        in.b_ids = b == nullptr ? nullptr : (b->ids() != nullptr ? b->ids() : no_ids);
    }
    return in;
}

using detail::input_of;

namespace {

/// The sorted pairs of `input`, a query in the working memory of `spare`.
/// collect_once frees what the query reads no more before the sort, so that
/// a query whose memory is not kept peaks lower: a double query's float
/// stand-ins of its rows as soon as its order is made. A double query whose
/// memory is kept sorts into its answer with the stand-ins' memory kept too,
/// which the next double query writes over instead of taking fresh pages
/// (32 MB on 1M rows, which the OS clears on every call).
std::vector<pair_index> spare_pairs(detail::spare_search& spare, const detail::query_input& input) {
    detail::pair_search& search = spare.get();
    const std::size_t rows = input.a_count + (input.b == nullptr ? 0 : input.b_count);
    if (input.doubles && detail::double_query_kept(rows)) {
        std::vector<pair_index> pairs;
        search.collect_into(input, pairs);
        return pairs;
    }
    return search.collect_once(input);
}

}  // namespace

std::vector<pair_index> find_pairs(box_view boxes, const collide_options& options) {
    const detail::executor_scope scope(options.executor);
    detail::spare_search spare(options);
    return spare_pairs(spare, spare.get().bound_doubles(input_of(boxes, nullptr)));
}

std::vector<pair_index> find_pairs(box_view a, box_view b, const collide_options& options) {
    const detail::executor_scope scope(options.executor);
    detail::spare_search spare(options);
    return spare_pairs(spare, spare.get().bound_doubles(input_of(a, &b)));
}

void find_pairs(box_view boxes, const collide_options& options, std::vector<pair_index>& out) {
    const detail::executor_scope scope(options.executor);
    detail::spare_search spare(options);
    detail::pair_search& search = spare.get();
    search.collect_into(search.bound_doubles(input_of(boxes, nullptr)), out);
}

void find_pairs(box_view a, box_view b, const collide_options& options, std::vector<pair_index>& out) {
    const detail::executor_scope scope(options.executor);
    detail::spare_search spare(options);
    detail::pair_search& search = spare.get();
    search.collect_into(search.bound_doubles(input_of(a, &b)), out);
}

void find_pairs_each(box_view boxes, const collide_options& options, const pair_chunk_sink& sink) {
    const detail::executor_scope scope(options.executor);
    detail::spare_search spare(options);
    detail::pair_search& search = spare.get();
    search.run(search.bound_doubles(input_of(boxes, nullptr)), sink);
}

void find_pairs_each(box_view a, box_view b, const collide_options& options, const pair_chunk_sink& sink) {
    const detail::executor_scope scope(options.executor);
    detail::spare_search spare(options);
    detail::pair_search& search = spare.get();
    search.run(search.bound_doubles(input_of(a, &b)), sink);
}

void release_scratch() {
    detail::release_spare_search();
    detail::release_kept_contacts();
}

pair_finder::pair_finder(const collide_options& options)
    : search_(std::make_unique<detail::pair_search>(options)) {}

pair_finder::~pair_finder() = default;
pair_finder::pair_finder(pair_finder&&) noexcept = default;
pair_finder& pair_finder::operator=(pair_finder&&) noexcept = default;

namespace {

/// The engine of a pair_finder; a moved-from one has none (find_pairs.hpp).
detail::pair_search& engine_of(const std::unique_ptr<detail::pair_search>& search, const char* call) {
    if (!search) {
        throw invalid_input(std::string("pair_finder::") + call +
                            " on a moved-from pair_finder: assign it a pair_finder before calling it again");
    }
    return *search;
}

}  // namespace

const std::vector<pair_index>& pair_finder::find(box_view boxes) {
    detail::pair_search& search = engine_of(search_, "find");
    const detail::executor_scope scope(search.caller_executor());
    const detail::query_input input = search.bound_doubles(input_of(boxes, nullptr, true));
    const std::vector<pair_index>& found = search.collect(input);
    if (events_) {
        events_->update(found, false, input.with_ids ? input.a_ids : nullptr, nullptr, input.a_count, 0);
    }
    return found;
}

const std::vector<pair_index>& pair_finder::find(box_view a, box_view b) {
    detail::pair_search& search = engine_of(search_, "find");
    const detail::executor_scope scope(search.caller_executor());
    const detail::query_input input = search.bound_doubles(input_of(a, &b, true));
    const std::vector<pair_index>& found = search.collect(input);
    if (events_) {
        events_->update(found, true, input.with_ids ? input.a_ids : nullptr, input.with_ids ? input.b_ids : nullptr,
                        input.a_count, input.b_count);
    }
    return found;
}

const find_pairs_stats& pair_finder::stats() const { return engine_of(search_, "stats").stats(); }

void pair_finder::track_events(bool on) {
    engine_of(search_, "track_events");
    if (!on) {
        events_.reset();
    } else if (!events_) {
        events_ = std::make_unique<detail::pair_events>();
    }
}

bool pair_finder::tracks_events() const { return events_ != nullptr; }

namespace {

/// The events of a pair_finder, or invalid_input saying why there are none.
const detail::pair_events& events_of(const std::unique_ptr<detail::pair_search>& search,
                                     const std::unique_ptr<detail::pair_events>& events, const char* call) {
    engine_of(search, call);
    if (!events) {
        throw invalid_input(std::string("pair_finder::") + call +
                            ": begin/end events are off; call track_events(true) before the calls to compare");
    }
    return *events;
}

}  // namespace

namespace {

/// Row pairs of events, or invalid_input when the last call's rows carried ids.
const std::vector<pair_index>& row_events(const detail::pair_events& events, bool began, const char* call) {
    if (events.by_id()) {
        throw invalid_input(std::string("pair_finder::") + call +
                            ": the last call's rows carried ids, so its events are id pairs; read " + call + "_ids()");
    }
    return began ? events.began() : events.ended();
}

/// Id pairs of events, or invalid_input when the last call's rows carried none.
const std::vector<id_pair>& id_events(const detail::pair_events& events, bool began, const char* call) {
    if (!events.by_id() && events.has_last()) {
        throw invalid_input(std::string("pair_finder::") + call +
                            ": the last call's rows carried no ids, so its events are row pairs; read " +
                            (began ? "began()" : "ended()"));
    }
    return began ? events.began_ids() : events.ended_ids();
}

}  // namespace

const std::vector<pair_index>& pair_finder::began() const {
    return row_events(events_of(search_, events_, "began"), true, "began");
}

const std::vector<pair_index>& pair_finder::ended() const {
    return row_events(events_of(search_, events_, "ended"), false, "ended");
}

const std::vector<id_pair>& pair_finder::began_ids() const {
    return id_events(events_of(search_, events_, "began_ids"), true, "began_ids");
}

const std::vector<id_pair>& pair_finder::ended_ids() const {
    return id_events(events_of(search_, events_, "ended_ids"), false, "ended_ids");
}

}  // namespace obbsat
