// Output that appears at its path whole or not at all.
//
// Bytes go to a temporary file beside the target (same directory, so the final
// rename stays within one file system and is atomic; a short name of its own,
// see temporary_files.hpp, so that it fits wherever the target's name fits);
// commit() flushes it to disk and renames it over the target. Until then an
// existing target is left untouched, and if commit() is never reached the
// temporary file is removed: by the destructor, or by the signal handler of
// temporary_files.hpp when a signal ends the program.
//
// A target that is a symbolic link keeps the link: the file it names is
// replaced. A target that exists but is not a regular file (a device such as
// /dev/null, a named pipe) is written directly, since there is no file to
// replace and renaming over it would remove the device.
#pragma once

#include "io/temporary_files.hpp"

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace obbsat::io {

/// Output could not be created, written or committed; what() names the path.
class output_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class atomic_output {
public:
    /// Creates the temporary file for `target_path`; throws output_error.
    explicit atomic_output(std::string target_path);
    /// Removes the temporary file unless commit() succeeded.
    ~atomic_output();
    atomic_output(const atomic_output&) = delete;
    atomic_output& operator=(const atomic_output&) = delete;

    /// Appends bytes; throws output_error on a write error.
    void write(const char* data, std::size_t size);

    /// Makes the written bytes the content of the target; throws output_error.
    void commit();

    const std::string& target_path() const { return target_path_; }
    /// The temporary file's path, while it exists; empty when writing directly.
    const std::string& temp_path() const { return temp_path_; }

private:
    void open_direct();
    void open_temporary(const std::string& final_path);
    void discard() noexcept;
    void remove_temporary(int fd) noexcept;

    std::string target_path_;
    std::string final_path_;  // target_path_ with symbolic links resolved
    std::string temp_path_;
    temporary_registration temp_registered_;
    std::FILE* file_ = nullptr;
    bool direct_ = false;
    bool committed_ = false;
};

}  // namespace obbsat::io
