#include "scene/pair_events.hpp"

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

namespace {

/// The order of the answers: by a, then b.
std::uint64_t key_of(const pair_index& p) { return (std::uint64_t{p.a} << 32) | p.b; }

}  // namespace

void pair_events::update(const std::vector<pair_index>& answer, bool cross) {
    began_.clear();
    ended_.clear();
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
}

}  // namespace obbsat::detail
