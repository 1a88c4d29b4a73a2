// The subcommands that expose the hard-case suites: `gen` writes a family to
// files, `accuracy` scores every method on every family (see commands.hpp for
// how subcommands report errors).
#pragma once

#include "cli/commands.hpp"

#include <cstdio>

namespace obbsat::cli {

int run_gen(const arguments& args);
int run_accuracy(const arguments& args);

void print_gen_help(std::FILE* out);
void print_accuracy_help(std::FILE* out);

}  // namespace obbsat::cli
