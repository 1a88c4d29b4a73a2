// The built obbsat program run through the shell as a user runs it, in a
// scratch directory of its own: the tests see its exit status, its standard
// output and error, and the files it left behind.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <stdlib.h>
#include <sys/wait.h>

#ifndef OBBSAT_CLI_PATH
#error "OBBSAT_CLI_PATH must name the obbsat program"
#endif

namespace obbsat::cli_test {

struct run_result {
    int status;  // exit status; -1 if the program did not exit normally
    std::string out;
    std::string err;
};

/// The bytes of `file`; empty if it cannot be read.
inline std::string read_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

inline void write_file(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
}

/// The lines of `text`, without their '\n'.
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

// `work` is the program's current directory, so its messages carry the short
// relative names the tests expect; `capture` holds its stdout and stderr
// outside `work`, so they never count as files the program left behind.
class scratch {
public:
    scratch() {
        char pattern[] = "/tmp/obbsat_cli_XXXXXX";
        if (mkdtemp(pattern) == nullptr) {
            throw std::runtime_error("mkdtemp failed");
        }
        root_ = pattern;
        std::filesystem::create_directory(work());
        std::filesystem::create_directory(root_ / "capture");
    }
    ~scratch() {
        std::error_code ignored;
        std::filesystem::remove_all(root_, ignored);
    }
    scratch(const scratch&) = delete;
    scratch& operator=(const scratch&) = delete;

    std::filesystem::path work() const { return root_ / "work"; }
    std::filesystem::path file(const std::string& name) const { return work() / name; }

    /// Runs `obbsat ARGS` in work() with OBBSAT_BACKEND unset unless `env`
    /// (e.g. "OBBSAT_BACKEND=scalar") sets it; `redirects` (e.g. "< in.txt")
    /// comes after the captures, so it may replace them.
    run_result run(const std::string& args, const std::string& env = "",
                   const std::string& redirects = "") const {
        return run_command("", args, env, redirects);
    }

    /// Runs `obbsat ARGS` like run(), its standard input a pipe fed with the
    /// file `input` of work().
    run_result run_piped(const std::string& input, const std::string& args) const {
        return run_command("cat '" + input + "' | ", args, "", "");
    }

    /// The names in work(), sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(work())) {
            names.push_back(e.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    /// The names in work() that start with `prefix`, sorted.
    std::vector<std::string> entries_starting_with(const std::string& prefix) const {
        std::vector<std::string> names;
        for (const std::string& name : entries()) {
            if (name.rfind(prefix, 0) == 0) {
                names.push_back(name);
            }
        }
        return names;
    }

    /// Every path under work(), relative and sorted, directories included.
    std::vector<std::string> tree() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::recursive_directory_iterator(work())) {
            names.push_back(std::filesystem::relative(e.path(), work()).string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    run_result run_command(const std::string& feed, const std::string& args, const std::string& env,
                           const std::string& redirects) const {
        const std::filesystem::path out = root_ / "capture" / "stdout";
        const std::filesystem::path err = root_ / "capture" / "stderr";
        std::string command = "cd '" + work().string() + "' && " + feed + "env -u OBBSAT_BACKEND " +
                              env + " '" OBBSAT_CLI_PATH "' " + args + " > '" + out.string() + "' 2> '" +
                              err.string() + "'";
        if (!redirects.empty()) {
            command += " " + redirects;
        }
        const int raw = std::system(command.c_str());
        const int status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
        return run_result{status, read_file(out), read_file(err)};
    }

    std::filesystem::path root_;
};

}  // namespace obbsat::cli_test
