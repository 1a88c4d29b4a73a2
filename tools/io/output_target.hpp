// Where a command's text goes: the file named by its --out option, written
// all or nothing through atomic_output, or standard output when there is none.
//
// On standard output nothing can be taken back: text written before an error
// stays written, and the exit status says to discard it. A failed write (a
// full disk, a closed pipe) throws output_error either way.
#pragma once

#include "io/atomic_output.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace obbsat::io {

class output_target {
public:
    /// The atomic file at `path`, or standard output when there is none; the
    /// file is created at once, so an unwritable target fails before any work.
    /// Throws output_error.
    explicit output_target(const std::optional<std::string_view>& path);

    /// Appends bytes; throws output_error on a write error.
    void write(const char* data, std::size_t size);

    /// Makes the written bytes the content of the file (standard output is
    /// flushed by main); throws output_error.
    void commit();

private:
    std::unique_ptr<atomic_output> file_;
};

}  // namespace obbsat::io
