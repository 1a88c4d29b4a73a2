// Building the stores from other forms: eight coordinate arrays into rect_soa,
// rect_soa into rect_records; and the OBBSAT_BACKEND reading.
#include <obbsat/backend.hpp>
#include <obbsat/error.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace {

bool same_rect(const obbsat::rect& p, const obbsat::rect& q) { return std::memcmp(&p, &q, sizeof p) == 0; }

TEST(store_conversions, coordinate_arrays_fill_a_rect_soa_in_coord_order) {
    std::vector<std::vector<float>> columns(obbsat::coord_count);
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        for (unsigned i = 0; i < 5; ++i) {
            columns[c].push_back(static_cast<float>(10 * i + c));
        }
    }
    const float* arrays[obbsat::coord_count];
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        arrays[c] = columns[c].data();
    }
    const obbsat::rect_soa soa = obbsat::rect_soa::from_coordinate_arrays(arrays, 5);
    ASSERT_EQ(soa.size(), 5u);
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        for (unsigned i = 0; i < 5; ++i) {
            EXPECT_EQ(soa.data(obbsat::coord(c))[i], columns[c][i]);
        }
    }
    EXPECT_EQ(soa[3].lr.y, 35.0f);  // coord 5 is lry
}

TEST(store_conversions, a_non_finite_array_value_names_rectangle_and_coordinate) {
    std::vector<float> zeros(3, 0.0f), bad(3, 0.0f);
    bad[2] = NAN;
    const float* arrays[obbsat::coord_count] = {zeros.data(), zeros.data(), zeros.data(), bad.data(),
                                                zeros.data(), zeros.data(), zeros.data(), zeros.data()};
    try {
        (void)obbsat::rect_soa::from_coordinate_arrays(arrays, 3);
        FAIL() << "a NaN was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("rectangle 2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("ury"), std::string::npos) << e.what();
    }
}

TEST(store_conversions, records_from_a_rect_soa_hold_the_same_rectangles) {
    std::vector<obbsat::rect> rects;
    for (int i = 0; i < 37; ++i) {
        const float f = static_cast<float>(i);
        rects.push_back({{f, f + 1}, {f + 2, f + 1}, {f + 2, f - 1}, {f, -f}});
    }
    const obbsat::rect_soa soa(rects);
    const obbsat::rect_records records(soa);
    ASSERT_EQ(records.size(), rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        EXPECT_TRUE(same_rect(records[i], rects[i])) << i;
    }
}

TEST(store_conversions, forced_backend_agrees_with_the_environment) {
    // ctest runs this without OBBSAT_BACKEND unless a test sets it; either way
    // forced_backend must say what resolve_backend(automatic) honours.
    const auto forced = obbsat::forced_backend();
    if (!forced || *forced == obbsat::backend::automatic) {
        EXPECT_EQ(obbsat::resolve_backend(obbsat::backend::automatic), obbsat::best_supported_backend());
    } else {
        EXPECT_EQ(obbsat::resolve_backend(obbsat::backend::automatic), *forced);
    }
}

}  // namespace
