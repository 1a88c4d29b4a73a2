// What `obbsat contacts` and `obbsat distance` read: a rectangle file whole
// into a store, a pair file whole into a list, and the line of a record that
// the library refused after reading (a quad that is not strictly convex, a
// pose whose rotation is too short), so that errors name the file and line.
#pragma once

#include "io/csv_input.hpp"
#include "io/status_line.hpp"

#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>

#include <obbsat/error.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace obbsat::cli {

/// Every record of `file` (corners).
void read_box_store(const io::input_file& file, rect_records& out, io::status_line& status);
/// Every record of `file` (poses).
void read_box_store(const io::input_file& file, pose_records& out, io::status_line& status);
/// Every record of `file` (corners), each number read as a double.
void read_box_store(const io::input_file& file, rect_records64& out, io::status_line& status);
/// Every record of `file` (poses), each number read as a double.
void read_box_store(const io::input_file& file, pose_records64& out, io::status_line& status);

/// Every pair of `pairs_file`, each index checked below `rect_count` (errors
/// name `rect_file`).
std::vector<pair_index> read_pair_list(const io::input_file& pairs_file, std::uint64_t rect_count,
                                       const std::string& rect_file, io::status_line& status);

/// Runs `call`; an invalid_input that names a record ("rectangle K: ..." or
/// "pose K: ...") becomes an input_error at that record's line of the file at
/// `path` (found by reading it again; the file itself when it cannot be, as
/// standard input), any other stays as it is.
template <class Call>
auto naming_record_line(const std::string& path, const Call& call) -> decltype(call());

/// The input_error for `reason`, a library message naming a record, at that
/// record's line of the file at `path`; nothing when it names no record.
std::optional<io::input_error> record_error(const std::string& path, const std::string& reason);

template <class Call>
auto naming_record_line(const std::string& path, const Call& call) -> decltype(call()) {
    try {
        return call();
    } catch (const invalid_input& e) {
        if (auto located = record_error(path, e.what())) {
            throw *located;
        }
        throw;
    }
}

}  // namespace obbsat::cli
