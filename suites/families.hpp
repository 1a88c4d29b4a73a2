// One builder per family: each appends rects and tagged pairs until the
// builder is full, drawing only from `random`.
#pragma once

#include "suite_builder.hpp"

#include <obbsat/scene.hpp>

namespace obbsat::suites::detail {

void build_random(suite_builder& out, seeded_random& random);
void build_far(suite_builder& out, seeded_random& random);
void build_integer_touching(suite_builder& out, seeded_random& random);
void build_tiles(suite_builder& out, seeded_random& random);
void build_grazing(suite_builder& out, seeded_random& random);
void build_near_parallel(suite_builder& out, seeded_random& random);
void build_slivers(suite_builder& out, seeded_random& random);
void build_tiny(suite_builder& out, seeded_random& random);
void build_huge(suite_builder& out, seeded_random& random);
void build_degenerate(suite_builder& out, seeded_random& random);
void build_nested_cross(suite_builder& out, seeded_random& random);

}  // namespace obbsat::suites::detail
