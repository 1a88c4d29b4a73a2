#include <obbsat/suites/suite.hpp>

#include "families.hpp"

namespace obbsat::suites {

suite make_family(family f, std::uint64_t seed, std::size_t pairs) {
    suite out;
    out.source = f;
    out.seed = seed;
    detail::suite_builder builder(out, pairs);
    // Each family draws from its own stream, so the same seed gives unrelated
    // families rather than shifted copies of one stream.
    seeded_random random(seed ^ (0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(f) + 1)));
    switch (f) {
        case family::random: detail::build_random(builder, random); break;
        case family::far: detail::build_far(builder, random); break;
        case family::integer_touching: detail::build_integer_touching(builder, random); break;
        case family::tiles: detail::build_tiles(builder, random); break;
        case family::grazing: detail::build_grazing(builder, random); break;
        case family::near_parallel: detail::build_near_parallel(builder, random); break;
        case family::slivers: detail::build_slivers(builder, random); break;
        case family::tiny: detail::build_tiny(builder, random); break;
        case family::huge: detail::build_huge(builder, random); break;
        case family::degenerate: detail::build_degenerate(builder, random); break;
        case family::nested_cross: detail::build_nested_cross(builder, random); break;
    }
    return out;
}

}  // namespace obbsat::suites
