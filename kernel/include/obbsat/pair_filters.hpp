// Pair filters of the scene queries (obbsat/find_pairs.hpp), after Box2D v3's
// b2Filter: which pairs of rectangles may collide at all, decided before the
// method tests them.
//
// Each rectangle i has a category bit set category_i, a collide-with mask
// mask_i and a group id group_i. A pair (i, j) is reported only if
//   (category_i & mask_j) != 0  and  (category_j & mask_i) != 0
// and not group_i == group_j != 0: two rectangles of one group (say the
// pieces of one compound body) never pair, whatever their bits. Unlike
// Box2D, the sign of a group means nothing: any group but 0 keeps its own
// members apart, and no group makes a pair collide that the bits refuse.
//
// An array that is not given takes its default for every rectangle:
//   category all ones (~0), mask all ones (~0), group 0,
// so a rectangle left at the defaults pairs with every rectangle whose own
// category and mask are not zero (all ones meets any bit). The three arrays
// are given independently (categories alone, groups alone, ...). A query
// whose sets give no array at all takes the plain path: it costs what a
// query cost before filters existed. In a query across two sets each set
// has its own filters, and a group number names one body on both sides.
//
// Filtered pairs cost nothing in the narrowphase: the broadphase drops them
// as it finds them, before the method's kernel, and find_pairs_stats::
// candidates counts only the pairs that pass.
#pragma once

#include <cstdint>

namespace obbsat {

/// The filters of one set of rectangles: each pointer, when not nullptr,
/// points to one value per rectangle of the box_view that carries it
/// (box_view::with_filters), read in place by every query, so it must
/// outlive the query; nullptr takes the default for every rectangle.
struct pair_filters {
    /// Category bits of each rectangle; nullptr: every bit set.
    const std::uint64_t* categories = nullptr;
    /// The categories each rectangle collides with; nullptr: every bit set.
    const std::uint64_t* masks = nullptr;
    /// Group of each rectangle, 0 for none; two rectangles of one group other than 0 never pair; nullptr: all 0.
    const std::int32_t* groups = nullptr;

    /// True iff at least one of the three arrays is given.
    bool any() const { return categories != nullptr || masks != nullptr || groups != nullptr; }
};

/// The default category and mask: every bit set.
constexpr std::uint64_t all_categories = ~std::uint64_t{0};

}  // namespace obbsat
