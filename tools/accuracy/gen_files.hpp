// The files `obbsat gen` writes: a suite's five files (its shapes, pairs,
// truth by class and by verdict, and tags) put into a directory all or
// nothing, and a scene's poses one line each.
#pragma once

#include "accuracy/double_families.hpp"
#include "io/output_target.hpp"

#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/suites/pose_suite.hpp>
#include <obbsat/suites/suite.hpp>

#include <string>
#include <vector>

namespace obbsat::cli {

/// How gen writes its CSV files: floats in decimal (the shortest text that
/// reads back to the same float) or, with `hex`, as C99 hex floats (%a); with
/// `header`, each CSV file (rects.csv or poses.csv, pairs.csv, a scene) starts
/// with the header line its reader skips (io/csv_input.hpp).
struct csv_style {
    bool hex = false;
    bool header = false;
};

/// Writes rects.csv, pairs.csv, truth_class.txt, truth.txt and tags.txt of
/// `s` and its `truth` into `dir`: all five complete, flushed to disk in a
/// temporary directory, then moved into place (a missing `dir` is that
/// directory renamed; an existing one, `dir_exists`, gets each file renamed
/// into it). On an error (io::output_error) `dir` is left as it was.
void write_suite_dir(const std::string& dir, bool dir_exists, const suites::suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style);
/// The same with poses.csv in place of rects.csv.
void write_suite_dir(const std::string& dir, bool dir_exists, const suites::pose_suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style);

/// The same for a double family (gen --precision double): rects.csv of
/// doubles, each written as the shortest decimal that reads back to the same
/// double (or %a with style.hex).
void write_suite_dir(const std::string& dir, bool dir_exists, const accuracy::double_rect_suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style);
/// The same with poses.csv of doubles.
void write_suite_dir(const std::string& dir, bool dir_exists, const accuracy::double_pose_suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style);

/// The poses of a scene, one line each in `style`, handed to `out` a megabyte
/// at a time.
void write_pose_lines(const std::vector<rect_pose>& poses, io::output_target& out, const csv_style& style);

/// `path` without the slashes at its end ("/" stays "/").
std::string without_trailing_slashes(std::string path);

}  // namespace obbsat::cli
