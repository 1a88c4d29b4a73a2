// Floats and rectangles as exact text for failure messages: C99 hex floats,
// which strtof reads back bit for bit, so a reported case can be replayed.
#pragma once

#include <obbsat/rect.hpp>

#include <cstdio>
#include <string>

namespace obbsat::test_support {

inline std::string hex_float(float value) {
    char text[48];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(value));
    return text;
}

inline std::string describe(point p) { return "(" + hex_float(p.x) + ", " + hex_float(p.y) + ")"; }

/// "UL (x, y) UR (x, y) LR (x, y) LL (x, y)" in hex floats.
inline std::string describe(const rect& r) {
    return "UL " + describe(r.ul) + " UR " + describe(r.ur) + " LR " + describe(r.lr) + " LL " +
           describe(r.ll);
}

}  // namespace obbsat::test_support
