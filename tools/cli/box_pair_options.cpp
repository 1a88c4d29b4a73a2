#include "cli/box_pair_options.hpp"

#include <optional>

namespace obbsat::cli {

namespace {

/// The rectangle file, refused with a pair file when both would read standard
/// input: the rectangles are read to the end first, leaving no pairs.
rectangle_input checked_input(const parsed_options& options, bool pairs_required) {
    rectangle_input input = rectangle_option(options);
    const std::optional<std::string_view> pairs =
        pairs_required ? std::optional<std::string_view>(options.required("pairs")) : options.value("pairs");
    if (pairs && input.path == "-" && *pairs == "-") {
        throw usage_error("--" + input.option + " and --pairs cannot both read standard input ('-')");
    }
    return input;
}

unsigned threads_option(const parsed_options& options) {
    const auto threads = options.value("threads");
    return threads ? static_cast<unsigned>(parse_number_option("threads", *threads, 0, 1024)) : 1u;
}

/// The --pairs file, if given, checked not to be the rectangle file under
/// another name ("-" and /dev/stdin).
std::unique_ptr<const io::input_file> opened_pairs(const parsed_options& options, const rectangle_input& input,
                                                   const io::input_file& rects_file) {
    const auto path = options.value("pairs");
    if (!path) {
        return nullptr;
    }
    auto pairs = std::make_unique<const io::input_file>(std::string(*path));
    if (io::same_input(rects_file, *pairs)) {
        throw same_input_error(input.option, input.path, *path);
    }
    return pairs;
}

/// The backend a run uses: --backend resolved (contacts and distances have
/// lanes in float and in double alike).
backend backend_for(const parsed_options& options) { return resolve_backend(backend_option(options)); }

}  // namespace

std::vector<option_spec> box_pair_option_specs(std::string_view pairs_help, std::string_view out_help,
                                               std::string_view header_help, const std::vector<option_spec>& own) {
    std::vector<option_spec> specs = {
        {"rects", "FILE", "corners, one 'ulx,uly,urx,ury,lrx,lry,llx,lly' per line"},
        {"poses", "FILE", "poses, one 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle' per line"},
        {"pairs", "FILE", pairs_help},
    };
    specs.insert(specs.end(), own.begin(), own.end());
    specs.insert(specs.end(), {
                                  {"backend", "NAME", "auto, scalar, sse2, avx2 or avx512 (default: auto)"},
                                  {"threads", "N", "cores to split the work over, 0 for all (default: 1)"},
                                  precision_option_spec(),
                                  {"out", "FILE", out_help},
                                  {"header", "", header_help},
                                  {"help", "", "show this help"},
                              });
    return specs;
}

box_pair_run::box_pair_run(const parsed_options& given, bool pairs_required, const char* command)
    : options(given),
      input(checked_input(options, pairs_required)),
      digits(precision_option(options)),
      threads(threads_option(options)),
      use(backend_for(options)),
      header(options.has("header")),
      rects_file(input.path),
      pairs_file(opened_pairs(options, input, rects_file)),
      target(output_option(options, "out")),
      status(command) {}

}  // namespace obbsat::cli
