// The exact oracle over a batch of candidate pairs of rects or of poses, split
// over threads. Every
// input is checked before any pair is classified, so on an error nothing is
// written.
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <cstddef>
#include <vector>

namespace obbsat::oracle {

/// out[i] = classify(rects[pairs[i].a], rects[pairs[i].b]) for i < pair_count, over
/// `threads` threads (0: all cores). Throws std::out_of_range naming the first pair
/// with an index >= rect_count, std::invalid_argument naming the first rect with a
/// non-finite coordinate.
void classify_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs,
                    std::size_t pair_count, contact* out, unsigned threads = 1);

/// The contacts of classify_pairs as a vector.
std::vector<contact> classify_pairs(const std::vector<rect>& rects,
                                    const std::vector<pair_index>& pairs, unsigned threads = 1);

/// out[i] = classify(poses[pairs[i].a], poses[pairs[i].b]) for i < pair_count, over
/// `threads` threads (0: all cores). Throws std::out_of_range naming the first pair
/// with an index >= pose_count, std::invalid_argument naming the first invalid pose.
void classify_pairs(const rect_pose* poses, std::size_t pose_count, const pair_index* pairs,
                    std::size_t pair_count, contact* out, unsigned threads = 1);

/// The contacts of classify_pairs over poses as a vector.
std::vector<contact> classify_pairs(const std::vector<rect_pose>& poses,
                                    const std::vector<pair_index>& pairs, unsigned threads = 1);

}  // namespace obbsat::oracle
