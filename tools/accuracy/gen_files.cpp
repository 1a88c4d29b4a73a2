#include "accuracy/gen_files.hpp"

#include "io/atomic_output.hpp"
#include "io/csv_input.hpp"
#include "io/output_target.hpp"
#include "io/temporary_files.hpp"

#include <obbsat/oracle/contact.hpp>
#include <obbsat/suites/pose_suite.hpp>
#include <obbsat/suites/suite.hpp>

#include <array>
#include <cerrno>
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace obbsat::cli {

namespace {

// The five files of a suite: the shapes first, then pairs, truth and tags.
using file_set = std::array<const char*, 5>;
constexpr file_set rect_file_names = {"rects.csv", "pairs.csv", "truth_class.txt", "truth.txt",
                                      "tags.txt"};
constexpr file_set pose_file_names = {"poses.csv", "pairs.csv", "truth_class.txt", "truth.txt",
                                      "tags.txt"};

std::string error_text(const std::string& path, const char* what, int error) {
    return path + ": " + what + ": " + std::strerror(error);
}

// One file of the suite, written into the temporary directory; errors name
// the path the file is meant for, as that is the one the user knows.
class suite_file {
public:
    suite_file(const std::string& temp_path, std::string final_path)
        : final_path_(std::move(final_path)) {
        file_ = std::fopen(temp_path.c_str(), "wb");
        if (file_ == nullptr) {
            throw io::output_error(error_text(final_path_, "cannot create", errno));
        }
    }
    ~suite_file() {
        if (file_ != nullptr) {
            std::fclose(file_);
        }
    }
    suite_file(const suite_file&) = delete;
    suite_file& operator=(const suite_file&) = delete;

    void line(const char* text, std::size_t size) {
        buffer_.append(text, size);
        buffer_ += '\n';
        if (buffer_.size() >= (std::size_t{1} << 20)) {
            flush_buffer();
        }
    }
    void line(const std::string& text) { line(text.data(), text.size()); }

    // Everything on disk before anything is renamed into place.
    void finish() {
        flush_buffer();
        if (std::fflush(file_) != 0) {
            throw io::output_error(error_text(final_path_, "write error", errno));
        }
        if (::fsync(::fileno(file_)) != 0) {
            throw io::output_error(error_text(final_path_, "cannot flush to disk", errno));
        }
        const int closed = std::fclose(file_);
        file_ = nullptr;
        if (closed != 0) {
            throw io::output_error(error_text(final_path_, "write error", errno));
        }
    }

private:
    void flush_buffer() {
        if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
            throw io::output_error(error_text(final_path_, "write error", errno));
        }
        buffer_.clear();
    }

    std::string final_path_;
    std::FILE* file_ = nullptr;
    std::string buffer_;
};

// A temporary directory, created from `pattern` (mkdtemp's), removed with the
// files of `names` unless released, on an error and on a signal alike; errors
// name `dir`.
class temp_directory {
public:
    temp_directory(const std::string& pattern, const std::string& dir, const file_set& names)
        : names_(names) {
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        {
            const io::signals_held held;  // no signal finds it unregistered
            if (::mkdtemp(name.data()) == nullptr) {
                throw io::output_error(error_text(dir, "cannot create a temporary directory for it", errno));
            }
            path_ = name.data();
            registered_.emplace_back(path_, io::temporary_registration::kind::directory);
        }
        // Registered before they exist: removing a missing file is harmless.
        for (const char* file : names_) {
            registered_.emplace_back(path_ + "/" + file, io::temporary_registration::kind::file);
        }
    }
    ~temp_directory() {
        if (path_.empty()) {
            return;
        }
        for (const char* name : names_) {
            ::unlink((path_ + "/" + name).c_str());
        }
        ::rmdir(path_.c_str());
    }
    temp_directory(const temp_directory&) = delete;
    temp_directory& operator=(const temp_directory&) = delete;

    const std::string& path() const { return path_; }
    /// The directory is in place under its final name: nothing to remove.
    void release() {
        path_.clear();
        registered_.clear();
    }

private:
    file_set names_;
    std::string path_;
    std::vector<io::temporary_registration> registered_;
};


// The directory that will hold DIR.
std::string parent_of(const std::string& dir) {
    const std::size_t slash = dir.rfind('/');
    if (slash == std::string::npos) {
        return ".";
    }
    return slash == 0 ? "/" : dir.substr(0, slash);
}

void sync_directory(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);  // durability of the renames only; the files are complete either way
        ::close(fd);
    }
}

// One line of rects.csv or of poses.csv, its floats joined by ','. In
// decimal, std::to_chars without a precision gives the shortest text that
// reads back to the same float (subnormals and -0 too); in hex, %a prints the
// float (promoted to double, exactly) as a C99 hex float that strtof and
// from_chars read back to the same float, the format gen wrote before
// decimal became the default.
// The same for doubles (--precision double): to_chars(double) gives the
// shortest text that reads back to the same double, %a the double exactly.
template <class Real, std::size_t N>
std::size_t float_line(char* text, std::size_t size, const std::array<Real, N>& values, bool hex) {
    char* at = text;
    char* const end = text + size;
    for (std::size_t k = 0; k < N; ++k) {
        if (k > 0) {
            *at++ = ',';
        }
        if (hex) {
            const int n = std::snprintf(at, static_cast<std::size_t>(end - at), "%a", static_cast<double>(values[k]));
            at += n;
        } else {
            at = std::to_chars(at, end, values[k]).ptr;
        }
    }
    return static_cast<std::size_t>(at - text);
}

std::size_t shape_line(char* text, std::size_t size, const rect& r, bool hex) {
    return float_line<float, 8>(text, size, {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y}, hex);
}

std::size_t shape_line(char* text, std::size_t size, const rect_pose& p, bool hex) {
    return float_line<float, 6>(text, size,
                                {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x, p.rotation.y},
                                hex);
}

std::size_t shape_line(char* text, std::size_t size, const rect64& r, bool hex) {
    return float_line<double, 8>(text, size, {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y}, hex);
}

std::size_t shape_line(char* text, std::size_t size, const rect_pose64& p, bool hex) {
    return float_line<double, 6>(
        text, size, {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x, p.rotation.y}, hex);
}

std::string_view header_of(const suites::suite&) { return io::rect_header; }
std::string_view header_of(const suites::pose_suite&) { return io::pose_header; }
std::string_view header_of(const accuracy::double_rect_suite&) { return io::rect_header; }
std::string_view header_of(const accuracy::double_pose_suite&) { return io::pose_header; }

const std::vector<rect>& shapes_of(const suites::suite& s) { return s.rects; }
const std::vector<rect_pose>& shapes_of(const suites::pose_suite& s) { return s.poses; }
const std::vector<rect64>& shapes_of(const accuracy::double_rect_suite& s) { return s.rects; }
const std::vector<rect_pose64>& shapes_of(const accuracy::double_pose_suite& s) { return s.poses; }

// Suite is suites::suite or suites::pose_suite; names[0] is its shapes' file.
template <class Suite>
void write_suite_files(const std::string& temp, const std::string& dir, const Suite& s,
                       const std::vector<oracle::contact>& truth, const file_set& names, const csv_style& style) {
    auto temp_path = [&](const char* name) { return temp + "/" + name; };
    auto final_path = [&](const char* name) { return dir + "/" + name; };
    char text[512];  // eight doubles of at most 24 characters, seven commas

    {
        suite_file shapes(temp_path(names[0]), final_path(names[0]));
        if (style.header) {
            shapes.line(std::string(header_of(s)));
        }
        for (const auto& shape : shapes_of(s)) {
            shapes.line(text, shape_line(text, sizeof text, shape, style.hex));
        }
        shapes.finish();
    }
    {
        suite_file pairs(temp_path("pairs.csv"), final_path("pairs.csv"));
        if (style.header) {
            pairs.line(std::string(io::pair_header));
        }
        for (const pair_index& p : s.pairs) {
            const int size = std::snprintf(text, sizeof text, "%" PRIu32 ",%" PRIu32, p.a, p.b);
            pairs.line(text, static_cast<std::size_t>(size));
        }
        pairs.finish();
    }
    {
        suite_file classes(temp_path("truth_class.txt"), final_path("truth_class.txt"));
        suite_file verdicts(temp_path("truth.txt"), final_path("truth.txt"));
        for (const oracle::contact c : truth) {
            const char letter = oracle::contact_letter(c);
            const char verdict = c == oracle::contact::separated ? '0' : '1';
            classes.line(&letter, 1);
            verdicts.line(&verdict, 1);
        }
        classes.finish();
        verdicts.finish();
    }
    {
        suite_file tags(temp_path("tags.txt"), final_path("tags.txt"));
        for (std::size_t i = 0; i < s.pairs.size(); ++i) {
            tags.line(s.tag_of(i));
        }
        tags.finish();
    }
}

// Moves the complete files from `temp` into `dir`, which exists.
void move_files_into(const std::string& temp, const std::string& dir, const file_set& names) {
    // Checked for every file before any moves, so that a name taken by a
    // directory cannot leave DIR with some files new and some old.
    for (const char* name : names) {
        struct stat existing {};
        const std::string target = dir + "/" + name;
        if (::stat(target.c_str(), &existing) == 0 && S_ISDIR(existing.st_mode)) {
            throw io::output_error(target + ": is a directory, not a file name");
        }
    }
    for (const char* name : names) {
        const std::string target = dir + "/" + name;
        if (::rename((temp + "/" + name).c_str(), target.c_str()) != 0) {
            throw io::output_error(error_text(target, "cannot replace it", errno));
        }
    }
}

// Writes the suite `s` and its `truth` into `dir`, all or nothing.
template <class Suite>
void write_suite(const std::string& dir, bool dir_exists, const Suite& s,
                 const std::vector<oracle::contact>& truth, const file_set& names, const csv_style& style) {
    const std::string parent = parent_of(dir);
    temp_directory temp(io::temporary_pattern((dir_exists ? dir : parent) + "/", "gen"), dir,
                        names);
    write_suite_files(temp.path(), dir, s, truth, names, style);

    if (dir_exists) {
        move_files_into(temp.path(), dir, names);
        sync_directory(dir);
    } else {
        // mkdtemp made it private (0700); DIR gets what mkdir would give it.
        const mode_t mask = ::umask(0);
        ::umask(mask);
        if (::chmod(temp.path().c_str(), static_cast<mode_t>(0777 & ~mask)) != 0 ||
            ::rename(temp.path().c_str(), dir.c_str()) != 0) {
            throw io::output_error(error_text(dir, "cannot create it", errno));
        }
        temp.release();
        sync_directory(parent);
    }
}

}  // namespace

std::string without_trailing_slashes(std::string path) {
    while (path.size() > 1 && path.back() == '/') {
        path.pop_back();
    }
    return path;
}

// The poses of a scene, one line each, handed to `out` a megabyte at a time.
void write_pose_lines(const std::vector<rect_pose>& poses, io::output_target& out, const csv_style& style) {
    constexpr std::size_t buffer_bytes = std::size_t{1} << 20;
    std::string buffer;
    buffer.reserve(buffer_bytes + 256);
    if (style.header) {
        buffer.append(io::pose_header);
        buffer += '\n';
    }
    char text[256];
    for (const rect_pose& p : poses) {
        buffer.append(text, shape_line(text, sizeof text, p, style.hex));
        buffer += '\n';
        if (buffer.size() >= buffer_bytes) {
            out.write(buffer.data(), buffer.size());
            buffer.clear();
        }
    }
    out.write(buffer.data(), buffer.size());
}

void write_suite_dir(const std::string& dir, bool dir_exists, const suites::suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style) {
    write_suite(dir, dir_exists, s, truth, rect_file_names, style);
}

void write_suite_dir(const std::string& dir, bool dir_exists, const suites::pose_suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style) {
    write_suite(dir, dir_exists, s, truth, pose_file_names, style);
}

void write_suite_dir(const std::string& dir, bool dir_exists, const accuracy::double_rect_suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style) {
    write_suite(dir, dir_exists, s, truth, rect_file_names, style);
}

void write_suite_dir(const std::string& dir, bool dir_exists, const accuracy::double_pose_suite& s,
                     const std::vector<oracle::contact>& truth, const csv_style& style) {
    write_suite(dir, dir_exists, s, truth, pose_file_names, style);
}

}  // namespace obbsat::cli
