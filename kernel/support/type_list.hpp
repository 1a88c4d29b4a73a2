// A compile-time list of row types, for the catalogues that every table of
// methods and backends is derived from (method_catalogue.hpp,
// backend_catalogue.hpp). A row is an empty struct of static members.
#pragma once

#include <array>
#include <cstddef>

namespace obbsat::detail {

template <class... Rows>
struct type_list {
    static constexpr std::size_t size = sizeof...(Rows);

    /// {f(Row{})...} in list order: one table entry per row.
    template <class F>
    static constexpr auto map(F f) {
        return std::array<decltype(f(first_row())), size>{f(Rows{})...};
    }

private:
    template <class Row, class...>
    struct first {
        using type = Row;
    };
    static constexpr auto first_row() { return typename first<Rows...>::type{}; }
};

}  // namespace obbsat::detail
