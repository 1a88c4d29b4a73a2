// What a store says when it refuses rows: the message of the invalid_input its
// constructor throws, or "" when it takes them.
#pragma once

#include <obbsat/error.hpp>

#include <string>

namespace obbsat::test_support {

template <class Store, class Rows>
std::string refusal_of(const Rows& rows) {
    try {
        const Store store(rows);
    } catch (const obbsat::invalid_input& e) {
        return e.what();
    }
    return "";
}

}  // namespace obbsat::test_support
