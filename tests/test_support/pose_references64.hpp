// The scalar reference of a method on double poses, chosen at run time: what
// every test of the double pose lanes compares its verdicts with.
#pragma once

#include <obbsat/method.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

namespace obbsat::test {

/// The verdict of `m` (exact, conservative or local) on double poses a and b, by its scalar reference.
inline bool reference64(method m, const rect_pose64& a, const rect_pose64& b) {
    switch (m) {
        case method::exact: return ref::exact(a, b);
        case method::conservative: return ref::conservative(a, b);
        default: return ref::local(a, b);
    }
}

}  // namespace obbsat::test
