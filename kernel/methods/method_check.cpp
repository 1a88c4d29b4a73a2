#include "methods/method_check.hpp"

#include <obbsat/error.hpp>

#include <string>

namespace obbsat::detail {

void require_method_on(const collide_options& options, store_kind store) {
    if (!is_method(options.test)) {
        throw invalid_input("collide_options::test holds " + std::to_string(static_cast<unsigned>(options.test)) +
                            ", which names no method");
    }
    if (!runs_on(options.test, store)) {
        std::string offered;
        for (const method m : methods_on(store)) {
            offered += std::string(offered.empty() ? "" : ", ") + method_name(m);
        }
        throw invalid_input(std::string("method ") + method_name(options.test) + " does not run on " +
                            store_name(store) + " (" + (store == store_kind::poses ? "pose_records" : "rect stores") +
                            " take " + offered + ")");
    }
}

}  // namespace obbsat::detail
