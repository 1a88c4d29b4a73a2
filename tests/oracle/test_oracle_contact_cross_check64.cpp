// The double corner oracle against GMP: orientation64 against the exact
// determinant over the whole double range, and the contact of two rect64
// against rational_model.hpp (segment intersection, ray crossing, clipped area)
// on the corners of every family of test_support/pose_cases64.hpp, and on the
// same with corners moved by a few ulps (concave and self-crossing quads).
#include "rational_model.hpp"

#include "test_support/pose_cases64.hpp"

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/orientation64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

namespace {

using obbsat::point64;
using obbsat::rect64;
using obbsat::test::rational_point;
using obbsat::test::rect_pair64;

std::string show(const rect64& r) {
    char text[300];
    std::snprintf(text, sizeof text, "{%a,%a %a,%a %a,%a %a,%a}", r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y,
                  r.ll.x, r.ll.y);
    return text;
}

int gmp_orientation(point64 p, point64 q, point64 r) {
    const mpq_class px(p.x), py(p.y), qx(q.x), qy(q.y), rx(r.x), ry(r.y);
    return sgn((qx - px) * (ry - py) - (qy - py) * (rx - px));
}

double random_double(obbsat::seeded_random& random, int lo, int hi) {
    const double m = static_cast<double>(random.next() >> 11) * 0x1p-54 + 0.5;  // in [0.5, 1)
    const double v = std::ldexp(m, obbsat::test::integer_in(random, lo, hi));
    return random.below(2) == 0 ? v : -v;
}

TEST(orientation64, agrees_with_gmp_over_the_whole_range_and_on_near_lines) {
    obbsat::seeded_random random(51);
    int zeros = 0;
    for (int i = 0; i < 200000 && !::testing::Test::HasFailure(); ++i) {
        point64 p, q, r;
        switch (random.below(3)) {
            case 0: {  // anywhere, subnormals to 1e308
                const int lo = -1073, hi = random.below(2) == 0 ? 1024 : 0;
                p = {random_double(random, lo, hi), random_double(random, lo, hi)};
                q = {random_double(random, lo, hi), random_double(random, lo, hi)};
                r = {random_double(random, lo, hi), random_double(random, lo, hi)};
                break;
            }
            default: {  // r on the line p-q at UTM-like coordinates, then a few ulps off
                p = {obbsat::test::uniform64(random, 1e5, 1e7), obbsat::test::uniform64(random, 1e5, 1e7)};
                const double step = 0.125 * obbsat::test::integer_in(random, -400, 400);
                const double rise = 0.125 * obbsat::test::integer_in(random, -400, 400);
                p.x = std::round(p.x * 8) / 8;
                p.y = std::round(p.y * 8) / 8;
                q = {p.x + step, p.y + rise};
                const double t = obbsat::test::integer_in(random, -3, 3);
                r = {p.x + t * step, p.y + t * rise};
                if (random.below(2) == 0) {
                    r.x = obbsat::test::nudged64(r.x, obbsat::test::integer_in(random, -2, 2));
                }
            }
        }
        const int expected = gmp_orientation(p, q, r);
        zeros += expected == 0 ? 1 : 0;
        ASSERT_EQ(obbsat::oracle::orientation(p, q, r), expected)
            << std::hexfloat << p.x << "," << p.y << " " << q.x << "," << q.y << " " << r.x << "," << r.y;
        ASSERT_EQ(obbsat::oracle::orientation_exact(p, q, r), expected);
    }
    EXPECT_GT(zeros, 20000);
}

obbsat::test::rational_corners rational_corners_of(const rect64& r) {
    auto point = [](point64 p) { return rational_point{mpq_class(p.x), mpq_class(p.y)}; };
    return {point(r.ul), point(r.ur), point(r.lr), point(r.ll)};
}

std::map<char, int> cross_check(const char* name, std::uint64_t seed, int count,
                                rect_pair64 (*make)(obbsat::seeded_random&)) {
    obbsat::seeded_random random(seed);
    std::map<char, int> classes;
    std::map<std::string, int> forms;
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const rect_pair64 pair = make(random);
        const char model = obbsat::test::rational_contact(obbsat::test::rational_region_of(rational_corners_of(pair.a)),
                                                          obbsat::test::rational_region_of(rational_corners_of(pair.b)));
        EXPECT_EQ(obbsat::oracle::contact_letter(obbsat::oracle::classify(pair.a, pair.b)), model)
            << "A " << show(pair.a) << "\nB " << show(pair.b);
        EXPECT_EQ(obbsat::oracle::contact_letter(obbsat::oracle::classify(pair.b, pair.a)), model)
            << "swapped: A " << show(pair.a) << "\nB " << show(pair.b);
        ++classes[model];
        ++forms[obbsat::oracle::quad_form_name(obbsat::oracle::region_of(pair.a).form)];
        ++forms[obbsat::oracle::quad_form_name(obbsat::oracle::region_of(pair.b).form)];
    }
    std::printf("[ corners64] %-28s %6d pairs  S %6d  T %6d  O %6d  forms:", name, count, classes['S'], classes['T'],
                classes['O']);
    for (const auto& [form, n] : forms) {
        std::printf(" %s %d", form.c_str(), n);
    }
    std::printf("\n");
    return classes;
}

using obbsat::test::corner_pair;

TEST(contact_cross_check64, utm_random_corners) {
    auto classes = cross_check("UTM random", 52, 10000, corner_pair<obbsat::test::utm_random_pair>);
    EXPECT_GT(classes['S'], 1000);
    EXPECT_GT(classes['O'], 1000);
}

TEST(contact_cross_check64, utm_contact_corners) {
    auto classes = cross_check("UTM contacts 500000.125", 53, 10000, corner_pair<obbsat::test::utm_contact_pair>);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 500) << c;
    }
}

TEST(contact_cross_check64, far_contact_corners) {
    auto classes = cross_check("contacts 1e9..1e15", 54, 10000, corner_pair<obbsat::test::far_contact_pair>);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 500) << c;
    }
}

TEST(contact_cross_check64, sliver_and_near_parallel_corners) {
    auto slivers = cross_check("slivers", 55, 10000, corner_pair<obbsat::test::sliver_pair>);
    EXPECT_GT(slivers['T'], 500);
    auto parallel = cross_check("near parallel", 56, 10000, corner_pair<obbsat::test::near_parallel_pair>);
    EXPECT_GT(parallel['O'], 500);
}

TEST(contact_cross_check64, corners_moved_by_ulps) {
    auto classes = cross_check("corners moved by ulps", 57, 20000, obbsat::test::nudged_corner_pair);
    EXPECT_GT(classes['S'], 1000);
    EXPECT_GT(classes['O'], 1000);
}

TEST(contact_cross_check64, non_finite_corners_are_refused) {
    rect64 r{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    rect64 bad = r;
    bad.lr.x = NAN;
    EXPECT_THROW(obbsat::oracle::classify(r, bad), std::invalid_argument);
}

}  // namespace
