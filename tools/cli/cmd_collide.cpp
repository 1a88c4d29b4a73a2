// obbsat collide: one verdict line per pair of a pair file.
//
// The rectangle file (corners with --rects, poses with --poses) is read whole
// into packed records (one cache line per rectangle, half of one per pose, as
// pairs fetch them at random); the pair file is streamed a chunk at a time
// (parse, collide, write), so memory stays bounded however many pairs there
// are. With --out, verdicts go to a temporary file renamed over the target at
// the end, so a bad line anywhere leaves the target as it was. On standard
// output, verdicts of chunks before a bad line have already been written when
// the error is found; the exit status says to discard them.
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "io/csv_input.hpp"
#include "io/output_target.hpp"
#include "io/status_line.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/method.hpp>

#include <optional>
#include <string>

namespace obbsat::cli {

namespace {

// Large enough that per-chunk overhead (a thread wake-up, a write call) is
// negligible, small enough that 100M pairs run in a few tens of MB.
constexpr std::size_t pairs_per_chunk = std::size_t{1} << 20;

const std::vector<option_spec>& collide_option_specs() {
    static const std::vector<option_spec> specs = {
        {"rects", "FILE", "corners, one 'ulx,uly,urx,ury,lrx,lry,llx,lly' per line"},
        {"poses", "FILE", "poses, one 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle' per line"},
        {"pairs", "FILE", "pairs, one 'i,j' of 0-based indices per line (required)"},
        {"out", "FILE", "write verdicts here, all or nothing (default: standard output)"},
        {"backend", "NAME", "auto, scalar, sse2, avx2 or avx512 (default: auto)"},
        {"threads", "N", "cores to split each chunk over, 0 for all (default: 1)"},
        {"method", "NAME", "collision test (default: sat4 on --rects, local on --poses)"},
        {"header", "", "start the output with the header line 'verdict'"},
        precision_option_spec(),
        {"help", "", "show this help"},
    };
    return specs;
}

// Verdicts as text, one '0' or '1' line per pair, to --out or standard output.
class verdict_writer {
public:
    verdict_writer(const std::optional<std::string_view>& out_path, bool header) : out_(out_path) {
        if (header) {
            std::string line(io::verdict_header);
            line += '\n';
            out_.write(line.data(), line.size());
        }
    }

    void write(const std::vector<std::uint8_t>& verdicts, std::size_t count) {
        text_.resize(2 * count);
        for (std::size_t i = 0; i < count; ++i) {
            text_[2 * i] = static_cast<char>('0' + verdicts[i]);
            text_[2 * i + 1] = '\n';
        }
        out_.write(text_.data(), text_.size());
    }

    void finish() { out_.commit(); }

private:
    io::output_target out_;
    std::vector<char> text_;
};

// Every record of the rectangle file, by `read` (a reader of csv_input.hpp);
// the line buffer is gone before the pairs are read.
template <class Read>
auto read_whole(const io::input_file& file, io::status_line& status, const char* plural, Read read) {
    io::line_reader lines(file.get(), file.name());
    return read(lines, [&](std::uint64_t records) {
        if (status.due()) {
            status.show("reading " + file.name() + ": " + std::to_string(records) + " " + plural);
        }
    });
}

// Decides the pairs of `pairs_file` a chunk at a time over `rects`, read from
// `rects_file`, and hands the verdicts to `writer`.
template <class Store>
std::uint64_t collide_pair_file(const Store& rects, const io::input_file& rects_file,
                                const io::input_file& pairs_file, const collide_options& run,
                                verdict_writer& writer, io::status_line& status) {
    io::line_reader pair_lines(pairs_file.get(), pairs_file.name());
    io::pair_reader pairs(pair_lines, rects.size(), rects_file.name());
    std::vector<pair_index> chunk;
    std::vector<std::uint8_t> verdicts;
    chunk.reserve(pairs_per_chunk);
    verdicts.reserve(pairs_per_chunk);
    while (pairs.read_chunk(chunk, pairs_per_chunk)) {
        verdicts.resize(chunk.size());
        collide_pairs(rects, chunk.data(), chunk.size(), verdicts.data(), run);
        writer.write(verdicts, chunk.size());
        if (status.due()) {
            status.show(std::to_string(pairs.pairs_read()) + " pairs decided");
        }
    }
    return pairs.pairs_read();
}

}  // namespace

void print_collide_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat collide (--rects FILE | --poses FILE) --pairs FILE [--out FILE]\n"
                 "                      [--backend NAME] [--threads N] [--method NAME] [--header]\n"
                 "                      [--precision float|double]\n"
                 "\n"
                 "Writes one line per pair, in pair order: 1 if the two rectangles collide\n"
                 "(touching counts), else 0. The rectangles come from --rects or --poses (one\n"
                 "of them); '-' reads standard input, for one of the two files at most.\n"
                 "\n"
                 "options:\n");
    print_options(out, collide_option_specs());
    std::fprintf(out,
                 "\n"
                 "methods (default: sat4 on --rects, local on --poses; any other pairing is\n"
                 "an error):\n"
                 "  on --rects: %s\n"
                 "  on --poses: %s\n",
                 method_list(methods_on(store_kind::corners)).c_str(),
                 method_list(methods_on(store_kind::poses)).c_str());
    std::fprintf(out,
                 "\n"
                 "--precision double reads every number as a double (std::from_chars, strtod;\n"
                 "decimal or hex) into the double stores and decides the pairs for those\n"
                 "doubles, not for a float rounding of them (UTM metres, for one). Methods\n"
                 "(default: exact on --rects, local on --poses; any other is an error):\n"
                 "  on --rects: %s\n"
                 "  on --poses: %s\n",
                 method_list(methods_on_doubles(store_kind::corners)).c_str(),
                 method_list(methods_on_doubles(store_kind::poses)).c_str());
    std::fprintf(out,
                 "\n"
                 "poses: 'cx,cy,hx,hy,c,s' is the rectangle with center (cx,cy), half extents\n"
                 "hx,hy >= 0 along its own axes, and its x axis along (c,s), not normalised\n"
                 "(its length scales the rectangle) and not (0,0). 'cx,cy,hx,hy,angle' gives\n"
                 "the angle in radians instead: (c,s) = (cos, sin) in double, rounded to float.\n"
                 "Both kinds of line may be mixed in one file.\n"
                 "\n"
                 "input: numbers as strtof reads them (decimal or hex float like 0x1.8p+1);\n"
                 "blanks around fields, CRLF line ends and a last line without a line end are\n"
                 "accepted; blank lines and lines starting with '#' are skipped. Infinities,\n"
                 "NaNs and values beyond float range are errors; subnormals are accepted.\n"
                 "Line 1 may be the file's header, exactly 'ulx,uly,urx,ury,lrx,lry,llx,lly',\n"
                 "'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle', or 'i,j': it is skipped; a line 1\n"
                 "of names only that is not the header is an error.\n"
                 "\n"
                 "status: on a terminal, standard error shows the progress once the run takes\n"
                 "more than a second, and a summary at the end; elsewhere nothing.\n"
                 "\n"
                 "errors: 'obbsat: FILE:LINE: reason' on stderr and exit status 2. With --out\n"
                 "the target is replaced only on success; on standard output, verdicts written\n"
                 "before the error must be discarded.\n"
                 "\n"
                 "example:\n"
                 "  obbsat collide --rects rects.csv --pairs pairs.csv --out verdicts.txt --threads 2\n"
                 "  obbsat collide --poses poses.csv --pairs pairs.csv --method conservative\n"
                 "  obbsat collide --poses utm.csv --pairs pairs.csv --precision double --method exact\n");
}

int run_collide(const arguments& args) {
    const parsed_options options = parse_options(args, collide_option_specs());
    const rectangle_input input = rectangle_option(options);
    const std::string pairs_path(options.required("pairs"));
    // The rectangles are read to the end before the first pair, so a shared
    // standard input would leave no pairs and pass as an empty answer.
    if (input.path == "-" && pairs_path == "-") {
        throw usage_error("--" + input.option + " and --pairs cannot both read standard input ('-')");
    }
    const precision digits = precision_option(options);
    collide_options run;
    run.test = digits == precision::double_ ? double_store_method_option(options, input)
                                            : store_method_option(options, input);
    if (const auto threads = options.value("threads")) {
        run.threads = static_cast<unsigned>(parse_number_option("threads", *threads, 0, 1024));
    }
    // Resolved once, before any file is read, so a backend this CPU lacks (or
    // a bad OBBSAT_BACKEND) fails at once, and every chunk runs on the same one.
    run.use = resolve_backend(backend_option(options));

    // Open everything before the long parse, so a missing file or an
    // unwritable --out is reported at once.
    const io::input_file rects_file(input.path);
    const io::input_file pairs_file(pairs_path);
    // The same stream under two names ("-" and /dev/stdin) is caught here.
    if (io::same_input(rects_file, pairs_file)) {
        throw same_input_error(input.option, input.path, pairs_path);
    }
    verdict_writer writer(output_option(options, "out"), options.has("header"));

    io::status_line status("obbsat collide");
    // Reads the rectangle file whole with `read`, decides every pair over it
    // and says what was done.
    const auto decide = [&](const char* plural, auto read) {
        const auto store = read_whole(rects_file, status, plural, read);
        const std::uint64_t pairs = collide_pair_file(store, rects_file, pairs_file, run, writer, status);
        return std::to_string(store.size()) + " " + plural + ", " + std::to_string(pairs) + " pairs";
    };
    using io::line_reader;
    using io::record_progress;
    const bool corners = input.kind == store_kind::corners;
    const std::string summary =
        digits == precision::double_
            ? (corners ? decide("rectangles", [](line_reader& l, const record_progress& p) {
                   return io::read_rect_records64(l, UINT32_MAX, p);
               })
                       : decide("poses", [](line_reader& l, const record_progress& p) {
                             return io::read_pose_records64(l, UINT32_MAX, p);
                         }))
            : (corners ? decide("rectangles", [](line_reader& l, const record_progress& p) {
                   return io::read_rect_records(l, UINT32_MAX, p);
               })
                       : decide("poses", [](line_reader& l, const record_progress& p) {
                             return io::read_pose_records(l, UINT32_MAX, p);
                         }));
    writer.finish();
    status.finish(summary);
    return exit_success;
}

}  // namespace obbsat::cli
