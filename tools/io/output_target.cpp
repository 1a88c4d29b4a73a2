#include "io/output_target.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace obbsat::io {

output_target::output_target(const std::optional<std::string_view>& path) {
    if (path) {
        file_ = std::make_unique<atomic_output>(std::string(*path));
    }
}

void output_target::write(const char* data, std::size_t size) {
    if (file_) {
        file_->write(data, size);
    } else if (size != 0 && std::fwrite(data, 1, size, stdout) != size) {
        throw output_error(std::string("standard output: write error: ") + std::strerror(errno));
    }
}

void output_target::commit() {
    if (file_) {
        file_->commit();
    }
}

}  // namespace obbsat::io
