#include "case_files.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace obbsat::test {

namespace {

[[noreturn]] void fail_at(const std::string& file, std::size_t line, const std::string& what) {
    throw std::runtime_error(file + ":" + std::to_string(line) + ": " + what);
}

std::vector<std::string> read_lines(const std::string& file) {
    std::ifstream in(file);
    if (!in) {
        throw std::runtime_error(file + ": cannot open");
    }
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        lines.push_back(line);
    }
    while (!lines.empty() && lines.back().empty()) {
        lines.pop_back();
    }
    return lines;
}

std::vector<std::string> split_commas(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos) {
            return fields;
        }
        start = comma + 1;
    }
}

float parse_float(const std::string& text, const std::string& file, std::size_t line) {
    char* end = nullptr;
    const float value = std::strtof(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
        fail_at(file, line, "not a finite float: '" + text + "'");
    }
    return value;
}

std::uint32_t parse_index(const std::string& text, const std::string& file, std::size_t line) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || end != text.c_str() + text.size() || value > 0xffffffffUL) {
        fail_at(file, line, "not an index: '" + text + "'");
    }
    return static_cast<std::uint32_t>(value);
}

std::string read_letters(const std::string& file, std::size_t expected, const std::string& allowed) {
    const std::vector<std::string> lines = read_lines(file);
    if (lines.size() != expected) {
        fail_at(file, lines.size(), "expected " + std::to_string(expected) + " lines");
    }
    std::string letters;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].size() != 1 || allowed.find(lines[i][0]) == std::string::npos) {
            fail_at(file, i + 1, "expected one of '" + allowed + "', got '" + lines[i] + "'");
        }
        letters += lines[i][0];
    }
    return letters;
}

}  // namespace

case_folder read_case_folder(const std::string& path) {
    case_folder folder;
    const std::string rects_file = path + "/rects.csv";
    const std::vector<std::string> rect_lines = read_lines(rects_file);
    for (std::size_t i = 0; i < rect_lines.size(); ++i) {
        const std::vector<std::string> f = split_commas(rect_lines[i]);
        if (f.size() != 8) {
            fail_at(rects_file, i + 1, "expected 8 values");
        }
        float v[8];
        for (std::size_t k = 0; k < 8; ++k) {
            v[k] = parse_float(f[k], rects_file, i + 1);
        }
        folder.rects.push_back(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
    }
    const std::string pairs_file = path + "/pairs.csv";
    const std::vector<std::string> pair_lines = read_lines(pairs_file);
    for (std::size_t i = 0; i < pair_lines.size(); ++i) {
        const std::vector<std::string> f = split_commas(pair_lines[i]);
        if (f.size() != 2) {
            fail_at(pairs_file, i + 1, "expected 2 indices");
        }
        const pair_index p{parse_index(f[0], pairs_file, i + 1), parse_index(f[1], pairs_file, i + 1)};
        if (p.a >= folder.rects.size() || p.b >= folder.rects.size()) {
            fail_at(pairs_file, i + 1, "index beyond rects.csv");
        }
        folder.pairs.push_back(p);
    }
    folder.truth = read_letters(path + "/truth.txt", folder.pairs.size(), "01");
    folder.truth_class = read_letters(path + "/truth_class.txt", folder.pairs.size(), "STO");
    folder.tags = read_lines(path + "/tags.txt");
    if (folder.tags.size() != folder.pairs.size()) {
        fail_at(path + "/tags.txt", folder.tags.size(), "expected one tag per pair");
    }
    return folder;
}

}  // namespace obbsat::test
