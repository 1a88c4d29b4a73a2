// The backends a kernel-internals test runs over, as gtest parameters: every
// compiled backend, from the dispatcher's registry, with its kernel table
// when this CPU runs it (a test skips the others, never calls them).
#pragma once

#include "dispatch/backend_registry.hpp"

#include <obbsat/backend.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace obbsat_test {

struct backend_case {
    obbsat::backend id;
    const obbsat::detail::kernel_table* table;  ///< nullptr when this CPU does not run the backend
};

inline std::vector<backend_case> backends_here() {
    std::vector<backend_case> out;
    for (const obbsat::backend b : obbsat::compiled_backends()) {
        out.push_back({b, obbsat::cpu_supports(b) ? &obbsat::detail::kernels_for(b) : nullptr});
    }
    return out;
}

/// The test name suffix of a case: the backend's name.
inline std::string backend_case_name(const ::testing::TestParamInfo<backend_case>& info) {
    return obbsat::backend_name(info.param.id);
}

}  // namespace obbsat_test
