// The pairs one thread of a scene query finds, in blocks that never move.
// A std::vector growing to millions of pairs copies them at each doubling
// and touches about twice their memory; here each pair is written once.
// Blocks grow from 512 KiB to 4 MiB, the size from which record memory
// takes huge pages: a scene of millions of pairs then takes a page fault per
// 2 MiB of them, not per 4 KiB, and the OS serves page faults one at a time
// however many threads take them. Cleared, the blocks stay for the next
// query. Internal to the library.
#pragma once

#include "sort/pair_sort.hpp"
#include "support/scratch_vector.hpp"

#include <obbsat/rect.hpp>

#include <cstddef>
#include <vector>

namespace obbsat::detail {

class pair_blocks {
public:
    /// Pairs of the first block (512 KiB), the most one room() may ask for.
    static constexpr std::size_t block_pairs = std::size_t{1} << 16;
    /// Pairs of block `b`: block_pairs, doubled at each block up to 4 MiB.
    static constexpr std::size_t pairs_of_block(std::size_t b) { return block_pairs << (b < 3 ? b : 3); }

    /// Room for `count` <= block_pairs pairs after the last ones; add() then
    /// says how many of them were written.
    pair_index* room(std::size_t count) {
        if (blocks_.empty() || used_[current_] + count > blocks_[current_].size()) {
            if (!blocks_.empty() && used_[current_] > 0) {
                ++current_;
            }
            if (current_ == blocks_.size()) {
                blocks_.emplace_back(pairs_of_block(blocks_.size()));
                used_.push_back(0);
            }
        }
        return blocks_[current_].data() + used_[current_];
    }
    /// The first `count` pairs of the last room() join the list.
    void add(std::size_t count) {
        used_[current_] += count;
        size_ += count;
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    /// Forgets the pairs and keeps the blocks.
    void clear() {
        for (std::size_t b = 0; b <= current_ && b < used_.size(); ++b) {
            used_[b] = 0;
        }
        current_ = 0;
        size_ = 0;
    }
    /// Bytes the blocks hold.
    std::size_t bytes() const {
        std::size_t sum = 0;
        for (const auto& block : blocks_) {
            sum += block.capacity() * sizeof(pair_index);
        }
        return sum;
    }
    /// The pairs in the order they were added, block by block.
    pair_source<pair_index> spans() const {
        pair_source<pair_index> out;
        for (std::size_t b = 0; b < blocks_.size() && b <= current_; ++b) {
            if (used_[b] > 0) {
                out.push_back({blocks_[b].data(), used_[b]});
            }
        }
        return out;
    }

private:
    std::vector<scratch_records<pair_index>> blocks_;  ///< block b pairs_of_block(b) long
    std::vector<std::size_t> used_;                   ///< pairs in each block
    std::size_t current_ = 0;                         ///< the block being filled; those after it are spare
    std::size_t size_ = 0;
};

}  // namespace obbsat::detail
