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
#include <obbsat/collide64.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <type_traits>
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
/// scene, exact by default, any method that runs on the store (on its double
/// store with --precision double). With --pairs the list says which pairs, so
/// a method there is refused, not ignored.
method contacts_method_option(const parsed_options& options, const rectangle_input& input, bool doubles) {
    if (!options.has("method")) {
        return method::exact;
    }
    if (options.has("pairs")) {
        throw usage_error("--method chooses the colliding pairs of the file; with --pairs the list does");
    }
    return doubles ? double_store_method_option(options, input) : store_method_option(options, input);
}

/// The --margin value: a decimal number, finite and >= 0, read as a float
/// (strtof) or, for the double stores, as a double (strtod).
template <class Real>
Real margin_option(const parsed_options& options) {
    const auto text = options.value("margin");
    if (!text) {
        return Real(0);
    }
    const std::string value(*text);
    char* end = nullptr;
    const Real margin = std::is_same<Real, float>::value ? static_cast<Real>(std::strtof(value.c_str(), &end))
                                                         : static_cast<Real>(std::strtod(value.c_str(), &end));
    if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(margin) || !(margin >= Real(0))) {
        throw usage_error("--margin: expected a finite number >= 0, got '" + value + "'");
    }
    return margin;
}

/// Appends "," and the shortest decimal text that reads back as `value` (a float or a double).
template <class Real>
char* put_number(char* at, char* end, Real value) {
    *at++ = ',';
    return std::to_chars(at, end, value).ptr;
}

/// One line per contact (contact or contact64), `keep` choosing which, in the order given.
template <class Contact, class Keep>
void write_contact_lines(const std::vector<pair_index>& pairs, const std::vector<Contact>& contacts, bool header,
                         io::output_target& out, const Keep& keep) {
    // Two indices, eleven numbers of at most 24 characters (a double's
    // shortest text at worst), eleven commas and a line end.
    constexpr std::size_t longest_line = 2 * 10 + 11 * 24 + 11 + 1;
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
        const Contact& c = contacts[k];
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
        at = put_number(at, end, c.nx);
        at = put_number(at, end, c.ny);
        at = put_number(at, end, c.depth);
        *at++ = ',';
        at = std::to_chars(at, end, c.point_count).ptr;
        for (std::uint32_t p = 0; p < 2; ++p) {
            if (p < c.point_count) {
                at = put_number(at, end, c.points[p].x);
                at = put_number(at, end, c.points[p].y);
                at = put_number(at, end, c.points[p].separation);
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

/// The contact options of a store: float ones for the float stores, double
/// ones (margin in double) for the double stores.
template <class Store>
struct contact_options_for {
    using type = contact_options;
};
template <>
struct contact_options_for<pose_records64> {
    using type = contact_options64;
};
template <>
struct contact_options_for<rect_records64> {
    using type = contact_options64;
};

/// Reads the rectangles and the pair list, computes the contacts of the
/// pairs and writes those with points: it overlaps, touches, or is apart by
/// at most the margin.
template <class Store>
std::string contacts_of_pair_file(box_pair_run& run, const collide_options& scene) {
    using options_type = typename contact_options_for<Store>::type;
    Store store;
    read_box_store(run.rects_file, store, run.status);
    options_type options;
    options.use = scene.use;
    options.threads = scene.threads;
    options.margin = margin_option<decltype(options.margin)>(run.options);
    const std::vector<pair_index> pairs =
        read_pair_list(*run.pairs_file, store.size(), run.rects_file.name(), run.status);
    const auto contacts = naming_record_line(run.input.path, [&] { return contact_pairs(store, pairs, options); });
    std::size_t written = 0;
    write_contact_lines(pairs, contacts, run.header, run.target, [&](const auto& c) {
        written += c.point_count > 0;
        return c.point_count > 0;
    });
    return std::to_string(pairs.size()) + " pairs, " + std::to_string(written) + " with contacts";
}

/// The scene's answer of a store: float contacts for the float stores,
/// double ones for the double stores.
template <class Store>
using scene_answer_for = std::conditional_t<std::is_same<typename contact_options_for<Store>::type, contact_options64>::value,
                                            scene_contacts64, scene_contacts>;

/// Reads the rectangles and writes every pair the method calls colliding
/// (and, with a margin, every pair within it) with its contact, in double
/// for a double store (find_contacts into a scene_contacts64).
template <class Store>
std::string contacts_of_scene(box_pair_run& run, const collide_options& scene) {
    Store store;
    read_box_store(run.rects_file, store, run.status);
    const auto margin = margin_option<decltype(contact_options_for<Store>::type::margin)>(run.options);
    scene_answer_for<Store> found;
    naming_record_line(run.input.path, [&] { find_contacts(store, scene, margin, found); });
    write_contact_lines(found.pairs, found.contacts, run.header, run.target, [](const auto&) { return true; });
    return std::to_string(store.size()) + " boxes, " + std::to_string(found.pairs.size()) + " pairs";
}

}  // namespace

void print_contacts_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat contacts (--rects FILE | --poses FILE) [--pairs FILE] [--margin D]\n"
                 "                       [--method NAME] [--backend NAME] [--threads N]\n"
                 "                       [--precision float|double] [--out FILE] [--header]\n"
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
                 "--precision double reads every number, the margin too, as a double and\n"
                 "computes in double (the same steps; nothing rounded to float), printing the\n"
                 "shortest text that reads back as the same double, on every backend. Without\n"
                 "--pairs the pairs are those of 'obbsat pairs --precision double' (methods on\n"
                 "double rects: %s; on double poses: %s), with a margin every other\n"
                 "pair whose double contact has points within it.\n"
                 "\n"
                 "methods: on --rects %s; on --poses %s\n"
                 "\n"
                 "options:\n",
                 method_list(methods_on_doubles(store_kind::corners)).c_str(),
                 method_list(methods_on_doubles(store_kind::poses)).c_str(),
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
                 "  obbsat contacts --rects rects.csv --pairs pairs.csv --header\n"
                 "  obbsat contacts --poses utm.csv --pairs pairs.csv --precision double\n"
                 "  obbsat contacts --poses utm.csv --precision double --margin 0.05\n");
}

int run_contacts(const arguments& args) {
    const parsed_options options = parse_options(args, contacts_option_specs());
    const bool doubles = precision_option(options) == precision::double_;
    margin_option<double>(options);  // a bad margin is reported before any file is opened
    box_pair_run run(options, false, "obbsat contacts");
    collide_options scene;
    scene.test = contacts_method_option(options, run.input, doubles);
    scene.threads = run.threads;
    scene.use = run.use;
    const bool corners = run.input.kind == store_kind::corners;
    std::string summary;
    if (!run.pairs_file && doubles) {
        summary = corners ? contacts_of_scene<rect_records64>(run, scene)
                          : contacts_of_scene<pose_records64>(run, scene);
    } else if (!run.pairs_file) {
        summary = corners ? contacts_of_scene<rect_records>(run, scene) : contacts_of_scene<pose_records>(run, scene);
    } else if (doubles) {
        summary = corners ? contacts_of_pair_file<rect_records64>(run, scene)
                          : contacts_of_pair_file<pose_records64>(run, scene);
    } else {
        summary = corners ? contacts_of_pair_file<rect_records>(run, scene)
                          : contacts_of_pair_file<pose_records>(run, scene);
    }
    run.target.commit();
    run.status.finish(summary);
    return exit_success;
}

}  // namespace obbsat::cli
