// The rows of a scene query: refusing a row that fails its check (query_input.hpp).
#include "scene/query_input.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_records.hpp>

#include <stdexcept>
#include <string>

namespace obbsat::detail {

[[noreturn]] void refuse_row(const query_input& input, std::size_t id) {
    const bool second = id >= input.a_count;
    const std::size_t index = second ? id - input.a_count : id;
    const float* v = record_at(input, id);
    try {
        if (input.kind == store_kind::poses) {
            require_valid_pose(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}, index);
        } else {
            require_finite(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}, index);
        }
    } catch (const invalid_input& e) {
        if (input.b == nullptr) {
            throw;
        }
        throw invalid_input(std::string(second ? "b: " : "a: ") + e.what());
    }
    throw std::logic_error("obbsat: a row refused by the scene query passed its store's check");
}

void require_valid_rows(const query_input& input) {
    const std::size_t n = input.a_count + (input.b == nullptr ? 0 : input.b_count);
    for (std::size_t id = 0; id < n; ++id) {
        if (!(id < input.a_count ? input.a_checked : input.b_checked) && !valid_row(input.kind, record_at(input, id))) {
            refuse_row(input, id);
        }
    }
}

}  // namespace obbsat::detail
