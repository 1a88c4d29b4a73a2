// The scalar reference of each method on double stores, by method: what the
// double tests compare collide_pairs over pose_records64 and rect_records64 with.
#pragma once

#include <obbsat/method.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/exact64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

namespace obbsat::test {

/// The reference verdict of `m` (local, conservative or exact) on double poses.
inline bool double_reference(method m, const rect_pose64& a, const rect_pose64& b) {
    switch (m) {
        case method::exact: return ref::exact(a, b);
        case method::conservative: return ref::conservative(a, b);
        default: return ref::local(a, b);
    }
}

/// The reference verdict of `m` (conservative or exact) on double corners.
inline bool double_reference(method m, const rect64& a, const rect64& b) {
    return m == method::exact ? ref::exact(a, b) : ref::conservative(a, b);
}

}  // namespace obbsat::test
