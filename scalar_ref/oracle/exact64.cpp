#include <obbsat/ref/exact64.hpp>

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/ref/certified64.hpp>

namespace obbsat::ref {

bool exact(const rect64& a, const rect64& b) {
    const certified_verdict fast = certify(a, b);
    if (fast.separated) {
        return false;
    }
    if (fast.intersecting) {
        return true;
    }
    return oracle::intersects(a, b);
}

}  // namespace obbsat::ref
