// Reader for the labelled case folders outside the project (rects.csv with
// hex-float corners, pairs.csv with index pairs), found through the
// environment variable OBBSAT_SHARED_CASES, which CTest sets from the CMake
// cache variable OBBSAT_SHARED_CASES_DIR. Clones of the project do not have
// them, so tests that use them skip, naming the path, when the folder is missing.
#pragma once

#include <obbsat/rect.hpp>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace obbsat::test_support {

struct case_family {
    std::string name;
    std::vector<rect> rects;
    std::vector<pair_index> pairs;
};

/// The path in OBBSAT_SHARED_CASES, empty when it is unset.
inline std::string shared_cases_path() {
    const char* folder = std::getenv("OBBSAT_SHARED_CASES");
    return folder == nullptr ? std::string() : std::string(folder);
}

/// The folder named by OBBSAT_SHARED_CASES if it holds a README.md, else nothing.
inline std::optional<std::string> shared_cases_folder() {
    const std::string folder = shared_cases_path();
    if (folder.empty() || !std::ifstream(folder + "/README.md")) {
        return std::nullopt;
    }
    return folder;
}

/// Why a test that needs the labelled cases skips: where they were looked for.
inline std::string shared_cases_missing() {
    const std::string folder = shared_cases_path();
    if (folder.empty()) {
        return "labelled case families not found: OBBSAT_SHARED_CASES is not set "
               "(configure with -DOBBSAT_SHARED_CASES_DIR=FOLDER)";
    }
    return "labelled case families not found at '" + folder +
           "' (no README.md there; configure with -DOBBSAT_SHARED_CASES_DIR=FOLDER)";
}

inline std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) {
        fields.push_back(field);
    }
    return fields;
}

inline float parse_hex_float(const std::string& text, const std::string& where) {
    char* end = nullptr;
    const float value = std::strtof(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') {
        throw std::runtime_error(where + ": not a float: " + text);
    }
    return value;
}

inline std::uint32_t parse_index(const std::string& text, const std::string& where) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || value > 0xffffffffUL) {
        throw std::runtime_error(where + ": not an index: " + text);
    }
    return static_cast<std::uint32_t>(value);
}

/// Reads `folder`/`name`/rects.csv and pairs.csv; throws naming file:line on a bad line.
inline case_family read_case_family(const std::string& folder, const std::string& name) {
    case_family family{name, {}, {}};
    const std::string rects_path = folder + "/" + name + "/rects.csv";
    const std::string pairs_path = folder + "/" + name + "/pairs.csv";
    std::ifstream rects_file(rects_path);
    std::ifstream pairs_file(pairs_path);
    if (!rects_file || !pairs_file) {
        throw std::runtime_error("cannot open " + rects_path + " or " + pairs_path);
    }
    std::string line;
    for (std::size_t number = 1; std::getline(rects_file, line); ++number) {
        const std::string where = rects_path + ":" + std::to_string(number);
        const auto f = csv_fields(line);
        if (f.size() != 8) {
            throw std::runtime_error(where + ": expected 8 fields");
        }
        float v[8];
        for (unsigned k = 0; k < 8; ++k) {
            v[k] = parse_hex_float(f[k], where);
        }
        family.rects.push_back(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
    }
    for (std::size_t number = 1; std::getline(pairs_file, line); ++number) {
        const std::string where = pairs_path + ":" + std::to_string(number);
        const auto f = csv_fields(line);
        if (f.size() != 2) {
            throw std::runtime_error(where + ": expected 2 fields");
        }
        family.pairs.push_back(pair_index{parse_index(f[0], where), parse_index(f[1], where)});
    }
    return family;
}

/// The family folders the README lists.
inline std::vector<std::string> case_family_names() {
    return {"random", "tiles", "near_parallel", "slivers",
            "tiny",   "huge",  "degenerate",    "nested_cross"};
}

}  // namespace obbsat::test_support
