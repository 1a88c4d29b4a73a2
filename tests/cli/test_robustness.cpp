// The obbsat program on hostile input: binary garbage, directories, a line
// past the length limit, both files on standard input, full devices, and
// corners and poses at the ends of the float range. Every refusal is exit
// status 2 with one "obbsat: ..." line naming the file (and line), --out
// untouched; every accepted extreme input gives each method's reference
// verdicts.
#include "io/csv_input.hpp"
#include "program_runner.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using obbsat::backend;
using obbsat::method;
using obbsat::rect;

using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;

const std::string unit_rect = "0,1,1,1,1,0,0,0\n";
const std::string previous = "previous verdicts\n";

// Checks a refusal: status 2, exactly one line on stderr that starts with
// `message_start`, nothing on stdout, v.txt as it was, no temporary left.
void expect_refused(const scratch& s, const run_result& r, const std::string& message_start,
                    const std::string& what) {
    EXPECT_EQ(r.status, 2) << what << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("obbsat: " + message_start, 0), 0u) << what << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << "\n" << r.err;
    EXPECT_EQ(r.out, "") << what;
    EXPECT_EQ(read_file(s.file("v.txt")), previous) << what;
    EXPECT_TRUE(s.entries_starting_with(".").empty()) << what << ": temporary output left behind";
}

TEST(robustness, both_files_on_standard_input_are_refused) {
    const scratch s;
    write_file(s.file("v.txt"), previous);
    write_file(s.file("in.txt"), unit_rect + "0,0\n");
    const run_result r = s.run("collide --rects - --pairs - --out v.txt", "", "< in.txt");
    expect_refused(s, r, "collide: --rects and --pairs cannot both read standard input ('-')", "both -");
    const run_result poses = s.run("collide --poses - --pairs - --out v.txt", "", "< in.txt");
    expect_refused(s, poses, "collide: --poses and --pairs cannot both read standard input ('-')",
                   "both - with --poses");
}

TEST(robustness, a_directory_is_refused_as_either_input) {
    const scratch s;
    write_file(s.file("v.txt"), previous);
    write_file(s.file("R.csv"), unit_rect);
    write_file(s.file("P.csv"), "0,0\n");
    fs::create_directory(s.file("dir"));
    expect_refused(s, s.run("collide --rects dir --pairs P.csv --out v.txt"), "dir: read error: Is a directory",
                   "--rects dir");
    expect_refused(s, s.run("collide --rects R.csv --pairs dir --out v.txt"), "dir: read error: Is a directory",
                   "--pairs dir");
}

TEST(robustness, binary_garbage_is_refused_with_file_and_line) {
    const scratch s;
    write_file(s.file("v.txt"), previous);
    write_file(s.file("R.csv"), unit_rect + unit_rect);
    write_file(s.file("P.csv"), "0,1\n");
    // Bytes from a fixed linear congruential sequence: every value, NULs
    // and line ends included, the same on every run.
    std::string noise;
    std::uint32_t state = 12345;
    for (int i = 0; i < 20000; ++i) {
        state = state * 1103515245u + 12345u;
        noise += static_cast<char>(state >> 24);
    }
    const std::vector<std::pair<std::string, std::string>> garbage = {
        {"noise", noise},
        {"nul bytes", std::string(1000, '\0')},
        {"high bytes", std::string(100, '\xff') + "\n"},
        {"a valid line, then NUL inside a number", unit_rect + std::string("0,1,1\0,1,1,0,0,0\n", 17)},
        {"commas only", unit_rect + ",,,,,,,\n"},
        {"bare carriage returns", "\r\r\r0,1,1,1,1,0,0,0\r\r\n"},
    };
    for (const auto& [what, bytes] : garbage) {
        write_file(s.file("bad.csv"), bytes);
        const run_result as_rects = s.run("collide --rects bad.csv --pairs P.csv --out v.txt");
        expect_refused(s, as_rects, "bad.csv:", what + " as rectangles");
        const run_result as_poses = s.run("collide --poses bad.csv --pairs P.csv --out v.txt");
        expect_refused(s, as_poses, "bad.csv:", what + " as poses");
        const run_result as_pairs = s.run("collide --rects R.csv --pairs bad.csv --out v.txt");
        expect_refused(s, as_pairs, "bad.csv:", what + " as pairs");
    }
}

TEST(robustness, a_line_longer_than_16_mib_is_refused_naming_it) {
    const scratch s;
    write_file(s.file("v.txt"), previous);
    write_file(s.file("P.csv"), "0,0\n");
    // Blanks around a field are allowed, so only the length is wrong here.
    write_file(s.file("long.csv"), unit_rect + std::string(std::size_t{17} << 20, ' ') + unit_rect);
    const run_result r = s.run("collide --rects long.csv --pairs P.csv --out v.txt");
    expect_refused(s, r, "long.csv:2: line is longer than 16777216 bytes", "17 MiB line");
}

TEST(robustness, the_line_limit_is_exact_for_every_chunk_size_and_line_end) {
    constexpr std::size_t limit = 1024;
    for (const std::size_t chunk : {1u, 7u, 64u, 1000u, 1025u, 1026u, 8192u}) {
        for (const std::string line_end : {"\n", "\r\n", ""}) {
            for (const std::size_t length : {limit - 1, limit, limit + 1, limit + 2}) {
                const std::string text = "first\n" + std::string(length, 'x') + line_end;
                obbsat::io::line_reader lines(std::string_view(text), "T", chunk, limit);
                std::string_view line;
                const std::string what = "chunk " + std::to_string(chunk) + ", line of " +
                                         std::to_string(length) + " bytes, line end " +
                                         std::to_string(line_end.size());
                ASSERT_TRUE(lines.next(line)) << what;
                EXPECT_EQ(line, "first") << what;
                if (length <= limit) {
                    ASSERT_TRUE(lines.next(line)) << what;
                    EXPECT_EQ(line.size(), length) << what;
                    EXPECT_FALSE(lines.next(line)) << what;
                } else {
                    try {
                        lines.next(line);
                        ADD_FAILURE() << what << ": no error";
                    } catch (const obbsat::io::input_error& e) {
                        EXPECT_EQ(std::string(e.what()), "T:2: line is longer than 1024 bytes") << what;
                    }
                }
            }
        }
    }
}

TEST(robustness, an_unwritable_output_is_an_error_not_a_success) {
    const scratch s;
    write_file(s.file("R.csv"), unit_rect);
    write_file(s.file("P.csv"), "0,0\n");
    const run_result to_file = s.run("collide --rects R.csv --pairs P.csv --out /dev/full");
    EXPECT_EQ(to_file.status, 2);
    EXPECT_EQ(to_file.err, "obbsat: /dev/full: write error: No space left on device\n");
    const run_result to_stdout = s.run("collide --rects R.csv --pairs P.csv", "", "> /dev/full");
    EXPECT_EQ(to_stdout.status, 2);
}

// Corners at the ends of the float range: the largest magnitudes, the
// smallest subnormals, and both in one rectangle.
std::vector<rect> extreme_rects() {
    const float m = FLT_MAX;
    const float d = 0x1p-149f;
    return {
        {{-m, m}, {m, m}, {m, -m}, {-m, -m}},
        {{0, m}, {m, 0}, {0, -m}, {-m, 0}},
        {{-m, m}, {-m / 2, m}, {-m / 2, m / 2}, {-m, m / 2}},
        {{0, 2 * d}, {3 * d, 2 * d}, {3 * d, 0}, {0, 0}},
        {{3 * d, 2 * d}, {6 * d, 2 * d}, {6 * d, 0}, {3 * d, 0}},
        {{4 * d, 2 * d}, {7 * d, 2 * d}, {7 * d, 0}, {4 * d, 0}},
        {{-d, m}, {d, m}, {d, -m}, {-d, -m}},
        {{-m, d}, {m, d}, {m, -d}, {-m, -d}},
        {{0x1p100f, 0x1p100f + 0x1p80f}, {0x1p100f + 0x1p80f, 0x1p100f + 0x1p80f},
         {0x1p100f + 0x1p80f, 0x1p100f}, {0x1p100f, 0x1p100f}},
        {{1e30f, 1e-30f}, {2e30f, 1e-30f}, {2e30f, -1e-30f}, {1e30f, -1e-30f}},
        {{0, 1}, {1, 1}, {1, 0}, {0, 0}},
    };
}

std::string hex(float value) {
    char text[48];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(value));
    return text;
}

TEST(robustness, extreme_coordinates_give_every_reference_verdict_on_every_backend) {
    const scratch s;
    const std::vector<rect> rects = extreme_rects();
    std::string rect_text = "# ends of the float range, in hex floats\n";
    for (const rect& r : rects) {
        const float v[8] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
        for (int k = 0; k < 8; ++k) {
            rect_text += (k == 0 ? "" : ",") + hex(v[k]);
        }
        rect_text += "\n";
    }
    // The largest magnitudes as decimal text too: they must read to the same floats.
    rect_text += "-3.4028235e38,3.4028235e38,3.4028235e38,3.4028235e38,3.4028235e38,-3.4028235e38,"
                 "-3.4028235e38,-3.4028235e38\n";
    std::vector<rect> all = rects;
    all.push_back(rects[0]);
    write_file(s.file("R.csv"), rect_text);
    std::string pair_text;
    for (std::size_t a = 0; a < all.size(); ++a) {
        for (std::size_t b = 0; b < all.size(); ++b) {
            pair_text += std::to_string(a) + "," + std::to_string(b) + "\n";
        }
    }
    write_file(s.file("P.csv"), pair_text);

    std::size_t runs = 0;
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        const obbsat::reference_fn reference = obbsat::method_reference(m);
        std::string expected;
        for (std::size_t a = 0; a < all.size(); ++a) {
            for (std::size_t b = 0; b < all.size(); ++b) {
                expected += reference(all[a], all[b]) ? "1\n" : "0\n";
            }
        }
        // The true answers hold both verdicts, or the comparison proves little
        // (conservative may say 1 throughout: these areas are beyond its guard).
        if (m == method::exact) {
            EXPECT_NE(expected.find('0'), std::string::npos);
            EXPECT_NE(expected.find('1'), std::string::npos);
        }
        for (const backend b : obbsat::compiled_backends()) {
            if (!obbsat::cpu_supports(b)) {
                continue;
            }
            const std::string args = std::string("collide --rects R.csv --pairs P.csv --method ") +
                                     obbsat::method_name(m) + " --backend " + obbsat::backend_name(b);
            const run_result r = s.run(args);
            EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
            EXPECT_EQ(r.out, expected) << args;
            ++runs;
        }
    }
    EXPECT_GE(runs, obbsat::methods_on(obbsat::store_kind::corners).size());
}

// Poses at the ends of the float range: the largest centers and half
// extents, subnormal ones, rotation vectors far from unit length (the
// largest, a subnormal one), and mixtures.
std::vector<obbsat::rect_pose> extreme_poses() {
    const float m = FLT_MAX;
    const float d = 0x1p-149f;
    return {
        {{0, 0}, {m, m}, {1, 0}},
        {{m, -m}, {m / 2, 0}, {0, 1}},
        {{-m, m}, {m, m}, {-1, 0}},
        {{m / 2, m / 2}, {1, 1}, {m, m}},
        {{0, 0}, {1, 1}, {d, 0}},
        {{0, 0}, {d, d}, {1, 0}},
        {{3 * d, 0}, {d, d}, {0, -1}},
        {{0, 0}, {0, 0}, {d, d}},
        {{0x1p100f, 0x1p100f}, {0x1p80f, 0x1p80f}, {0.6f, 0.8f}},
        {{1e30f, 0}, {1e30f, 1e-30f}, {0x1p-60f, 0x1p60f}},
        {{0.5f, 0.5f}, {0.5f, 0.5f}, {1, 0}},
        {{1.5f, 0.5f}, {0.5f, 0.5f}, {0, 2}},
    };
}

TEST(robustness, extreme_poses_give_every_reference_verdict_on_every_backend) {
    const scratch s;
    const std::vector<obbsat::rect_pose> poses = extreme_poses();
    std::string pose_text = "# ends of the float range, in hex floats\n";
    for (const obbsat::rect_pose& p : poses) {
        const float v[6] = {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                            p.rotation.y};
        for (int k = 0; k < 6; ++k) {
            pose_text += (k == 0 ? "" : ",") + hex(v[k]);
        }
        pose_text += "\n";
    }
    // The largest magnitudes as decimal text, with an angle: the same floats.
    pose_text += "0,0,3.4028235e38,3.4028235e38,0\n";
    std::vector<obbsat::rect_pose> all = poses;
    all.push_back(poses[0]);
    write_file(s.file("Q.csv"), pose_text);
    std::string pair_text;
    for (std::size_t a = 0; a < all.size(); ++a) {
        for (std::size_t b = 0; b < all.size(); ++b) {
            pair_text += std::to_string(a) + "," + std::to_string(b) + "\n";
        }
    }
    write_file(s.file("P.csv"), pair_text);

    std::size_t runs = 0;
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        const obbsat::pose_reference_fn reference = obbsat::pose_method_reference(m);
        std::string expected;
        for (std::size_t a = 0; a < all.size(); ++a) {
            for (std::size_t b = 0; b < all.size(); ++b) {
                expected += reference(all[a], all[b]) ? "1\n" : "0\n";
            }
        }
        for (const backend b : obbsat::compiled_backends()) {
            if (!obbsat::cpu_supports(b)) {
                continue;
            }
            const std::string args = std::string("collide --poses Q.csv --pairs P.csv --method ") +
                                     obbsat::method_name(m) + " --backend " + obbsat::backend_name(b);
            const run_result r = s.run(args);
            EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
            EXPECT_EQ(r.out, expected) << args;
            ++runs;
        }
    }
    EXPECT_GE(runs, obbsat::methods_on(obbsat::store_kind::poses).size());
}

// ---------------------------------------------------------------------------
// Output names and interrupted runs.

// Every command that writes a file takes any name the file system takes: up
// to NAME_MAX (255) bytes, with no room left for a longer temporary name.
TEST(robustness, output_names_up_to_255_bytes_are_written_by_every_command) {
    const scratch s;
    write_file(s.file("R.csv"), unit_rect + unit_rect);
    write_file(s.file("P.csv"), "0,1\n");
    for (const std::size_t length : {std::size_t{200}, std::size_t{244}, std::size_t{250}, std::size_t{255}}) {
        const std::string name(length, 'v');
        SCOPED_TRACE(std::to_string(length) + " bytes");
        const run_result collide = s.run("collide --rects R.csv --pairs P.csv --out " + name);
        EXPECT_EQ(collide.status, 0) << collide.err;
        EXPECT_EQ(read_file(s.file(name)), "1\n");
        fs::remove(s.file(name));

        const run_result draw = s.run("draw --rects R.csv --pairs P.csv --select 0 --out " + name);
        EXPECT_EQ(draw.status, 0) << draw.err;
        EXPECT_EQ(read_file(s.file(name)).rfind("<?xml", 0), 0u);
        fs::remove(s.file(name));

        const run_result accuracy =
            s.run("accuracy --pairs 10 --reps 1 --json " + name + " --svg " + std::string(length, 's'));
        EXPECT_EQ(accuracy.status, 0) << accuracy.err;
        EXPECT_EQ(read_file(s.file(name)).rfind("{", 0), 0u);
        EXPECT_EQ(read_file(s.file(std::string(length, 's'))).rfind("<?xml", 0), 0u);
        fs::remove(s.file(name));
        fs::remove(s.file(std::string(length, 's')));

        const run_result gen = s.run("gen tiles --pairs 10 --out " + name);
        EXPECT_EQ(gen.status, 0) << gen.err;
        EXPECT_TRUE(fs::is_regular_file(s.file(name) / "truth.txt"));
        const run_result again = s.run("gen tiles --pairs 10 --out " + name);
        EXPECT_EQ(again.status, 0) << again.err;
        fs::remove_all(s.file(name));

        EXPECT_EQ(s.entries(), (std::vector<std::string>{"P.csv", "R.csv"}));
    }
}

TEST(robustness, an_empty_output_name_is_called_empty) {
    const scratch s;
    write_file(s.file("R.csv"), unit_rect);
    write_file(s.file("P.csv"), "0,0\n");
    const std::vector<std::pair<std::string, std::string>> runs = {
        {"collide --rects R.csv --pairs P.csv --out ''", "collide: --out: the file name is empty"},
        {"draw --rects R.csv --pairs P.csv --select 0 --out ''", "draw: --out: the file name is empty"},
        {"accuracy --pairs 10 --json ''", "accuracy: --json: the file name is empty"},
        {"accuracy --pairs 10 --svg=", "accuracy: --svg: the file name is empty"},
    };
    for (const auto& [args, message] : runs) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err.rfind("obbsat: " + message + " (see 'obbsat ", 0), 0u) << args << "\n" << r.err;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(s.entries(), (std::vector<std::string>{"P.csv", "R.csv"})) << args;
    }
}

// Runs obbsat with `args` in work() as a child process whose pair file,
// P.fifo, is a named pipe held open and empty: the run waits for pairs with
// its output already begun. Once a hidden file (the temporary output) shows
// in work(), the child gets `signal`; returns how it ended.
int interrupted_run(const scratch& s, const std::vector<std::string>& args, int signal) {
    const std::string fifo = s.file("P.fifo").string();
    if (::mkfifo(fifo.c_str(), 0600) != 0 && errno != EEXIST) {
        ADD_FAILURE() << "mkfifo failed";
        return -1;
    }
    const int writer = ::open(fifo.c_str(), O_RDWR | O_CLOEXEC);  // never blocks, keeps the pipe open
    std::vector<char*> argv;
    const std::string program = OBBSAT_CLI_PATH;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    const pid_t child = ::fork();
    if (child == 0) {
        // The test's own dispositions (an ignored SIGINT, say) must not decide the outcome.
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        const int null = ::open("/dev/null", O_WRONLY);
        if (::chdir(s.work().c_str()) != 0 || null < 0 || ::dup2(null, 1) < 0 || ::dup2(null, 2) < 0) {
            ::_exit(126);
        }
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    bool began = false;
    for (int wait = 0; wait < 2000 && !began; ++wait) {
        began = !s.entries_starting_with(".").empty();
        if (!began) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    EXPECT_TRUE(began) << "no temporary output appeared";
    ::kill(child, began ? signal : SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ::close(writer);
    ::unlink(fifo.c_str());
    return status;
}

TEST(robustness, an_interrupted_run_leaves_no_temporary_file) {
    const scratch s;
    write_file(s.file("v.txt"), previous);
    write_file(s.file("R.csv"), unit_rect);
    for (const int signal : {SIGINT, SIGTERM}) {
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"collide", "--rects", "R.csv", "--pairs", "P.fifo", "--out", "v.txt"},
              std::vector<std::string>{"draw", "--rects", "R.csv", "--pairs", "P.fifo", "--select", "0",
                                       "--out", "v.txt"}}) {
            SCOPED_TRACE(args[0] + " stopped by signal " + std::to_string(signal));
            const int status = interrupted_run(s, args, signal);
            // The default action of the signal ends the run, as the shell expects.
            EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << status;
            EXPECT_EQ(read_file(s.file("v.txt")), previous);
            EXPECT_EQ(s.entries(), (std::vector<std::string>{"R.csv", "v.txt"}));
        }
    }
}

// Both inputs are read to their end, one after the other: a stream named
// twice would give the rectangles every byte and the pairs none, and a file
// named twice holds either rectangles or pairs, not both.
TEST(robustness, two_names_for_standard_input_are_refused) {
    const scratch s;
    write_file(s.file("v.txt"), previous);
    write_file(s.file("in.txt"), unit_rect + "0,0\n");
    const std::vector<std::pair<std::string, std::string>> names = {
        {"/dev/stdin", "-"}, {"-", "/dev/stdin"}, {"/dev/fd/0", "-"}, {"/proc/self/fd/0", "/dev/stdin"}};
    for (const auto& [rects, pairs] : names) {
        for (const std::string command : {"collide", "draw"}) {
            const std::string args = command + " --rects " + rects + " --pairs " + pairs +
                                     (command == "draw" ? " --select 0" : "") + " --out v.txt";
            const std::string message = command + ": --rects '" + rects + "' and --pairs '" + pairs +
                                        "' name the same input; rectangles and pairs need one each";
            expect_refused(s, s.run_piped("in.txt", args), message, args + " from a pipe");
            expect_refused(s, s.run(args, "", "< in.txt"), message, args + " from a file");
        }
    }
    for (const auto& [poses, pairs] : names) {
        const std::string args = "collide --poses " + poses + " --pairs " + pairs + " --out v.txt";
        const std::string message = "collide: --poses '" + poses + "' and --pairs '" + pairs +
                                    "' name the same input; rectangles and pairs need one each";
        expect_refused(s, s.run_piped("in.txt", args), message, args + " from a pipe");
        expect_refused(s, s.run(args, "", "< in.txt"), message, args + " from a file");
    }
    fs::create_symlink("in.txt", s.file("link.txt"));
    const run_result twice = s.run("collide --rects in.txt --pairs link.txt --out v.txt");
    expect_refused(s, twice,
                   "collide: --rects 'in.txt' and --pairs 'link.txt' name the same input; rectangles and "
                   "pairs need one each",
                   "a file and a link to it");
}

}  // namespace
