#include "pair_search.hpp"

#include <obbsat/find_pairs.hpp>

namespace obbsat {

namespace {

detail::query_input input_of(const pose_records& a, const pose_records* b) {
    detail::query_input in;
    in.kind = store_kind::poses;
    in.a = a.data();
    in.a_count = a.size();
    if (b != nullptr) {
        in.b = b->data();
        in.b_count = b->size();
    }
    return in;
}

const float* floats_of(const rect_records& r) {
    return r.empty() ? nullptr : &r.data()->ul.x;
}

detail::query_input input_of(const rect_records& a, const rect_records* b) {
    detail::query_input in;
    in.kind = store_kind::corners;
    in.a = floats_of(a);
    in.a_count = a.size();
    if (b != nullptr) {
        in.b = floats_of(*b);
        in.b_count = b->size();
    }
    return in;
}

/// An empty store's data() may be nullptr, but a second store's records
/// pointer must not be: nullptr there means "a query within the first store".
detail::query_input with_nonnull_a(detail::query_input in, bool cross) {
    static const float none[8] = {};
    if (in.a == nullptr) {
        in.a = none;
    }
    if (cross && in.b == nullptr) {
        in.b = none;
    }
    return in;
}

std::vector<pair_index> collected(const detail::query_input& in, bool cross, const collide_options& options) {
    detail::pair_search search(options);
    return search.collect_once(with_nonnull_a(in, cross));
}

void streamed(const detail::query_input& in, bool cross, const collide_options& options,
              const pair_chunk_sink& sink) {
    detail::pair_search search(options);
    search.run(with_nonnull_a(in, cross), sink);
}

}  // namespace

std::vector<pair_index> find_pairs(const pose_records& boxes, const collide_options& options) {
    return collected(input_of(boxes, nullptr), false, options);
}

std::vector<pair_index> find_pairs(const pose_records& a, const pose_records& b, const collide_options& options) {
    return collected(input_of(a, &b), true, options);
}

std::vector<pair_index> find_pairs(const rect_records& boxes, const collide_options& options) {
    return collected(input_of(boxes, nullptr), false, options);
}

std::vector<pair_index> find_pairs(const rect_records& a, const rect_records& b, const collide_options& options) {
    return collected(input_of(a, &b), true, options);
}

void find_pairs_each(const pose_records& boxes, const collide_options& options, const pair_chunk_sink& sink) {
    streamed(input_of(boxes, nullptr), false, options, sink);
}

void find_pairs_each(const pose_records& a, const pose_records& b, const collide_options& options,
                     const pair_chunk_sink& sink) {
    streamed(input_of(a, &b), true, options, sink);
}

void find_pairs_each(const rect_records& boxes, const collide_options& options, const pair_chunk_sink& sink) {
    streamed(input_of(boxes, nullptr), false, options, sink);
}

void find_pairs_each(const rect_records& a, const rect_records& b, const collide_options& options,
                     const pair_chunk_sink& sink) {
    streamed(input_of(a, &b), true, options, sink);
}

pair_finder::pair_finder(const collide_options& options)
    : search_(std::make_unique<detail::pair_search>(options)) {}

pair_finder::~pair_finder() = default;
pair_finder::pair_finder(pair_finder&&) noexcept = default;
pair_finder& pair_finder::operator=(pair_finder&&) noexcept = default;

const std::vector<pair_index>& pair_finder::find(const pose_records& boxes) {
    return search_->collect(with_nonnull_a(input_of(boxes, nullptr), false));
}

const std::vector<pair_index>& pair_finder::find(const pose_records& a, const pose_records& b) {
    return search_->collect(with_nonnull_a(input_of(a, &b), true));
}

const std::vector<pair_index>& pair_finder::find(const rect_records& boxes) {
    return search_->collect(with_nonnull_a(input_of(boxes, nullptr), false));
}

const std::vector<pair_index>& pair_finder::find(const rect_records& a, const rect_records& b) {
    return search_->collect(with_nonnull_a(input_of(a, &b), true));
}

const find_pairs_stats& pair_finder::stats() const { return search_->stats(); }

}  // namespace obbsat
