// Rows of poses in the caller's memory as the scene query reads them
// (query_input), unchecked, so that the query checks them: for tests that
// drive pair_search's steps themselves.
#pragma once

#include "scene/query_input.hpp"

#include <obbsat/rect_pose.hpp>

#include <vector>

namespace obbsat::test_support {

/// One set `a`, or two sets `a` and `*b`.
inline detail::query_input pose_query_rows(const std::vector<rect_pose>& a, const std::vector<rect_pose>* b = nullptr) {
    detail::query_input in;
    in.kind = store_kind::poses;
    in.a = &a.data()->center.x;
    in.a_count = a.size();
    in.a_stride = 6;
    in.a_checked = false;
    if (b != nullptr) {
        in.b = &b->data()->center.x;
        in.b_count = b->size();
        in.b_stride = 6;
        in.b_checked = false;
    }
    return in;
}

}  // namespace obbsat::test_support
