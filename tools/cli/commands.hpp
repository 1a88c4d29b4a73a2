// The subcommands of the obbsat program. Each takes the words after its name
// and returns the exit status; bad usage and bad input are thrown
// (cli::usage_error, io::input_error, io::output_error, obbsat's own
// exceptions) and turned into a message and exit_bad_input by main.
#pragma once

#include <cstdio>
#include <string_view>
#include <vector>

namespace obbsat::cli {

/// Success.
inline constexpr int exit_success = 0;
/// An internal failure: an unexpected exception, or verdicts that disagree.
inline constexpr int exit_internal_error = 1;
/// Bad usage or bad input; the message on stderr says what and where.
inline constexpr int exit_bad_input = 2;

using arguments = std::vector<std::string_view>;

int run_collide(const arguments& args);
int run_backends(const arguments& args);
int run_demo(const arguments& args);
int run_draw(const arguments& args);
int run_pairs(const arguments& args);
int run_contacts(const arguments& args);
int run_distance(const arguments& args);

void print_collide_help(std::FILE* out);
void print_backends_help(std::FILE* out);
void print_demo_help(std::FILE* out);
void print_draw_help(std::FILE* out);
void print_pairs_help(std::FILE* out);
void print_contacts_help(std::FILE* out);
void print_distance_help(std::FILE* out);

}  // namespace obbsat::cli
