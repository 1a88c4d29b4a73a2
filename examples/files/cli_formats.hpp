// The obbsat program's three file formats, read and written with the standard
// library only:
//   rectangles  one per line: ulx,uly,urx,ury,lrx,lry,llx,lly (decimal or C99 hex floats)
//   pairs       one per line: i,j (0-based indices into the rectangle file)
//   verdicts    one per line: 0 or 1
// Line 1 may be the file's header (ulx,uly,urx,ury,lrx,lry,llx,lly, i,j or
// verdict, as 'obbsat ... --header' writes it), which is skipped.
// Blank lines and lines whose first non-blank character is '#' hold no record;
// blanks around a field are ignored; lines may end in "\n" or "\r\n".
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace cli_formats {

/// A file that breaks its format; what() is "FILE:LINE: reason" (or "FILE: reason").
class format_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Every rectangle of the file at `path`; throws format_error.
std::vector<obbsat::rect> read_rects(const std::string& path);

/// Every pair of the file at `path`, each index below `rect_count` (the number
/// of rectangles in `rect_path`, which errors name); throws format_error.
std::vector<obbsat::pair_index> read_pairs(const std::string& path, std::size_t rect_count,
                                           const std::string& rect_path);

/// Every verdict of the file at `path`; throws format_error.
std::vector<std::uint8_t> read_verdicts(const std::string& path);

/// Writes rectangles with the fewest digits that read back to the same floats.
/// Like every writer here, the file appears whole or not at all; throws
/// std::runtime_error naming the path.
void write_rects(const std::string& path, const std::vector<obbsat::rect>& rects);

/// Writes one "i,j" line per pair.
void write_pairs(const std::string& path, const std::vector<obbsat::pair_index>& pairs);

/// Writes one "0" or "1" line per verdict.
void write_verdicts(const std::string& path, const std::vector<std::uint8_t>& verdicts);

}  // namespace cli_formats
