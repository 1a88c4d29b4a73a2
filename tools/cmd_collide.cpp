// obbsat collide: one verdict line per pair of a pair file.
//
// The rectangle file is read whole into packed records (one cache line per
// rectangle, as pairs fetch them at random); the pair file is streamed
// a chunk at a time (parse, collide, write), so memory stays bounded however
// many pairs there are. With --out, verdicts go to a temporary file renamed
// over the target at the end, so a bad line anywhere leaves the target as it
// was. On standard output, verdicts of chunks before a bad line have already
// been written when the error is found; the exit status says to discard them.
#include "atomic_output.hpp"
#include "cli_args.hpp"
#include "commands.hpp"
#include "csv_input.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>

#include <cerrno>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

namespace obbsat::cli {

namespace {

// Large enough that per-chunk overhead (a thread wake-up, a write call) is
// negligible, small enough that 100M pairs run in a few tens of MB.
constexpr std::size_t pairs_per_chunk = std::size_t{1} << 20;

const std::vector<option_spec>& collide_option_specs() {
    static const std::string method_help = "collision test: " + method_list() + " (default: sat4)";
    static const std::vector<option_spec> specs = {
        {"rects", "FILE", "rectangles, one 'ulx,uly,urx,ury,lrx,lry,llx,lly' per line (required)"},
        {"pairs", "FILE", "pairs, one 'i,j' of 0-based rectangle indices per line; '-' is stdin (required)"},
        {"out", "FILE", "write verdicts here, all or nothing (default: standard output)"},
        {"backend", "NAME", "auto, scalar, sse2, avx2 or avx512 (default: auto)"},
        {"threads", "N", "cores to split each chunk over, 0 for all (default: 1)"},
        {"method", "NAME", method_help},
        {"help", "", "show this help"},
    };
    return specs;
}

// Where verdict text goes: the atomic file of --out, or standard output.
class verdict_writer {
public:
    explicit verdict_writer(const std::optional<std::string_view>& out_path) {
        if (out_path) {
            file_ = std::make_unique<io::atomic_output>(std::string(*out_path));
        }
    }

    void write(const std::vector<std::uint8_t>& verdicts, std::size_t count) {
        text_.resize(2 * count);
        for (std::size_t i = 0; i < count; ++i) {
            text_[2 * i] = static_cast<char>('0' + verdicts[i]);
            text_[2 * i + 1] = '\n';
        }
        if (file_) {
            file_->write(text_.data(), text_.size());
        } else if (!text_.empty() && std::fwrite(text_.data(), 1, text_.size(), stdout) != text_.size()) {
            throw io::output_error(std::string("standard output: write error: ") +
                                   std::strerror(errno));
        }
    }

    void finish() {
        if (file_) {
            file_->commit();
        }
    }

private:
    std::unique_ptr<io::atomic_output> file_;
    std::vector<char> text_;
};

}  // namespace

void print_collide_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat collide --rects FILE --pairs FILE [--out FILE] [--backend NAME]\n"
                 "                      [--threads N] [--method NAME]\n"
                 "\n"
                 "Writes one line per pair, in pair order: 1 if the two rectangles collide\n"
                 "(touching counts), else 0.\n"
                 "\n"
                 "options:\n");
    print_options(out, collide_option_specs());
    std::fprintf(out,
                 "\n"
                 "input: numbers as strtof reads them (decimal or hex float like 0x1.8p+1);\n"
                 "blanks around fields, CRLF line ends and a last line without a line end are\n"
                 "accepted; blank lines and lines starting with '#' are skipped. Infinities,\n"
                 "NaNs and values beyond float range are errors; subnormals are accepted.\n"
                 "\n"
                 "errors: 'obbsat: FILE:LINE: reason' on stderr and exit status 2. With --out\n"
                 "the target is replaced only on success; on standard output, verdicts written\n"
                 "before the error must be discarded.\n"
                 "\n"
                 "example:\n"
                 "  obbsat collide --rects rects.csv --pairs pairs.csv --out verdicts.txt --threads 2\n");
}

int run_collide(const arguments& args) {
    const parsed_options options = parse_options(args, collide_option_specs());
    const std::string rects_path(options.required("rects"));
    const std::string pairs_path(options.required("pairs"));
    // The rectangles are read to the end before the first pair, so a shared
    // standard input would leave no pairs and pass as an empty answer.
    if (rects_path == "-" && pairs_path == "-") {
        throw usage_error("--rects and --pairs cannot both read standard input ('-')");
    }
    collide_options run;
    run.test = method_option(options);
    if (const auto threads = options.value("threads")) {
        run.threads = static_cast<unsigned>(parse_number_option("threads", *threads, 0, 1024));
    }
    // Resolved once, before any file is read, so a backend this CPU lacks (or
    // a bad OBBSAT_BACKEND) fails at once, and every chunk runs on the same one.
    run.use = resolve_backend(backend_option(options));

    // Open everything before the long parse, so a missing file or an
    // unwritable --out is reported at once.
    const io::input_file rects_file(rects_path);
    const io::input_file pairs_file(pairs_path);
    // The same stream under two names ("-" and /dev/stdin) is caught here.
    if (io::same_input(rects_file, pairs_file)) {
        throw same_input_error(rects_path, pairs_path);
    }
    verdict_writer writer(output_option(options, "out"));

    rect_records rects;
    {
        io::line_reader lines(rects_file.get(), rects_file.name());
        rects = io::read_rect_records(lines);
    }

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
    }
    writer.finish();
    return exit_success;
}

}  // namespace obbsat::cli
