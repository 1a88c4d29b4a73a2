#include "io/atomic_output.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace obbsat::io {

namespace {

std::string failure(const std::string& path, const char* what, int error) {
    return path + ": " + what + ": " + std::strerror(error);
}

// The mode the target ends with: that of the file it replaces, else what a
// plain open() would give a new file under the current umask (mkstemp's 0600
// would surprise whoever reads the output next).
mode_t final_mode(const std::string& target_path) {
    struct stat existing {};
    if (::stat(target_path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) {
        return existing.st_mode & 07777;
    }
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
}

}  // namespace

atomic_output::atomic_output(std::string target_path) : target_path_(std::move(target_path)) {
    if (target_path_.empty()) {
        throw output_error("the output file name is empty");
    }
    const std::size_t slash = target_path_.rfind('/');
    const std::string base =
        slash == std::string::npos ? target_path_ : target_path_.substr(slash + 1);
    struct stat existing {};
    const bool exists = ::stat(target_path_.c_str(), &existing) == 0;
    if (base.empty() || base == "." || base == ".." || (exists && S_ISDIR(existing.st_mode))) {
        throw output_error(target_path_ + ": is a directory, not a file name");
    }
    if (exists && !S_ISREG(existing.st_mode)) {
        open_direct();
        return;
    }
    std::string final_path = target_path_;
    if (exists) {
        if (char* resolved = ::realpath(target_path_.c_str(), nullptr)) {
            final_path = resolved;
            std::free(resolved);
        }
    }
    open_temporary(final_path);
}

void atomic_output::open_direct() {
    file_ = std::fopen(target_path_.c_str(), "wb");
    if (file_ == nullptr) {
        throw output_error(failure(target_path_, "cannot open", errno));
    }
    direct_ = true;
}

void atomic_output::open_temporary(const std::string& final_path) {
    final_path_ = final_path;
    const std::size_t slash = final_path_.rfind('/');
    const std::string directory =
        slash == std::string::npos ? std::string() : final_path_.substr(0, slash + 1);

    const std::string pattern = temporary_pattern(directory, "out");
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = -1;
    {
        // Created and registered with the handled signals held, so that no
        // signal finds the file unregistered.
        const signals_held held;
        fd = ::mkstemp(name.data());
        if (fd < 0) {
            throw output_error(failure(target_path_, "cannot create a temporary file beside it", errno));
        }
        temp_path_ = name.data();
        try {
            temp_registered_ = temporary_registration(temp_path_, temporary_registration::kind::file);
        } catch (...) {
            remove_temporary(fd);
            throw;
        }
    }
    if (::fchmod(fd, final_mode(final_path_)) != 0) {
        const int error = errno;
        remove_temporary(fd);
        throw output_error(failure(target_path_, "cannot set the temporary file's mode", error));
    }
    file_ = ::fdopen(fd, "wb");
    if (file_ == nullptr) {
        const int error = errno;
        remove_temporary(fd);
        throw output_error(failure(target_path_, "cannot open the temporary file", error));
    }
}

void atomic_output::remove_temporary(int fd) noexcept {
    ::close(fd);
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
    temp_registered_.release();
}

atomic_output::~atomic_output() {
    if (!committed_) {
        discard();
    }
}

void atomic_output::discard() noexcept {
    if (file_ != nullptr) {
        std::fclose(file_);
        file_ = nullptr;
    }
    if (!temp_path_.empty()) {
        ::unlink(temp_path_.c_str());
        temp_path_.clear();
        temp_registered_.release();
    }
}

void atomic_output::write(const char* data, std::size_t size) {
    if (file_ == nullptr) {
        throw output_error(target_path_ + ": write after commit");
    }
    if (size != 0 && std::fwrite(data, 1, size, file_) != size) {
        throw output_error(failure(target_path_, "write error", errno));
    }
}

void atomic_output::commit() {
    if (file_ == nullptr) {
        throw output_error(target_path_ + ": committed twice");
    }
    if (std::fflush(file_) != 0) {
        throw output_error(failure(target_path_, "write error", errno));
    }
    if (direct_) {
        const int closed = std::fclose(file_);
        file_ = nullptr;
        if (closed != 0) {
            throw output_error(failure(target_path_, "write error", errno));
        }
        committed_ = true;
        return;
    }
    // Data reaches the disk before the rename makes it visible, so a crash
    // leaves the old target or the complete new one, never a truncated file.
    if (::fsync(::fileno(file_)) != 0) {
        throw output_error(failure(target_path_, "cannot flush to disk", errno));
    }
    const int closed = std::fclose(file_);
    file_ = nullptr;
    if (closed != 0) {
        throw output_error(failure(target_path_, "write error", errno));
    }
    if (::rename(temp_path_.c_str(), final_path_.c_str()) != 0) {
        throw output_error(failure(target_path_, "cannot replace it", errno));
    }
    temp_path_.clear();
    temp_registered_.release();
    committed_ = true;
}

}  // namespace obbsat::io
