#include "certified_steps.hpp"

#include <obbsat/ref/certified.hpp>

namespace obbsat::ref {

certified_verdict certify(const rect& a, const rect& b) {
    // Step 2's guard and step 3's factor, 2^-20 = 16u.
    constexpr certified_steps::limits<float> float_limits{0x1p-80f, 0x1p100f, 0x1p-20f};
    return certified_steps::certify<point>(a, b, float_limits);
}

}  // namespace obbsat::ref
