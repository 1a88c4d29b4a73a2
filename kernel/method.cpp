#include <obbsat/method.hpp>

namespace obbsat {

namespace {

struct method_entry {
    method id;
    const char* name;
};

const method_entry methods[method_count] = {
    {method::sat4, "sat4"},
    {method::sat4_centered, "sat4_centered"},
    {method::sat4_double, "sat4_double"},
};

}  // namespace

const char* method_name(method m) {
    for (const auto& e : methods) {
        if (e.id == m) {
            return e.name;
        }
    }
    return "unknown";
}

std::optional<method> parse_method(std::string_view name) {
    for (const auto& e : methods) {
        if (name == e.name) {
            return e.id;
        }
    }
    return std::nullopt;
}

std::vector<method> all_methods() {
    std::vector<method> out;
    for (const auto& e : methods) {
        out.push_back(e.id);
    }
    return out;
}

}  // namespace obbsat
