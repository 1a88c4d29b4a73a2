// The pair-filter files of `obbsat pairs --filters` (filter_input.hpp).
#include "io/filter_input.hpp"

#include <charconv>
#include <limits>
#include <string>

namespace obbsat::io {

namespace {

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
        s.remove_prefix(1);
    }
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
        s.remove_suffix(1);
    }
    return s;
}

/// The integer of `field` (decimal, or hex after "0x"; a '-' first only when
/// `is_signed`), which must lie in [lowest, highest]; fails naming the field.
template <class T>
T parse_integer(std::string_view field, std::size_t index, const char* name, const line_reader& where) {
    const std::string label = "field " + std::to_string(index + 1) + " (" + name + ")";
    if (field.empty()) {
        where.fail(label + " is empty");
    }
    std::string_view digits = field;
    const bool negative = digits.front() == '-';
    if (negative) {
        digits.remove_prefix(1);
    }
    int base = 10;
    if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
        digits.remove_prefix(2);
        base = 16;
    }
    std::uint64_t magnitude = 0;
    const char* const last = digits.data() + digits.size();
    const auto [stop, ec] = digits.empty() || digits.front() == '-' || digits.front() == '+'
                                ? std::from_chars_result{digits.data(), std::errc::invalid_argument}
                                : std::from_chars(digits.data(), last, magnitude, base);
    const std::string shown = "'" + std::string(field) + "'";
    if (ec == std::errc::result_out_of_range) {
        where.fail(label + ": " + shown + " is out of range");
    }
    if (ec != std::errc() || stop != last) {
        where.fail(label + ": " + shown + " is not an integer (decimal, or hexadecimal after 0x)");
    }
    constexpr bool is_signed = std::numeric_limits<T>::is_signed;
    if (negative && !is_signed && magnitude != 0) {
        where.fail(label + ": " + shown + " is negative; " + name + " is a set of bits");
    }
    constexpr auto highest = static_cast<std::uint64_t>(std::numeric_limits<T>::max());
    const std::uint64_t most = negative ? highest + (is_signed ? 1 : 0) : highest;
    if (magnitude > most) {
        where.fail(label + ": " + shown + " is out of range (" + std::to_string(std::numeric_limits<T>::min()) +
                   " to " + std::to_string(std::numeric_limits<T>::max()) + ")");
    }
    if (negative) {
        // Two's complement of the magnitude, which fits: -2^31 included.
        return static_cast<T>(-static_cast<std::int64_t>(magnitude));
    }
    return static_cast<T>(magnitude);
}

}  // namespace

filter_columns read_filters(line_reader& lines, std::uint64_t rect_count, const std::string& rect_file) {
    filter_columns out;
    std::string_view line;
    while (lines.next(line)) {
        if (is_skipped_line(line)) {
            continue;
        }
        if (lines.line_number() == 1 && is_header_line(line, lines, {filter_header}, "filter line")) {
            continue;
        }
        if (out.groups.size() == rect_count) {
            lines.fail("one filter line more than the " + std::to_string(rect_count) + " rectangles of " + rect_file);
        }
        std::string_view fields[3];
        std::size_t count = 0;
        for (std::size_t start = 0;;) {
            const std::size_t comma = line.find(',', start);
            if (count < 3) {
                fields[count] = trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
            }
            ++count;
            if (comma == std::string_view::npos) {
                break;
            }
            start = comma + 1;
        }
        if (count != 3) {
            lines.fail("expected 3 comma-separated fields (category,mask,group), found " + std::to_string(count));
        }
        out.categories.push_back(parse_integer<std::uint64_t>(fields[0], 0, "category", lines));
        out.masks.push_back(parse_integer<std::uint64_t>(fields[1], 1, "mask", lines));
        out.groups.push_back(parse_integer<std::int32_t>(fields[2], 2, "group", lines));
    }
    if (out.groups.size() != rect_count) {
        throw input_error(lines.name(), 0,
                          std::to_string(out.groups.size()) + " filter lines for the " + std::to_string(rect_count) +
                              " rectangles of " + rect_file + ": one line per rectangle");
    }
    return out;
}

}  // namespace obbsat::io
