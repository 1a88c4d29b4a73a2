// obbsat: decide which pairs of rotated rectangles collide, from the command
// line. This file picks the subcommand and turns every failure into a message
// on stderr and an exit status.
#include "accuracy/accuracy_commands.hpp"
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "io/atomic_output.hpp"
#include "io/csv_input.hpp"
#include "io/temporary_files.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#ifndef OBBSAT_VERSION
#error "OBBSAT_VERSION must be defined by the build (the CMake project version)"
#endif

namespace {

using namespace obbsat::cli;

struct subcommand {
    std::string_view name;
    std::string_view summary;
    int (*run)(const arguments&);
    void (*print_help)(std::FILE*);
};

constexpr subcommand subcommands[] = {
    {"collide", "verdicts for a pair file over rectangles, as corners or as poses", run_collide,
     print_collide_help},
    {"pairs", "every colliding pair of a rectangle file, or across two, sorted", run_pairs,
     print_pairs_help},
    {"contacts", "normal, depth and contact points of every colliding pair, or of a pair file", run_contacts, print_contacts_help},
    {"distance", "distance and closest points of each pair of a pair file", run_distance, print_distance_help},
    {"backends", "the backends compiled in, which this CPU runs, and which 'auto' picks",
     run_backends, print_backends_help},
    {"demo", "time every backend on a seeded scene and check they all agree", run_demo,
     print_demo_help},
    {"gen", "write a hard-case suite family (rects or poses) and its exact truth to files, or a scene",
     run_gen, print_gen_help},
    {"accuracy", "score every method against the exact oracle on every suite family",
     run_accuracy, print_accuracy_help},
    {"draw", "an SVG picture of chosen pairs: verdict, axes and exact class",
     run_draw, print_draw_help},
};

void print_main_help(std::FILE* out) {
    std::fprintf(out,
                 "obbsat %s: which pairs of 2D rotated rectangles collide (separating axis test)\n"
                 "\n"
                 "usage: obbsat COMMAND [OPTIONS]\n"
                 "       obbsat COMMAND --help\n"
                 "       obbsat --help | --version\n"
                 "\n"
                 "commands:\n",
                 OBBSAT_VERSION);
    for (const subcommand& sub : subcommands) {
        std::fprintf(out, "  %-9.*s %.*s\n", static_cast<int>(sub.name.size()), sub.name.data(),
                     static_cast<int>(sub.summary.size()), sub.summary.data());
    }
    std::fprintf(out,
                 "\n"
                 "environment:\n"
                 "  OBBSAT_BACKEND  forces the backend that 'auto' picks (scalar, sse2, avx2, avx512);\n"
                 "                  any other value is an error (exit status 2) for every command\n"
                 "\n"
                 "exit status: 0 success, 1 internal error, 2 bad usage or bad input\n"
                 "\n"
                 "example:\n"
                 "  obbsat collide --rects rects.csv --pairs pairs.csv --out verdicts.txt\n"
                 "  obbsat collide --poses poses.csv --pairs pairs.csv\n"
                 "  obbsat pairs --poses poses.csv --out colliding.csv\n"
                 "  obbsat collide --poses utm.csv --pairs pairs.csv --precision double\n");
}

void report(const std::string& message) { std::fprintf(stderr, "obbsat: %s\n", message.c_str()); }

const subcommand* find_subcommand(std::string_view name) {
    for (const subcommand& sub : subcommands) {
        if (sub.name == name) {
            return &sub;
        }
    }
    return nullptr;
}

bool asks_for_help(const arguments& args) {
    for (const std::string_view word : args) {
        if (word == "--help" || word == "-h") {
            return true;
        }
    }
    return false;
}

int dispatch(const arguments& words) {
    if (words.empty()) {
        print_main_help(stderr);
        return exit_bad_input;
    }
    const std::string_view first = words.front();
    if (first == "--help" || first == "-h" || first == "help") {
        print_main_help(stdout);
        return exit_success;
    }
    if (first == "--version") {
        std::printf("obbsat %s\n", OBBSAT_VERSION);
        return exit_success;
    }
    const subcommand* sub = find_subcommand(first);
    if (sub == nullptr) {
        report("unknown command '" + std::string(first) + "' (see 'obbsat --help')");
        return exit_bad_input;
    }
    const arguments rest(words.begin() + 1, words.end());
    if (asks_for_help(rest)) {
        sub->print_help(stdout);
        return exit_success;
    }
    try {
        // A bad OBBSAT_BACKEND is an error for every command, used or not (a
        // command given --backend, or one that runs every backend), so that a
        // typo never passes unnoticed. `backends` lists the backends first and
        // reports it after, when it resolves 'auto'.
        if (sub->name != "backends") {
            obbsat::forced_backend();
        }
        return sub->run(rest);
    } catch (const usage_error& e) {
        report(std::string(sub->name) + ": " + e.what() + " (see 'obbsat " + std::string(sub->name) +
               " --help')");
        return exit_bad_input;
    }
}

}  // namespace

int main(int argc, char** argv) {
    // Before any output begins: a temporary file must not outlive a Ctrl-C.
    obbsat::io::remove_temporaries_on_signal();
    int status = exit_internal_error;
    try {
        const arguments words(argv + 1, argv + argc);
        status = dispatch(words);
    } catch (const obbsat::io::input_error& e) {
        report(e.what());
        status = exit_bad_input;
    } catch (const obbsat::io::output_error& e) {
        report(e.what());
        status = exit_bad_input;
    } catch (const obbsat::unsupported_backend& e) {
        report(e.what());
        status = exit_bad_input;
    } catch (const obbsat::invalid_input& e) {
        report(e.what());
        status = exit_bad_input;
    } catch (const std::bad_alloc&) {
        report("internal error: out of memory");
        status = exit_internal_error;
    } catch (const std::exception& e) {
        report(std::string("internal error: ") + e.what());
        status = exit_internal_error;
    } catch (...) {
        report("internal error: unknown exception");
        status = exit_internal_error;
    }
    // Output to a full disk or a closed pipe must not pass as success.
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        report(std::string("cannot write to standard output: ") + std::strerror(errno));
        if (status == exit_success) {
            status = exit_bad_input;
        }
    }
    return status;
}
