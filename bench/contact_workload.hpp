// The pairs the contact rows time (bench_contact.cpp, peer_box2d_contacts.cpp):
// the collide rows' scenes (bench_workload.hpp) as poses, one workload per
// size, shared by obbsat's rows and Box2D's so both run the same pairs.
#pragma once

#include "bench_workload.hpp"

#include <cstddef>

namespace obbsat_bench {

/// The typical-density workload of `pairs` pairs, built once per size.
workload& contact_workload(std::size_t pairs);

/// The sizes of the contact rows: 4K and 256K pairs.
inline constexpr std::size_t contact_sizes[] = {4096, 262144};

}  // namespace obbsat_bench
