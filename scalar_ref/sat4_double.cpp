#include "sat4_steps.hpp"

#include <obbsat/ref/sat4_double.hpp>

namespace obbsat::ref {

bool sat4_double(const rect& a, const rect& b) {
    return steps::collide(steps::quad<double>(a), steps::quad<double>(b));
}

}  // namespace obbsat::ref
