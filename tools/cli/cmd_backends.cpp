// obbsat backends: what this build and this CPU offer, and what 'auto' picks.
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"

#include <obbsat/backend.hpp>

#include <cstdlib>
#include <string>

namespace obbsat::cli {

namespace {

const std::vector<option_spec>& backends_option_specs() {
    static const std::vector<option_spec> specs = {
        {"help", "", "show this help"},
    };
    return specs;
}

}  // namespace

void print_backends_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat backends\n"
                 "\n"
                 "Lists the backends compiled into this build, best first, with their lanes\n"
                 "(pairs per vector) and whether this CPU runs them; then the backend 'auto'\n"
                 "resolves to, which OBBSAT_BACKEND overrides. A bad OBBSAT_BACKEND is an error\n"
                 "(exit status 2) after the list.\n"
                 "\n"
                 "options:\n");
    print_options(out, backends_option_specs());
    std::fprintf(out,
                 "\n"
                 "example:\n"
                 "  obbsat backends\n"
                 "  OBBSAT_BACKEND=scalar obbsat backends   # 'auto' now picks scalar\n");
}

int run_backends(const arguments& args) {
    parse_options(args, backends_option_specs());
    std::printf("%-8s %5s  %s\n", "backend", "lanes", "this cpu");
    for (const backend b : compiled_backends()) {
        std::printf("%-8s %5u  %s\n", backend_name(b), backend_lanes(b),
                    cpu_supports(b) ? "runs" : "lacks");
    }
    const char* forced = std::getenv("OBBSAT_BACKEND");
    const bool is_forced = forced != nullptr && *forced != '\0';
    // The list is printed first so that it is there even when the variable is
    // bad; resolve_backend then throws, and main reports it.
    std::fflush(stdout);
    const backend chosen = resolve_backend(backend::automatic);
    std::printf("auto: %s (%s)\n", backend_name(chosen),
                is_forced ? (std::string("OBBSAT_BACKEND=") + forced).c_str()
                          : "best this CPU runs");
    return exit_success;
}

}  // namespace obbsat::cli
