// Reading a labelled case folder (rects.csv, pairs.csv, truth.txt,
// truth_class.txt, tags.txt) exactly: coordinates are C99 hex floats read
// with strtof. A malformed line throws std::runtime_error naming file:line.
#pragma once

#include <obbsat/rect.hpp>

#include <string>
#include <vector>

namespace obbsat::test {

struct case_folder {
    std::vector<rect> rects;
    std::vector<pair_index> pairs;
    std::string truth;        ///< one '0' or '1' per pair
    std::string truth_class;  ///< one 'S', 'T' or 'O' per pair
    std::vector<std::string> tags;
};

/// Reads the folder `path`; every pair must have a truth, a class and a tag.
case_folder read_case_folder(const std::string& path);

}  // namespace obbsat::test
