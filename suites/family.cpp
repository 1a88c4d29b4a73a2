#include <obbsat/suites/family.hpp>

#include <obbsat/error.hpp>

#include <string>

namespace obbsat::suites {

const char* family_name(family f) {
    switch (f) {
        case family::random: return "random";
        case family::far: return "far";
        case family::integer_touching: return "integer_touching";
        case family::tiles: return "tiles";
        case family::grazing: return "grazing";
        case family::near_parallel: return "near_parallel";
        case family::slivers: return "slivers";
        case family::tiny: return "tiny";
        case family::huge: return "huge";
        case family::degenerate: return "degenerate";
        case family::nested_cross: return "nested_cross";
    }
    return "unknown";
}

const std::vector<family>& all_families() {
    static const std::vector<family> families = {
        family::random,        family::far,     family::integer_touching, family::tiles,
        family::grazing,       family::near_parallel, family::slivers,    family::tiny,
        family::huge,          family::degenerate,    family::nested_cross};
    return families;
}

family parse_family(std::string_view name) {
    std::string known;
    for (const family f : all_families()) {
        if (name == family_name(f)) {
            return f;
        }
        known += known.empty() ? "" : ", ";
        known += family_name(f);
    }
    throw invalid_input("unknown suite family '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace obbsat::suites
