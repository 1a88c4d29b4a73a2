// The reader of the CLI's pair-filter files (`obbsat pairs --filters`): one
// line per rectangle of the file it goes with, giving that rectangle's pair
// filters (obbsat/pair_filters.hpp), with errors that name file and line.
//
// Format (the common rules of csv_input.hpp: blank and '#' lines skipped,
// blanks around fields ignored, "\r\n" line ends):
//   - Line 1 may be the header `category,mask,group` (filter_header).
//   - Each record line holds 3 fields category,mask,group: category and mask
//     unsigned 64-bit integers, group a signed 32-bit integer, each decimal
//     or hexadecimal with a 0x prefix ("-0x10" for a group); nothing else
//     (no '+', no fraction, no value out of range).
//   - There are exactly as many record lines as rectangles: the i-th gives
//     rectangle i's filters (record numbers, blank and comment lines not
//     counted, as the pairs count them).
#pragma once

#include "io/csv_input.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace obbsat::io {

inline constexpr std::string_view filter_header = "category,mask,group";

/// The filters of every rectangle of a file, one entry per rectangle.
struct filter_columns {
    std::vector<std::uint64_t> categories;
    std::vector<std::uint64_t> masks;
    std::vector<std::int32_t> groups;
};

/// Reads `lines`, which must hold one record per rectangle of `rect_file`
/// (`rect_count` of them); throws input_error naming the file and line of a
/// bad field or of the first extra line, or the file when lines are missing.
filter_columns read_filters(line_reader& lines, std::uint64_t rect_count, const std::string& rect_file);

}  // namespace obbsat::io
