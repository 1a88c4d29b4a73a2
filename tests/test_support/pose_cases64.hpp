// The double pose and corner makes of the tests, under their test names. They
// live in suites/ (obbsat/suites/double_cases.hpp), where `obbsat gen` and
// `obbsat accuracy` use the same makes for their double families; this header
// includes that one by path, so the tests need no link to obbsat_suites.
#pragma once

#include "../../suites/include/obbsat/suites/double_cases.hpp"

namespace obbsat::test {

using suites::contact_pair_at;
using suites::corner_pair;
using suites::corners64;
using suites::dyadic_half_extent;
using suites::dyadic_rotation64;
using suites::far_contact_pair;
using suites::far_random_pair;
using suites::integer_in;
using suites::near_parallel_pair;
using suites::nudge;
using suites::nudge_center;
using suites::nudged64;
using suites::nudged_corner_pair;
using suites::pose_pair64;
using suites::pose_point;
using suites::random_pair_at;
using suites::rect_pair64;
using suites::scaled_rotation_pair;
using suites::sliver_pair;
using suites::uniform64;
using suites::unit_rotation64;
using suites::utm_contact_pair;
using suites::utm_northing_contact_pair;
using suites::utm_random_pair;

}  // namespace obbsat::test
