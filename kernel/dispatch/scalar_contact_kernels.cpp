// The scalar contact and distance kernels (the references one pair at a time) and the
// choice of a backend's contact table. Compiled at the baseline ISA.
#include "dispatch/backend_catalogue.hpp"
#include "dispatch/compiled_kernels.hpp"
#include "dispatch/contact_kernel_table.hpp"

#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/distance.hpp>

namespace obbsat::detail {

namespace {

rect_pose pose_in(const float* v) { return rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}; }

rect rect_in(const float* v) { return rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}; }

rect_pose64 pose64_in(const double* v) { return rect_pose64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}; }

rect64 rect64_in(const double* v) { return rect64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}; }

template <class Shape, class Real, class Contact, Shape (*Read)(const Real*)>
void contacts_one_by_one(const Real* a, std::size_t a_stride, const Real* b, std::size_t b_stride,
                         const pair_index* pairs, std::size_t count, Real margin, Contact* out) {
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t ia = pairs != nullptr ? pairs[i].a : i;
        const std::size_t ib = pairs != nullptr ? pairs[i].b : i;
        out[i] = ref::contact_of(Read(a + a_stride * ia), Read(b + b_stride * ib), margin);
    }
}

template <class Shape, class Real, class Closest, Shape (*Read)(const Real*)>
void distances_one_by_one(const Real* a, std::size_t a_stride, const Real* b, std::size_t b_stride,
                          const pair_index* pairs, std::size_t count, Closest* out) {
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t ia = pairs != nullptr ? pairs[i].a : i;
        const std::size_t ib = pairs != nullptr ? pairs[i].b : i;
        out[i] = ref::distance_of(Read(a + a_stride * ia), Read(b + b_stride * ib));
    }
}

template <class Shape, class Real, Shape (*Read)(const Real*)>
bool poses_accepted_one_by_one(const Real* records, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        if (!ref::pose_accepted(Read(records + 8 * i))) {
            return false;
        }
    }
    return true;
}

/// The table of the first row of the catalogue that is `resolved` and compiled.
template <class... Rows>
const contact_kernel_table& table_for(backend resolved, type_list<Rows...>) {
    const contact_kernel_table* found = nullptr;
    auto consider = [&](auto row) {
        using Row = decltype(row);
        if constexpr (kernels_compiled<Row>()) {
            if (found == nullptr && Row::id == resolved) {
                found = &contact_kernels_of<Row>();
            }
        }
    };
    (consider(Rows{}), ...);
    return found != nullptr ? *found : contact_kernels_of<scalar_backend>();
}

}  // namespace

template <>
const contact_kernel_table& contact_kernels_of<scalar_backend>() {
    static constexpr contact_kernel_table table{
        contacts_one_by_one<rect_pose, float, contact, pose_in>,
        contacts_one_by_one<rect_pose, float, contact, pose_in>,
        contacts_one_by_one<rect, float, contact, rect_in>,
        distances_one_by_one<rect_pose, float, closest_points, pose_in>,
        distances_one_by_one<rect, float, closest_points, rect_in>,
        contacts_one_by_one<rect_pose64, double, contact64, pose64_in>,
        contacts_one_by_one<rect_pose64, double, contact64, pose64_in>,
        contacts_one_by_one<rect64, double, contact64, rect64_in>,
        distances_one_by_one<rect_pose64, double, closest_points64, pose64_in>,
        distances_one_by_one<rect64, double, closest_points64, rect64_in>,
        poses_accepted_one_by_one<rect_pose, float, pose_in>,
        poses_accepted_one_by_one<rect_pose64, double, pose64_in>};
    return table;
}

const contact_kernel_table& contact_kernels_for(backend resolved) {
    return table_for(resolved, backend_catalogue{});
}

}  // namespace obbsat::detail
