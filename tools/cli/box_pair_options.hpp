// The command line that `obbsat contacts` and `obbsat distance` share: the
// rectangle file (--rects or --poses), the pair file, --backend, --threads,
// --precision, --out and --header, read and checked once, before any file is
// read, then the files opened in the order that reports a missing file or an
// unwritable --out at once.
#pragma once

#include "cli/cli_args.hpp"
#include "io/csv_input.hpp"
#include "io/output_target.hpp"
#include "io/status_line.hpp"

#include <obbsat/backend.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace obbsat::cli {

/// The help lines of the options a box-pair command takes: --rects, --poses,
/// --pairs (`pairs_help`), then `own` (the command's own options), --backend,
/// --threads, --precision, --out (`out_help`), --header (`header_help`), --help.
std::vector<option_spec> box_pair_option_specs(std::string_view pairs_help, std::string_view out_help,
                                               std::string_view header_help, const std::vector<option_spec>& own);

/// The checked options and the opened files of one run of a box-pair command.
class box_pair_run {
public:
    /// Reads the shared options of `options` (--pairs required when
    /// `pairs_required`), opens the files and the output; throws usage_error
    /// for a bad option, --rects/--poses and --pairs both on standard input, or
    /// both naming one file, and input_error or output_error for a file that
    /// cannot be opened. `command` ("obbsat contacts") prefixes the status line.
    box_pair_run(const parsed_options& options, bool pairs_required, const char* command);

    const parsed_options& options;  ///< every option, for the command's own (must outlive the run)
    const rectangle_input input;
    const precision digits;  ///< --precision: the float stores, or the double ones
    const unsigned threads;  ///< --threads, 0 for all cores
    /// --backend resolved once, before any file is read (a backend this CPU
    /// lacks fails at once); with --precision double always backend::scalar,
    /// the only one with double contacts (another given is a usage error).
    const backend use;
    const bool header;  ///< --header
    const io::input_file rects_file;
    /// The pair file, when --pairs was given.
    const std::unique_ptr<const io::input_file> pairs_file;
    io::output_target target;  ///< opened after the inputs, so a missing one is reported first
    io::status_line status;
};

}  // namespace obbsat::cli
