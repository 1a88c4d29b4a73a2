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

bool kept_filters::side_copy::same_arrays(const pair_filters& f) const {
    return (f.categories != nullptr) == has_categories && (f.masks != nullptr) == has_masks &&
           (f.groups != nullptr) == has_groups;
}

bool kept_filters::side_copy::changed_rows(const pair_filters& f, const row_match& m,
                                           std::vector<std::uint32_t>& changed) const {
    const std::size_t last = m.last_count;
    if (!same_arrays(f) || (has_categories && categories.size() != last) || (has_masks && masks.size() != last) ||
        (has_groups && groups.size() != last)) {
        return false;
    }
    if (!has_categories && !has_masks && !has_groups) {
        return true;
    }
    // Each last row against its row now: in order where the rows kept theirs.
    const std::uint32_t* const now_of = m.now_of_last.data();
    for (std::size_t l = 0; l < last; ++l) {
        const std::uint32_t r = now_of[l];
        if (r == no_row) {
            continue;
        }
        const bool differs = (has_categories && categories[l] != f.categories[r]) ||
                             (has_masks && masks[l] != f.masks[r]) || (has_groups && groups[l] != f.groups[r]);
        if (differs) {
            changed.push_back(static_cast<std::uint32_t>(l));
        }
    }
    return true;
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

bool kept_filters::changed_rows(const query_input& input, const row_match& a, const row_match* b,
                                std::vector<std::uint32_t>& changed_a, std::vector<std::uint32_t>& changed_b) const {
    if (!a_.changed_rows(input.a_filters, a, changed_a)) {
        return false;
    }
    if (b == nullptr) {
        return b_.same_arrays(pair_filters{});
    }
    return b_.changed_rows(input.b_filters, *b, changed_b);
}

void kept_filters::take(const query_input& input) {
    const bool cross = input.b != nullptr;
    a_.take(input.a_filters, input.a_count);
    b_.take(cross ? input.b_filters : pair_filters{}, cross ? input.b_count : 0);
}

}  // namespace obbsat::detail
