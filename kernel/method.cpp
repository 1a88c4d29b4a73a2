#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>

namespace obbsat {

namespace {

struct method_entry {
    method id;
    const char* name;
    reference_fn reference;
};

const method_entry methods[method_count] = {
    {method::sat4, "sat4", ref::sat4},
    {method::sat4_centered, "sat4_centered", ref::sat4_centered},
    {method::sat4_double, "sat4_double", ref::sat4_double},
    {method::conservative, "conservative", ref::conservative},
    {method::exact, "exact", oracle::intersects},
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

reference_fn method_reference(method m) {
    for (const auto& e : methods) {
        if (e.id == m) {
            return e.reference;
        }
    }
    return nullptr;
}

std::vector<method> all_methods() {
    std::vector<method> out;
    for (const auto& e : methods) {
        out.push_back(e.id);
    }
    return out;
}

}  // namespace obbsat
