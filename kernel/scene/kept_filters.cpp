// The pair filters of pair_finder's kept candidates (kept_filters.hpp).
#include "scene/kept_filters.hpp"

#include <algorithm>

namespace obbsat::detail {

namespace {

/// `given` holds `count` values equal to `copy`'s, or is nullptr while `copy` is not `had`.
template <class T>
bool same_values(const T* given, std::size_t count, bool had, const std::vector<T>& copy) {
    if ((given != nullptr) != had) {
        return false;
    }
    return given == nullptr || (copy.size() == count && std::equal(copy.begin(), copy.end(), given));
}

template <class T>
void copy_values(const T* given, std::size_t count, bool& has, std::vector<T>& copy) {
    has = given != nullptr;
    if (has) {
        copy.assign(given, given + count);
    } else {
        copy.clear();
    }
}

}  // namespace

bool kept_filters::side_copy::same_as(const pair_filters& f, std::size_t count) const {
    return same_values(f.categories, count, has_categories, categories) &&
           same_values(f.masks, count, has_masks, masks) && same_values(f.groups, count, has_groups, groups);
}

void kept_filters::side_copy::take(const pair_filters& f, std::size_t count) {
    copy_values(f.categories, count, has_categories, categories);
    copy_values(f.masks, count, has_masks, masks);
    copy_values(f.groups, count, has_groups, groups);
}

bool kept_filters::same_as(const query_input& input) const {
    const bool cross = input.b != nullptr;
    return a_.same_as(input.a_filters, input.a_count) &&
           b_.same_as(cross ? input.b_filters : pair_filters{}, cross ? input.b_count : 0);
}

void kept_filters::take(const query_input& input) {
    const bool cross = input.b != nullptr;
    a_.take(input.a_filters, input.a_count);
    b_.take(cross ? input.b_filters : pair_filters{}, cross ? input.b_count : 0);
}

}  // namespace obbsat::detail
