// collide_pairs over records in the caller's memory: the same verdicts as the
// rect_records store for every method and backend, at any 4-byte alignment;
// a non-finite coordinate or a bad index refused with nothing written.
#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::pair_index;
using obbsat::rect;

struct caller_scene {
    std::vector<rect> rects;
    std::vector<pair_index> pairs;
};

caller_scene scene_of(std::size_t rects, std::size_t pairs) {
    const obbsat::scene s = obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::typical, rects, pairs, 9));
    caller_scene out;
    for (std::size_t i = 0; i < s.rects.size(); ++i) {
        out.rects.push_back(s.rects[i]);
    }
    out.pairs = s.pairs;
    return out;
}

TEST(CollideCallerMemory, MatchesTheRecordStoreForEveryMethodBackendAndAlignment) {
    const caller_scene s = scene_of(3000, 40000);
    const obbsat::rect_records store(s.rects);
    // Records starting 4 bytes past a 64-byte boundary, as a numpy array may.
    std::vector<float> shifted(s.rects.size() * 8 + 32);
    const std::size_t skip = (16 - reinterpret_cast<std::uintptr_t>(shifted.data()) / 4 % 16) % 16 + 1;
    std::memcpy(shifted.data() + skip, s.rects.data(), s.rects.size() * sizeof(rect));
    const rect* unaligned = reinterpret_cast<const rect*>(shifted.data() + skip);
    for (const obbsat::method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        for (const obbsat::backend b : obbsat::compiled_backends()) {
            if (!obbsat::cpu_supports(b)) {
                continue;
            }
            for (const unsigned threads : {1u, 2u}) {
                obbsat::collide_options options;
                options.test = m;
                options.use = b;
                options.threads = threads;
                const std::vector<std::uint8_t> expected = obbsat::collide_pairs(store, s.pairs, options);
                for (const rect* base : {s.rects.data(), unaligned}) {
                    std::vector<std::uint8_t> got(s.pairs.size(), 0xa5);
                    EXPECT_EQ(obbsat::collide_pairs(base, s.rects.size(), s.pairs.data(), s.pairs.size(),
                                                    got.data(), options),
                              b);
                    EXPECT_EQ(got, expected) << obbsat::method_name(m) << " on " << obbsat::backend_name(b);
                }
            }
        }
    }
}

TEST(CollideCallerMemory, RefusesANonFiniteCoordinateAnywhereWithNothingWritten) {
    caller_scene s = scene_of(50000, 20000);
    const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                         -std::numeric_limits<float>::infinity()};
    for (const std::size_t where : {std::size_t{0}, std::size_t{31337}, s.rects.size() - 1}) {
        for (const float value : bad) {
            caller_scene broken = s;
            broken.rects[where].lr.y = value;
            for (const unsigned threads : {1u, 2u}) {
                obbsat::collide_options options;
                options.threads = threads;
                std::vector<std::uint8_t> verdicts(s.pairs.size(), 0xa5);
                try {
                    obbsat::collide_pairs(broken.rects.data(), broken.rects.size(), broken.pairs.data(),
                                          broken.pairs.size(), verdicts.data(), options);
                    FAIL() << "accepted a non-finite coordinate";
                } catch (const obbsat::invalid_input& e) {
                    EXPECT_EQ(std::string(e.what()),
                              "rectangle " + std::to_string(where) + ": coordinate lry is not finite");
                }
                EXPECT_EQ(verdicts, std::vector<std::uint8_t>(s.pairs.size(), 0xa5));
            }
        }
    }
}

TEST(CollideCallerMemory, RefusesAnIndexOutOfRangeWithNothingWritten) {
    caller_scene s = scene_of(1000, 5000);
    s.pairs[1234].b = static_cast<std::uint32_t>(s.rects.size());
    std::vector<std::uint8_t> verdicts(s.pairs.size(), 0xa5);
    try {
        obbsat::collide_pairs(s.rects.data(), s.rects.size(), s.pairs.data(), s.pairs.size(), verdicts.data());
        FAIL() << "accepted an index out of range";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_EQ(std::string(e.what()), "pair 1234: index 1000 is out of range (1000 rectangles)");
    }
    EXPECT_EQ(verdicts, std::vector<std::uint8_t>(s.pairs.size(), 0xa5));
}

TEST(CollideCallerMemory, EmptyInputs) {
    std::uint8_t verdict = 0xa5;
    EXPECT_NO_THROW(obbsat::collide_pairs(static_cast<const obbsat::rect*>(nullptr), 0, nullptr, 0, &verdict));
    EXPECT_NO_THROW(obbsat::collide_pairs(static_cast<const obbsat::rect_pose*>(nullptr), 0, nullptr, 0, &verdict,
                                          [] {
                                              obbsat::collide_options options;
                                              options.test = obbsat::method::local;
                                              return options;
                                          }()));
    EXPECT_EQ(verdict, 0xa5);
}

}  // namespace
