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
// io::output_target: all or nothing at --out, else on standard output.
#include "accuracy/accuracy_commands.hpp"
#include "cli/cli_args.hpp"
#include "io/atomic_output.hpp"
#include "io/output_target.hpp"
#include "io/temporary_files.hpp"

#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/suites/family.hpp>
#include <obbsat/suites/pose_family.hpp>
#include <obbsat/suites/pose_suite.hpp>
#include <obbsat/suites/suite.hpp>

#include <array>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace obbsat::cli {

namespace {

// The five files of a suite: the shapes first, then pairs, truth and tags.
using file_set = std::array<const char*, 5>;
constexpr file_set rect_file_names = {"rects.csv", "pairs.csv", "truth_class.txt", "truth.txt",
                                      "tags.txt"};
constexpr file_set pose_file_names = {"poses.csv", "pairs.csv", "truth_class.txt", "truth.txt",
                                      "tags.txt"};

const std::vector<option_spec>& gen_option_specs() {
    static const std::vector<option_spec> specs = {
        {"out", "DIR", "directory for the five files, created if missing (required); with --scene, FILE"},
        {"poses", "", "FAMILY is a pose family: write poses.csv, not rects.csv"},
        {"pairs", "N", "pairs to generate (default: 10000)"},
        {"seed", "S", "suite or scene seed (default: 1)"},
        {"scene", "SIZES", "uniform or mixed: write a seeded scene of poses, not a family"},
        {"boxes", "N", "with --scene: rectangles, 1 to 4294967295 (required)"},
        {"pairs-per-box", "D", "with --scene: colliding pairs per rectangle, about (default: 2)"},
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

std::string error_text(const std::string& path, const char* what, int error) {
    return path + ": " + what + ": " + std::strerror(error);
}

// One file of the suite, written into the temporary directory; errors name
// the path the file is meant for, as that is the one the user knows.
class suite_file {
public:
    suite_file(const std::string& temp_path, std::string final_path)
        : final_path_(std::move(final_path)) {
        file_ = std::fopen(temp_path.c_str(), "wb");
        if (file_ == nullptr) {
            throw io::output_error(error_text(final_path_, "cannot create", errno));
        }
    }
    ~suite_file() {
        if (file_ != nullptr) {
            std::fclose(file_);
        }
    }
    suite_file(const suite_file&) = delete;
    suite_file& operator=(const suite_file&) = delete;

    void line(const char* text, std::size_t size) {
        buffer_.append(text, size);
        buffer_ += '\n';
        if (buffer_.size() >= (std::size_t{1} << 20)) {
            flush_buffer();
        }
    }
    void line(const std::string& text) { line(text.data(), text.size()); }

    // Everything on disk before anything is renamed into place.
    void finish() {
        flush_buffer();
        if (std::fflush(file_) != 0) {
            throw io::output_error(error_text(final_path_, "write error", errno));
        }
        if (::fsync(::fileno(file_)) != 0) {
            throw io::output_error(error_text(final_path_, "cannot flush to disk", errno));
        }
        const int closed = std::fclose(file_);
        file_ = nullptr;
        if (closed != 0) {
            throw io::output_error(error_text(final_path_, "write error", errno));
        }
    }

private:
    void flush_buffer() {
        if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
            throw io::output_error(error_text(final_path_, "write error", errno));
        }
        buffer_.clear();
    }

    std::string final_path_;
    std::FILE* file_ = nullptr;
    std::string buffer_;
};

// A temporary directory, created from `pattern` (mkdtemp's), removed with the
// files of `names` unless released, on an error and on a signal alike; errors
// name `dir`.
class temp_directory {
public:
    temp_directory(const std::string& pattern, const std::string& dir, const file_set& names)
        : names_(names) {
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        {
            const io::signals_held held;  // no signal finds it unregistered
            if (::mkdtemp(name.data()) == nullptr) {
                throw io::output_error(error_text(dir, "cannot create a temporary directory for it", errno));
            }
            path_ = name.data();
            registered_.emplace_back(path_, io::temporary_registration::kind::directory);
        }
        // Registered before they exist: removing a missing file is harmless.
        for (const char* file : names_) {
            registered_.emplace_back(path_ + "/" + file, io::temporary_registration::kind::file);
        }
    }
    ~temp_directory() {
        if (path_.empty()) {
            return;
        }
        for (const char* name : names_) {
            ::unlink((path_ + "/" + name).c_str());
        }
        ::rmdir(path_.c_str());
    }
    temp_directory(const temp_directory&) = delete;
    temp_directory& operator=(const temp_directory&) = delete;

    const std::string& path() const { return path_; }
    /// The directory is in place under its final name: nothing to remove.
    void release() {
        path_.clear();
        registered_.clear();
    }

private:
    file_set names_;
    std::string path_;
    std::vector<io::temporary_registration> registered_;
};

std::string without_trailing_slashes(std::string path) {
    while (path.size() > 1 && path.back() == '/') {
        path.pop_back();
    }
    return path;
}

// The directory that will hold DIR.
std::string parent_of(const std::string& dir) {
    const std::size_t slash = dir.rfind('/');
    if (slash == std::string::npos) {
        return ".";
    }
    return slash == 0 ? "/" : dir.substr(0, slash);
}

void sync_directory(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);  // durability of the renames only; the files are complete either way
        ::close(fd);
    }
}

// One line of rects.csv or of poses.csv. %a prints a float (promoted to
// double, exactly) as a C99 hex float that strtof reads back to the same
// float, subnormals too.
int shape_line(char* text, std::size_t size, const rect& r) {
    return std::snprintf(text, size, "%a,%a,%a,%a,%a,%a,%a,%a", static_cast<double>(r.ul.x),
                         static_cast<double>(r.ul.y), static_cast<double>(r.ur.x),
                         static_cast<double>(r.ur.y), static_cast<double>(r.lr.x),
                         static_cast<double>(r.lr.y), static_cast<double>(r.ll.x),
                         static_cast<double>(r.ll.y));
}

int shape_line(char* text, std::size_t size, const rect_pose& p) {
    return std::snprintf(text, size, "%a,%a,%a,%a,%a,%a", static_cast<double>(p.center.x),
                         static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                         static_cast<double>(p.half_extents.y), static_cast<double>(p.rotation.x),
                         static_cast<double>(p.rotation.y));
}

// The poses of a scene, one line each, handed to `out` a megabyte at a time.
void write_pose_lines(const std::vector<rect_pose>& poses, io::output_target& out) {
    constexpr std::size_t buffer_bytes = std::size_t{1} << 20;
    std::string buffer;
    buffer.reserve(buffer_bytes + 256);
    char text[256];
    for (const rect_pose& p : poses) {
        const int size = shape_line(text, sizeof text, p);
        buffer.append(text, static_cast<std::size_t>(size));
        buffer += '\n';
        if (buffer.size() >= buffer_bytes) {
            out.write(buffer.data(), buffer.size());
            buffer.clear();
        }
    }
    out.write(buffer.data(), buffer.size());
}

const std::vector<rect>& shapes_of(const suites::suite& s) { return s.rects; }
const std::vector<rect_pose>& shapes_of(const suites::pose_suite& s) { return s.poses; }

// Suite is suites::suite or suites::pose_suite; names[0] is its shapes' file.
template <class Suite>
void write_suite_files(const std::string& temp, const std::string& dir, const Suite& s,
                       const std::vector<oracle::contact>& truth, const file_set& names) {
    auto temp_path = [&](const char* name) { return temp + "/" + name; };
    auto final_path = [&](const char* name) { return dir + "/" + name; };
    char text[256];

    {
        suite_file shapes(temp_path(names[0]), final_path(names[0]));
        for (const auto& shape : shapes_of(s)) {
            const int size = shape_line(text, sizeof text, shape);
            shapes.line(text, static_cast<std::size_t>(size));
        }
        shapes.finish();
    }
    {
        suite_file pairs(temp_path("pairs.csv"), final_path("pairs.csv"));
        for (const pair_index& p : s.pairs) {
            const int size = std::snprintf(text, sizeof text, "%" PRIu32 ",%" PRIu32, p.a, p.b);
            pairs.line(text, static_cast<std::size_t>(size));
        }
        pairs.finish();
    }
    {
        suite_file classes(temp_path("truth_class.txt"), final_path("truth_class.txt"));
        suite_file verdicts(temp_path("truth.txt"), final_path("truth.txt"));
        for (const oracle::contact c : truth) {
            const char letter = oracle::contact_letter(c);
            const char verdict = c == oracle::contact::separated ? '0' : '1';
            classes.line(&letter, 1);
            verdicts.line(&verdict, 1);
        }
        classes.finish();
        verdicts.finish();
    }
    {
        suite_file tags(temp_path("tags.txt"), final_path("tags.txt"));
        for (std::size_t i = 0; i < s.pairs.size(); ++i) {
            tags.line(s.tag_of(i));
        }
        tags.finish();
    }
}

// Moves the complete files from `temp` into `dir`, which exists.
void move_files_into(const std::string& temp, const std::string& dir, const file_set& names) {
    // Checked for every file before any moves, so that a name taken by a
    // directory cannot leave DIR with some files new and some old.
    for (const char* name : names) {
        struct stat existing {};
        const std::string target = dir + "/" + name;
        if (::stat(target.c_str(), &existing) == 0 && S_ISDIR(existing.st_mode)) {
            throw io::output_error(target + ": is a directory, not a file name");
        }
    }
    for (const char* name : names) {
        const std::string target = dir + "/" + name;
        if (::rename((temp + "/" + name).c_str(), target.c_str()) != 0) {
            throw io::output_error(error_text(target, "cannot replace it", errno));
        }
    }
}

}  // namespace

void print_gen_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat gen FAMILY --out DIR [--pairs N] [--seed S]\n"
                 "       obbsat gen --poses FAMILY --out DIR [--pairs N] [--seed S]\n"
                 "       obbsat gen --scene uniform|mixed --boxes N [--seed S] [--pairs-per-box D]\n"
                 "                  [--out FILE]\n"
                 "\n"
                 "Writes N pairs of one hard-case suite family (pairs on or within a few float\n"
                 "steps of the boundary between separated, touching and overlapping) into DIR:\n"
                 "  rects.csv        one rect per line, ulx,uly,urx,ury,lrx,lry,llx,lly as C99\n"
                 "                   hex floats (strtof reads them back exactly)\n"
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
                 "  poses.csv        one pose per line, cx,cy,hx,hy,c,s as C99 hex floats, what\n"
                 "                   'obbsat collide --poses' reads; the truth is the exact pose\n"
                 "                   oracle's, the tags say how each pair was built, e.g. v:x+2:y-1\n"
                 "                   (placed on contact along the first pose's axis (-s, c), then\n"
                 "                   the second's center moved 2 float steps in x and -1 in y)\n"
                 "\n"
                 "pose families: %s\n"
                 "\n"
                 "all or nothing: the files are written and flushed in a temporary directory\n"
                 "beside DIR (inside it, if DIR exists) and only then moved into place; a new\n"
                 "DIR appears whole in one rename, an existing DIR gets each of the five files\n"
                 "replaced and keeps its other files. On an error DIR is left as it was.\n"
                 "\n"
                 "With --scene, no FAMILY: N rectangles at random positions and orientations in\n"
                 "a square sized for about D colliding pairs per rectangle (make_pose_scene,\n"
                 "obbsat/pose_scene.hpp), as one pose file, cx,cy,hx,hy,c,s per line in C99 hex\n"
                 "floats, what 'obbsat pairs --poses' reads. uniform: half extents in [0.5, 1.5];\n"
                 "mixed: sizes over two decades, [0.2, 20], aspect ratios in [0.3, 1]. D is from\n"
                 "1e-6 to 1000. The same N, sizes, seed and D give the same scene. The file goes\n"
                 "to --out FILE, all or nothing, or else to standard output; a scene takes 32\n"
                 "bytes per rectangle in memory and about 85 bytes per line on disk.\n"
                 "\n"
                 "options:\n",
                 family_list().c_str(), pose_family_list().c_str());
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
                 "  obbsat gen --scene mixed --boxes 1000000 --seed 7 --out scene.csv\n"
                 "  obbsat pairs --poses scene.csv --out pairs.csv\n");
}

namespace {

struct gen_request {
    std::string dir;
    bool dir_exists = false;
    std::size_t pairs = 10000;
    std::uint64_t seed = 1;
};

// Writes the suite `s` and its `truth` into request.dir, all or nothing.
template <class Suite>
void write_suite(const gen_request& request, const Suite& s, const std::vector<oracle::contact>& truth,
                 const file_set& names) {
    const std::string& dir = request.dir;
    const std::string parent = parent_of(dir);
    temp_directory temp(io::temporary_pattern((request.dir_exists ? dir : parent) + "/", "gen"), dir,
                        names);
    write_suite_files(temp.path(), dir, s, truth, names);

    if (request.dir_exists) {
        move_files_into(temp.path(), dir, names);
        sync_directory(dir);
    } else {
        // mkdtemp made it private (0700); DIR gets what mkdir would give it.
        const mode_t mask = ::umask(0);
        ::umask(mask);
        if (::chmod(temp.path().c_str(), static_cast<mode_t>(0777 & ~mask)) != 0 ||
            ::rename(temp.path().c_str(), dir.c_str()) != 0) {
            throw io::output_error(error_text(dir, "cannot create it", errno));
        }
        temp.release();
        sync_directory(parent);
    }
}

void gen_rects(const gen_request& request, suites::family family) {
    const suites::suite s = suites::make_family(family, request.seed, request.pairs);
    std::vector<oracle::contact> truth(s.pairs.size());
    oracle::classify_pairs(s.rects.data(), s.rects.size(), s.pairs.data(), s.pairs.size(),
                           truth.data());
    write_suite(request, s, truth, rect_file_names);
    std::printf("%s: %zu pairs of family %s (seed %" PRIu64 ") over %zu rects\n", request.dir.c_str(),
                s.pairs.size(), suites::family_name(family), request.seed, s.rects.size());
}

void gen_poses(const gen_request& request, suites::pose_family family) {
    const suites::pose_suite s = suites::make_pose_family(family, request.seed, request.pairs);
    std::vector<oracle::contact> truth(s.pairs.size());
    oracle::classify_pairs(s.poses.data(), s.poses.size(), s.pairs.data(), s.pairs.size(),
                           truth.data());
    write_suite(request, s, truth, pose_file_names);
    std::printf("%s: %zu pairs of pose family %s (seed %" PRIu64 ") over %zu poses\n",
                request.dir.c_str(), s.pairs.size(), suites::pose_family_name(family), request.seed,
                s.poses.size());
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

void gen_scene(const split_words& words, const parsed_options& options) {
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
    write_pose_lines(make_pose_scene(spec), target);
    target.commit();
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
    if (options.has("scene")) {
        gen_scene(words, options);
        return exit_success;
    }
    for (const std::string_view name : scene_only_options) {
        if (options.has(name)) {
            throw usage_error("--" + std::string(name) + " needs --scene");
        }
    }
    const bool poses = options.has("poses");
    const std::string known = poses ? pose_family_list() : family_list();
    if (words.positional.empty()) {
        throw usage_error("missing FAMILY (one of " + known + ")");
    }
    if (words.positional.size() > 1) {
        throw usage_error("unexpected argument '" + std::string(words.positional[1]) + "'");
    }
    const std::string_view family_word = words.positional.front();
    const std::optional<suites::family> family = poses ? std::nullopt : find_family(family_word);
    const std::optional<suites::pose_family> pose_family =
        poses ? find_pose_family(family_word) : std::nullopt;
    if (!family && !pose_family) {
        throw usage_error("unknown " + std::string(poses ? "pose family" : "family") + " '" +
                          std::string(family_word) + "' (known: " + known + ")");
    }
    gen_request request;
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

    if (pose_family) {
        gen_poses(request, *pose_family);
    } else {
        gen_rects(request, *family);
    }
    return exit_success;
}

}  // namespace obbsat::cli
