// obbsat gen: one hard-case suite family (of rects, or with --poses of poses)
// written as files the collide command reads, with the exact oracle's truth
// beside them; or, with --scene, a seeded scene of poses (obbsat/pose_scene.hpp)
// as one pose file for the pairs command.
//
// All or nothing: the suite and its truth are computed first, then the five
// files are written and flushed to disk inside a fresh temporary directory;
// only when all five are complete do they move into place. A DIR that does not
// exist yet is that temporary directory renamed (one atomic step); an existing
// DIR gets each file renamed into it (each file replaced atomically, other
// files in DIR left alone). Any error before that removes the temporary
// directory and leaves DIR as it was. A scene is one file, written through
// io::output_target: all or nothing at --out, else on standard output. The
// writing of both is in gen_files.cpp.
#include "accuracy/accuracy_commands.hpp"
#include "accuracy/gen_files.hpp"
#include "cli/cli_args.hpp"
#include "io/atomic_output.hpp"
#include "io/output_target.hpp"
#include "io/status_line.hpp"

#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/suites/family.hpp>
#include <obbsat/suites/pose_family.hpp>
#include <obbsat/suites/pose_suite.hpp>
#include <obbsat/suites/suite.hpp>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace obbsat::cli {

namespace {

const std::vector<option_spec>& gen_option_specs() {
    static const std::vector<option_spec> specs = {
        {"out", "DIR", "directory for the five files, created if missing (required); with --scene, FILE"},
        {"poses", "", "FAMILY is a pose family: write poses.csv, not rects.csv"},
        {"pairs", "N", "pairs to generate (default: 10000)"},
        {"seed", "S", "suite or scene seed (default: 1)"},
        {"scene", "SIZES", "uniform or mixed: write a seeded scene of poses, not a family"},
        {"boxes", "N", "with --scene: rectangles, 1 to 4294967295 (required)"},
        {"pairs-per-box", "D", "with --scene: colliding pairs per rectangle, about (default: 2)"},
        {"hex", "", "write floats as C99 hex floats (%a), not shortest decimal"},
        {"header", "", "start each CSV file with its header line (e.g. cx,cy,hx,hy,c,s)"},
        {"precision", "P", "float (default) or double: FAMILY is a double family, written in doubles"},
        {"help", "", "show this help"},
    };
    return specs;
}

std::string family_list() {
    std::string known;
    for (const suites::family f : suites::all_families()) {
        known += known.empty() ? "" : ", ";
        known += suites::family_name(f);
    }
    return known;
}

std::string pose_family_list() {
    std::string known;
    for (const suites::pose_family f : suites::all_pose_families()) {
        known += known.empty() ? "" : ", ";
        known += suites::pose_family_name(f);
    }
    return known;
}

std::optional<suites::family> find_family(std::string_view name) {
    for (const suites::family f : suites::all_families()) {
        if (name == suites::family_name(f)) {
            return f;
        }
    }
    return std::nullopt;
}

std::optional<suites::pose_family> find_pose_family(std::string_view name) {
    for (const suites::pose_family f : suites::all_pose_families()) {
        if (name == suites::pose_family_name(f)) {
            return f;
        }
    }
    return std::nullopt;
}

// The words that are not options nor the values of options given as
// "--name value", so FAMILY may stand anywhere on the line. An option takes
// the next word unless it is a flag (or unknown: parse_options names it).
struct split_words {
    std::vector<std::string_view> positional;
    arguments options;
};

bool is_flag(std::string_view word) {
    for (const option_spec& spec : gen_option_specs()) {
        if (word.substr(2) == spec.name) {
            return spec.value_name.empty();
        }
    }
    return false;
}

split_words split_positional(const arguments& args) {
    split_words out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view word = args[i];
        if (word.size() < 2 || word.substr(0, 2) != "--") {
            out.positional.push_back(word);
            continue;
        }
        out.options.push_back(word);
        const bool takes_value = !is_flag(word) && word.find('=') == std::string_view::npos;
        if (takes_value && i + 1 < args.size()) {
            out.options.push_back(args[++i]);
        }
    }
    return out;
}


}  // namespace

void print_gen_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat gen FAMILY --out DIR [--pairs N] [--seed S] [--hex] [--header]\n"
                 "       obbsat gen --poses FAMILY --out DIR [--pairs N] [--seed S] [--hex] [--header]\n"
                 "       obbsat gen --scene uniform|mixed --boxes N [--seed S] [--pairs-per-box D]\n"
                 "                  [--out FILE] [--hex] [--header]\n"
                 "\n"
                 "Writes N pairs of one hard-case suite family (pairs on or within a few float\n"
                 "steps of the boundary between separated, touching and overlapping) into DIR:\n"
                 "  rects.csv        one rect per line, ulx,uly,urx,ury,lrx,lry,llx,lly\n"
                 "  pairs.csv        one pair per line, i,j (0-based lines of rects.csv)\n"
                 "  truth_class.txt  per pair, the exact oracle's S (separated), T (touching)\n"
                 "                   or O (overlapping)\n"
                 "  truth.txt        per pair, 1 if the rects collide (touching counts), else 0:\n"
                 "                   what 'obbsat collide --method exact' prints\n"
                 "  tags.txt         per pair, how it was built, e.g. corner:touch\n"
                 "Line k of pairs.csv, truth_class.txt, truth.txt and tags.txt is pair k.\n"
                 "The same family, N and seed give the same bytes on every machine.\n"
                 "\n"
                 "families: %s\n"
                 "\n"
                 "With --poses, FAMILY is a pose family, pairs of rectangles given as poses for\n"
                 "the methods on poses, and poses.csv replaces rects.csv:\n"
                 "  poses.csv        one pose per line, cx,cy,hx,hy,c,s, what 'obbsat collide\n"
                 "                   --poses' reads; the truth is the exact pose\n"
                 "                   oracle's, the tags say how each pair was built, e.g. v:x+2:y-1\n"
                 "                   (placed on contact along the first pose's axis (-s, c), then\n"
                 "                   the second's center moved 2 float steps in x and -1 in y)\n"
                 "\n"
                 "pose families: %s\n"
                 "\n"
                 "With --precision double, FAMILY is a double family: pairs at coordinates\n"
                 "float32 rounds (UTM-like 1e5..1e7 m with millimetre and 1-4 ulp gaps, exact\n"
                 "contacts from decimals such as 500000.125, 1e9..1e15, slivers, near-parallel,\n"
                 "rotation lengths 1e-60..1e60), written as doubles (shortest round-trip\n"
                 "decimal, or %%a with --hex) for 'obbsat collide --precision double', the truth\n"
                 "by the exact double oracle. Tags name the family.\n"
                 "  double families:      %s\n"
                 "  double pose families: %s\n"
                 "\n"
                 "all or nothing: the files are written and flushed in a temporary directory\n"
                 "beside DIR (inside it, if DIR exists) and only then moved into place; a new\n"
                 "DIR appears whole in one rename, an existing DIR gets each of the five files\n"
                 "replaced and keeps its other files. On an error DIR is left as it was.\n"
                 "\n"
                 "With --scene, no FAMILY: N rectangles at random positions and orientations in\n"
                 "a square sized for about D colliding pairs per rectangle (make_pose_scene,\n"
                 "obbsat/pose_scene.hpp), as one pose file, cx,cy,hx,hy,c,s per line, what\n"
                 "'obbsat pairs --poses' reads. uniform: half extents in [0.5, 1.5];\n"
                 "mixed: sizes over two decades, [0.2, 20], aspect ratios in [0.3, 1]. D is from\n"
                 "1e-6 to 1000. The same N, sizes, seed and D give the same scene. The file goes\n"
                 "to --out FILE, all or nothing, or else to standard output; a scene takes 32\n"
                 "bytes per rectangle in memory and about 70 bytes per line on disk.\n"
                 "\n"
                 "numbers: every float is written as the shortest decimal that reads back to\n"
                 "the same float (std::to_chars), which numpy.loadtxt and pandas read; with\n"
                 "--hex, as a C99 hex float (%%a, e.g. 0x1.8p+1), the format gen wrote before.\n"
                 "Both read back to the same bits, so every command gives the same output.\n"
                 "With --header, rects.csv or poses.csv and pairs.csv (or the scene) start\n"
                 "with a header line, ulx,uly,urx,ury,lrx,lry,llx,lly or cx,cy,hx,hy,c,s and\n"
                 "i,j, which every reader skips; then line k+1 of pairs.csv is pair k. On a\n"
                 "terminal, standard error gets a one-line summary at the end.\n"
                 "\n"
                 "options:\n",
                 family_list().c_str(), pose_family_list().c_str(),
                 accuracy::name_list(accuracy::double_corner_family_names()).c_str(),
                 accuracy::name_list(accuracy::double_pose_family_names()).c_str());
    print_options(out, gen_option_specs());
    std::fprintf(out,
                 "\n"
                 "example:\n"
                 "  obbsat gen tiles --out tiles --pairs 50000 --seed 3\n"
                 "  obbsat collide --rects tiles/rects.csv --pairs tiles/pairs.csv --method exact"
                 " | cmp - tiles/truth.txt\n"
                 "  obbsat gen --poses contact --out contact\n"
                 "  obbsat collide --poses contact/poses.csv --pairs contact/pairs.csv --method exact"
                 " | cmp - contact/truth.txt\n"
                 "  obbsat gen --precision double --poses utm_contact --out utm\n"
                 "  obbsat collide --poses utm/poses.csv --pairs utm/pairs.csv --precision double"
                 " --method exact | cmp - utm/truth.txt\n"
                 "  obbsat gen --scene mixed --boxes 1000000 --seed 7 --out scene.csv\n"
                 "  obbsat pairs --poses scene.csv --out pairs.csv\n");
}

namespace {

struct gen_request {
    csv_style style;
    std::string dir;
    bool dir_exists = false;
    std::size_t pairs = 10000;
    std::uint64_t seed = 1;
};


void gen_rects(const gen_request& request, suites::family family) {
    const suites::suite s = suites::make_family(family, request.seed, request.pairs);
    std::vector<oracle::contact> truth(s.pairs.size());
    oracle::classify_pairs(s.rects.data(), s.rects.size(), s.pairs.data(), s.pairs.size(),
                           truth.data());
    write_suite_dir(request.dir, request.dir_exists, s, truth, request.style);
    std::printf("%s: %zu pairs of family %s (seed %" PRIu64 ") over %zu rects\n", request.dir.c_str(),
                s.pairs.size(), suites::family_name(family), request.seed, s.rects.size());
}

void gen_poses(const gen_request& request, suites::pose_family family) {
    const suites::pose_suite s = suites::make_pose_family(family, request.seed, request.pairs);
    std::vector<oracle::contact> truth(s.pairs.size());
    oracle::classify_pairs(s.poses.data(), s.poses.size(), s.pairs.data(), s.pairs.size(),
                           truth.data());
    write_suite_dir(request.dir, request.dir_exists, s, truth, request.style);
    std::printf("%s: %zu pairs of pose family %s (seed %" PRIu64 ") over %zu poses\n",
                request.dir.c_str(), s.pairs.size(), suites::pose_family_name(family), request.seed,
                s.poses.size());
}

void gen_double_rects(const gen_request& request, std::size_t family) {
    const accuracy::double_rect_suite s = accuracy::make_double_corner_family(family, request.seed, request.pairs);
    write_suite_dir(request.dir, request.dir_exists, s, accuracy::double_truth(s), request.style);
    std::printf("%s: %zu pairs of double family %s (seed %" PRIu64 ") over %zu rects\n", request.dir.c_str(),
                s.pairs.size(), s.family.c_str(), request.seed, s.rects.size());
}

void gen_double_poses(const gen_request& request, std::size_t family) {
    const accuracy::double_pose_suite s = accuracy::make_double_pose_family(family, request.seed, request.pairs);
    write_suite_dir(request.dir, request.dir_exists, s, accuracy::double_truth(s), request.style);
    std::printf("%s: %zu pairs of double pose family %s (seed %" PRIu64 ") over %zu poses\n",
                request.dir.c_str(), s.pairs.size(), s.family.c_str(), request.seed, s.poses.size());
}

// The options that shape a scene, and those that shape a family: one set
// given with the other is a usage error naming the word.
constexpr std::string_view scene_only_options[] = {"boxes", "pairs-per-box"};
constexpr std::string_view family_only_options[] = {"poses", "pairs"};

// The --pairs-per-box value: a decimal number from 1e-6 to 1000. The bounds
// catch slips, not limits of the generator: at 0 or below there is no square
// to size (make_pose_scene would use a unit square), far below 1e-6 the
// positions grow too coarse for boxes of size 1, and above 1000 a million
// boxes would make a billion pairs.
double pairs_per_box_option(std::string_view text) {
    constexpr double least = 1e-6;
    constexpr double most = 1000;
    const std::string terminated(text);
    char* stop = nullptr;
    const double value = terminated.empty() ? 0 : std::strtod(terminated.c_str(), &stop);
    const bool whole = stop == terminated.c_str() + terminated.size();
    if (!whole || !std::isfinite(value) || value < least || value > most) {
        throw usage_error("--pairs-per-box: expected a number from 1e-6 to 1000, got '" + terminated + "'");
    }
    return value;
}

csv_style style_option(const parsed_options& options) {
    csv_style style;
    style.hex = options.has("hex");
    style.header = options.has("header");
    return style;
}

void gen_scene(const split_words& words, const parsed_options& options, io::status_line& status) {
    if (!words.positional.empty()) {
        throw usage_error("unexpected argument '" + std::string(words.positional.front()) +
                          "' (--scene takes no FAMILY)");
    }
    for (const std::string_view name : family_only_options) {
        if (options.has(name)) {
            throw usage_error("--" + std::string(name) + " does not apply to --scene");
        }
    }
    const std::string_view sizes_word = *options.value("scene");
    const std::optional<scene_sizes> sizes = parse_scene_sizes(sizes_word);
    if (!sizes) {
        throw usage_error("--scene: unknown sizes '" + std::string(sizes_word) + "' (expected uniform or mixed)");
    }
    pose_scene_spec spec;
    spec.sizes = *sizes;
    // Pairs index a file's poses with 32-bit indices.
    spec.boxes = static_cast<std::size_t>(parse_number_option("boxes", options.required("boxes"), 1, UINT32_MAX));
    if (const auto v = options.value("seed")) {
        spec.seed = parse_number_option("seed", *v, 0, UINT64_MAX);
    }
    if (const auto v = options.value("pairs-per-box")) {
        spec.pairs_per_box = pairs_per_box_option(*v);
    }
    const std::optional<std::string_view> out_path = output_option(options, "out");
    // Created before the scene is made, so an unwritable --out fails at once.
    io::output_target target(out_path);
    status.show("making " + std::to_string(spec.boxes) + " poses");
    const std::vector<rect_pose> poses = make_pose_scene(spec);
    status.show("writing " + std::to_string(spec.boxes) + " poses");
    write_pose_lines(poses, target, style_option(options));
    target.commit();
    status.finish(std::to_string(spec.boxes) + " poses");
    if (out_path) {
        std::printf("%.*s: %zu poses, %s sizes (seed %" PRIu64 "), about %g pairs per box, side %g\n",
                    static_cast<int>(out_path->size()), out_path->data(), spec.boxes, scene_sizes_name(spec.sizes),
                    spec.seed, spec.pairs_per_box, pose_scene_side(spec));
    }
}

}  // namespace

int run_gen(const arguments& args) {
    const split_words words = split_positional(args);
    const parsed_options options = parse_options(words.options, gen_option_specs());
    io::status_line status("obbsat gen");
    const bool doubles = precision_option(options) == precision::double_;
    if (doubles && options.has("scene")) {
        throw usage_error("--scene with --precision double: scenes are float poses only; the double families "
                          "are " + accuracy::name_list(accuracy::double_corner_family_names()) +
                          " and, with --poses, " + accuracy::name_list(accuracy::double_pose_family_names()));
    }
    if (options.has("scene")) {
        gen_scene(words, options, status);
        return exit_success;
    }
    for (const std::string_view name : scene_only_options) {
        if (options.has(name)) {
            throw usage_error("--" + std::string(name) + " needs --scene");
        }
    }
    const bool poses = options.has("poses");
    const std::vector<std::string_view>& double_names =
        poses ? accuracy::double_pose_family_names() : accuracy::double_corner_family_names();
    const std::string known = doubles ? accuracy::name_list(double_names) : poses ? pose_family_list() : family_list();
    if (words.positional.empty()) {
        throw usage_error("missing FAMILY (one of " + known + ")");
    }
    if (words.positional.size() > 1) {
        throw usage_error("unexpected argument '" + std::string(words.positional[1]) + "'");
    }
    const std::string_view family_word = words.positional.front();
    const std::optional<suites::family> family = poses || doubles ? std::nullopt : find_family(family_word);
    const std::optional<suites::pose_family> pose_family =
        poses && !doubles ? find_pose_family(family_word) : std::nullopt;
    // An index, not an optional: GCC 12 sees the optional's value as maybe
    // uninitialised on the paths below.
    const std::size_t no_family = double_names.size();
    const std::size_t double_family =
        doubles ? accuracy::find_name(double_names, family_word).value_or(no_family) : no_family;
    if (!family && !pose_family && double_family == no_family) {
        const std::string kind = std::string(doubles ? "double " : "") + (poses ? "pose family" : "family");
        throw usage_error("unknown " + kind + " '" + std::string(family_word) + "' (known: " + known + ")");
    }
    gen_request request;
    request.style = style_option(options);
    request.dir = without_trailing_slashes(std::string(options.required("out")));
    if (request.dir.empty()) {
        throw usage_error("--out: expected a directory name, got ''");
    }
    if (const auto v = options.value("pairs")) {
        request.pairs = static_cast<std::size_t>(parse_number_option("pairs", *v, 1, 100000000));
    }
    if (const auto v = options.value("seed")) {
        request.seed = parse_number_option("seed", *v, 0, UINT64_MAX);
    }

    struct stat existing {};
    request.dir_exists = ::stat(request.dir.c_str(), &existing) == 0;
    if (request.dir_exists && !S_ISDIR(existing.st_mode)) {
        throw io::output_error(request.dir + ": exists and is not a directory");
    }

    if (double_family != no_family && poses) {
        gen_double_poses(request, double_family);
    } else if (double_family != no_family) {
        gen_double_rects(request, double_family);
    } else if (pose_family) {
        gen_poses(request, *pose_family);
    } else {
        gen_rects(request, *family);
    }
    status.finish(std::to_string(request.pairs) + " pairs");
    return exit_success;
}

}  // namespace obbsat::cli
