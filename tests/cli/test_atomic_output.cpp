// All-or-nothing output: the target changes only on commit, and no temporary
// file outlives the writer.
#include "io/atomic_output.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace {

namespace fs = std::filesystem;
using obbsat::io::atomic_output;
using obbsat::io::output_error;

class atomic_output_test : public ::testing::Test {
protected:
    void SetUp() override {
        char pattern[] = "/tmp/obbsat_atomic_output_XXXXXX";
        ASSERT_NE(mkdtemp(pattern), nullptr);
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) {
            names.push_back(e.path().filename().string());
        }
        return names;
    }

    static std::string content(const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream out;
        out << in.rdbuf();
        return out.str();
    }

    static void put(const std::string& file, const std::string& text) {
        std::ofstream(file, std::ios::binary) << text;
    }

    fs::path dir_;
};

TEST_F(atomic_output_test, commit_makes_the_content_appear) {
    {
        atomic_output out(path("v.txt"));
        EXPECT_FALSE(fs::exists(path("v.txt")));
        EXPECT_EQ(fs::path(out.temp_path()).parent_path(), dir_);
        out.write("1\n0\n", 4);
        out.write("", 0);
        out.commit();
        EXPECT_EQ(content(path("v.txt")), "1\n0\n");
    }
    EXPECT_EQ(entries(), std::vector<std::string>{"v.txt"});
}

TEST_F(atomic_output_test, without_commit_an_existing_target_is_untouched) {
    put(path("v.txt"), "old verdicts\n");
    std::string temp;
    {
        atomic_output out(path("v.txt"));
        temp = out.temp_path();
        out.write("1\n", 2);
        EXPECT_TRUE(fs::exists(temp));
    }
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(content(path("v.txt")), "old verdicts\n");
    EXPECT_EQ(entries(), std::vector<std::string>{"v.txt"});
}

TEST_F(atomic_output_test, commit_replaces_an_existing_target_and_keeps_its_mode) {
    put(path("v.txt"), "old\n");
    ASSERT_EQ(chmod(path("v.txt").c_str(), 0640), 0);
    atomic_output out(path("v.txt"));
    out.write("new\n", 4);
    out.commit();
    EXPECT_EQ(content(path("v.txt")), "new\n");
    struct stat info {};
    ASSERT_EQ(stat(path("v.txt").c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0640u);
}

TEST_F(atomic_output_test, a_new_file_gets_the_umask_mode_not_0600) {
    const mode_t old_mask = umask(022);
    {
        atomic_output out(path("v.txt"));
        out.commit();
    }
    umask(old_mask);
    struct stat info {};
    ASSERT_EQ(stat(path("v.txt").c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0644u);
}

TEST_F(atomic_output_test, a_missing_directory_is_an_error_naming_the_target) {
    const std::string target = path("no/such/dir/v.txt");
    try {
        atomic_output out(target);
        FAIL() << "no error";
    } catch (const output_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  target + ": cannot create a temporary file beside it: No such file or directory");
    }
}

TEST_F(atomic_output_test, a_directory_is_not_a_target) {
    fs::create_directory(path("sub"));
    EXPECT_THROW(atomic_output out(path("sub")), output_error);
    EXPECT_THROW(atomic_output out(path("sub") + "/"), output_error);
    EXPECT_TRUE(fs::is_directory(path("sub")));
}

TEST_F(atomic_output_test, a_symbolic_link_survives_and_its_file_is_replaced) {
    put(path("real.txt"), "old\n");
    fs::create_symlink("real.txt", path("link.txt"));
    {
        atomic_output out(path("link.txt"));
        out.write("new\n", 4);
        out.commit();
    }
    EXPECT_TRUE(fs::is_symlink(path("link.txt")));
    EXPECT_EQ(content(path("real.txt")), "new\n");
    EXPECT_EQ(entries().size(), 2u);
}

TEST_F(atomic_output_test, a_device_is_written_directly_and_stays_a_device) {
    ASSERT_TRUE(fs::is_character_file("/dev/null"));
    {
        atomic_output out("/dev/null");
        EXPECT_EQ(out.temp_path(), "");
        out.write("1\n", 2);
        out.commit();
    }
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(atomic_output_test, writing_after_commit_is_an_error) {
    atomic_output out(path("v.txt"));
    out.commit();
    EXPECT_THROW(out.write("1\n", 2), output_error);
    EXPECT_THROW(out.commit(), output_error);
}

TEST_F(atomic_output_test, a_target_name_of_255_bytes_has_room_for_its_temporary) {
    for (const std::size_t length : {std::size_t{1}, std::size_t{244}, std::size_t{255}}) {
        const std::string name(length, 'n');
        {
            atomic_output out(path(name));
            EXPECT_EQ(fs::path(out.temp_path()).parent_path(), dir_);
            EXPECT_LE(fs::path(out.temp_path()).filename().string().size(), 255u);
            out.write("1\n", 2);
            out.commit();
        }
        EXPECT_EQ(content(path(name)), "1\n");
        EXPECT_EQ(entries(), std::vector<std::string>{name});
        fs::remove(path(name));
    }
}

TEST_F(atomic_output_test, an_empty_name_is_called_empty) {
    try {
        atomic_output out("");
        ADD_FAILURE() << "no error";
    } catch (const output_error& e) {
        EXPECT_STREQ(e.what(), "the output file name is empty");
    }
    EXPECT_TRUE(entries().empty());
}

}  // namespace
