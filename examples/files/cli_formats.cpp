#include "cli_formats.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string_view>

namespace cli_formats {

namespace {

std::string_view trimmed(std::string_view s) {
    const std::size_t begin = s.find_first_not_of(" \t");
    if (begin == std::string_view::npos) {
        return {};
    }
    return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

// The lines of a file that hold records, each with its line number for errors.
// The header line a file may start with ('obbsat gen --header', 'obbsat
// pairs --header', 'obbsat collide --header'): skipped when it is line 1.
constexpr std::string_view rect_header = "ulx,uly,urx,ury,lrx,lry,llx,lly";
constexpr std::string_view pair_header = "i,j";
constexpr std::string_view verdict_header = "verdict";

class record_lines {
public:
    explicit record_lines(const std::string& path) : path_(path) {
        errno = 0;
        in_.open(path, std::ios::binary);
        if (!in_) {
            const int reason = errno;
            throw format_error(path + ": cannot open for reading" +
                               (reason != 0 ? std::string(": ") + std::strerror(reason) : std::string()));
        }
    }

    /// The next line that holds a record, without its line end; false at the end.
    bool next(std::string_view& record) {
        while (std::getline(in_, line_)) {
            ++number_;
            std::string_view view(line_);
            if (!view.empty() && view.back() == '\r') {
                view.remove_suffix(1);
            }
            // Spreadsheets often start a CSV file with a UTF-8 byte order mark.
            if (number_ == 1 && view.substr(0, 3) == "\xef\xbb\xbf") {
                view.remove_prefix(3);
            }
            const std::string_view content = trimmed(view);
            if (content.empty() || content.front() == '#') {
                continue;
            }
            record = view;
            return true;
        }
        if (in_.bad()) {
            throw format_error(path_ + ": read error after line " + std::to_string(number_));
        }
        return false;
    }

    /// Throws format_error for the line next() returned last.
    [[noreturn]] void fail(const std::string& reason) const {
        throw format_error(path_ + ":" + std::to_string(number_) + ": " + reason);
    }

    const std::string& path() const { return path_; }
    /// The 1-based number of the line next() returned last.
    std::uint64_t number() const { return number_; }

private:
    std::string path_;
    std::ifstream in_;
    std::string line_;
    std::uint64_t number_ = 0;
};

template <std::size_t N>
std::array<std::string_view, N> split_fields(std::string_view line, const record_lines& where,
                                             const char* layout) {
    std::array<std::string_view, N> fields;
    std::size_t count = 0;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        if (count < N) {
            fields[count] = trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
        }
        ++count;
        if (comma == std::string_view::npos) {
            break;
        }
        start = comma + 1;
    }
    if (count != N) {
        where.fail("expected " + std::to_string(N) + " comma-separated fields (" + layout + "), found " +
                   std::to_string(count));
    }
    return fields;
}

std::string field_label(std::size_t index, const char* name) {
    return "field " + std::to_string(index + 1) + " (" + name + ")";
}

float parse_coordinate(std::string_view field, std::size_t index, const record_lines& where) {
    static constexpr const char* names[] = {"ulx", "uly", "urx", "ury", "lrx", "lry", "llx", "lly"};
    const std::string label = field_label(index, names[index]);
    if (field.empty()) {
        where.fail(label + " is empty");
    }
    // strtof, unlike std::from_chars, reads C99 hex floats with their 0x prefix,
    // as the obbsat program does; this program never changes the "C" locale.
    const std::string text(field);
    char* stop = nullptr;
    errno = 0;
    const float value = std::strtof(text.c_str(), &stop);
    if (stop != text.c_str() + text.size()) {
        where.fail(label + ": '" + text + "' is not a number");
    }
    if (errno == ERANGE && std::isinf(value)) {
        where.fail(label + ": '" + text + "' is out of float range");
    }
    if (!std::isfinite(value)) {
        where.fail(label + ": '" + text + "' is not finite");
    }
    return value;
}

std::uint32_t parse_index(std::string_view field, std::size_t index, const char* name, std::size_t rect_count,
                          const std::string& rect_path, const record_lines& where) {
    const std::string label = field_label(index, name);
    std::uint64_t value = 0;
    const char* const last = field.data() + field.size();
    const auto [stop, error] = std::from_chars(field.data(), last, value);
    if (field.empty() || error == std::errc::invalid_argument || stop != last) {
        where.fail(label + ": '" + std::string(field) + "' is not an unsigned decimal integer");
    }
    if (error == std::errc::result_out_of_range || value >= rect_count) {
        where.fail(label + ": index " + std::string(field) + " is out of range: " + rect_path + " holds " +
                   std::to_string(rect_count) + " rectangles");
    }
    return static_cast<std::uint32_t>(value);
}

// A reader of the file at `path` would otherwise see half of it while it is
// being written, or a truncated file after a failure: the bytes go to a
// temporary file beside it, which is renamed over `path` once complete.
void write_whole_file(const std::string& path, const std::string& content) {
    const std::string temporary = path + ".partial";
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
        throw std::runtime_error(temporary + ": cannot create");
    }
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
        std::remove(temporary.c_str());
        throw std::runtime_error(temporary + ": write error");
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int reason = errno;
        std::remove(temporary.c_str());
        throw std::runtime_error(path + ": cannot replace: " + std::strerror(reason));
    }
}

void append_float(std::string& out, float value) {
    std::array<char, 32> text;
    const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
    (void)error;  // 32 characters hold any float in its shortest form
    out.append(text.data(), end);
}

}  // namespace

std::vector<obbsat::rect> read_rects(const std::string& path) {
    record_lines lines(path);
    std::vector<obbsat::rect> rects;
    std::string_view line;
    while (lines.next(line)) {
        if (lines.number() == 1 && line == rect_header) {
            continue;
        }
        const auto fields = split_fields<8>(line, lines, "ulx,uly,urx,ury,lrx,lry,llx,lly");
        std::array<float, 8> v;
        for (std::size_t k = 0; k < v.size(); ++k) {
            v[k] = parse_coordinate(fields[k], k, lines);
        }
        if (rects.size() == UINT32_MAX) {
            lines.fail("more rectangles than 32-bit pair indices can address");
        }
        rects.push_back({{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
    }
    return rects;
}

std::vector<obbsat::pair_index> read_pairs(const std::string& path, std::size_t rect_count,
                                           const std::string& rect_path) {
    record_lines lines(path);
    std::vector<obbsat::pair_index> pairs;
    std::string_view line;
    while (lines.next(line)) {
        if (lines.number() == 1 && line == pair_header) {
            continue;
        }
        const auto fields = split_fields<2>(line, lines, "i,j");
        pairs.push_back({parse_index(fields[0], 0, "i", rect_count, rect_path, lines),
                         parse_index(fields[1], 1, "j", rect_count, rect_path, lines)});
    }
    return pairs;
}

std::vector<std::uint8_t> read_verdicts(const std::string& path) {
    record_lines lines(path);
    std::vector<std::uint8_t> verdicts;
    std::string_view line;
    while (lines.next(line)) {
        if (lines.number() == 1 && line == verdict_header) {
            continue;
        }
        const std::string_view field = trimmed(line);
        if (field != "0" && field != "1") {
            lines.fail("'" + std::string(field) + "' is not a verdict (0 or 1)");
        }
        verdicts.push_back(field == "1" ? 1 : 0);
    }
    return verdicts;
}

void write_rects(const std::string& path, const std::vector<obbsat::rect>& rects) {
    std::string content;
    for (const obbsat::rect& r : rects) {
        for (const obbsat::point& p : {r.ul, r.ur, r.lr, r.ll}) {
            append_float(content, p.x);
            content += ',';
            append_float(content, p.y);
            content += ',';
        }
        content.back() = '\n';
    }
    write_whole_file(path, content);
}

void write_pairs(const std::string& path, const std::vector<obbsat::pair_index>& pairs) {
    std::string content;
    for (const obbsat::pair_index& p : pairs) {
        content += std::to_string(p.a);
        content += ',';
        content += std::to_string(p.b);
        content += '\n';
    }
    write_whole_file(path, content);
}

void write_verdicts(const std::string& path, const std::vector<std::uint8_t>& verdicts) {
    std::string content;
    content.reserve(2 * verdicts.size());
    for (const std::uint8_t v : verdicts) {
        content += v != 0 ? "1\n" : "0\n";
    }
    write_whole_file(path, content);
}

}  // namespace cli_formats
