// The oracle against every label of the labelled case folders, which were
// computed outside the project with exact rational arithmetic. The folder
// comes from OBBSAT_SHARED_CASES; the test is skipped where it is absent.
#include "case_files.hpp"
#include "test_support/shared_cases.hpp"

#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/oracle/quad_region.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <sys/stat.h>

namespace {

using obbsat::oracle::contact;

bool is_directory(const std::string& path) {
    struct stat info {};
    return !path.empty() && stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

std::string hex(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(v));
    return text;
}

std::string describe(const obbsat::rect& r) {
    return "{" + hex(r.ul.x) + "," + hex(r.ul.y) + " " + hex(r.ur.x) + "," + hex(r.ur.y) + " " +
           hex(r.lr.x) + "," + hex(r.lr.y) + " " + hex(r.ll.x) + "," + hex(r.ll.y) + "}";
}

std::string folder_name(const ::testing::TestParamInfo<const char*>& param) {
    return param.param;
}

class shared_cases : public ::testing::TestWithParam<const char*> {};

TEST_P(shared_cases, oracle_agrees_with_every_label) {
    const std::optional<std::string> root = obbsat::test_support::shared_cases_folder();
    if (!root) {
        GTEST_SKIP() << obbsat::test_support::shared_cases_missing();
    }
    const std::string folder = *root + "/" + GetParam();
    if (!is_directory(folder)) {
        GTEST_SKIP() << "no family folder '" << folder << "' among the labelled cases";
    }
    const obbsat::test::case_folder cases = obbsat::test::read_case_folder(folder);
    ASSERT_FALSE(cases.pairs.empty());
    const std::vector<contact> got = obbsat::oracle::classify_pairs(cases.rects, cases.pairs, 2);

    std::map<char, std::size_t> agreed;
    std::map<char, std::size_t> labelled;
    std::map<std::string, std::size_t> forms;
    std::size_t disagreements = 0;
    for (std::size_t i = 0; i < cases.pairs.size(); ++i) {
        const char want = cases.truth_class[i];
        const char have = obbsat::oracle::contact_letter(got[i]);
        ++labelled[want];
        // truth.txt and truth_class.txt must tell the same story.
        ASSERT_EQ(cases.truth[i] == '1', want != 'S') << "pair " << i << " labels disagree";
        if (have == want) {
            ++agreed[want];
            continue;
        }
        if (++disagreements <= 10) {
            const obbsat::rect& a = cases.rects[cases.pairs[i].a];
            const obbsat::rect& b = cases.rects[cases.pairs[i].b];
            ADD_FAILURE() << GetParam() << " pair " << i << " (" << cases.tags[i] << "): label "
                          << want << ", oracle " << have << "\n  A " << describe(a) << "\n  B "
                          << describe(b);
        }
    }
    for (const obbsat::rect& r : cases.rects) {
        ++forms[obbsat::oracle::quad_form_name(obbsat::oracle::region_of(r).form)];
    }
    std::string summary;
    for (const char c : {'S', 'T', 'O'}) {
        summary += std::string(1, c) + " " + std::to_string(agreed[c]) + "/" +
                   std::to_string(labelled[c]) + "  ";
    }
    std::string form_summary;
    for (const auto& [name, count] : forms) {
        form_summary += name + "=" + std::to_string(count) + " ";
    }
    std::printf("[ shared   ] %-13s agreed %zu/%zu pairs: %s| rects: %s\n", GetParam(),
                cases.pairs.size() - disagreements, cases.pairs.size(), summary.c_str(),
                form_summary.c_str());
    EXPECT_EQ(disagreements, 0u);
}

INSTANTIATE_TEST_SUITE_P(family, shared_cases,
                         ::testing::Values("random", "tiles", "near_parallel", "slivers", "tiny",
                                           "huge", "degenerate", "nested_cross"),
                         folder_name);

}  // namespace
