#include "scene/pair_events.hpp"

#include "scene/out_of_order.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

namespace {

/// The order of the answers: by a, then b.
std::uint64_t key_of(const pair_index& p) { return (std::uint64_t{p.a} << 32) | p.b; }

bool id_less(const id_pair& x, const id_pair& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

}  // namespace

void pair_events::read_by_id(const std::vector<pair_index>& answer, bool cross, const std::uint64_t* a_ids,
                             const std::uint64_t* b_ids, std::size_t a_count, std::size_t b_count,
                             std::vector<id_pair>& out) {
    // The pairs of rows in increasing id order keep the answer's order when
    // read as ids; the others are sorted apart and merged in.
    const std::uint64_t* const second_ids = cross ? b_ids : a_ids;
    mark_out_of_order(a_ids, a_count, false, std::uint64_t{0}, a_out_of_order_);
    if (cross) {
        mark_out_of_order(b_ids, b_count, false, std::uint64_t{0}, b_out_of_order_);
    }
    const std::uint8_t* const first_marks = a_out_of_order_.data();
    const std::uint8_t* const second_marks = cross ? b_out_of_order_.data() : a_out_of_order_.data();
    unsorted_ids_.clear();
    out.resize(answer.size());
    std::size_t in_order = 0;
    for (const pair_index& p : answer) {
        std::uint64_t x = a_ids[p.a];
        std::uint64_t y = second_ids[p.b];
        if ((first_marks[p.a] | second_marks[p.b]) == 0) {
            out[in_order++] = id_pair{x, y};
        } else {
            if (!cross && x > y) {
                std::swap(x, y);
            }
            unsorted_ids_.push_back(id_pair{x, y});
        }
    }
    std::sort(unsorted_ids_.begin(), unsorted_ids_.end(), id_less);
    // Merged from the back, in place: out holds the in-order pairs at its front.
    std::size_t i = in_order;
    std::size_t j = unsorted_ids_.size();
    std::size_t w = answer.size();
    while (j > 0) {
        if (i > 0 && id_less(unsorted_ids_[j - 1], out[i - 1])) {
            out[--w] = out[--i];
        } else {
            out[--w] = unsorted_ids_[--j];
        }
    }
}

void pair_events::update_by_id(const std::vector<pair_index>& answer, bool cross, const std::uint64_t* a_ids,
                               const std::uint64_t* b_ids, std::size_t a_count, std::size_t b_count) {
    began_ids_.clear();
    ended_ids_.clear();
    read_by_id(answer, cross, a_ids, b_ids, a_count, b_count, spare_ids_);
    if (!has_last_ || cross != last_cross_ || !last_by_id_) {
        // Nothing to match against: every pair begins (and across a change
        // of the kind of query, every pair of the last ends).
        if (has_last_ && last_by_id_) {
            ended_ids_.assign(last_ids_.begin(), last_ids_.end());
        }
        began_ids_.assign(spare_ids_.begin(), spare_ids_.end());
    } else {
        std::size_t i = 0, j = 0;
        const std::size_t now_count = spare_ids_.size();
        const std::size_t before_count = last_ids_.size();
        while (i < now_count && j < before_count) {
            const id_pair& x = spare_ids_[i];
            const id_pair& y = last_ids_[j];
            if (x == y) {
                ++i;
                ++j;
            } else if (id_less(x, y)) {
                began_ids_.push_back(x);
                ++i;
            } else {
                ended_ids_.push_back(y);
                ++j;
            }
        }
        began_ids_.insert(began_ids_.end(), spare_ids_.begin() + static_cast<std::ptrdiff_t>(i), spare_ids_.end());
        ended_ids_.insert(ended_ids_.end(), last_ids_.begin() + static_cast<std::ptrdiff_t>(j), last_ids_.end());
    }
    last_ids_.swap(spare_ids_);
    began_.clear();
    ended_.clear();
    last_.clear();
    has_last_ = true;
    last_cross_ = cross;
    last_by_id_ = true;
}

void pair_events::update(const std::vector<pair_index>& answer, bool cross, const std::uint64_t* a_ids,
                         const std::uint64_t* b_ids, std::size_t a_count, std::size_t b_count) {
    if (a_ids != nullptr) {
        update_by_id(answer, cross, a_ids, b_ids, a_count, b_count);
        return;
    }
    began_.clear();
    ended_.clear();
    began_ids_.clear();
    ended_ids_.clear();
    if (has_last_ && last_by_id_) {
        // A call without ids after one with: the events start anew.
        has_last_ = false;
        last_.clear();
    }
    if (!has_last_ || cross != last_cross_) {
        // Nothing to match against: everything of the last answer ends, all of this one begins.
        ended_.assign(last_.begin(), last_.end());
        began_.assign(answer.begin(), answer.end());
        last_.assign(answer.begin(), answer.end());
    } else {
        // One merge of two sorted lists; this answer is copied into spare_ on the way.
        spare_.resize(answer.size());
        const pair_index* now = answer.data();
        const pair_index* before = last_.data();
        const std::size_t now_count = answer.size();
        const std::size_t before_count = last_.size();
        pair_index* copy = spare_.data();
        std::size_t i = 0, j = 0;
        while (i < now_count && j < before_count) {
            const std::uint64_t x = key_of(now[i]);
            const std::uint64_t y = key_of(before[j]);
            if (x == y) {
                copy[i] = now[i];
                ++i;
                ++j;
            } else if (x < y) {
                copy[i] = now[i];
                began_.push_back(now[i]);
                ++i;
            } else {
                ended_.push_back(before[j]);
                ++j;
            }
        }
        for (; i < now_count; ++i) {
            copy[i] = now[i];
            began_.push_back(now[i]);
        }
        ended_.insert(ended_.end(), before + j, before + before_count);
        last_.swap(spare_);
    }
    has_last_ = true;
    last_cross_ = cross;
    last_by_id_ = false;
}

}  // namespace obbsat::detail
