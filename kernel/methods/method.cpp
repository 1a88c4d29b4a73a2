// The public facts of each method, read off the method catalogue.
#include "methods/method_catalogue.hpp"

#include <obbsat/method.hpp>

namespace obbsat {

namespace {

struct method_facts {
    method id;
    const char* name;
    method_guarantee guarantee;
    reference_fn reference;            ///< on corners; nullptr when not offered there
    pose_reference_fn pose_reference;  ///< on poses; nullptr when not offered there
};

template <class Store>
constexpr auto reference_on() {
    if constexpr (detail::offered<Store>) {
        return Store::reference;
    } else {
        return nullptr;
    }
}

constexpr auto facts = detail::method_catalogue::map([](auto row) {
    using row_type = decltype(row);
    return method_facts{row_type::id, row_type::name, row_type::guarantee,
                        reference_on<typename row_type::corners>(), reference_on<typename row_type::poses>()};
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

pose_reference_fn pose_method_reference(method m) {
    return is_method(m) ? facts[static_cast<unsigned>(m)].pose_reference : nullptr;
}

bool runs_on(method m, store_kind s) {
    return s == store_kind::corners ? method_reference(m) != nullptr : pose_method_reference(m) != nullptr;
}

std::vector<method> methods_on(store_kind s) {
    std::vector<method> out;
    for (const auto& f : facts) {
        if (runs_on(f.id, s)) {
            out.push_back(f.id);
        }
    }
    return out;
}

const char* store_name(store_kind s) { return s == store_kind::corners ? "corners" : "poses"; }

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
