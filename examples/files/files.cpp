// The obbsat program's files from C++ (formats in cli_formats.hpp):
//
//   files scene R.csv P.csv [RECTS PAIRS SEED]   write a seeded scene (default 1000 10000 1)
//   files collide R.csv P.csv V.txt              write the verdicts of P.csv's pairs over R.csv
//   files verify R.csv P.csv V.txt               check each verdict of V.txt against obbsat::ref::sat4
//
// Exit status: 0 success, 1 a verdict disagrees or an internal error, 2 bad usage or bad input.
#include "cli_formats.hpp"

#include <obbsat/obbsat.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr int exit_disagreement = 1;
constexpr int exit_bad_input = 2;

class usage_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

std::uint64_t parse_count(const std::string& text, const char* what, std::uint64_t high) {
    char* stop = nullptr;
    const unsigned long long value = std::strtoull(text.c_str(), &stop, 10);
    if (text.empty() || text[0] == '-' || *stop != '\0' || value > high) {
        throw usage_error(std::string(what) + " must be an integer from 0 to " + std::to_string(high) + ", not '" +
                          text + "'");
    }
    return value;
}

int write_scene(const std::vector<std::string>& args) {
    obbsat::scene_spec spec;
    spec.rects = 1000;
    spec.pairs = 10000;
    if (args.size() == 5) {
        spec.rects = static_cast<std::size_t>(parse_count(args[2], "RECTS", UINT32_MAX));
        spec.pairs = static_cast<std::size_t>(parse_count(args[3], "PAIRS", 100000000));
        spec.seed = parse_count(args[4], "SEED", UINT64_MAX);
    }
    const obbsat::scene scene = obbsat::make_scene(spec);
    std::vector<obbsat::rect> rects(scene.rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        rects[i] = scene.rects[i];
    }
    cli_formats::write_rects(args[0], rects);
    cli_formats::write_pairs(args[1], scene.pairs);
    std::printf("%s: %zu rectangles, %s: %zu pairs\n", args[0].c_str(), rects.size(), args[1].c_str(),
                scene.pairs.size());
    return 0;
}

int collide(const std::vector<std::string>& args) {
    const std::vector<obbsat::rect> rects = cli_formats::read_rects(args[0]);
    const std::vector<obbsat::pair_index> pairs = cli_formats::read_pairs(args[1], rects.size(), args[0]);
    const std::vector<std::uint8_t> verdicts = obbsat::collide_pairs(obbsat::rect_records(rects), pairs);
    cli_formats::write_verdicts(args[2], verdicts);
    std::size_t hits = 0;
    for (const std::uint8_t v : verdicts) {
        hits += v;
    }
    std::printf("%s: %zu of %zu pairs collide\n", args[2].c_str(), hits, verdicts.size());
    return 0;
}

int verify(const std::vector<std::string>& args) {
    const std::vector<obbsat::rect> rects = cli_formats::read_rects(args[0]);
    const std::vector<obbsat::pair_index> pairs = cli_formats::read_pairs(args[1], rects.size(), args[0]);
    const std::vector<std::uint8_t> verdicts = cli_formats::read_verdicts(args[2]);
    if (verdicts.size() != pairs.size()) {
        throw cli_formats::format_error(args[2] + ": " + std::to_string(verdicts.size()) + " verdicts for " +
                                        std::to_string(pairs.size()) + " pairs in " + args[1]);
    }
    std::size_t disagreements = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const bool expected = obbsat::ref::sat4(rects[pairs[i].a], rects[pairs[i].b]);
        if ((verdicts[i] != 0) != expected) {
            if (++disagreements <= 10) {
                std::fprintf(stderr, "%s: verdict %zu (pair %u,%u) is %u, obbsat::ref::sat4 says %d\n",
                             args[2].c_str(), i + 1, pairs[i].a, pairs[i].b, unsigned{verdicts[i]},
                             expected ? 1 : 0);
            }
        }
    }
    if (disagreements != 0) {
        std::fprintf(stderr, "%s: %zu of %zu verdicts disagree with obbsat::ref::sat4\n", args[2].c_str(),
                     disagreements, pairs.size());
        return exit_disagreement;
    }
    std::printf("%s: all %zu verdicts agree with obbsat::ref::sat4\n", args[2].c_str(), pairs.size());
    return 0;
}

void print_usage() {
    std::fprintf(stderr,
                 "usage: files scene R.csv P.csv [RECTS PAIRS SEED]\n"
                 "       files collide R.csv P.csv V.txt\n"
                 "       files verify R.csv P.csv V.txt\n");
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> words(argv + std::min(argc, 1), argv + argc);
    const std::string command = words.empty() ? "" : words[0];
    const std::vector<std::string> args(words.begin() + (words.empty() ? 0 : 1), words.end());
    try {
        if (command == "scene" && (args.size() == 2 || args.size() == 5)) {
            return write_scene(args);
        }
        if (command == "collide" && args.size() == 3) {
            return collide(args);
        }
        if (command == "verify" && args.size() == 3) {
            return verify(args);
        }
        print_usage();
        return exit_bad_input;
    } catch (const usage_error& e) {
        std::fprintf(stderr, "files: %s\n", e.what());
        print_usage();
        return exit_bad_input;
    } catch (const cli_formats::format_error& e) {
        std::fprintf(stderr, "files: %s\n", e.what());
        return exit_bad_input;
    } catch (const obbsat::invalid_input& e) {
        std::fprintf(stderr, "files: %s\n", e.what());
        return exit_bad_input;
    } catch (const obbsat::unsupported_backend& e) {
        std::fprintf(stderr, "files: %s\n", e.what());
        return exit_bad_input;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "files: %s\n", e.what());
        return 1;
    }
}
