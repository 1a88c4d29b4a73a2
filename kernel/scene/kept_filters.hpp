// The pair filters pair_finder's kept candidates were built with
// (kept_pairs.hpp). The sweep drops a filtered pair before it is kept, so
// the kept candidates hold only pairs that the filters of the full query
// that kept them let through: they serve a later call only if its filters
// are those, value for value. Each call with kept candidates compares its
// filters with a copy of those (20 bytes per rectangle at most, read in
// order), and a change, or filters given or taken away, makes the call a
// full query that keeps anew. Keeping the candidates unfiltered instead would
// keep and refresh pairs that no call reports (a compound body's own pairs,
// which always overlap) and gather every rectangle's filters on each call.
// Internal to the library.
#pragma once

#include "scene/query_input.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

class kept_filters {
public:
    /// True iff `input` carries the filters take() last copied: the same
    /// arrays given, holding the same values (same counts assumed checked).
    bool same_as(const query_input& input) const;
    /// Copies the filters of `input`, those the kept candidates are built with.
    void take(const query_input& input);

private:
    /// The filters of one set; an array not given is empty and not `has_`.
    struct side_copy {
        bool has_categories = false;
        bool has_masks = false;
        bool has_groups = false;
        std::vector<std::uint64_t> categories, masks;
        std::vector<std::int32_t> groups;

        bool same_as(const pair_filters& f, std::size_t count) const;
        void take(const pair_filters& f, std::size_t count);
    };
    side_copy a_, b_;
};

}  // namespace obbsat::detail
