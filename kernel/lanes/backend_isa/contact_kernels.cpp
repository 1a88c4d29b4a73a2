// The contact kernels of one instruction set (this_isa.hpp):
// contact_kernels_of<that backend>() (dispatch/contact_kernel_table.hpp), on
// float and double poses and corners, contacts and distances.
#include "dispatch/contact_kernel_table.hpp"
#include "lanes/backend_isa/this_isa.hpp"
#include "lanes/contact_batch.hpp"

namespace obbsat::detail {

template <>
const contact_kernel_table& contact_kernels_of<this_backend>() {
    static constexpr contact_kernel_table table = contact_table_of<isa_arch>();
    return table;
}

}  // namespace obbsat::detail
