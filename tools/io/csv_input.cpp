#include "io/csv_input.hpp"

#include <obbsat/pose.hpp>
#include <obbsat/rect_soa.hpp>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>

#include <sys/stat.h>

namespace obbsat::io {

namespace {

std::string located_message(const std::string& file, std::uint64_t line,
                            const std::string& reason) {
    if (line == 0) {
        return file + ": " + reason;
    }
    return file + ":" + std::to_string(line) + ": " + reason;
}

// A field as an error message shows it: quoted, control bytes escaped, and cut
// short, so a binary file or a megabyte-long field gives a readable message.
std::string quoted(std::string_view field) {
    constexpr std::size_t shown = 40;
    std::string out = "'";
    for (std::size_t i = 0; i < field.size() && i < shown; ++i) {
        const auto c = static_cast<unsigned char>(field[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            constexpr char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 0xf];
        }
    }
    if (field.size() > shown) {
        out += "...";
    }
    out += "'";
    return out;
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
    std::size_t begin = 0;
    std::size_t end = s.size();
    while (begin < end && is_blank(s[begin])) {
        ++begin;
    }
    while (end > begin && is_blank(s[end - 1])) {
        --end;
    }
    return s.substr(begin, end - begin);
}

// Splits `line` at commas into its first (up to N) trimmed fields; returns
// how many fields the line has, more than N when it has more.
template <std::size_t N>
std::size_t split_at_commas(std::string_view line, std::array<std::string_view, N>& fields) {
    std::size_t count = 0;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        const std::string_view field =
            line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (count < N) {
            fields[count] = trimmed(field);
        }
        ++count;
        if (comma == std::string_view::npos) {
            return count;
        }
        start = comma + 1;
    }
}

[[noreturn]] void fail_field_count(const line_reader& where, const std::string& expected,
                                   const char* layout, std::size_t found) {
    where.fail("expected " + expected + " comma-separated fields (" + layout + "), found " +
               std::to_string(found));
}

// Splits `line` at commas into exactly N trimmed fields, or fails naming how
// many fields the line really has.
template <std::size_t N>
std::array<std::string_view, N> split_fields(std::string_view line, const line_reader& where,
                                             const char* record_name) {
    std::array<std::string_view, N> fields;
    const std::size_t count = split_at_commas(line, fields);
    if (count != N) {
        fail_field_count(where, std::to_string(N), record_name, count);
    }
    return fields;
}

std::string field_label(std::size_t index, const char* name) {
    return "field " + std::to_string(index + 1) + " (" + name + ")";
}

// The common number, read by std::from_chars: a decimal float, or a C99 hex
// float "0x..." ("-0x...", "0X..."), consumed whole and finite. Anything else
// (a '+', an infinity, a NaN, a value beyond the type's range or one that
// underflows, text that is not a number) returns false and takes the strtof
// (strtod) path below, which accepts and refuses exactly as before and gives
// the precise error. On the forms both read, both round correctly to nearest,
// so they give the same value; tests/cli/test_csv_input.cpp checks it. `Real`
// is float (the float stores) or double (--precision double).
template <class Real>
bool parse_plain_number(std::string_view field, Real& out) {
    const char* const first = field.data();
    const char* const last = first + field.size();
    const char* digits = first;
    const bool negative = digits != last && *digits == '-';
    if (negative) {
        ++digits;
    }
    Real value = 0;
    std::from_chars_result result{};
    if (last - digits > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
        // from_chars reads hex without its prefix, and would take a sign
        // after it, which strtof refuses.
        digits += 2;
        if (*digits == '-' || *digits == '+') {
            return false;
        }
        result = std::from_chars(digits, last, value, std::chars_format::hex);
        value = negative ? -value : value;
    } else {
        result = std::from_chars(first, last, value);
    }
    if (result.ec != std::errc() || result.ptr != last || !std::isfinite(value)) {
        return false;
    }
    out = value;
    return true;
}

// strtof or strtod, as the type read asks.
float parse_c_number(const char* text, char** stop, float) { return std::strtof(text, stop); }
double parse_c_number(const char* text, char** stop, double) { return std::strtod(text, stop); }

const char* range_text(float) { return "float range (magnitude above 3.40282347e+38)"; }
const char* range_text(double) { return "double range (magnitude above 1.7976931348623157e+308)"; }

// The number in `field`, the field at 0-based `index` called `name`: every
// number of the rectangle and pose files is read here, as a float or (for
// the double stores) a double.
template <class Real>
Real parse_number(std::string_view field, std::size_t index, const char* name, const line_reader& where) {
    Real plain = 0;
    if (parse_plain_number(field, plain)) {
        return plain;
    }
    if (field.empty()) {
        where.fail(field_label(index, name) + " is empty");
    }
    // strtof needs a terminated string; fields of sane length use the stack.
    std::array<char, 128> small;
    std::string large;
    const char* text = nullptr;
    if (field.size() < small.size()) {
        std::memcpy(small.data(), field.data(), field.size());
        small[field.size()] = '\0';
        text = small.data();
    } else {
        large.assign(field);
        text = large.c_str();
    }
    char* stop = nullptr;
    errno = 0;
    const Real value = parse_c_number(text, &stop, Real{});
    const int parse_errno = errno;
    if (stop != text + field.size()) {
        where.fail(field_label(index, name) + ": " + quoted(field) + " is not a number");
    }
    if (std::isinf(value) && parse_errno == ERANGE) {
        where.fail(field_label(index, name) + ": " + quoted(field) + " is out of " + range_text(Real{}));
    }
    if (!std::isfinite(value)) {
        where.fail(field_label(index, name) + ": " + quoted(field) + " is not finite");
    }
    // ERANGE with a finite result is underflow: the value rounded to a
    // subnormal or to zero, which is a valid number, so it is accepted.
    return value;
}

std::uint32_t parse_index(std::string_view field, std::size_t index, const char* name,
                          const line_reader& where) {
    if (field.empty()) {
        where.fail(field_label(index, name) + " is empty");
    }
    if (field.front() == '-') {
        where.fail(field_label(index, name) + ": " + quoted(field) +
                   " is negative; indices are 0-based and unsigned");
    }
    std::uint64_t value = 0;
    const char* const first = field.data();
    const char* const last = field.data() + field.size();
    const auto [stop, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::invalid_argument || stop != last) {
        where.fail(field_label(index, name) + ": " + quoted(field) +
                   " is not an unsigned decimal integer");
    }
    if (ec == std::errc::result_out_of_range || value > UINT32_MAX) {
        where.fail(field_label(index, name) + ": " + quoted(field) +
                   " is too large for a 32-bit index (largest 4294967295)");
    }
    return static_cast<std::uint32_t>(value);
}

}  // namespace

input_error::input_error(std::string file, std::uint64_t line, std::string reason)
    : std::runtime_error(located_message(file, line, reason)),
      file_(std::move(file)),
      line_(line),
      reason_(std::move(reason)) {}

input_file::input_file(const std::string& path) {
    if (path == "-") {
        file_ = stdin;
        name_ = "<stdin>";
        return;
    }
    name_ = path;
    file_ = std::fopen(path.c_str(), "rb");
    if (file_ == nullptr) {
        throw input_error(path, 0, std::string("cannot open: ") + std::strerror(errno));
    }
    owned_ = true;
}

input_file::~input_file() {
    if (owned_) {
        std::fclose(file_);
    }
}

bool same_input(const input_file& a, const input_file& b) {
    struct stat sa {};
    struct stat sb {};
    return ::fstat(::fileno(a.get()), &sa) == 0 && ::fstat(::fileno(b.get()), &sb) == 0 &&
           sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

line_reader::line_reader(std::FILE* file, std::string name, std::size_t chunk_bytes,
                         std::size_t max_line_bytes)
    : file_(file),
      name_(std::move(name)),
      buffer_(chunk_bytes == 0 ? 1 : chunk_bytes),
      max_line_bytes_(max_line_bytes) {}

line_reader::line_reader(std::string_view text, std::string name, std::size_t chunk_bytes,
                         std::size_t max_line_bytes)
    : text_(text),
      name_(std::move(name)),
      buffer_(chunk_bytes == 0 ? 1 : chunk_bytes),
      max_line_bytes_(max_line_bytes) {}

void line_reader::fail(const std::string& reason) const {
    throw input_error(name_, line_number_, reason);
}

void line_reader::fail_line_too_long() const {
    throw input_error(name_, line_number_ + 1,
                      "line is longer than " + std::to_string(max_line_bytes_) + " bytes");
}

void line_reader::refill() {
    if (begin_ != 0) {
        std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
        end_ -= begin_;
        begin_ = 0;
    }
    if (end_ == buffer_.size()) {
        // The whole buffer is one unfinished line: grow, up to the longest
        // line allowed plus its line end ("\r\n"); a full buffer of that size
        // holds more than max_line_bytes_ of one line.
        const std::size_t most =
            max_line_bytes_ > SIZE_MAX - 2 ? SIZE_MAX : max_line_bytes_ + 2;
        if (buffer_.size() >= most) {
            fail_line_too_long();
        }
        buffer_.resize(std::min(buffer_.size() * 2, most));
    }
    const std::size_t room = buffer_.size() - end_;
    std::size_t got = 0;
    if (file_ != nullptr) {
        got = std::fread(buffer_.data() + end_, 1, room, file_);
        if (got < room && std::ferror(file_)) {
            throw input_error(name_, 0, std::string("read error: ") + std::strerror(errno));
        }
    } else {
        got = std::min(room, text_.size());
        std::memcpy(buffer_.data() + end_, text_.data(), got);
        text_.remove_prefix(got);
    }
    end_ += got;
    if (got == 0) {
        input_done_ = true;
    }
}

bool line_reader::next(std::string_view& line) {
    for (;;) {
        const char* const base = buffer_.data();
        const std::size_t from = begin_ + scanned_;
        const void* found = std::memchr(base + from, '\n', end_ - from);
        std::size_t line_end = 0;
        std::size_t resume = 0;
        if (found != nullptr) {
            line_end = static_cast<std::size_t>(static_cast<const char*>(found) - base);
            resume = line_end + 1;
        } else if (input_done_) {
            if (begin_ == end_) {
                return false;
            }
            line_end = end_;
            resume = end_;
        } else {
            scanned_ = end_ - begin_;
            refill();
            continue;
        }
        line = std::string_view(base + begin_, line_end - begin_);
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        // A buffer larger than the limit (a large chunk size) can hold a
        // longer line whole; the limit is the same for every chunk size.
        if (line.size() > max_line_bytes_) {
            fail_line_too_long();
        }
        // Spreadsheets often start a CSV file with a UTF-8 byte order mark.
        constexpr std::string_view byte_order_mark = "\xef\xbb\xbf";
        if (line_number_ == 0 && line.substr(0, byte_order_mark.size()) == byte_order_mark) {
            line.remove_prefix(byte_order_mark.size());
        }
        begin_ = resume;
        scanned_ = 0;
        ++line_number_;
        return true;
    }
}

bool is_skipped_line(std::string_view line) {
    const std::string_view content = trimmed(line);
    return content.empty() || content.front() == '#';
}

namespace {

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
        if (lower(a[i]) != lower(b[i])) {
            return false;
        }
    }
    return true;
}

// A field that is a column name rather than a number: it starts with a
// letter, '_' or '"' (a quoted name) and is not a word strtof reads (inf,
// infinity, nan, nan(...)).
bool is_name(std::string_view field) {
    if (field.empty()) {
        return false;
    }
    const char c = field.front();
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '"';
    if (!letter) {
        return false;
    }
    if (equals_ignoring_case(field, "inf") || equals_ignoring_case(field, "infinity") ||
        equals_ignoring_case(field, "nan")) {
        return false;
    }
    return !(field.size() >= 4 && equals_ignoring_case(field.substr(0, 4), "nan("));
}

// Every field of `line` is a name: it was meant as a header.
bool is_header_attempt(std::string_view line) {
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        const std::string_view field =
            line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (!is_name(trimmed(field))) {
            return false;
        }
        if (comma == std::string_view::npos) {
            return true;
        }
        start = comma + 1;
    }
}

std::string header_list(std::initializer_list<std::string_view> headers) {
    std::string out;
    std::size_t k = 0;
    for (const std::string_view h : headers) {
        out += k == 0 ? "" : (k + 1 == headers.size() ? " or " : ", ");
        out += "'" + std::string(h) + "'";
        ++k;
    }
    return out;
}

}  // namespace

bool is_header_line(std::string_view line, const line_reader& where, std::initializer_list<std::string_view> headers,
                    const char* record_name) {
    if (where.line_number() != 1) {
        return false;
    }
    for (const std::string_view h : headers) {
        if (line == h) {
            return true;
        }
    }
    if (is_header_attempt(line)) {
        where.fail("expected the header " + header_list(headers) + " or a " + record_name + ", found " +
                   quoted(line));
    }
    return false;
}

namespace {

// The eight corner coordinates of a line, as `Real`.
template <class Real>
std::array<Real, coord_count> corner_values(std::string_view line, const line_reader& where) {
    const auto fields = split_fields<coord_count>(line, where, "ulx,uly,urx,ury,lrx,lry,llx,lly");
    std::array<Real, coord_count> v{};
    for (std::size_t k = 0; k < coord_count; ++k) {
        v[k] = parse_number<Real>(fields[k], k, coord_name(static_cast<coord>(k)), where);
    }
    return v;
}

// A pose line's values as `Real`: cx, cy, hx, hy and either c, s (`count` 6)
// or the angle (`count` 5), with the half extents and the rotation vector
// checked; the pose is built by the caller, who knows how to turn an angle.
template <class Real>
struct pose_values {
    std::array<Real, 6> v{};
    std::size_t count = 0;
};

template <class Real>
pose_values<Real> pose_line_values(std::string_view line, const line_reader& where) {
    // Field 5 is the angle on a line of five fields, c on a line of six.
    constexpr const char* names[6] = {"cx", "cy", "hx", "hy", "c", "s"};
    std::array<std::string_view, 6> fields;
    pose_values<Real> out;
    out.count = split_at_commas(line, fields);
    if (out.count != 5 && out.count != 6) {
        fail_field_count(where, "5 or 6", "cx,cy,hx,hy,angle or cx,cy,hx,hy,c,s", out.count);
    }
    const bool has_angle = out.count == 5;
    for (std::size_t k = 0; k < out.count; ++k) {
        const char* name = has_angle && k == 4 ? "angle" : names[k];
        out.v[k] = parse_number<Real>(fields[k], k, name, where);
        // -0 and values that round to -0 are zero, and accepted.
        if ((k == 2 || k == 3) && out.v[k] < 0) {
            where.fail(field_label(k, name) + ": " + quoted(fields[k]) +
                       " is negative (a half extent must be >= 0)");
        }
    }
    if (!has_angle && out.v[4] == 0 && out.v[5] == 0) {
        where.fail("fields 5 and 6 (c, s): " + quoted(fields[4]) + ", " + quoted(fields[5]) +
                   " make the rotation vector (0, 0), which has no direction");
    }
    return out;
}

}  // namespace

rect parse_rect_line(std::string_view line, const line_reader& where) {
    const auto v = corner_values<float>(line, where);
    return rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}

rect64 parse_rect64_line(std::string_view line, const line_reader& where) {
    const auto v = corner_values<double>(line, where);
    return rect64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}

rect_pose parse_pose_line(std::string_view line, const line_reader& where) {
    const pose_values<float> p = pose_line_values<float>(line, where);
    const point center{p.v[0], p.v[1]};
    const point half_extents{p.v[2], p.v[3]};
    if (p.count == 5) {
        return rect_pose_of(pose{center, half_extents, p.v[4]});
    }
    return rect_pose{center, half_extents, point{p.v[4], p.v[5]}};
}

rect_pose64 parse_pose64_line(std::string_view line, const line_reader& where) {
    const pose_values<double> p = pose_line_values<double>(line, where);
    const point64 center{p.v[0], p.v[1]};
    const point64 half_extents{p.v[2], p.v[3]};
    if (p.count == 5) {
        // (cos, sin) of a finite angle is never (0, 0): cos and sin are not
        // both zero, rounded or not.
        return rect_pose64{center, half_extents, point64{std::cos(p.v[4]), std::sin(p.v[4])}};
    }
    return rect_pose64{center, half_extents, point64{p.v[4], p.v[5]}};
}

pair_index parse_pair_line(std::string_view line, const line_reader& where,
                           std::uint64_t rect_count, const std::string& rect_file) {
    const auto fields = split_fields<2>(line, where, "i,j");
    const std::uint32_t a = parse_index(fields[0], 0, "i", where);
    const std::uint32_t b = parse_index(fields[1], 1, "j", where);
    if (a >= rect_count || b >= rect_count) {
        const std::uint32_t bad = a >= rect_count ? a : b;
        if (rect_count == 0) {
            where.fail("index " + std::to_string(bad) + " refers to a rectangle, but " + rect_file +
                       " holds none");
        }
        where.fail("index " + std::to_string(bad) + " is out of range: " + rect_file + " holds " +
                   std::to_string(rect_count) + " rectangles (indices 0 to " +
                   std::to_string(rect_count - 1) + ")");
    }
    return pair_index{a, b};
}

namespace {

// Every record of `lines` parsed by `parse`, into a store of `Store`; `plural`
// names the records in the error for more than `max_records` of them. A first
// line equal to one of `headers` is skipped; `progress`, if set, hears the
// count every progress_interval records.
template <class Store, class Parse>
Store read_records(line_reader& lines, std::uint64_t max_records, const std::string& plural,
                   std::initializer_list<std::string_view> headers, const char* record_name,
                   const record_progress& progress, Parse parse) {
    Store store;
    std::string_view line;
    while (lines.next(line)) {
        if (is_skipped_line(line)) {
            continue;
        }
        if (lines.line_number() == 1 && is_header_line(line, lines, headers, record_name)) {
            continue;
        }
        if (store.size() >= max_records) {
            lines.fail("more than " + std::to_string(max_records) + " " + plural + "; pairs index " +
                       plural + " with 32-bit indices");
        }
        store.push_back(parse(line, lines));
        if (progress && store.size() % progress_interval == 0) {
            progress(store.size());
        }
    }
    return store;
}

}  // namespace

rect_soa read_rects(line_reader& lines, std::uint64_t max_rects, const record_progress& progress) {
    return read_records<rect_soa>(lines, max_rects, "rectangles", {rect_header}, "rectangle", progress,
                                  parse_rect_line);
}

rect_records read_rect_records(line_reader& lines, std::uint64_t max_rects, const record_progress& progress) {
    return read_records<rect_records>(lines, max_rects, "rectangles", {rect_header}, "rectangle", progress,
                                      parse_rect_line);
}

pose_records read_pose_records(line_reader& lines, std::uint64_t max_poses, const record_progress& progress) {
    return read_records<pose_records>(lines, max_poses, "poses", {pose_header, pose_angle_header}, "pose",
                                      progress, parse_pose_line);
}

rect_records64 read_rect_records64(line_reader& lines, std::uint64_t max_rects, const record_progress& progress) {
    return read_records<rect_records64>(lines, max_rects, "rectangles", {rect_header}, "rectangle", progress,
                                        parse_rect64_line);
}

pose_records64 read_pose_records64(line_reader& lines, std::uint64_t max_poses, const record_progress& progress) {
    return read_records<pose_records64>(lines, max_poses, "poses", {pose_header, pose_angle_header}, "pose",
                                        progress, parse_pose64_line);
}

rect_soa read_rects_file(const std::string& path) {
    const input_file file(path);
    line_reader lines(file.get(), file.name());
    return read_rects(lines);
}

pair_reader::pair_reader(line_reader& lines, std::uint64_t rect_count, std::string rect_file)
    : lines_(lines), rect_count_(rect_count), rect_file_(std::move(rect_file)) {}

namespace {

// The common line "digits,digits" with both indices in range, parsed without
// splitting and trimming; anything else (blanks, comments, errors) returns
// false and takes the general path, which gives the same pair or the precise
// error. This roughly doubles the pair lines read per second.
bool parse_plain_pair(std::string_view line, std::uint64_t rect_count, pair_index& out) {
    const char* const last = line.data() + line.size();
    std::uint64_t a = 0;
    const auto [comma, ec_a] = std::from_chars(line.data(), last, a);
    if (ec_a != std::errc() || comma == last || *comma != ',') {
        return false;
    }
    std::uint64_t b = 0;
    const auto [stop, ec_b] = std::from_chars(comma + 1, last, b);
    if (ec_b != std::errc() || stop != last || a >= rect_count || b >= rect_count) {
        return false;
    }
    out = pair_index{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)};
    return true;
}

}  // namespace

bool pair_reader::read_chunk(std::vector<pair_index>& out, std::size_t max_pairs) {
    out.clear();
    std::string_view line;
    pair_index plain{};
    while (out.size() < max_pairs && lines_.next(line)) {
        if (parse_plain_pair(line, rect_count_, plain)) {
            out.push_back(plain);
            continue;
        }
        if (is_skipped_line(line)) {
            continue;
        }
        if (lines_.line_number() == 1 && is_header_line(line, lines_, {pair_header}, "pair")) {
            continue;
        }
        out.push_back(parse_pair_line(line, lines_, rect_count_, rect_file_));
    }
    pairs_read_ += out.size();
    return !out.empty();
}

}  // namespace obbsat::io
