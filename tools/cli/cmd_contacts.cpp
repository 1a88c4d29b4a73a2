// obbsat contacts: the contact (normal, depth, up to two points) of every
// colliding pair of a rectangle file, or of the pairs of a pair file, by the
// library's contact entry points (obbsat/contact.hpp, obbsat/find_contacts.hpp).
//
// The files are read whole (records, then pairs), the contacts computed and
// every line formatted before the first is written, so an input error leaves
// standard output empty as well as --out untouched (written through a
// temporary file renamed at the end).
#include "cli/box_pair_input.hpp"
#include "cli/box_pair_options.hpp"
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "io/csv_input.hpp"
#include "io/output_target.hpp"
#include "io/status_line.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace obbsat::cli {

namespace {

constexpr std::string_view contact_header = "i,j,nx,ny,depth,count,x1,y1,s1,x2,y2,s2";

const std::vector<option_spec>& contacts_option_specs() {
    static const std::vector<option_spec> specs = box_pair_option_specs(
        "pairs, one 'i,j' per line (default: every colliding pair of the file)",
        "write the contacts here, all or nothing (default: standard output)",
        "start the output with the header line 'i,j,nx,ny,depth,count,x1,y1,s1,x2,y2,s2'",
        {
            {"margin", "D", "speculative margin, finite and >= 0: pairs apart by at most D too (default: 0)"},
            {"method", "NAME", "which verdict decides the colliding pairs without --pairs (default: exact)"},
        });
    return specs;
}

/// The --method value: which verdict decides the colliding pairs of the
/// scene, exact by default, any method that runs on the store. With --pairs
/// the list says which pairs, so a method there is refused, not ignored.
method contacts_method_option(const parsed_options& options, const rectangle_input& input) {
    if (!options.has("method")) {
        return method::exact;
    }
    if (options.has("pairs")) {
        throw usage_error("--method chooses the colliding pairs of the file; with --pairs the list does");
    }
    return store_method_option(options, input);
}

/// The --margin value: a decimal float, finite and >= 0.
float margin_option(const parsed_options& options) {
    const auto text = options.value("margin");
    if (!text) {
        return 0.0f;
    }
    const std::string value(*text);
    char* end = nullptr;
    const float margin = std::strtof(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(margin) || !(margin >= 0.0f)) {
        throw usage_error("--margin: expected a finite number >= 0, got '" + value + "'");
    }
    return margin;
}

/// Appends "," and the shortest decimal text that reads back as `value`.
char* put_float(char* at, char* end, float value) {
    *at++ = ',';
    return std::to_chars(at, end, value).ptr;
}

/// One line per contact, `keep` choosing which, in the order given.
template <class Keep>
void write_contact_lines(const std::vector<pair_index>& pairs, const std::vector<contact>& contacts, bool header,
                         io::output_target& out, const Keep& keep) {
    // Two indices, eleven floats of at most 15 characters, eleven commas and a line end.
    constexpr std::size_t longest_line = 2 * 10 + 11 * 15 + 11 + 1;
    constexpr std::size_t buffer_bytes = std::size_t{1} << 20;
    std::vector<char> text(buffer_bytes);
    char* const begin = text.data();
    char* const end = begin + buffer_bytes;
    char* at = begin;
    if (header) {
        at = std::copy(contact_header.begin(), contact_header.end(), at);
        *at++ = '\n';
    }
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const contact& c = contacts[k];
        if (!keep(c)) {
            continue;
        }
        if (static_cast<std::size_t>(end - at) < longest_line) {
            out.write(begin, static_cast<std::size_t>(at - begin));
            at = begin;
        }
        at = std::to_chars(at, end, pairs[k].a).ptr;
        *at++ = ',';
        at = std::to_chars(at, end, pairs[k].b).ptr;
        at = put_float(at, end, c.nx);
        at = put_float(at, end, c.ny);
        at = put_float(at, end, c.depth);
        *at++ = ',';
        at = std::to_chars(at, end, c.point_count).ptr;
        for (std::uint32_t p = 0; p < 2; ++p) {
            if (p < c.point_count) {
                at = put_float(at, end, c.points[p].x);
                at = put_float(at, end, c.points[p].y);
                at = put_float(at, end, c.points[p].separation);
            } else {  // an unused point: its three fields empty
                *at++ = ',';
                *at++ = ',';
                *at++ = ',';
            }
        }
        *at++ = '\n';
    }
    out.write(begin, static_cast<std::size_t>(at - begin));
}

/// Reads the rectangles (and pairs), computes the contacts and writes them.
template <class Store>
std::string contacts_of_files(const rectangle_input& input, const io::input_file& rects_file,
                              const io::input_file* pairs_file, const collide_options& run, float margin,
                              bool header, io::output_target& out, io::status_line& status) {
    Store store;
    read_box_store(rects_file, store, status);
    contact_options options;
    options.use = run.use;
    options.threads = run.threads;
    options.margin = margin;
    if (pairs_file) {
        const std::vector<pair_index> pairs = read_pair_list(*pairs_file, store.size(), rects_file.name(), status);
        const std::vector<contact> contacts =
            naming_record_line(input.path, [&] { return contact_pairs(store, pairs, options); });
        // A pair of the list is written when its contact has a point: it
        // overlaps, touches, or is apart by at most the margin.
        std::size_t written = 0;
        write_contact_lines(pairs, contacts, header, out, [&](const contact& c) {
            written += c.point_count > 0;
            return c.point_count > 0;
        });
        return std::to_string(pairs.size()) + " pairs, " + std::to_string(written) + " with contacts";
    }
    const scene_contacts found = naming_record_line(input.path, [&] { return find_contacts(store, run, margin); });
    write_contact_lines(found.pairs, found.contacts, header, out, [](const contact&) { return true; });
    return std::to_string(store.size()) + " boxes, " + std::to_string(found.pairs.size()) + " pairs";
}

}  // namespace

void print_contacts_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat contacts (--rects FILE | --poses FILE) [--pairs FILE] [--margin D]\n"
                 "                       [--method NAME] [--backend NAME] [--threads N]\n"
                 "                       [--out FILE] [--header]\n"
                 "\n"
                 "Writes the contact of each colliding pair, one line\n"
                 "  i,j,nx,ny,depth,count,x1,y1,s1,x2,y2,s2\n"
                 "with the unit normal (nx,ny) from box i to box j, the penetration depth along\n"
                 "it (> 0 overlapping, 0 touching, < 0 apart), the number of contact points\n"
                 "(0, 1 or 2) and each point's position and separation from the reference face\n"
                 "(< 0 penetrating); the fields of an unused point are empty. Numbers are the\n"
                 "shortest decimal text that reads back as the same float. docs/contacts.md\n"
                 "says how every value is computed; every backend gives the same bits.\n"
                 "\n"
                 "Without --pairs: every pair i < j of the file that collides by --method (as\n"
                 "'obbsat pairs'; exact unless told), sorted by i then j, and with a margin\n"
                 "every other pair whose contact has points within it. With --pairs: the pairs\n"
                 "of the list in its order, those whose contact has at least one point\n"
                 "(overlapping, touching or, with a margin, apart by at most it); the others\n"
                 "are left out, and --method is refused.\n"
                 "\n"
                 "methods: on --rects %s; on --poses %s\n"
                 "\n"
                 "options:\n",
                 method_list(methods_on(store_kind::corners)).c_str(),
                 method_list(methods_on(store_kind::poses)).c_str());
    print_options(out, contacts_option_specs());
    std::fprintf(out,
                 "\n"
                 "input: as 'obbsat collide' (see its --help). Corners must be strictly convex\n"
                 "quads (a degenerate one is an error naming its line); poses need a rotation\n"
                 "vector whose squared length is a normal float.\n"
                 "\n"
                 "errors: 'obbsat: FILE:LINE: reason' on stderr and exit status 2; nothing is\n"
                 "written, to --out or to standard output.\n"
                 "\n"
                 "example:\n"
                 "  obbsat contacts --poses poses.csv --margin 0.01 --out contacts.csv\n"
                 "  obbsat contacts --rects rects.csv --pairs pairs.csv --header\n");
}

int run_contacts(const arguments& args) {
    const parsed_options options = parse_options(args, contacts_option_specs());
    const float margin = margin_option(options);
    box_pair_run run(options, false, "obbsat contacts");
    collide_options scene;
    scene.test = contacts_method_option(options, run.input);
    scene.threads = run.threads;
    scene.use = run.use;
    const io::input_file* pairs = run.pairs_file.get();
    const std::string summary =
        run.input.kind == store_kind::corners
            ? contacts_of_files<rect_records>(run.input, run.rects_file, pairs, scene, margin, run.header,
                                              run.target, run.status)
            : contacts_of_files<pose_records>(run.input, run.rects_file, pairs, scene, margin, run.header,
                                              run.target, run.status);
    run.target.commit();
    run.status.finish(summary);
    return exit_success;
}

}  // namespace obbsat::cli
