// The whole public API of obbsat in one include.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/ref/certified.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/pose_corners.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/validate.hpp>
