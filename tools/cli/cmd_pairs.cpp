// obbsat pairs: every colliding pair of a rectangle file, or of two, by the
// library's scene query (obbsat/find_pairs.hpp).
//
// The files are read whole into packed records, with collide's readers and
// errors; the pairs are found, held and sorted before the first is written,
// so an input error leaves standard output empty as well as --out untouched.
// Memory is the records, the query's own working set while it runs, and the
// pair list, which must be whole to be sorted (see pair_rows).
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "io/csv_input.hpp"
#include "io/filter_input.hpp"
#include "io/output_target.hpp"
#include "io/status_line.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records64.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <sys/stat.h>

namespace obbsat::cli {

namespace {

const std::vector<option_spec>& pairs_option_specs() {
    static const std::vector<option_spec> specs = {
        {"rects", "FILE", "corners, one 'ulx,uly,urx,ury,lrx,lry,llx,lly' per line"},
        {"poses", "FILE", "poses, one 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle' per line"},
        {"against-rects", "FILE", "a second corner file (with --rects): pairs across the two"},
        {"against-poses", "FILE", "a second pose file (with --poses): pairs across the two"},
        {"filters", "FILE", "pair filters of the first file, one 'category,mask,group' per rectangle"},
        {"against-filters", "FILE", "pair filters of the second file (with --against-rects or --against-poses)"},
        {"method", "NAME", "collision test (default: exact)"},
        {"backend", "NAME", "auto, scalar, sse2, avx2 or avx512 (default: auto)"},
        {"threads", "N", "cores to split the query over, 0 for all (default: 1)"},
        {"out", "FILE", "write the pairs here, all or nothing (default: standard output)"},
        {"header", "", "start the output with the header line 'i,j'"},
        {"precision", "P", "float (default) or double: every number read as a double and decided in double"},
        {"help", "", "show this help"},
    };
    return specs;
}

// The second file of a cross query, if one is given; it must hold the same
// kind of rectangle as the first, as find_pairs takes two stores of one kind.
std::optional<rectangle_input> against_option(const parsed_options& options, const rectangle_input& first) {
    const auto rects = options.value("against-rects");
    const auto poses = options.value("against-poses");
    if (rects && poses) {
        throw usage_error("--against-rects and --against-poses both given; the second rectangles come from "
                          "one of them");
    }
    if (!rects && !poses) {
        return std::nullopt;
    }
    const rectangle_input against = rects ? rectangle_input{store_kind::corners, "against-rects", std::string(*rects)}
                                          : rectangle_input{store_kind::poses, "against-poses", std::string(*poses)};
    if (against.kind != first.kind) {
        throw usage_error("--" + against.option + " with --" + first.option +
                          ": both files must hold one kind of rectangle (--against-" + first.option + " with --" +
                          first.option + ")");
    }
    return against;
}

// Refuses a method that does not run on `Store` before any file is read, in
// the library's own words: find_pairs checks the method before any work, on
// an empty store too.
template <class Store>
void require_method_on(const collide_options& run) {
    try {
        find_pairs_each(Store{}, run, [](const pair_index*, std::size_t) {});
    } catch (const invalid_input& e) {
        throw usage_error(e.what());
    }
}

// True iff `a` and `b` are one stream that cannot be read twice ("-" and
// /dev/stdin on a pipe): the first store would read it to its end and leave
// the second empty. A regular file opened twice is read twice.
bool one_stream(const io::input_file& a, const io::input_file& b) {
    struct stat status {};
    const bool regular = ::fstat(::fileno(a.get()), &status) == 0 && S_ISREG(status.st_mode);
    return io::same_input(a, b) && !regular;
}

// What the status line shows while `file` is read.
io::record_progress reading(io::status_line& status, const io::input_file& file, const char* plural) {
    return [&status, &file, plural](std::uint64_t records) {
        if (status.due()) {
            status.show("reading " + file.name() + ": " + std::to_string(records) + " " + plural);
        }
    };
}

// Every record of `file` into `out`: a float or (--precision double) a
// double store of corners or of poses.
template <class Store>
void read_store(const io::input_file& file, Store& out, io::status_line& status) {
    io::line_reader lines(file.get(), file.name());
    if constexpr (std::is_same_v<Store, rect_records>) {
        out = io::read_rect_records(lines, UINT32_MAX, reading(status, file, "rectangles"));
    } else if constexpr (std::is_same_v<Store, pose_records>) {
        out = io::read_pose_records(lines, UINT32_MAX, reading(status, file, "poses"));
    } else if constexpr (std::is_same_v<Store, rect_records64>) {
        out = io::read_rect_records64(lines, UINT32_MAX, reading(status, file, "rectangles"));
    } else {
        static_assert(std::is_same_v<Store, pose_records64>, "a store the program reads");
        out = io::read_pose_records64(lines, UINT32_MAX, reading(status, file, "poses"));
    }
}

// The colliding pairs grouped by first index: row i holds the j of every
// pair (i, j), sorted, so the rows in order are find_pairs' sorted list.
// Two runs of the streaming query build them, one counting each row's pairs,
// one storing each j in its row, so the list takes 4 bytes per pair and 8 per
// row (16 during the second run). find_pairs gathers (i, j) pairs in growing
// buffers, sorts them into a list of its own and returns a copy: about 24
// bytes per pair at its peak. A million poses with twenty million pairs:
// 0.9 s and 220 MB here, 1.1 s and 600 MB through find_pairs.
class pair_rows {
public:
    template <class... Stores>
    pair_rows(std::size_t row_count, const collide_options& run, io::status_line& status, const Stores&... stores)
        : starts_(row_count + 1, 0) {
        std::uint64_t found = 0;
        find_pairs_each(stores..., run, [&](const pair_index* pairs, std::size_t count) {
            for (std::size_t k = 0; k < count; ++k) {
                ++starts_[pairs[k].a + 1];
            }
            found += count;
            if (status.due()) {
                status.show("finding pairs: " + std::to_string(found) + " so far");
            }
        });
        if (status.due()) {
            status.show("storing " + std::to_string(found) + " pairs");
        }
        std::partial_sum(starts_.begin(), starts_.end(), starts_.begin());
        js_.resize(starts_.back());
        std::vector<std::uint64_t> next(starts_.begin(), starts_.end() - 1);
        find_pairs_each(stores..., run, [&](const pair_index* pairs, std::size_t count) {
            for (std::size_t k = 0; k < count; ++k) {
                const std::uint32_t i = pairs[k].a;
                if (next[i] == starts_[i + 1]) {
                    throw std::logic_error("the query's second run found a pair its first did not");
                }
                js_[next[i]++] = pairs[k].b;
            }
        });
        for (std::size_t i = 0; i < row_count; ++i) {
            if (next[i] != starts_[i + 1]) {
                throw std::logic_error("the query's second run missed a pair its first found");
            }
            std::sort(js_.begin() + static_cast<std::ptrdiff_t>(starts_[i]),
                      js_.begin() + static_cast<std::ptrdiff_t>(starts_[i + 1]));
        }
    }

    std::size_t rows() const { return starts_.size() - 1; }
    /// Row i is [row_begin(i), row_end(i)) of js().
    std::uint64_t row_begin(std::size_t i) const { return starts_[i]; }
    std::uint64_t row_end(std::size_t i) const { return starts_[i + 1]; }
    const std::vector<std::uint32_t>& js() const { return js_; }

private:
    std::vector<std::uint64_t> starts_;
    std::vector<std::uint32_t> js_;
};

// The pair filters of the rectangles of `rects` (`count` of them) in
// `filters`, or none when no filter file is given; `columns` holds them.
box_view with_filter_file(box_view view, const io::input_file* filters, const io::input_file& rects,
                          io::filter_columns& columns) {
    if (filters == nullptr) {
        return view;
    }
    io::line_reader lines(filters->get(), filters->name());
    columns = io::read_filters(lines, view.size(), rects.name());
    pair_filters f;
    f.categories = columns.categories.data();
    f.masks = columns.masks.data();
    f.groups = columns.groups.data();
    return view.with_filters(f);
}

// The files of one side of the query: its rectangles and, optionally, their filters.
struct side_files {
    const io::input_file* rects = nullptr;
    const io::input_file* filters = nullptr;
};

// The colliding pairs of `first`, or across `first` and `against` (its
// rects nullptr for none); the records are gone when the pairs come back.
// Instantiated only for the stores the scene query takes.
template <class Store>
pair_rows pairs_of_files(const side_files& first, const side_files& against, const collide_options& run,
                         io::status_line& status, std::uint64_t& records) {
    Store a;
    read_store(*first.rects, a, status);
    records = a.size();
    io::filter_columns a_filters, b_filters;
    const box_view va = with_filter_file(a, first.filters, *first.rects, a_filters);
    if (against.rects == nullptr) {
        return pair_rows(a.size(), run, status, va);
    }
    Store b;
    read_store(*against.rects, b, status);
    records += b.size();
    const box_view vb = with_filter_file(b, against.filters, *against.rects, b_filters);
    return pair_rows(a.size(), run, status, va, vb);
}

// The pairs of double files: the scene query on the double store of `kind`.
pair_rows double_pairs_of_files(store_kind kind, const side_files& first, const side_files& against,
                                const collide_options& run, io::status_line& status, std::uint64_t& records) {
    return kind == store_kind::corners ? pairs_of_files<rect_records64>(first, against, run, status, records)
                                       : pairs_of_files<pose_records64>(first, against, run, status, records);
}

// The method check of require_method_on for a double store.
void require_double_method_on(store_kind kind, const collide_options& run) {
    if (kind == store_kind::corners) {
        require_method_on<rect_records64>(run);
    } else {
        require_method_on<pose_records64>(run);
    }
}

// Writes "i,j\n" per pair, formatted by to_chars into a buffer handed out a
// megabyte at a time, "i," once per row: 20 million lines take about 0.2 s,
// where one fprintf or two stream insertions per line take 1.2 s.
void write_pair_lines(const pair_rows& pairs, io::output_target& out, bool header) {
    constexpr std::size_t buffer_bytes = std::size_t{1} << 20;
    constexpr std::size_t longest_line = 10 + 1 + 10 + 1;  // two 32-bit indices, ',' and '\n'
    std::vector<char> text(buffer_bytes);
    char* const begin = text.data();
    char* const end = begin + buffer_bytes;
    char* at = begin;
    if (header) {
        at = std::copy(io::pair_header.begin(), io::pair_header.end(), at);
        *at++ = '\n';
    }
    const std::uint32_t* const js = pairs.js().data();
    for (std::size_t i = 0; i < pairs.rows(); ++i) {
        char prefix[11];
        char* const prefix_end = std::to_chars(prefix, prefix + sizeof prefix, i).ptr;
        *prefix_end = ',';
        const std::size_t prefix_size = static_cast<std::size_t>(prefix_end - prefix) + 1;
        for (std::uint64_t k = pairs.row_begin(i); k < pairs.row_end(i); ++k) {
            if (static_cast<std::size_t>(end - at) < longest_line) {
                out.write(begin, static_cast<std::size_t>(at - begin));
                at = begin;
            }
            std::memcpy(at, prefix, prefix_size);
            at = std::to_chars(at + prefix_size, end, js[k]).ptr;
            *at++ = '\n';
        }
    }
    out.write(begin, static_cast<std::size_t>(at - begin));
}

}  // namespace

void print_pairs_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat pairs (--rects FILE | --poses FILE)\n"
                 "                    [--against-rects FILE | --against-poses FILE]\n"
                 "                    [--method NAME] [--backend NAME] [--threads N] [--out FILE]\n"
                 "                    [--filters FILE] [--against-filters FILE] [--header]\n"
                 "\n"
                 "Writes every pair of rectangles that collide (touching counts), one line 'i,j'\n"
                 "per pair, sorted by i then j. i and j are 0-based record numbers (blank and\n"
                 "comment lines are not counted), the indices 'obbsat collide' takes. With one\n"
                 "file each pair comes once, with i < j. With --against-rects (after --rects) or\n"
                 "--against-poses (after --poses), the pairs are across the two files: i in the\n"
                 "first, j in the second. '-' reads standard input, for one file at most.\n"
                 "\n"
                 "The rectangles whose bounds overlap are found first, then the method decides\n"
                 "them (find_pairs, obbsat/find_pairs.hpp). With exact, the default, that is\n"
                 "exactly every colliding pair. Another method gives the pairs it calls\n"
                 "colliding among those whose bounds overlap, the same on every backend and\n"
                 "thread count.\n"
                 "\n"
                 "With --filters (and --against-filters for the second file), a pair (i, j) is\n"
                 "reported only if category_i & mask_j and category_j & mask_i are not zero and\n"
                 "i and j are not of one group other than 0 (obbsat/pair_filters.hpp). A filter\n"
                 "file holds one line 'category,mask,group' per rectangle of its file, in order\n"
                 "(header 'category,mask,group' optional); category and mask are 64-bit bit sets,\n"
                 "group a 32-bit signed integer, each decimal or 0x hex. A file left out gives\n"
                 "every rectangle of its side category and mask all ones and group 0. Filtered\n"
                 "pairs are dropped before the method tests them.\n"
                 "\n"
                 "options:\n");
    print_options(out, pairs_option_specs());
    std::fprintf(out,
                 "\n"
                 "methods (any other pairing is refused before a file is read):\n"
                 "  on --rects: %s\n"
                 "  on --poses: %s\n",
                 method_list(methods_on(store_kind::corners)).c_str(),
                 method_list(methods_on(store_kind::poses)).c_str());
    std::fprintf(out,
                 "\n"
                 "input: the formats of 'obbsat collide' (see 'obbsat collide --help'); poses\n"
                 "may be 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle', mixed in one file; a first\n"
                 "line that is the file's header (e.g. cx,cy,hx,hy,c,s) is skipped.\n"
                 "\n"
                 "status: on a terminal, standard error shows what is being done once the run\n"
                 "takes more than a second, and a summary at the end, e.g.\n"
                 "'obbsat pairs: 1000000 poses, 1996130 pairs, 1.2 s'; elsewhere nothing.\n"
                 "\n"
                 "memory: about 140 bytes per rectangle and 4 per colliding pair at the peak:\n"
                 "a 32-byte record per rectangle (up to 64 while the record array has room to\n"
                 "grow), about 90 for the query's working set while it runs and 16 to index the\n"
                 "pairs by i; each pair is held as its j, 4 bytes, found by two runs of the\n"
                 "query (one counts, one stores); the output goes through a 1 MiB buffer. A\n"
                 "million boxes peak at 150 MB with two million pairs, 220 MB with twenty.\n"
                 "Filter files add 44 bytes per rectangle (20 read, 24 in the query).\n"
                 "\n"
                 "errors: 'obbsat: FILE:LINE: reason' on stderr and exit status 2. Nothing is\n"
                 "written before every pair is found, so after a bad input --out is as it was\n"
                 "and standard output is empty.\n"
                 "\n"
                 "example:\n"
                 "  obbsat gen --scene uniform --boxes 100000 --out scene.csv\n"
                 "  obbsat pairs --poses scene.csv --out pairs.csv --threads 2\n"
                 "  obbsat pairs --rects A.csv --against-rects B.csv --method conservative\n"
                 "  obbsat pairs --poses scene.csv --filters bodies.csv\n");
}

int run_pairs(const arguments& args) {
    const parsed_options options = parse_options(args, pairs_option_specs());
    const rectangle_input input = rectangle_option(options);
    const std::optional<rectangle_input> against = against_option(options, input);
    // The first file is read to its end before the second, so a shared
    // standard input would leave the second empty and pass as no pairs.
    if (against && input.path == "-" && against->path == "-") {
        throw usage_error("--" + input.option + " and --" + against->option +
                          " cannot both read standard input ('-')");
    }
    const bool doubles = precision_option(options) == precision::double_;
    const std::optional<std::string_view> out_path = output_option(options, "out");
    collide_options run;
    run.test = method_option(options, method::exact);
    if (const auto threads = options.value("threads")) {
        run.threads = static_cast<unsigned>(parse_number_option("threads", *threads, 0, 1024));
    }
    // Resolved once, before any file is read, so a backend this CPU lacks (or
    // a bad OBBSAT_BACKEND) fails at once.
    run.use = resolve_backend(backend_option(options));
    if (doubles) {
        require_double_method_on(input.kind, run);
    } else if (input.kind == store_kind::corners) {
        require_method_on<rect_records>(run);
    } else {
        require_method_on<pose_records>(run);
    }

    // Open everything before the long parse, so a missing file or an
    // unwritable --out is reported at once.
    const io::input_file first_file(input.path);
    std::optional<io::input_file> against_file;
    if (against) {
        against_file.emplace(against->path);
        if (one_stream(first_file, *against_file)) {
            throw usage_error("--" + input.option + " '" + input.path + "' and --" + against->option + " '" +
                              against->path + "' name one stream, which can be read only once");
        }
    }
    // Filter files are read after the rectangles they describe, so neither may be standard input.
    std::optional<io::input_file> filters_file, against_filters_file;
    for (const auto& [option, file] : {std::make_pair("filters", &filters_file),
                                       std::make_pair("against-filters", &against_filters_file)}) {
        if (const auto path = options.value(option)) {
            if (*path == "-") {
                throw usage_error(std::string("--") + option + " reads a file, not standard input ('-')");
            }
            file->emplace(std::string(*path));
        }
    }
    if (against_filters_file && !against) {
        throw usage_error("--against-filters without --against-rects or --against-poses");
    }
    io::output_target target(out_path);

    io::status_line status("obbsat pairs");
    const side_files first{&first_file, filters_file ? &*filters_file : nullptr};
    const side_files second{against_file ? &*against_file : nullptr,
                            against_filters_file ? &*against_filters_file : nullptr};
    std::uint64_t records = 0;
    const pair_rows pairs = doubles ? double_pairs_of_files(input.kind, first, second, run, status, records)
                            : input.kind == store_kind::corners
                                ? pairs_of_files<rect_records>(first, second, run, status, records)
                                : pairs_of_files<pose_records>(first, second, run, status, records);
    if (status.due()) {
        status.show("writing " + std::to_string(pairs.js().size()) + " pairs");
    }
    write_pair_lines(pairs, target, options.has("header"));
    target.commit();
    status.finish(std::to_string(records) + (input.kind == store_kind::corners ? " rectangles, " : " poses, ") +
                  std::to_string(pairs.js().size()) + " pairs");
    return exit_success;
}

}  // namespace obbsat::cli
