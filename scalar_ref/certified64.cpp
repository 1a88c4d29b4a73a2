#include "certified_steps.hpp"

#include <obbsat/ref/certified64.hpp>

namespace obbsat::ref {

certified_verdict certify(const rect64& a, const rect64& b) {
    constexpr certified_steps::limits<double> double_limits{0x1p-900, 0x1p1000, 0x1p-49};
    return certified_steps::certify<point64>(a, b, double_limits);
}

}  // namespace obbsat::ref
