// Fuzz target: arbitrary bytes as a rectangle file, a pose file and a pair
// file through the readers of the obbsat program (obbsat_io). Each file must
// either parse or throw obbsat::io::input_error naming the file (and a line
// that exists); anything else (another exception, a crash, a hang) is a
// failure. What was read must not depend on how the input is cut into chunks,
// both rectangle stores must read the same rectangles, and every pose read
// must be valid (finite, half extents >= 0, rotation not (0, 0)).
//
// Input format: byte 0 picks the read chunk size, byte 1 a limit on the
// number of rectangles, byte 2 a limit on the line length, byte 3 the pair
// chunk size and the rectangle count used for the pair file when the
// rectangle file is refused, bytes 4-5 the length of the rectangle file
// (little-endian); the rest is the pair file. The rectangle file's bytes are
// read as a pose file too.
#include "fuzz_bytes.hpp"

#include "io/csv_input.hpp"

#include <obbsat/pose_records.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace {

using obbsat::pair_index;
using obbsat::rect;
using obbsat::fuzz::byte_source;
using obbsat::io::input_error;
using obbsat::io::line_reader;

[[noreturn]] void stop(const std::string& what) {
    std::fprintf(stderr, "fuzz_csv: %s\n", what.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

// What reading one file gave: its records, or the error's message.
template <class Value>
struct outcome {
    std::vector<Value> values;
    std::optional<std::string> error;
};

std::uint64_t line_count(std::string_view text) {
    std::uint64_t lines = 1;
    for (const char c : text) {
        lines += c == '\n' ? 1 : 0;
    }
    return lines;
}

void check_error(const input_error& e, const std::string& file, std::string_view text) {
    if (e.file() != file) {
        stop("an error about " + file + " names '" + e.file() + "': " + e.what());
    }
    if (e.line() > line_count(text)) {
        stop("an error names line " + std::to_string(e.line()) + " of a text with " +
             std::to_string(line_count(text)) + " lines: " + e.what());
    }
    if (e.reason().empty() || std::string(e.what()).rfind(file + ":", 0) != 0) {
        stop(std::string("an error message does not start with the file name: ") + e.what());
    }
}

std::vector<rect> as_vector(const obbsat::rect_records& records) {
    return std::vector<rect>(records.data(), records.data() + records.size());
}

std::vector<rect> as_vector(const obbsat::rect_soa& soa) {
    std::vector<rect> out;
    for (std::size_t i = 0; i < soa.size(); ++i) {
        out.push_back(soa[i]);
    }
    return out;
}

template <class Store>
outcome<rect> read_rects(std::string_view text, std::size_t chunk_bytes, std::size_t max_line_bytes,
                         std::uint64_t max_rects) {
    outcome<rect> out;
    line_reader lines(text, "R.csv", chunk_bytes, max_line_bytes);
    try {
        Store store;
        if constexpr (std::is_same_v<Store, obbsat::rect_records>) {
            store = obbsat::io::read_rect_records(lines, max_rects);
        } else {
            store = obbsat::io::read_rects(lines, max_rects);
        }
        out.values = as_vector(store);
    } catch (const input_error& e) {
        check_error(e, "R.csv", text);
        out.error = e.what();
    }
    for (const rect& r : out.values) {
        const float v[8] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
        for (const float c : v) {
            if (!std::isfinite(c)) {
                stop("a rectangle with a non-finite coordinate was read");
            }
        }
    }
    return out;
}

outcome<obbsat::rect_pose> read_poses(std::string_view text, std::size_t chunk_bytes,
                                     std::size_t max_line_bytes, std::uint64_t max_poses) {
    outcome<obbsat::rect_pose> out;
    line_reader lines(text, "Q.csv", chunk_bytes, max_line_bytes);
    try {
        const obbsat::pose_records poses = obbsat::io::read_pose_records(lines, max_poses);
        for (std::size_t i = 0; i < poses.size(); ++i) {
            out.values.push_back(poses[i]);
        }
    } catch (const input_error& e) {
        check_error(e, "Q.csv", text);
        out.error = e.what();
    }
    for (const obbsat::rect_pose& p : out.values) {
        const float v[6] = {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                            p.rotation.y};
        for (const float c : v) {
            if (!std::isfinite(c)) {
                stop("a pose with a non-finite value was read");
            }
        }
        if (p.half_extents.x < 0.0f || p.half_extents.y < 0.0f) {
            stop("a pose with a negative half extent was read");
        }
        if (p.rotation.x == 0.0f && p.rotation.y == 0.0f) {
            stop("a pose with the rotation vector (0, 0) was read");
        }
    }
    return out;
}

outcome<pair_index> read_pairs(std::string_view text, std::size_t chunk_bytes, std::size_t max_line_bytes,
                               std::uint64_t rect_count, std::size_t pairs_per_chunk) {
    outcome<pair_index> out;
    line_reader lines(text, "P.csv", chunk_bytes, max_line_bytes);
    obbsat::io::pair_reader reader(lines, rect_count, "R.csv");
    std::vector<pair_index> chunk;
    try {
        while (reader.read_chunk(chunk, pairs_per_chunk)) {
            if (chunk.size() > pairs_per_chunk) {
                stop("a pair chunk is larger than asked for");
            }
            out.values.insert(out.values.end(), chunk.begin(), chunk.end());
        }
    } catch (const input_error& e) {
        check_error(e, "P.csv", text);
        out.error = e.what();
    }
    if (out.values.size() != reader.pairs_read() && !out.error) {
        stop("pairs_read() differs from the pairs returned");
    }
    for (const pair_index& p : out.values) {
        if (p.a >= rect_count || p.b >= rect_count) {
            stop("a pair with an index out of range was read");
        }
    }
    return out;
}

template <class Record>
bool same_bits(const Record& x, const Record& y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// After an error only the message counts: how many records came before it
// depends on the chunk they were read in.
template <class Record>
bool same(const outcome<Record>& x, const outcome<Record>& y) {
    if (x.error || y.error) {
        return x.error == y.error;
    }
    if (x.values.size() != y.values.size()) {
        return false;
    }
    for (std::size_t i = 0; i < x.values.size(); ++i) {
        if (!same_bits(x.values[i], y.values[i])) {
            return false;
        }
    }
    return true;
}

bool same(const outcome<pair_index>& x, const outcome<pair_index>& y) {
    if (x.error || y.error) {
        return x.error == y.error;
    }
    if (x.values.size() != y.values.size()) {
        return false;
    }
    for (std::size_t i = 0; i < x.values.size(); ++i) {
        if (x.values[i].a != y.values[i].a || x.values[i].b != y.values[i].b) {
            return false;
        }
    }
    return true;
}

std::string describe(const std::optional<std::string>& error, std::size_t count) {
    return error ? "error '" + *error + "'" : std::to_string(count) + " records";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    byte_source in(data, size);
    const std::uint8_t chunk_byte = in.byte();
    const std::uint8_t limit_byte = in.byte();
    const std::uint8_t line_byte = in.byte();
    const std::uint8_t pair_byte = in.byte();
    const std::string_view rect_text = in.text(in.u16());
    const std::string_view pair_text = in.text(in.remaining());

    // One chunk that holds the whole text; the default (1 MiB, cleared on
    // construction) would cost more than the parse itself.
    const std::size_t whole_rects = rect_text.size() + 1;
    const std::size_t whole_pairs = pair_text.size() + 1;
    constexpr std::size_t default_line = line_reader::default_max_line_bytes;
    const std::size_t chunk = 1 + chunk_byte % 97;
    const std::uint64_t max_rects = (limit_byte & 0x80) != 0 ? limit_byte & 0x7f : UINT32_MAX;

    // Every input here is far below the default line limit, so no line is
    // too long and the result must be the same for every chunk size.
    const outcome<rect> records = read_rects<obbsat::rect_records>(rect_text, chunk, default_line, max_rects);
    const outcome<rect> whole = read_rects<obbsat::rect_records>(rect_text, whole_rects, default_line, max_rects);
    const outcome<rect> soa = read_rects<obbsat::rect_soa>(rect_text, chunk, default_line, max_rects);
    if (!same(records, whole)) {
        stop("rectangles read in chunks of " + std::to_string(chunk) + " bytes: " +
             describe(records.error, records.values.size()) + "; in one chunk: " +
             describe(whole.error, whole.values.size()));
    }
    if (!same(records, soa)) {
        stop("rect_records read " + describe(records.error, records.values.size()) + ", rect_soa " +
             describe(soa.error, soa.values.size()));
    }
    // A small line limit must give a clean error or the same result, never anything else.
    if (line_byte != 0) {
        const std::size_t small_line = 1 + line_byte;
        const outcome<rect> limited = read_rects<obbsat::rect_records>(rect_text, chunk, small_line, max_rects);
        if (!limited.error && !same(limited, records)) {
            stop("a line limit of " + std::to_string(small_line) + " bytes changed what was read");
        }
    }

    // The same bytes as a pose file.
    const outcome<obbsat::rect_pose> poses = read_poses(rect_text, chunk, default_line, max_rects);
    const outcome<obbsat::rect_pose> whole_poses = read_poses(rect_text, whole_rects, default_line, max_rects);
    if (!same(poses, whole_poses)) {
        stop("poses read in chunks of " + std::to_string(chunk) + " bytes: " +
             describe(poses.error, poses.values.size()) + "; in one chunk: " +
             describe(whole_poses.error, whole_poses.values.size()));
    }
    if (line_byte != 0) {
        const outcome<obbsat::rect_pose> limited = read_poses(rect_text, chunk, 1 + line_byte, max_rects);
        if (!limited.error && !same(limited, poses)) {
            stop("a line limit changed the poses read");
        }
    }

    // Index checks: the rectangles read, or a count that reaches the 32-bit
    // limit when the rectangle file was refused.
    const std::uint64_t rect_count = !records.error        ? records.values.size()
                                     : (pair_byte & 0x80) != 0 ? (std::uint64_t{1} << 32) - (pair_byte & 0x3)
                                                              : pair_byte & 0x7f;
    const std::size_t pairs_per_chunk = 1 + pair_byte % 5;
    const outcome<pair_index> pairs = read_pairs(pair_text, chunk, default_line, rect_count, pairs_per_chunk);
    const outcome<pair_index> all_pairs = read_pairs(pair_text, whole_pairs, default_line, rect_count, std::size_t{1} << 20);
    if (!same(pairs, all_pairs)) {
        stop("pairs read in chunks of " + std::to_string(chunk) + " bytes, " +
             std::to_string(pairs_per_chunk) + " pairs at a time: " +
             describe(pairs.error, pairs.values.size()) + "; at once: " +
             describe(all_pairs.error, all_pairs.values.size()));
    }
    if (line_byte != 0) {
        const outcome<pair_index> limited = read_pairs(pair_text, chunk, 1 + line_byte, rect_count, pairs_per_chunk);
        if (!limited.error && !same(limited, pairs)) {
            stop("a line limit changed the pairs read");
        }
    }
    return 0;
}
