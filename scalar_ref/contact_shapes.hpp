// The types the contact and distance references work on, by scalar type:
// float for the float boxes, double for the double ones. One template of each
// step serves both (scalar_ref/contact.cpp, distance.cpp), so the double
// reference is the float one's specification with every operation in double.
#pragma once

#include <obbsat/closest_points.hpp>
#include <obbsat/contact_manifold.hpp>
#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/local.hpp>
#include <obbsat/ref/local64.hpp>

namespace obbsat::ref::contact_steps {

template <class T>
struct shapes;

template <>
struct shapes<float> {
    using point_type = point;
    using box = contact_box;
    using quad = rect;
    using pose = rect_pose;
    using result = contact;
    using result_point = contact_point;
    using closest = closest_points;
};

template <>
struct shapes<double> {
    using point_type = point64;
    using box = contact_box64;
    using quad = rect64;
    using pose = rect_pose64;
    using result = contact64;
    using result_point = contact_point64;
    using closest = closest_points64;
};

template <class P>
auto dot(P p, P q) {
    return (p.x * q.x) + (p.y * q.y);
}

template <class P>
P minus(P p, P q) {
    return P{p.x - q.x, p.y - q.y};
}

}  // namespace obbsat::ref::contact_steps
