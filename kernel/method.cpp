// The public facts of each method, read off the method catalogue.
#include "method_catalogue.hpp"

#include <obbsat/method.hpp>

namespace obbsat {

namespace {

struct method_facts {
    method id;
    const char* name;
    method_guarantee guarantee;
    reference_fn reference;
};

constexpr auto facts = detail::method_catalogue::map([](auto row) {
    using row_type = decltype(row);
    return method_facts{row_type::id, row_type::name, row_type::guarantee, row_type::corners::reference};
});

}  // namespace

bool is_method(method m) { return static_cast<unsigned>(m) < method_count; }

const char* method_name(method m) { return is_method(m) ? facts[static_cast<unsigned>(m)].name : "unknown"; }

std::optional<method> parse_method(std::string_view name) {
    for (const auto& f : facts) {
        if (name == f.name) {
            return f.id;
        }
    }
    return std::nullopt;
}

reference_fn method_reference(method m) {
    return is_method(m) ? facts[static_cast<unsigned>(m)].reference : nullptr;
}

method_guarantee guarantee_of(method m) {
    return is_method(m) ? facts[static_cast<unsigned>(m)].guarantee : method_guarantee::none;
}

std::vector<method> all_methods() {
    std::vector<method> out;
    for (const auto& f : facts) {
        out.push_back(f.id);
    }
    return out;
}

}  // namespace obbsat
