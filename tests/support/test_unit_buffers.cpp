// The buffers units borrow from a set kept between steps (kernel/support/unit_buffers.hpp).
#include "support/unit_buffers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

namespace {

using buffers = obbsat::detail::unit_buffers<std::uint64_t>;

TEST(UnitBuffers, ALeaseGivesItsBufferBackForTheNextUnit) {
    buffers set;
    set.reserve_units(2);
    const std::uint64_t* first = nullptr;
    {
        const buffers::lease a(&set, 1000);
        first = a.data();
        ASSERT_NE(first, nullptr);
    }
    const buffers::lease b(&set, 500);  // shorter: the same buffer, not grown
    EXPECT_EQ(b.data(), first);
    EXPECT_EQ(set.bytes(), 1000 * sizeof(std::uint64_t));
}

TEST(UnitBuffers, UnitsAtOnceHoldBuffersOfTheirOwn) {
    buffers set;
    set.reserve_units(2);
    const buffers::lease a(&set, 100);
    const buffers::lease b(&set, 100);
    EXPECT_NE(a.data(), b.data());
    {
        // Every buffer held: a third unit works in memory of its own, which
        // the set does not keep.
        const buffers::lease c(&set, 100);
        EXPECT_NE(c.data(), a.data());
        EXPECT_NE(c.data(), b.data());
        c.data()[99] = 7;  // it is the unit's to write
    }
    EXPECT_EQ(set.buffers(), 2u);
    EXPECT_EQ(set.bytes(), 2 * 100 * sizeof(std::uint64_t));
}

TEST(UnitBuffers, ABufferGrowsToTheLongestUnitItServed) {
    buffers set;
    set.reserve_units(1);
    for (const std::size_t count : {10u, 4000u, 50u}) {
        const buffers::lease a(&set, count);
        a.data()[count - 1] = count;
    }
    EXPECT_EQ(set.bytes(), 4000 * sizeof(std::uint64_t));
    buffers other;
    other.swap(set);  // the memory goes with the set
    EXPECT_EQ(set.bytes(), 0u);
    EXPECT_EQ(other.bytes(), 4000 * sizeof(std::uint64_t));
}

TEST(UnitBuffers, NoSetGivesEachUnitItsOwnMemory) {
    const buffers::lease a(nullptr, 64);
    ASSERT_NE(a.data(), nullptr);
    a.data()[63] = 1;
}

}  // namespace
