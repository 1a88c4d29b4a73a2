// obbsat draw: an SVG picture of chosen pairs, one panel each, showing what
// the chosen method decided and why (see svg_pair_panel.hpp for the panel),
// for rectangles given as corners (--rects) or as poses (--poses).
//
// The verdicts drawn are the library's own (collide_pairs on the chosen
// backend); the panel replays the method's steps to find the separating axis
// and stops with an internal error if the replay disagrees with the library.
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "draw/svg_pair_panel.hpp"
#include "draw/svg_writer.hpp"
#include "io/atomic_output.hpp"
#include "io/csv_input.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/oracle/pose_contact64.hpp>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace obbsat::cli {

namespace {

// A picture with more panels than this is no longer something to look at.
constexpr std::uint64_t max_selected_pairs = 1024;
constexpr std::size_t pairs_per_chunk = std::size_t{1} << 16;
constexpr double picture_margin = 10;
constexpr double header_height = 40;

const std::vector<option_spec>& draw_option_specs() {
    static const std::string method_help =
        "collision test: " + method_list() + " (default: sat4 on --rects, local on --poses)";
    static const std::vector<option_spec> specs = {
        {"rects", "FILE", "corners, one 'ulx,uly,urx,ury,lrx,lry,llx,lly' per line"},
        {"poses", "FILE", "poses, one 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle' per line"},
        {"pairs", "FILE", "pairs, one 'i,j' of 0-based indices per line (required)"},
        {"select", "LIST", "pairs to draw: 0-based pair numbers and ranges, e.g. 0,4,9-12 (required)"},
        {"out", "FILE", "the SVG file to write, all or nothing (required)"},
        {"method", "NAME", method_help},
        {"backend", "NAME", "auto, scalar, sse2, avx2 or avx512 (default: auto)"},
        precision_option_spec(),
        {"help", "", "show this help"},
    };
    return specs;
}

std::uint64_t parse_pair_number(std::string_view item, std::string_view text) {
    std::uint64_t value = 0;
    const char* const last = text.data() + text.size();
    const auto [stop, ec] = std::from_chars(text.data(), last, value);
    if (text.empty() || ec != std::errc() || stop != last) {
        throw usage_error("--select: '" + std::string(item) +
                          "' is not a pair number or a range like 3-7");
    }
    return value;
}

// The pair numbers of --select, in the order given: "3", "0,4,9", "3-7"
// (both ends included) or a mix. A number given twice is an error, as it
// would name two panels alike.
std::vector<std::uint64_t> parse_selection(std::string_view text) {
    std::vector<std::uint64_t> chosen;
    std::size_t begin = 0;
    while (true) {
        const std::size_t comma = text.find(',', begin);
        const std::string_view item =
            text.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin);
        const std::size_t dash = item.find('-');
        const std::uint64_t first = parse_pair_number(item, item.substr(0, dash));
        const std::uint64_t last =
            dash == std::string_view::npos ? first : parse_pair_number(item, item.substr(dash + 1));
        if (last < first) {
            throw usage_error("--select: range '" + std::string(item) + "' runs backwards");
        }
        if (last - first >= max_selected_pairs || chosen.size() + (last - first) >= max_selected_pairs) {
            throw usage_error("--select: more than " + std::to_string(max_selected_pairs) +
                              " pairs to draw");
        }
        for (std::uint64_t n = first; n <= last; ++n) {
            if (std::find(chosen.begin(), chosen.end(), n) != chosen.end()) {
                throw usage_error("--select: pair " + std::to_string(n) + " is chosen twice");
            }
            chosen.push_back(n);
        }
        if (comma == std::string_view::npos) {
            break;
        }
        begin = comma + 1;
    }
    return chosen;
}

// The chosen pairs, in the order of `chosen`, read from the whole pair file
// (so that a bad line anywhere in it is reported).
std::vector<pair_index> read_chosen_pairs(const io::input_file& pairs_file, std::uint64_t rect_count,
                                          const std::string& rects_name,
                                          const std::vector<std::uint64_t>& chosen) {
    std::unordered_map<std::uint64_t, std::size_t> slot_of;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        slot_of.emplace(chosen[i], i);
    }
    std::vector<pair_index> found(chosen.size());
    io::line_reader lines(pairs_file.get(), pairs_file.name());
    io::pair_reader reader(lines, rect_count, rects_name);
    std::vector<pair_index> chunk;
    std::uint64_t number = 0;
    while (reader.read_chunk(chunk, pairs_per_chunk)) {
        for (const pair_index& p : chunk) {
            const auto slot = slot_of.find(number++);
            if (slot != slot_of.end()) {
                found[slot->second] = p;
            }
        }
    }
    for (const std::uint64_t n : chosen) {
        if (n >= number) {
            throw usage_error("--select: pair " + std::to_string(n) + " is out of range: " +
                              pairs_file.name() + " holds " + std::to_string(number) + " pairs");
        }
    }
    return found;
}

void draw_key(svg::writer& out, method m, backend ran, const std::string& rects_name,
              const std::string& pairs_name) {
    out.text("text",
             svg::attributes()
                 .set("class", "heading")
                 .set("x", picture_margin)
                 .set("y", 18)
                 .set("font-size", 13)
                 .set("font-weight", "bold")
                 .set("fill", "#111"),
             std::string("obbsat draw: method ") + method_name(m) + " (backend " + backend_name(ran) +
                 ") on " + rects_name + " and " + pairs_name);
    double x = picture_margin;
    const auto swatch = [&](const char* color, bool filled, const std::string& text) {
        svg::attributes box;
        box.set("x", x).set("y", 26).set("width", 14).set("height", 9).set("stroke", color);
        if (filled) {
            box.set("fill", color).set("fill-opacity", "0.25");
        } else {
            box.set("fill", "none").set("stroke-width", 2.5);
        }
        out.leaf("rect", box);
        out.text("text", svg::attributes().set("x", x + 18).set("y", 34).set("font-size", 10).set("fill", "#333"),
                 text);
        x += 22 + 5.6 * static_cast<double>(text.size());
    };
    swatch(svg::color_a, true, "A: first rect of the pair");
    swatch(svg::color_b, true, "B: second rect");
    swatch(svg::color_collide, false, "frame: the method says collide");
    swatch(svg::color_apart, false, "frame: the method says apart");
}

// The picture: the key, then one panel per pair, in rows; `drawing_of(i)`
// gives the panel of the i-th chosen pair.
template <class DrawingOf>
std::string picture(std::size_t count, method m, backend ran, const std::string& rects_name,
                    const std::string& pairs_name, DrawingOf drawing_of) {
    const std::size_t columns = count <= 1 ? 1 : count <= 4 ? 2 : 3;
    const std::size_t rows = (count + columns - 1) / columns;
    const double width = 2 * picture_margin + static_cast<double>(columns) * svg::panel_width +
                         static_cast<double>(columns - 1) * picture_margin;
    const double height = header_height + picture_margin +
                          static_cast<double>(rows) * (svg::panel_height + picture_margin);
    svg::writer out(width, height);
    out.open("g", svg::attributes().set("font-family", "DejaVu Sans, Arial, sans-serif"));
    draw_key(out, m, ran, rects_name, pairs_name);
    for (std::size_t i = 0; i < count; ++i) {
        const auto pair = drawing_of(i);
        const double left = picture_margin + static_cast<double>(i % columns) * (svg::panel_width + picture_margin);
        const double top = header_height + static_cast<double>(i / columns) * (svg::panel_height + picture_margin);
        try {
            svg::draw_pair_panel(out, pair, left, top);
        } catch (const std::logic_error& e) {
            // A replay that contradicts the library, or geometry placed outside
            // the picture: a bug, reported with the pair that shows it.
            throw std::logic_error("pair " + std::to_string(pair.pair_number) + ": " + e.what());
        }
    }
    out.close();
    return out.finish();
}

// The picture of the chosen pairs of the file `rects_file`, read whole by
// `read` into a store, each pair decided by the library on it and drawn as a
// `Drawing` (svg_pair_panel.hpp) with the exact class of its kind of pair.
template <class Drawing, class Read>
std::string picture_of_file(Read read, const io::input_file& rects_file, const io::input_file& pairs_file,
                            const std::vector<std::uint64_t>& chosen, const collide_options& run) {
    const auto store = [&] {
        io::line_reader lines(rects_file.get(), rects_file.name());
        return read(lines);
    }();
    const std::vector<pair_index> pairs = read_chosen_pairs(pairs_file, store.size(), rects_file.name(), chosen);
    std::vector<std::uint8_t> verdicts(pairs.size());
    const backend ran = collide_pairs(store, pairs.data(), pairs.size(), verdicts.data(), run);
    return picture(pairs.size(), run.test, ran, rects_file.name(), pairs_file.name(), [&](std::size_t i) {
        Drawing pair{chosen[i], pairs[i],  store[pairs[i].a], store[pairs[i].b],
                     run.test,  verdicts[i] != 0, oracle::contact::separated};
        pair.exact = oracle::classify(pair.a, pair.b);
        return pair;
    });
}

}  // namespace

void print_draw_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat draw (--rects FILE | --poses FILE) --pairs FILE --select LIST\n"
                 "                   --out FILE.svg [--method NAME] [--backend NAME]\n"
                 "                   [--precision float|double]\n"
                 "\n"
                 "Draws the chosen pairs as an SVG picture, one panel per pair: both rectangles\n"
                 "(A blue, B purple), the four axes of the method's test through the pair's\n"
                 "centre, and, when the method says apart, the axis that separates them with\n"
                 "both extents as bars along it. The frame is red when the method says\n"
                 "collide, green when it says apart; the title gives the exact class\n"
                 "(separated, touching, overlapping) and whether the method agrees with it.\n"
                 "A contact too fine to see at the pair's scale gets a zoomed inset.\n"
                 "\n"
                 "With --rects, the quads are drawn as given with their corners UL UR LR LL\n"
                 "and the article's four axes; the caption lists the corners as hex floats.\n"
                 "With --poses, each pose's rectangle is drawn with its centre marked, and the\n"
                 "axes are the pose test's: A.x and A.y, A's (c,s) and (-s,c), then B's; each\n"
                 "extent is the pose's centre plus or minus its reach on the axis; the exact\n"
                 "class is the pose oracle's, and the caption lists the poses as hex floats.\n"
                 "The methods on each kind of file are those of obbsat collide.\n"
                 "\n"
                 "With --precision double, the file is read in double (as 'obbsat collide\n"
                 "--precision double' reads it) and the double methods decide; each panel is\n"
                 "measured from the pair's own origin (A's centre, or A's UL corner), so pairs\n"
                 "at UTM or larger coordinates draw as well as pairs at the origin, and an\n"
                 "inset measures its width in double ulps. The exact class is the double\n"
                 "oracle's; the caption lists the doubles as hex floats.\n"
                 "\n"
                 "options:\n");
    print_options(out, draw_option_specs());
    std::fprintf(out,
                 "\n"
                 "pair numbers count the records of the pair file from 0 (blank and comment\n"
                 "lines do not count); at most %llu pairs per picture.\n"
                 "\n"
                 "errors: 'obbsat: FILE:LINE: reason' on stderr and exit status 2; the output\n"
                 "file is written only on success.\n"
                 "\n"
                 "example:\n"
                 "  obbsat draw --rects rects.csv --pairs pairs.csv --select 0,7,12-15 \\\n"
                 "              --method sat4 --out pairs.svg\n"
                 "  obbsat draw --poses poses.csv --pairs pairs.csv --select 0-3 --out poses.svg\n",
                 static_cast<unsigned long long>(max_selected_pairs));
}

int run_draw(const arguments& args) {
    const parsed_options options = parse_options(args, draw_option_specs());
    const rectangle_input input = rectangle_option(options);
    const std::string pairs_path(options.required("pairs"));
    const std::vector<std::uint64_t> chosen = parse_selection(options.required("select"));
    const std::string out_path(*output_option(options, "out", true));
    const precision digits = precision_option(options);
    collide_options run;
    run.test = digits == precision::double_ ? double_store_method_option(options, input)
                                            : store_method_option(options, input);
    run.use = resolve_backend(backend_option(options));

    const io::input_file rects_file(input.path);
    const io::input_file pairs_file(pairs_path);
    // Both are read to the end in turn: one stream named twice leaves no pairs.
    if (io::same_input(rects_file, pairs_file)) {
        throw same_input_error(input.option, input.path, pairs_path);
    }
    io::atomic_output output(out_path);

    // The panels of each kind of file: the drawing types list their fields in
    // one order (pair number, indices, A, B, method, verdict, exact class).
    const auto draw = [&](auto drawing, auto read) {
        return picture_of_file<decltype(drawing)>(read, rects_file, pairs_file, chosen, run);
    };
    const std::string text =
        digits == precision::double_
            ? (input.kind == store_kind::corners
                   ? draw(svg::rect64_pair_drawing{}, [](io::line_reader& l) { return io::read_rect_records64(l); })
                   : draw(svg::pose64_pair_drawing{}, [](io::line_reader& l) { return io::read_pose_records64(l); }))
            : (input.kind == store_kind::corners
                   ? draw(svg::pair_drawing{}, [](io::line_reader& l) { return io::read_rect_records(l); })
                   : draw(svg::pose_pair_drawing{}, [](io::line_reader& l) { return io::read_pose_records(l); }));
    output.write(text.data(), text.size());
    output.commit();
    return exit_success;
}

}  // namespace obbsat::cli
