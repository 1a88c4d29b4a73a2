#include <obbsat/ref/pose_exact64.hpp>

#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>

namespace obbsat::ref {

bool exact(const rect_pose64& a, const rect_pose64& b) {
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
