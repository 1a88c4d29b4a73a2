// The finite-coordinates invariant shared by the rectangle stores.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>

namespace obbsat::detail {

/// Throws invalid_input naming rectangle `index` and the first non-finite coordinate of `r`.
void require_finite(const rect& r, std::size_t index);

/// Throws invalid_input when index >= size, naming both.
void require_index(std::size_t index, std::size_t size);

}  // namespace obbsat::detail
