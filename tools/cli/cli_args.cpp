#include "cli/cli_args.hpp"

#include <obbsat/collide64.hpp>

#include <algorithm>
#include <charconv>

namespace obbsat::cli {

namespace {

std::string dashed(std::string_view name) { return "--" + std::string(name); }

const option_spec* find_spec(const std::vector<option_spec>& specs, std::string_view name) {
    for (const option_spec& spec : specs) {
        if (spec.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

}  // namespace

bool parsed_options::has(std::string_view name) const { return value(name).has_value(); }

std::optional<std::string_view> parsed_options::value(std::string_view name) const {
    for (const auto& [given, text] : values_) {
        if (given == name) {
            return text;
        }
    }
    return std::nullopt;
}

std::string_view parsed_options::required(std::string_view name) const {
    const auto text = value(name);
    if (!text) {
        throw usage_error("missing required option " + dashed(name));
    }
    return *text;
}

parsed_options parse_options(const std::vector<std::string_view>& args,
                             const std::vector<option_spec>& specs) {
    parsed_options out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view word = args[i];
        if (word.size() < 3 || word.substr(0, 2) != "--") {
            throw usage_error("unexpected argument '" + std::string(word) + "'");
        }
        const std::size_t equals = word.find('=');
        const std::string_view name = word.substr(2, equals == std::string_view::npos
                                                         ? std::string_view::npos
                                                         : equals - 2);
        const option_spec* spec = find_spec(specs, name);
        if (spec == nullptr) {
            throw usage_error("unknown option " + dashed(name));
        }
        if (out.has(name)) {
            throw usage_error("option " + dashed(name) + " given twice");
        }
        if (spec->value_name.empty()) {
            if (equals != std::string_view::npos) {
                throw usage_error("option " + dashed(name) + " takes no value");
            }
            out.add(spec->name, std::string_view());
            continue;
        }
        if (equals != std::string_view::npos) {
            out.add(spec->name, word.substr(equals + 1));
            continue;
        }
        if (i + 1 >= args.size()) {
            throw usage_error("option " + dashed(name) + " needs a value (" +
                              std::string(spec->value_name) + ")");
        }
        out.add(spec->name, args[++i]);
    }
    return out;
}

std::uint64_t parse_number_option(std::string_view option, std::string_view text,
                                  std::uint64_t lo, std::uint64_t hi) {
    std::uint64_t value = 0;
    const char* const last = text.data() + text.size();
    const auto [stop, ec] = std::from_chars(text.data(), last, value);
    const bool in_range = ec == std::errc() && stop == last && value >= lo && value <= hi;
    if (!in_range) {
        throw usage_error(dashed(option) + ": expected a whole number from " + std::to_string(lo) +
                          " to " + std::to_string(hi) + ", got '" + std::string(text) + "'");
    }
    return value;
}

std::optional<std::string_view> output_option(const parsed_options& options, std::string_view name,
                                              bool required) {
    const auto text = required ? std::optional<std::string_view>(options.required(name)) : options.value(name);
    if (text && text->empty()) {
        throw usage_error(dashed(name) + ": the file name is empty");
    }
    return text;
}

usage_error same_input_error(std::string_view rects_option, std::string_view rects_path,
                             std::string_view pairs_path) {
    return usage_error(dashed(rects_option) + " '" + std::string(rects_path) + "' and --pairs '" +
                       std::string(pairs_path) +
                       "' name the same input; rectangles and pairs need one each");
}

void print_options(std::FILE* out, const std::vector<option_spec>& specs) {
    std::size_t width = 0;
    for (const option_spec& spec : specs) {
        width = std::max(width, spec.name.size() + spec.value_name.size() + 3);
    }
    for (const option_spec& spec : specs) {
        std::string left = dashed(spec.name);
        if (!spec.value_name.empty()) {
            left += " " + std::string(spec.value_name);
        }
        std::fprintf(out, "  %-*s  %.*s\n", static_cast<int>(width), left.c_str(),
                     static_cast<int>(spec.help.size()), spec.help.data());
    }
}

std::string method_list(const std::vector<method>& methods) {
    std::string known;
    for (const method m : methods) {
        known += known.empty() ? "" : ", ";
        known += method_name(m);
    }
    return known;
}

method method_option(const parsed_options& options, method fallback) {
    const auto name = options.value("method");
    if (!name) {
        return fallback;
    }
    const auto parsed = parse_method(*name);
    if (!parsed) {
        throw usage_error("--method: unknown method '" + std::string(*name) + "' (expected " +
                          method_list() + ")");
    }
    return *parsed;
}

backend backend_option(const parsed_options& options) {
    const auto name = options.value("backend");
    if (!name) {
        return backend::automatic;
    }
    const auto parsed = parse_backend(*name);
    if (!parsed) {
        throw usage_error("--backend: unknown backend '" + std::string(*name) +
                          "' (expected auto, scalar, sse2, avx2 or avx512)");
    }
    return *parsed;
}

rectangle_input rectangle_option(const parsed_options& options) {
    const auto rects = options.value("rects");
    const auto poses = options.value("poses");
    if (rects && poses) {
        throw usage_error("--rects and --poses both given; the rectangles come from one of them");
    }
    if (rects) {
        return rectangle_input{store_kind::corners, "rects", std::string(*rects)};
    }
    if (poses) {
        return rectangle_input{store_kind::poses, "poses", std::string(*poses)};
    }
    throw usage_error("missing required option --rects or --poses");
}

method store_method_option(const parsed_options& options, const rectangle_input& input) {
    const method m = method_option(options, input.kind == store_kind::corners ? method::sat4 : method::local);
    if (!runs_on(m, input.kind)) {
        const std::string store = store_name(input.kind);
        throw usage_error("--method " + std::string(method_name(m)) + " does not run on " + store + " (--" +
                          input.option + "); the methods on " + store + " are " +
                          method_list(methods_on(input.kind)));
    }
    return m;
}

option_spec precision_option_spec() {
    return {"precision", "P", "float or double: read and decide numbers as float32 or as double (default: float)"};
}

precision precision_option(const parsed_options& options) {
    const auto word = options.value("precision");
    if (!word || *word == "float") {
        return precision::single;
    }
    if (*word == "double") {
        return precision::double_;
    }
    throw usage_error("--precision: unknown precision '" + std::string(*word) + "' (expected float or double)");
}

const char* precision_name(precision p) { return p == precision::double_ ? "double" : "float"; }

method double_store_method_option(const parsed_options& options, const rectangle_input& input) {
    const method m = method_option(options, input.kind == store_kind::corners ? method::exact : method::local);
    if (!runs_on_doubles(m, input.kind)) {
        const std::string store = store_name(input.kind);
        throw usage_error("--method " + std::string(method_name(m)) + " does not run on " + store + " (--" +
                          input.option + ") with --precision double; the methods on double " + store + " are " +
                          method_list(methods_on_doubles(input.kind)));
    }
    return m;
}

}  // namespace obbsat::cli
