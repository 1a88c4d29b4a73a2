// Readers for the CLI's input files (rectangles as corners or as poses, and
// pairs), with errors that name file and line.
//
// Format, shared by every file:
//   - One record per line; a line ends at "\n" or "\r\n"; the last line may
//     lack its line end. A UTF-8 byte order mark at the start is ignored.
//   - A line that is empty or holds only blanks (space, tab) is skipped, and so
//     is a line whose first non-blank character is '#' (a comment).
//   - Fields are separated by ','; blanks around a field are ignored.
//   - Line 1 may be a header naming the columns, exactly one of the headers
//     below (rect_header, pose_header, pose_angle_header, pair_header); it is
//     skipped. A line 1 whose every field is a name (starts with a letter, '"' or
//     '_', and is not inf, infinity, nan or nan(...)) but that is not such a
//     header is an error naming the headers expected.
//   - Rectangle file: 8 fields ulx,uly,urx,ury,lrx,lry,llx,lly, each a number
//     strtof reads completely in the "C" locale (decimal or C99 hex float; the
//     common forms are read by std::from_chars, to the same float). A
//     value that overflows float, or is an infinity or a NaN, is rejected; a
//     value that rounds to a subnormal or to zero is accepted as rounded.
//   - Pose file: per line either 6 fields cx,cy,hx,hy,c,s (obbsat/rect_pose.hpp)
//     or 5 fields cx,cy,hx,hy,angle (radians, turned into (c, s) by
//     rect_pose_of(const pose&)); the two kinds of line may be mixed. Numbers
//     as in the rectangle file; a half extent below zero (-0 is zero) and a
//     rotation vector (0, 0) are rejected.
//   - With --precision double, the same files are read into the double
//     stores (obbsat/rect_records64.hpp, pose_records64.hpp): every number as
//     std::from_chars or strtod reads it (decimal or hex), a value beyond
//     double range is rejected, and the same checks apply.
//   - Pair file: 2 fields i,j, each an unsigned decimal index below the number
//     of rectangles or poses (so at most 4294967294).
// Line numbers count every line of the file from 1, skipped lines included.
#pragma once

#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace obbsat::io {

/// The header line each kind of file may start with; `obbsat gen --header`,
/// `obbsat pairs --header` and `obbsat collide --header` write them.
inline constexpr std::string_view rect_header = "ulx,uly,urx,ury,lrx,lry,llx,lly";
inline constexpr std::string_view pose_header = "cx,cy,hx,hy,c,s";
/// A pose file may name its fifth column angle instead; both kinds of line
/// may follow either header.
inline constexpr std::string_view pose_angle_header = "cx,cy,hx,hy,angle";
inline constexpr std::string_view pair_header = "i,j";
/// The header of `obbsat collide --header`'s output (it is read by no reader).
inline constexpr std::string_view verdict_header = "verdict";

/// Hears how many records a reader has stored, every progress_interval records.
using record_progress = std::function<void(std::uint64_t records)>;
inline constexpr std::uint64_t progress_interval = std::uint64_t{1} << 16;

/// A file that cannot be read as the format demands; what() is
/// "FILE:LINE: reason", or "FILE: reason" when no single line is at fault.
class input_error : public std::runtime_error {
public:
    input_error(std::string file, std::uint64_t line, std::string reason);

    const std::string& file() const { return file_; }
    /// 1-based line number, 0 when the error concerns the whole file.
    std::uint64_t line() const { return line_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_;
    std::uint64_t line_;
    std::string reason_;
};

/// A FILE* opened for reading, closed when it goes out of scope.
class input_file {
public:
    /// Opens `path`, or standard input when `path` is "-"; throws input_error.
    explicit input_file(const std::string& path);
    ~input_file();
    input_file(const input_file&) = delete;
    input_file& operator=(const input_file&) = delete;

    std::FILE* get() const { return file_; }
    /// The name errors use: the path, or "<stdin>".
    const std::string& name() const { return name_; }

private:
    std::FILE* file_ = nullptr;
    bool owned_ = false;
    std::string name_;
};

/// True iff `a` and `b` read one and the same file (device and inode), as "-",
/// "/dev/stdin" and "/proc/self/fd/0" do.
bool same_input(const input_file& a, const input_file& b);

/// The lines of a file or of text in memory, read in large chunks so that a
/// line may cross a chunk boundary; memory stays bounded by the longest line.
class line_reader {
public:
    static constexpr std::size_t default_chunk_bytes = std::size_t{1} << 20;
    static constexpr std::size_t default_max_line_bytes = std::size_t{16} << 20;

    /// Lines of `file` (not owned); `name` is what errors call it.
    line_reader(std::FILE* file, std::string name, std::size_t chunk_bytes = default_chunk_bytes,
                std::size_t max_line_bytes = default_max_line_bytes);
    /// Lines of `text` (not copied, must outlive the reader), read through the
    /// same chunked path as a file.
    line_reader(std::string_view text, std::string name,
                std::size_t chunk_bytes = default_chunk_bytes,
                std::size_t max_line_bytes = default_max_line_bytes);
    /// A temporary string would be gone before its lines are read.
    line_reader(std::string&& text, std::string name, std::size_t chunk_bytes = 0,
                std::size_t max_line_bytes = 0) = delete;

    /// The next line without its line end, valid until the next call; false
    /// at the end of input. Throws input_error on a read error or a line
    /// longer than max_line_bytes.
    bool next(std::string_view& line);

    /// The 1-based number of the line next() returned last.
    std::uint64_t line_number() const { return line_number_; }
    const std::string& name() const { return name_; }

    /// Throws input_error for the line next() returned last.
    [[noreturn]] void fail(const std::string& reason) const;

private:
    void refill();
    [[noreturn]] void fail_line_too_long() const;

    std::FILE* file_ = nullptr;
    std::string_view text_;
    std::string name_;
    std::vector<char> buffer_;
    std::size_t max_line_bytes_;
    std::size_t begin_ = 0;    // first unread byte in buffer_
    std::size_t end_ = 0;      // one past the last filled byte in buffer_
    std::size_t scanned_ = 0;  // bytes from begin_ known to hold no '\n'
    bool input_done_ = false;
    std::uint64_t line_number_ = 0;
};

/// True iff `line` is blank or a comment, so it holds no record.
bool is_skipped_line(std::string_view line);

/// True iff `line`, the record line `where` returned last, is line 1 and
/// equals one of `headers`. Throws input_error if it is line 1 and every field
/// is a name (a header, but not one of these), naming the headers and the
/// `record_name` expected.
bool is_header_line(std::string_view line, const line_reader& where, std::initializer_list<std::string_view> headers,
                    const char* record_name);

/// The rectangle on one line (8 fields); throws input_error through `where`.
rect parse_rect_line(std::string_view line, const line_reader& where);

/// The pose on one line (5 or 6 fields); throws input_error through `where`.
rect_pose parse_pose_line(std::string_view line, const line_reader& where);

/// The rectangle on one line read in double (--precision double): every
/// number as std::from_chars or strtod reads it, so decimal text with more
/// digits than a float holds keeps them; a value beyond double range is an
/// error. Throws input_error through `where`.
rect64 parse_rect64_line(std::string_view line, const line_reader& where);

/// The pose on one line read in double, with the checks of parse_pose_line;
/// an angle gives (c, s) = (cos, sin) in double. Throws input_error through `where`.
rect_pose64 parse_pose64_line(std::string_view line, const line_reader& where);

/// The pair on one line (2 fields), each index below `rect_count`; throws
/// input_error through `where`, naming `rect_file` when an index is out of range.
pair_index parse_pair_line(std::string_view line, const line_reader& where,
                           std::uint64_t rect_count, const std::string& rect_file);

/// Every rectangle of `lines`, as arrays per coordinate. More than `max_rects`
/// rectangles is an error (pairs address rectangles with 32-bit indices).
rect_soa read_rects(line_reader& lines, std::uint64_t max_rects = UINT32_MAX,
                    const record_progress& progress = {});

/// Every rectangle of `lines`, as packed records (the faster store for pair
/// lists, see rect_records.hpp); the same checks as read_rects.
rect_records read_rect_records(line_reader& lines, std::uint64_t max_rects = UINT32_MAX,
                               const record_progress& progress = {});

/// Every pose of `lines`, as packed records; more than `max_poses` poses is an
/// error, as for read_rects.
pose_records read_pose_records(line_reader& lines, std::uint64_t max_poses = UINT32_MAX,
                               const record_progress& progress = {});

/// Every rectangle of `lines` read in double (parse_rect64_line), as double
/// records; the same checks and limits as read_rect_records.
rect_records64 read_rect_records64(line_reader& lines, std::uint64_t max_rects = UINT32_MAX,
                                   const record_progress& progress = {});

/// Every pose of `lines` read in double (parse_pose64_line), as double records.
pose_records64 read_pose_records64(line_reader& lines, std::uint64_t max_poses = UINT32_MAX,
                                   const record_progress& progress = {});

/// Every rectangle of the file at `path`.
rect_soa read_rects_file(const std::string& path);

/// The pairs of a pair file, a bounded chunk at a time, each checked against
/// the number of rectangles they index.
class pair_reader {
public:
    /// `rect_file` names the rectangle file in errors about indices.
    pair_reader(line_reader& lines, std::uint64_t rect_count, std::string rect_file);

    /// Replaces the content of `out` with the next up to `max_pairs` pairs;
    /// false when there are none left. Throws input_error on a bad line.
    bool read_chunk(std::vector<pair_index>& out, std::size_t max_pairs);

    /// Pairs returned so far.
    std::uint64_t pairs_read() const { return pairs_read_; }

private:
    line_reader& lines_;
    std::uint64_t rect_count_;
    std::string rect_file_;
    std::uint64_t pairs_read_ = 0;
};

}  // namespace obbsat::io
