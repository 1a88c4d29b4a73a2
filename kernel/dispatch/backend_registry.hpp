// The kernel table of a resolved backend. Internal to the library.
#pragma once

#include "dispatch/kernel_table.hpp"

#include <obbsat/backend.hpp>

namespace obbsat::detail {

/// The kernels of `resolved`, which resolve_backend has already checked.
const kernel_table& kernels_for(backend resolved);

}  // namespace obbsat::detail
