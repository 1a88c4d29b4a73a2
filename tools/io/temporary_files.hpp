// Temporary files and directories that must not outlive the program, even
// when a signal ends it.
//
// Output is written to a temporary beside its target and renamed into place
// at the end (atomic_output.hpp, obbsat gen). Destructors remove such a
// temporary on every error path; a signal that ends the program (Ctrl-C, a
// kill, a closed terminal or pipe) runs no destructor. So each temporary is
// also registered here while it exists, and a handler removes every
// registered one before the signal ends the program as it would have.
//
// Temporary names are short and of fixed length (a dot, "obbsat", a tag and
// six random characters), so that a temporary fits beside any target whose
// own name fits within NAME_MAX.
#pragma once

#include <string>

#include <signal.h>

namespace obbsat::io {

/// Installs, for SIGINT, SIGTERM, SIGHUP and SIGPIPE (each unless ignored), a
/// handler that removes every registered temporary and then ends the program
/// by the same signal, with its default action; call once, at start-up.
void remove_temporaries_on_signal();

/// While it lives (and until release()), the file or empty directory at `path`
/// is removed if a handled signal ends the program. Registering only makes a
/// promise: it creates and removes nothing itself.
class temporary_registration {
public:
    enum class kind { file, directory };

    temporary_registration() = default;
    /// Registers `path`; throws output_error if it is longer than a path can be.
    temporary_registration(const std::string& path, kind what);
    ~temporary_registration() { release(); }
    temporary_registration(temporary_registration&& other) noexcept;
    temporary_registration& operator=(temporary_registration&& other) noexcept;
    temporary_registration(const temporary_registration&) = delete;
    temporary_registration& operator=(const temporary_registration&) = delete;

    /// Withdraws the promise: the path is no longer a temporary (renamed into
    /// place, or removed already).
    void release() noexcept;

private:
    int slot_ = -1;
};

/// The name of a new temporary inside `directory` ("" for the current one, else
/// ending in '/'): `directory` + ".obbsat-" + `tag` + ".XXXXXX", the pattern
/// mkstemp and mkdtemp fill in.
std::string temporary_pattern(const std::string& directory, const char* tag);

/// Blocks the handled signals in the calling thread while it lives, so that a
/// temporary is never created without being registered.
class signals_held {
public:
    signals_held();
    ~signals_held();
    signals_held(const signals_held&) = delete;
    signals_held& operator=(const signals_held&) = delete;

private:
    sigset_t saved_;
};

}  // namespace obbsat::io
