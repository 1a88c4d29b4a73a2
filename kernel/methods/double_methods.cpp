// Which methods run on the double stores: those with a double reference in
// scalar_ref/ (the *64 files). One table, indexed by method.
#include <obbsat/collide64.hpp>

namespace obbsat {

namespace {

struct double_support {
    method m;
    bool on_corners;
    bool on_poses;
};

// In the order of obbsat::method; the static_assert below ties its length to it.
constexpr double_support double_table[] = {
    {method::sat4, false, false},         {method::sat4_centered, false, false},
    {method::sat4_double, false, false},  {method::conservative, true, true},
    {method::exact, true, true},          {method::local, false, true},
};
static_assert(sizeof(double_table) / sizeof(double_table[0]) == method_count,
              "every method says whether it runs on double stores");

constexpr bool table_in_method_order() {
    for (unsigned i = 0; i < method_count; ++i) {
        if (static_cast<unsigned>(double_table[i].m) != i) {
            return false;
        }
    }
    return true;
}
static_assert(table_in_method_order(), "double_table lists the methods in declaration order");

}  // namespace

bool runs_on_doubles(method m, store_kind s) {
    if (!is_method(m)) {
        return false;
    }
    const double_support& row = double_table[static_cast<unsigned>(m)];
    return s == store_kind::poses ? row.on_poses : row.on_corners;
}

std::vector<method> methods_on_doubles(store_kind s) {
    std::vector<method> out;
    for (const method m : all_methods()) {
        if (runs_on_doubles(m, s)) {
            out.push_back(m);
        }
    }
    return out;
}

}  // namespace obbsat
