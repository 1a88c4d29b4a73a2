// The short form of the accuracy report for `obbsat demo`: one line per
// method and store with its error rate over every hard-case family of its
// store at a small size, its false negatives, and its speed, in well under a
// few seconds.
#pragma once

#include <obbsat/method.hpp>

#include <cstddef>
#include <cstdio>
#include <vector>

namespace obbsat::accuracy {

/// A speed the caller measured itself for a method on a store.
struct timed_method {
    method test;
    double mpairs_per_second;
    store_kind store = store_kind::corners;
};

/// Prints the short form. Every method's speed is measured here on the
/// accuracy report's throughput scene (a few runs); the speeds in `timed`,
/// from the caller's own scene, are shown beside the rows of the same method
/// and store.
void print_accuracy_brief(std::FILE* out, const std::vector<timed_method>& timed,
                          std::size_t pairs_per_family = 2000);

}  // namespace obbsat::accuracy
