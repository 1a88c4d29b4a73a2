// The check every batch entry point makes of collide_options::test. Internal
// to the library.
#pragma once

#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>

namespace obbsat::detail {

/// Throws invalid_input unless options.test names a method that runs on
/// `store`; the message names the methods the store takes.
void require_method_on(const collide_options& options, store_kind store);

}  // namespace obbsat::detail
