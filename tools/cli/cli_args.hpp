// Option parsing for the subcommands: long options only, each given at most
// once, as "--name value" or "--name=value"; flags take no value.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace obbsat::cli {

/// The command line is wrong (unknown or repeated option, missing or bad value).
class usage_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct option_spec {
    std::string_view name;        ///< without the leading "--"
    std::string_view value_name;  ///< e.g. "FILE"; empty for a flag
    std::string_view help;        ///< one line for --help
};

class parsed_options {
public:
    /// True iff the option was given.
    bool has(std::string_view name) const;
    /// The value of an option, if given (empty for a flag).
    std::optional<std::string_view> value(std::string_view name) const;
    /// The value of an option that must be given; throws usage_error.
    std::string_view required(std::string_view name) const;

    void add(std::string_view name, std::string_view value) { values_.emplace_back(name, value); }

private:
    std::vector<std::pair<std::string_view, std::string_view>> values_;
};

/// Parses `args` (the words after the subcommand, which must outlive the
/// result) against `specs`; throws usage_error naming the offending word.
parsed_options parse_options(const std::vector<std::string_view>& args,
                             const std::vector<option_spec>& specs);

/// The decimal number `text` given to `--option`, checked to lie in [lo, hi];
/// throws usage_error.
std::uint64_t parse_number_option(std::string_view option, std::string_view text,
                                  std::uint64_t lo, std::uint64_t hi);

/// The file name given to the output option `name` (nothing when it is not
/// given and not `required`); throws usage_error when it is required and
/// missing, or empty.
std::optional<std::string_view> output_option(const parsed_options& options, std::string_view name,
                                              bool required = false);

/// The usage error for the rectangle file (given to --`rects_option`) and
/// --pairs naming one input (see io::same_input).
usage_error same_input_error(std::string_view rects_option, std::string_view rects_path,
                             std::string_view pairs_path);

/// Prints one aligned line per option.
void print_options(std::FILE* out, const std::vector<option_spec>& specs);

/// "sat4, sat4_centered, ...": the names of `methods` (by default every method
/// this build offers), for help and errors.
std::string method_list(const std::vector<method>& methods = all_methods());

/// The --method option, `fallback` when it is not given; throws usage_error
/// naming the known methods.
method method_option(const parsed_options& options, method fallback = method::sat4);

/// The --backend option (default auto); throws usage_error naming the known backends.
backend backend_option(const parsed_options& options);

/// The rectangle file of a command that takes corners or poses.
struct rectangle_input {
    store_kind kind;
    std::string option;  ///< "rects" or "poses"
    std::string path;
};

/// Exactly one of --rects (corners) and --poses; throws usage_error for both or neither.
rectangle_input rectangle_option(const parsed_options& options);

/// The --method option for the store of `input`, by default the article's test on each store
/// (sat4 on corners, local on poses); throws usage_error, before any file is read, for a method
/// that does not run there, naming those that do (the library would refuse it at the first pair).
method store_method_option(const parsed_options& options, const rectangle_input& input);

/// The precision numbers are read and decided in: float (the float stores, the
/// default) or double (the double stores, obbsat/collide64.hpp).
enum class precision { single, double_ };

/// The option spec of --precision, shared by the commands that take it.
option_spec precision_option_spec();

/// The --precision option (default float); throws usage_error for another word.
precision precision_option(const parsed_options& options);

/// "float" or "double".
const char* precision_name(precision p);

/// The --method option for the double store of `input` (default local on
/// poses, exact on corners); throws usage_error, before any file is read, for a
/// method that does not run on doubles, naming it, --precision double and the
/// methods that do.
method double_store_method_option(const parsed_options& options, const rectangle_input& input);

}  // namespace obbsat::cli
