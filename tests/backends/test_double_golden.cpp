// The golden digests of the methods on double stores: for each store kind
// (double poses, double corners) and each method that runs on it, the digest
// of its scalar reference's verdicts on a fixed set of pairs, which
// collide_pairs must reproduce on every backend this CPU runs and on one
// thread and two. Double corners run on the scalar backend only until their
// SIMD lanes exist; a SIMD backend collide_pairs refuses for them
// (invalid_input, as obbsat/collide64.hpp says) is skipped, so these digests
// bind the lanes as soon as they run.
#include "test_support/double_references.hpp"
#include "test_support/soak_pairs64.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/error.hpp>
#include <obbsat/method.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect64;
using obbsat::rect_pose64;
using obbsat::store_kind;
using verdicts = std::vector<std::uint8_t>;

// The digests (obbsat/digest.hpp) of each double method's scalar reference on
// golden_poses() and golden_corners() below, drawn from the portable families
// of soak_pairs64.hpp (integer arithmetic and correctly rounded double
// operations only, so the same pairs on every machine). Change one only with
// a deliberate change of the method or of the generator, and say so in the
// commit.
struct golden_entry {
    store_kind store;
    method test;
    std::uint64_t digest;
};
constexpr golden_entry golden_digests[] = {
    {store_kind::poses, method::local, 0x60a97bcfec0fe13a},
    {store_kind::poses, method::conservative, 0x3d670f6df26d8fcf},
    {store_kind::poses, method::exact, 0xe19c7f479c95fd64},
    {store_kind::corners, method::conservative, 0xfc53948e02954f96},
    {store_kind::corners, method::exact, 0x5096b6d846c6b9ff},
};

constexpr std::size_t golden_pair_count = 100000;

std::string hex_digest(std::uint64_t digest) {
    char text[32];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(digest));
    return text;
}

/// A fixed set of pairs as one pool: pair i is (pool[i], pool[count + i]).
template <class Item>
struct golden_set {
    std::vector<Item> pool;
    std::vector<pair_index> pairs;
};

template <class Item, class Pair, std::size_t family_count>
golden_set<Item> golden_set_of(const obbsat::test::soak_family64<Pair> (&families)[family_count],
                               std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<Item> a, b;
    obbsat::test::draw_pairs(random, obbsat::test::portable_families(families), golden_pair_count, a, b);
    golden_set<Item> set;
    set.pool = a;
    set.pool.insert(set.pool.end(), b.begin(), b.end());
    for (std::size_t i = 0; i < golden_pair_count; ++i) {
        set.pairs.push_back(pair_index{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(golden_pair_count + i)});
    }
    return set;
}

const golden_set<rect_pose64>& golden_poses() {
    static const golden_set<rect_pose64> set =
        golden_set_of<rect_pose64>(obbsat::test::pose_soak_families, 20261126);
    return set;
}

const golden_set<rect64>& golden_corners() {
    static const golden_set<rect64> set = golden_set_of<rect64>(obbsat::test::corner_soak_families, 20261127);
    return set;
}

template <class Item>
std::uint64_t reference_digest(method m, const golden_set<Item>& set) {
    verdicts v;
    for (const pair_index& p : set.pairs) {
        v.push_back(obbsat::test::double_reference(m, set.pool[p.a], set.pool[p.b]) ? 1 : 0);
    }
    return obbsat::verdict_digest(v.data(), v.size());
}

std::uint64_t reference_digest(const golden_entry& e) {
    return e.store == store_kind::poses ? reference_digest(e.test, golden_poses())
                                        : reference_digest(e.test, golden_corners());
}

TEST(double_golden, every_method_on_every_double_store_has_a_golden_digest) {
    for (const store_kind s : {store_kind::poses, store_kind::corners}) {
        for (const method m : obbsat::methods_on_doubles(s)) {
            const bool listed = std::any_of(std::begin(golden_digests), std::end(golden_digests),
                                            [&](const golden_entry& e) { return e.store == s && e.test == m; });
            EXPECT_TRUE(listed) << obbsat::method_name(m) << " on double " << obbsat::store_name(s)
                                << " has no golden digest";
        }
    }
}

TEST(double_golden, references_reproduce_the_golden_digests) {
    for (const golden_entry& e : golden_digests) {
        EXPECT_EQ(hex_digest(reference_digest(e)), hex_digest(e.digest))
            << obbsat::method_name(e.test) << " on double " << obbsat::store_name(e.store);
    }
}

TEST(double_golden, the_golden_sets_mix_colliding_and_separated_pairs) {
    // A digest of all ones or all zeros would prove little.
    for (const golden_entry& e : golden_digests) {
        const std::uint64_t all_apart = obbsat::verdict_digest(verdicts(golden_pair_count, 0).data(), golden_pair_count);
        const std::uint64_t all_colliding =
            obbsat::verdict_digest(verdicts(golden_pair_count, 1).data(), golden_pair_count);
        EXPECT_NE(e.digest, all_apart) << obbsat::method_name(e.test);
        EXPECT_NE(e.digest, all_colliding) << obbsat::method_name(e.test);
    }
}

class double_golden_backends : public testing::TestWithParam<backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << obbsat::backend_name(GetParam()) << " does not run on this CPU";
        }
    }

    /// The digest of collide_pairs on `set` forced to this backend, or nothing
    /// when collide_pairs refuses this SIMD backend for the store.
    template <class Store, class Item>
    bool backend_digest(const golden_set<Item>& set, method m, unsigned threads, std::uint64_t& digest) const {
        const Store store(set.pool);
        obbsat::collide_options options;
        options.test = m;
        options.use = GetParam();
        options.threads = threads;
        verdicts v(set.pairs.size(), 0xee);
        try {
            EXPECT_EQ(obbsat::collide_pairs(store, set.pairs.data(), set.pairs.size(), v.data(), options),
                      GetParam());  // the forced backend is the one that ran
        } catch (const obbsat::invalid_input&) {
            if (GetParam() == backend::scalar || std::is_same<Item, rect_pose64>::value) throw;
            return false;
        }
        digest = obbsat::verdict_digest(v.data(), v.size());
        return true;
    }
};

TEST_P(double_golden_backends, reproduce_the_golden_digests_on_one_thread_and_two) {
    std::size_t checked = 0;
    for (const golden_entry& e : golden_digests) {
        for (const unsigned threads : {1u, 2u}) {
            std::uint64_t digest = 0;
            const bool ran = e.store == store_kind::poses
                                 ? backend_digest<obbsat::pose_records64>(golden_poses(), e.test, threads, digest)
                                 : backend_digest<obbsat::rect_records64>(golden_corners(), e.test, threads, digest);
            if (!ran) continue;
            ++checked;
            EXPECT_EQ(hex_digest(digest), hex_digest(e.digest))
                << obbsat::method_name(e.test) << " on double " << obbsat::store_name(e.store) << ", " << threads
                << " threads";
        }
    }
    EXPECT_GE(checked, 6u);  // at least the three pose methods on one thread and two
}

INSTANTIATE_TEST_SUITE_P(every_backend, double_golden_backends, testing::ValuesIn(obbsat::compiled_backends()),
                         [](const testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace
