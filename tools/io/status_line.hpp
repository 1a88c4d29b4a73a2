// A status line on standard error for commands that run long: while the work
// goes on, one line overwritten in place ("\r" and an erase to the end of the
// line), shown only when the stream is a terminal and only once the command
// has run `delay` seconds, at most ten times a second; at the end, a one-line
// summary with the time taken, again only on a terminal. Anywhere else
// (a file, a pipe, a test capturing stderr) it writes nothing, so the
// program's standard error stays as it was.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace obbsat::io {

class status_line {
public:
    using clock = std::chrono::steady_clock;

    /// Writes to `out` only if `terminal`; `prefix` starts every line
    /// ("obbsat pairs").
    status_line(std::FILE* out, bool terminal, std::string prefix, double delay_seconds = 1.0);
    /// On standard error, a terminal if isatty says so.
    explicit status_line(std::string prefix);
    /// A status line still shown (an error ends the run) is erased, so the
    /// error message starts at the left margin.
    ~status_line();
    status_line(const status_line&) = delete;
    status_line& operator=(const status_line&) = delete;

    /// True iff a show() now would be written: a terminal, past the delay,
    /// and a tenth of a second since the last. Cheap, so callers test it
    /// before they build the text.
    bool due() const;
    /// Shows "PREFIX: text" in place of the line shown before, if due().
    void show(const std::string& text);
    /// Replaces the status line by "PREFIX: summary, T s" and a line end, on
    /// a terminal; nothing elsewhere.
    void finish(const std::string& summary);

    /// Seconds since the status line was made.
    double seconds() const;
    bool terminal() const { return terminal_; }

private:
    void erase();

    std::FILE* out_;
    bool terminal_;
    std::string prefix_;
    double delay_;
    clock::time_point start_;
    clock::time_point last_shown_;
    bool shown_ = false;
    bool finished_ = false;
};

}  // namespace obbsat::io
