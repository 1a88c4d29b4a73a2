// obbsat distance: the distance of each pair of a pair file and a closest
// point of each box, by the library's distance entry points
// (obbsat/contact.hpp, distance_pairs).
//
// As `obbsat contacts`: the files are read whole and every line formatted
// before the first is written, so an error leaves standard output empty and
// --out untouched.
#include "cli/box_pair_input.hpp"
#include "cli/box_pair_options.hpp"
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "io/csv_input.hpp"
#include "io/output_target.hpp"
#include "io/status_line.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>

#include <charconv>
#include <string>
#include <vector>

namespace obbsat::cli {

namespace {

constexpr std::string_view distance_header = "i,j,distance,ax,ay,bx,by";

const std::vector<option_spec>& distance_option_specs() {
    static const std::vector<option_spec> specs =
        box_pair_option_specs("pairs, one 'i,j' of 0-based indices per line (required)",
                              "write the distances here, all or nothing (default: standard output)",
                              "start the output with the header line 'i,j,distance,ax,ay,bx,by'", {});
    return specs;
}

/// One line per pair; `Closest` is closest_points or closest_points64.
template <class Closest>
void write_distance_lines(const std::vector<pair_index>& pairs, const std::vector<Closest>& found, bool header,
                          io::output_target& out) {
    // Two indices, five numbers of at most 24 characters (a double's shortest
    // text at worst), six commas and a line end.
    constexpr std::size_t longest_line = 2 * 10 + 5 * 24 + 6 + 1;
    constexpr std::size_t buffer_bytes = std::size_t{1} << 20;
    std::vector<char> text(buffer_bytes);
    char* const begin = text.data();
    char* const end = begin + buffer_bytes;
    char* at = begin;
    if (header) {
        at = std::copy(distance_header.begin(), distance_header.end(), at);
        *at++ = '\n';
    }
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (static_cast<std::size_t>(end - at) < longest_line) {
            out.write(begin, static_cast<std::size_t>(at - begin));
            at = begin;
        }
        at = std::to_chars(at, end, pairs[k].a).ptr;
        *at++ = ',';
        at = std::to_chars(at, end, pairs[k].b).ptr;
        for (const auto value : {found[k].distance, found[k].ax, found[k].ay, found[k].bx, found[k].by}) {
            *at++ = ',';
            at = std::to_chars(at, end, value).ptr;
        }
        *at++ = '\n';
    }
    out.write(begin, static_cast<std::size_t>(at - begin));
}

/// Reads the rectangles (a float or a double store) and the pairs, computes
/// and writes every distance.
template <class Store>
std::string distances_of_files(box_pair_run& run, const distance_options& options) {
    Store store;
    read_box_store(run.rects_file, store, run.status);
    const std::vector<pair_index> pairs =
        read_pair_list(*run.pairs_file, store.size(), run.rects_file.name(), run.status);
    const auto found = naming_record_line(run.input.path, [&] { return distance_pairs(store, pairs, options); });
    write_distance_lines(pairs, found, run.header, run.target);
    return std::to_string(store.size()) + " boxes, " + std::to_string(pairs.size()) + " pairs";
}

}  // namespace

void print_distance_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat distance (--rects FILE | --poses FILE) --pairs FILE\n"
                 "                       [--backend NAME] [--threads N] [--precision float|double]\n"
                 "                       [--out FILE] [--header]\n"
                 "\n"
                 "Writes one line per pair, in pair order:\n"
                 "  i,j,distance,ax,ay,bx,by\n"
                 "the Euclidean distance between the two closed boxes and a point of each at\n"
                 "that distance (a on box i, b on box j). A pair that collides (touching\n"
                 "counts) gets 0 for every field: see 'obbsat contacts' for its depth and\n"
                 "points. Numbers are the shortest decimal text that reads back as the same\n"
                 "float; every backend gives the same bits (docs/contacts.md).\n"
                 "\n"
                 "--precision double reads every number as a double and computes in double\n"
                 "(the same steps; nothing rounded to float), printing the shortest text that\n"
                 "reads back as the same double, on every backend.\n"
                 "\n"
                 "options:\n");
    print_options(out, distance_option_specs());
    std::fprintf(out,
                 "\n"
                 "input: as 'obbsat collide' (see its --help); corners must be strictly convex\n"
                 "quads, as for 'obbsat contacts'.\n"
                 "\n"
                 "errors: 'obbsat: FILE:LINE: reason' on stderr and exit status 2; nothing is\n"
                 "written, to --out or to standard output.\n"
                 "\n"
                 "example:\n"
                 "  obbsat distance --poses poses.csv --pairs pairs.csv --out distances.csv\n");
}

int run_distance(const arguments& args) {
    const parsed_options options = parse_options(args, distance_option_specs());
    box_pair_run run(options, true, "obbsat distance");
    distance_options computed;
    computed.threads = run.threads;
    computed.use = run.use;
    const bool corners = run.input.kind == store_kind::corners;
    const std::string summary =
        run.digits == precision::double_
            ? (corners ? distances_of_files<rect_records64>(run, computed)
                       : distances_of_files<pose_records64>(run, computed))
            : (corners ? distances_of_files<rect_records>(run, computed)
                       : distances_of_files<pose_records>(run, computed));
    run.target.commit();
    run.status.finish(summary);
    return exit_success;
}

}  // namespace obbsat::cli
