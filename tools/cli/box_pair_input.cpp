// The readers of box_pair_input.hpp.
#include "cli/box_pair_input.hpp"

#include <obbsat/error.hpp>

#include <cstdio>
#include <memory>

namespace obbsat::cli {

namespace {

io::record_progress reading(io::status_line& status, const io::input_file& file, const char* plural) {
    return [&status, &file, plural](std::uint64_t records) {
        if (status.due()) {
            status.show("reading " + file.name() + ": " + std::to_string(records) + " " + plural);
        }
    };
}

/// The 1-based line of record `index` (0-based, counting neither blank,
/// comment nor header lines) of the file at `path`; 0 when it cannot be read
/// again or holds fewer records.
std::uint64_t line_of_record(const std::string& path, std::uint64_t index) {
    if (path == "-") {
        return 0;
    }
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) {
        return 0;
    }
    io::line_reader lines(file.get(), path);
    std::string_view line;
    std::uint64_t records = 0;
    while (lines.next(line)) {
        if (io::is_skipped_line(line)) {
            continue;
        }
        // The header, if any, is line 1 and holds a letter; a record's numbers never start with one.
        const std::size_t first = line.find_first_not_of(" \t");
        const bool header = lines.line_number() == 1 && first != std::string_view::npos &&
                            ((line[first] >= 'a' && line[first] <= 'z') || (line[first] >= 'A' && line[first] <= 'Z'));
        if (header) {
            continue;
        }
        if (records == index) {
            return lines.line_number();
        }
        ++records;
    }
    return 0;
}

}  // namespace

void read_box_store(const io::input_file& file, rect_records& out, io::status_line& status) {
    io::line_reader lines(file.get(), file.name());
    out = io::read_rect_records(lines, UINT32_MAX, reading(status, file, "rectangles"));
}

void read_box_store(const io::input_file& file, rect_records64& out, io::status_line& status) {
    io::line_reader lines(file.get(), file.name());
    out = io::read_rect_records64(lines, UINT32_MAX, reading(status, file, "rectangles"));
}

void read_box_store(const io::input_file& file, pose_records64& out, io::status_line& status) {
    io::line_reader lines(file.get(), file.name());
    out = io::read_pose_records64(lines, UINT32_MAX, reading(status, file, "poses"));
}

void read_box_store(const io::input_file& file, pose_records& out, io::status_line& status) {
    io::line_reader lines(file.get(), file.name());
    out = io::read_pose_records(lines, UINT32_MAX, reading(status, file, "poses"));
}

std::vector<pair_index> read_pair_list(const io::input_file& pairs_file, std::uint64_t rect_count,
                                       const std::string& rect_file, io::status_line& status) {
    io::line_reader lines(pairs_file.get(), pairs_file.name());
    io::pair_reader reader(lines, rect_count, rect_file);
    std::vector<pair_index> pairs;
    std::vector<pair_index> chunk;
    while (reader.read_chunk(chunk, std::size_t{1} << 20)) {
        pairs.insert(pairs.end(), chunk.begin(), chunk.end());
        if (status.due()) {
            status.show("reading " + pairs_file.name() + ": " + std::to_string(pairs.size()) + " pairs");
        }
    }
    return pairs;
}

std::optional<io::input_error> record_error(const std::string& path, const std::string& reason) {
    for (const std::string prefix : {"rectangle ", "pose "}) {
        if (reason.rfind(prefix, 0) != 0) {
            continue;
        }
        const std::size_t colon = reason.find(':', prefix.size());
        if (colon == std::string::npos) {
            break;
        }
        std::uint64_t index = 0;
        try {
            index = std::stoull(reason.substr(prefix.size(), colon - prefix.size()));
        } catch (const std::exception&) {
            break;
        }
        return io::input_error(path, line_of_record(path, index), reason);
    }
    return std::nullopt;
}

}  // namespace obbsat::cli
