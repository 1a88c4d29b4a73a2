// The oracle against an independent exact construction in GMP rationals
// (rational_model.hpp: segment intersection, ray-crossing containment and the
// area of the clipped intersection), on quads of every form and on pairs from
// every suite family. Any difference fails with the pair in hex floats.
#include "rational_model.hpp"

#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/quad_region.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/suite.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace {

using obbsat::point;
using obbsat::rect;

std::string show(const rect& r) {
    char text[256];
    std::snprintf(text, sizeof text, "{%a,%a %a,%a %a,%a %a,%a}", static_cast<double>(r.ul.x),
                  static_cast<double>(r.ul.y), static_cast<double>(r.ur.x), static_cast<double>(r.ur.y),
                  static_cast<double>(r.lr.x), static_cast<double>(r.lr.y), static_cast<double>(r.ll.x),
                  static_cast<double>(r.ll.y));
    return text;
}

// Returns the model's letter; fails the test on a difference.
char expect_agreement(const rect& a, const rect& b) {
    const char oracle = obbsat::oracle::contact_letter(obbsat::oracle::classify(a, b));
    const char model = obbsat::test::rational_contact(a, b);
    EXPECT_EQ(oracle, model) << "A " << show(a) << "\nB " << show(b);
    return model;
}

float nudged(float v, int steps) {
    for (; steps > 0; --steps) v = std::nextafter(v, INFINITY);
    for (; steps < 0; ++steps) v = std::nextafter(v, -INFINITY);
    return v;
}

// A quad on the half-integer lattice [-1.5, 1.5]^2, of a randomly chosen
// make-up so that every form occurs often: four free corners (convex, reflex
// and crossed outlines), a point, a zero-width segment, four corners on one
// line in any order, or a repeated corner.
rect lattice_quad(obbsat::seeded_random& random) {
    auto coordinate = [&] { return 0.5f * static_cast<float>(static_cast<int>(random.below(7)) - 3); };
    auto lattice_point = [&] { return point{coordinate(), coordinate()}; };
    point c[4] = {lattice_point(), lattice_point(), lattice_point(), lattice_point()};
    switch (random.below(6)) {
        case 0: c[1] = c[2] = c[3] = c[0]; break;
        case 1: c[3] = c[0]; c[2] = c[1]; break;
        case 2: {
            const point step{0.5f * static_cast<float>(static_cast<int>(random.below(3)) - 1),
                             0.5f * static_cast<float>(static_cast<int>(random.below(3)) - 1)};
            for (point& p : c) {
                const auto k = static_cast<float>(static_cast<int>(random.below(5)) - 2);
                p = point{c[0].x + k * step.x, c[0].y + k * step.y};
            }
            break;
        }
        case 3: c[random.below(4)] = c[random.below(4)]; break;
        default: break;
    }
    return rect{c[0], c[1], c[2], c[3]};
}

TEST(cross_check, half_integer_lattice_quads_of_every_form) {
    // On a small lattice contacts are exact and frequent.
    obbsat::seeded_random random(101);
    std::map<std::string, int> forms;
    std::map<char, int> classes;
    for (int i = 0; i < 6000 && !HasFailure(); ++i) {
        const rect a = lattice_quad(random);
        const rect b = lattice_quad(random);
        ++forms[obbsat::oracle::quad_form_name(obbsat::oracle::region_of(a).form)];
        ++classes[expect_agreement(a, b)];
    }
    for (const char* form : {"point", "segment", "convex", "concave", "non_simple"}) {
        EXPECT_GT(forms[form], 100) << form;
    }
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 500) << c;
    }
}

TEST(cross_check, lattice_pairs_moved_by_float_steps_at_every_scale) {
    // Lattice pairs, often in contact, scaled to a random binade, then a
    // quarter of one quad's coordinates moved by -2 .. 2 float steps.
    obbsat::seeded_random random(202);
    std::map<char, int> classes;
    for (int i = 0; i < 6000 && !HasFailure(); ++i) {
        float v[16];
        for (float& x : v) {
            x = static_cast<float>(static_cast<int>(random.below(9)) - 4);
        }
        const int exponent = static_cast<int>(random.below(250)) - 140;
        for (float& x : v) {
            x = std::ldexp(x, exponent);
        }
        for (int k = 8; k < 16; ++k) {
            if (random.below(4) == 0) {
                v[k] = nudged(v[k], static_cast<int>(random.below(5)) - 2);
            }
        }
        const rect a{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
        const rect b{{v[8], v[9]}, {v[10], v[11]}, {v[12], v[13]}, {v[14], v[15]}};
        ++classes[expect_agreement(a, b)];
    }
    std::printf("[ model    ] moved lattice pairs: S %d  T %d  O %d\n", classes['S'], classes['T'], classes['O']);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 100) << c;
    }
}

std::string family_name_of(const ::testing::TestParamInfo<obbsat::suites::family>& param) {
    return obbsat::suites::family_name(param.param);
}

class cross_check_family : public ::testing::TestWithParam<obbsat::suites::family> {};

TEST_P(cross_check_family, oracle_agrees_with_the_rational_model) {
    const obbsat::suites::suite s = obbsat::suites::make_family(GetParam(), 9, 1500);
    std::map<char, int> classes;
    for (std::size_t i = 0; i < s.pairs.size() && !HasFailure(); ++i) {
        ++classes[expect_agreement(s.rects[s.pairs[i].a], s.rects[s.pairs[i].b])];
    }
    std::printf("[ model    ] %-17s S %d  T %d  O %d\n", obbsat::suites::family_name(GetParam()),
                classes['S'], classes['T'], classes['O']);
}

INSTANTIATE_TEST_SUITE_P(suites, cross_check_family,
                         ::testing::ValuesIn(obbsat::suites::all_families()),
                         family_name_of);

}  // namespace
