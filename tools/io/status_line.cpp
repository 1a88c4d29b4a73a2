#include "io/status_line.hpp"

#include <unistd.h>

namespace obbsat::io {

namespace {

// Between two writes of the line: fast enough to look alive, slow enough to
// cost nothing.
constexpr double refresh_seconds = 0.1;

double seconds_between(status_line::clock::time_point from, status_line::clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

}  // namespace

status_line::status_line(std::FILE* out, bool terminal, std::string prefix, double delay_seconds)
    : out_(out),
      terminal_(terminal),
      prefix_(std::move(prefix)),
      delay_(delay_seconds),
      start_(clock::now()),
      last_shown_(start_) {}

status_line::status_line(std::string prefix)
    : status_line(stderr, ::isatty(STDERR_FILENO) == 1, std::move(prefix)) {}

status_line::~status_line() {
    if (shown_ && !finished_) {
        erase();
        std::fflush(out_);
    }
}

bool status_line::due() const {
    if (!terminal_ || finished_) {
        return false;
    }
    const clock::time_point now = clock::now();
    if (seconds_between(start_, now) < delay_) {
        return false;
    }
    return !shown_ || seconds_between(last_shown_, now) >= refresh_seconds;
}

void status_line::erase() { std::fputs("\r\x1b[K", out_); }

void status_line::show(const std::string& text) {
    if (!due()) {
        return;
    }
    erase();
    std::fprintf(out_, "%s: %s", prefix_.c_str(), text.c_str());
    std::fflush(out_);
    shown_ = true;
    last_shown_ = clock::now();
}

void status_line::finish(const std::string& summary) {
    if (!terminal_ || finished_) {
        return;
    }
    if (shown_) {
        erase();
    }
    std::fprintf(out_, "%s: %s, %.1f s\n", prefix_.c_str(), summary.c_str(), seconds());
    std::fflush(out_);
    finished_ = true;
}

double status_line::seconds() const { return seconds_between(start_, clock::now()); }

}  // namespace obbsat::io
