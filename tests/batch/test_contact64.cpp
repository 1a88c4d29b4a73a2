// The contact and distance entry points over the double stores
// (obbsat/contact.hpp, pose_records64 and rect_records64): every result equal,
// byte for byte, to the double reference (obbsat/ref/contact.hpp,
// distance.hpp) on every backend this CPU runs and every thread count, pair
// lists and streams alike,
// stores the caches hold and larger ones; on the float contact families
// widened to double (random pairs, contact's own hard cases, near and far
// from the origin) and on the double families at UTM-like coordinates; and
// every error, before anything is written.
#include "test_support/contact_cases.hpp"
#include "test_support/pose_cases64.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/distance.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::closest_points64;
using obbsat::contact64;
using obbsat::pair_index;
using obbsat::rect64;
using obbsat::rect_pose64;

struct pairs64 {
    std::vector<rect_pose64> a, b;
};

rect_pose64 widened(const obbsat::rect_pose& p) {
    return {{p.center.x, p.center.y}, {p.half_extents.x, p.half_extents.y}, {p.rotation.x, p.rotation.y}};
}

pairs64 widened(const obbsat::test::pose_pairs& in) {
    pairs64 out;
    for (std::size_t i = 0; i < in.a.size(); ++i) {
        out.a.push_back(widened(in.a[i]));
        out.b.push_back(widened(in.b[i]));
    }
    return out;
}

/// `count` pairs of a double family make, those whose poses contacts accept.
template <obbsat::test::pose_pair64 (*make)(obbsat::seeded_random&)>
pairs64 family(std::uint64_t seed, std::size_t count) {
    obbsat::seeded_random random(seed);
    pairs64 out;
    for (std::size_t i = 0; i < count; ++i) {
        const obbsat::test::pose_pair64 p = make(random);
        if (obbsat::ref::pose_accepted(p.a) && obbsat::ref::pose_accepted(p.b)) {
            out.a.push_back(p.a);
            out.b.push_back(p.b);
        }
    }
    return out;
}

/// Every family the double entry points are checked on.
std::vector<std::pair<std::string, pairs64>> families() {
    using namespace obbsat::test;
    return {
        {"random pairs", widened(random_pairs(31, 6000))},
        {"hard cases", widened(hard_pairs(32, 6000, 1.0f, 0.0f))},
        {"hard cases at 2^20", widened(hard_pairs(33, 3000, 0x1p20f, 0.0f))},
        {"hard cases at 1e7", widened(hard_pairs(34, 3000, 1.0f, 1.0e7f))},
        {"utm contacts", family<obbsat::suites::utm_contact_pair>(35, 4000)},
        {"utm northing contacts", family<obbsat::suites::utm_northing_contact_pair>(36, 3000)},
        {"utm random", family<obbsat::suites::utm_random_pair>(37, 3000)},
        {"far contacts", family<far_contact_pair>(38, 2000)},
        {"near parallel", family<near_parallel_pair>(39, 2000)},
        {"slivers", family<sliver_pair>(40, 2000)},
    };
}

/// One store of a then b, and the pairs (i, n + i).
template <class Row>
std::vector<pair_index> stacked(const std::vector<Row>& a, const std::vector<Row>& b, std::vector<Row>& rows) {
    rows = a;
    rows.insert(rows.end(), b.begin(), b.end());
    std::vector<pair_index> pairs;
    const auto n = static_cast<std::uint32_t>(a.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        pairs.push_back({i, n + i});
    }
    return pairs;
}

template <class T>
bool same_bytes(const std::vector<T>& x, const std::vector<T>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(T)) == 0;
}

/// The first index where two results differ, for the message.
template <class T>
std::size_t first_difference(const std::vector<T>& x, const std::vector<T>& y) {
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (std::memcmp(&x[i], &y[i], sizeof(T)) != 0) {
            return i;
        }
    }
    return x.size();
}

/// Every double entry point on `rows` (poses or corners) against the
/// reference, on backend `use`.
template <class Store, class Row>
void expect_every_path_matches(const std::vector<Row>& a, const std::vector<Row>& b, double margin, backend use,
                               const std::string& what) {
    std::vector<Row> rows;
    const std::vector<pair_index> pairs = stacked(a, b, rows);
    const Store store(rows), store_a(a), store_b(b);
    std::vector<contact64> expected(a.size());
    std::vector<closest_points64> expected_distances(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        expected[i] = obbsat::ref::contact_of(a[i], b[i], margin);
        expected_distances[i] = obbsat::ref::distance_of(a[i], b[i]);
    }
    for (const unsigned threads : {1u, 2u, 0u}) {
        SCOPED_TRACE(what + ", threads " + std::to_string(threads));
        obbsat::contact_options64 options;
        options.threads = threads;
        options.margin = margin;
        options.use = use;
        std::vector<contact64> got(a.size());
        EXPECT_EQ(obbsat::contact_pairs(store, pairs.data(), pairs.size(), got.data(), options), use);
        EXPECT_TRUE(same_bytes(got, expected)) << "pair " << first_difference(got, expected);
        std::vector<contact64> streamed(a.size());
        EXPECT_EQ(obbsat::contact_stream(store_a, store_b, streamed.data(), options), use);
        EXPECT_TRUE(same_bytes(streamed, expected)) << "pair " << first_difference(streamed, expected);
        obbsat::distance_options distance;
        distance.threads = threads;
        distance.use = use;
        std::vector<closest_points64> d(a.size());
        EXPECT_EQ(obbsat::distance_pairs(store, pairs.data(), pairs.size(), d.data(), distance), use);
        EXPECT_TRUE(same_bytes(d, expected_distances)) << "pair " << first_difference(d, expected_distances);
        std::vector<closest_points64> ds(a.size());
        EXPECT_EQ(obbsat::distance_stream(store_a, store_b, ds.data(), distance), use);
        EXPECT_TRUE(same_bytes(ds, expected_distances)) << "pair " << first_difference(ds, expected_distances);
    }
}

/// The corners of the pairs, those whose corners contacts accept.
void corners_of(const pairs64& pairs, std::vector<rect64>& qa, std::vector<rect64>& qb) {
    for (std::size_t i = 0; i < pairs.a.size(); ++i) {
        const rect64 ca = obbsat::test::corners64(pairs.a[i]), cb = obbsat::test::corners64(pairs.b[i]);
        if (obbsat::ref::corners_accepted(ca) && obbsat::ref::corners_accepted(cb)) {
            qa.push_back(ca);
            qb.push_back(cb);
        }
    }
}

class contact64_backends : public testing::TestWithParam<backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << "backend " << obbsat::backend_name(GetParam())
                         << " is not compiled in or this CPU cannot run it: not tested here";
        }
    }
};

TEST_P(contact64_backends, every_entry_point_is_the_double_reference_on_every_family_and_thread_count) {
    for (const auto& [name, pairs] : families()) {
        ASSERT_GT(pairs.a.size(), 500u) << name;
        for (const double margin : {0.0, 0x1p-4}) {
            expect_every_path_matches<obbsat::pose_records64>(pairs.a, pairs.b, margin, GetParam(),
                                                              name + " (poses)");
            std::vector<rect64> qa, qb;
            corners_of(pairs, qa, qb);
            expect_every_path_matches<obbsat::rect_records64>(qa, qb, margin, GetParam(), name + " (corners)");
        }
    }
}

// A pose store larger than L2 (fetch_ahead.hpp's store_bytes_in_l2: 2 MiB,
// 32768 double poses) takes the kernel that fetches the records ahead; the
// families' stores take the one that does not.
TEST_P(contact64_backends, a_store_larger_than_l2_gives_the_reference_too) {
    const pairs64 pairs = widened(obbsat::test::random_pairs(41, 20000));
    ASSERT_GT(2 * pairs.a.size() * sizeof(double) * obbsat::pose_records64::record_doubles, std::size_t{2} << 20);
    expect_every_path_matches<obbsat::pose_records64>(pairs.a, pairs.b, 0x1p-4, GetParam(), "large store");
}

// Every partial last vector (1 to 15 pairs past whole vectors of every
// width) and every split of a few pairs over threads.
TEST_P(contact64_backends, every_length_of_a_batch_gives_the_reference) {
    const pairs64 all = widened(obbsat::test::hard_pairs(42, 80, 1.0f, 0.0f));
    for (std::size_t n = 1; n <= all.a.size(); ++n) {
        const std::vector<rect_pose64> a(all.a.begin(), all.a.begin() + static_cast<std::ptrdiff_t>(n));
        const std::vector<rect_pose64> b(all.b.begin(), all.b.begin() + static_cast<std::ptrdiff_t>(n));
        expect_every_path_matches<obbsat::pose_records64>(a, b, 0.0, GetParam(), std::to_string(n) + " pairs");
    }
}

INSTANTIATE_TEST_SUITE_P(every_backend, contact64_backends,
                         testing::Values(backend::scalar, backend::sse2, backend::avx2, backend::avx512),
                         [](const testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

TEST(contact64, the_families_reach_every_kind_of_answer) {
    std::size_t counts[3] = {}, flipped = 0, separated = 0;
    for (const auto& [name, pairs] : families()) {
        for (std::size_t i = 0; i < pairs.a.size(); ++i) {
            const contact64 c = obbsat::ref::contact_of(pairs.a[i], pairs.b[i]);
            ++counts[c.point_count];
            flipped += c.point_count > 0 && c.points[0].feature.type_b == obbsat::feature_type::face;
            separated += obbsat::ref::distance_of(pairs.a[i], pairs.b[i]).distance > 0.0;
        }
    }
    EXPECT_GT(counts[0], 1000u);
    EXPECT_GT(counts[1], 1000u);
    EXPECT_GT(counts[2], 1000u);
    EXPECT_GT(flipped, 100u) << "B's face the reference";
    EXPECT_GT(separated, 1000u);
}

// As the float store's check: every lane of a vector of double records and
// the rows after, on every backend, for a rotation whose square is below the
// least normal double or past the largest.
TEST(contact64, a_rejected_rotation_is_named_wherever_it_is_on_every_backend) {
    constexpr std::size_t rows = 21;  // two whole AVX-512 vectors of doubles and five rows more
    for (const backend use : obbsat::compiled_backends()) {
        if (!obbsat::cpu_supports(use)) {
            continue;
        }
        obbsat::contact_options64 options;
        options.use = use;
        for (const std::size_t bad : {std::size_t{0}, std::size_t{3}, std::size_t{7}, std::size_t{8},
                                      std::size_t{15}, std::size_t{16}, std::size_t{20}}) {
            for (const double length : {1e-200, 1e200}) {
                std::vector<rect_pose64> list;
                std::vector<pair_index> pairs;
                for (std::size_t i = 0; i < rows; ++i) {
                    list.push_back({{1.5 * static_cast<double>(i), 0}, {1, 1}, {1, 0}});
                    if (i + 1 < rows) {
                        pairs.push_back(pair_index{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
                    }
                }
                list[bad].rotation = {0, length};
                const obbsat::pose_records64 poses(list);
                std::vector<contact64> out(pairs.size());
                std::memset(out.data(), 0x5a, out.size() * sizeof(contact64));
                const std::vector<contact64> untouched = out;
                SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", pose " + std::to_string(bad));
                try {
                    obbsat::contact_pairs(poses, pairs.data(), pairs.size(), out.data(), options);
                    ADD_FAILURE() << "no error";
                } catch (const obbsat::invalid_input& e) {
                    EXPECT_NE(std::string(e.what()).find("pose " + std::to_string(bad) + ": rotation"),
                              std::string::npos)
                        << e.what();
                }
                EXPECT_EQ(std::memcmp(out.data(), untouched.data(), out.size() * sizeof(contact64)), 0)
                    << "written before the error";
            }
        }
    }
}

TEST(contact64, errors_name_what_is_wrong_and_write_nothing) {
    const std::vector<rect_pose64> rows = {{{0, 0}, {1, 1}, {1, 0}}, {{1.5, 0}, {1, 1}, {1, 0}}};
    const obbsat::pose_records64 poses(rows);
    const std::vector<pair_index> pairs = {{0, 1}, {1, 2}};
    contact64 out[2];
    std::memset(out, 0x5a, sizeof out);
    contact64 untouched[2];
    std::memcpy(untouched, out, sizeof out);
    auto expect_refused = [&](const auto& call, const std::string& words) {
        try {
            call();
            ADD_FAILURE() << "no error; expected one saying '" << words << "'";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
        EXPECT_EQ(std::memcmp(out, untouched, sizeof out), 0) << "written before the error";
    };
    expect_refused([&] { obbsat::contact_pairs(poses, pairs.data(), 2, out); }, "pair 1: index 2");
    obbsat::contact_options64 bad_margin;
    bad_margin.margin = -1.0;
    expect_refused([&] { obbsat::contact_pairs(poses, pairs.data(), 1, out, bad_margin); }, "margin");
    bad_margin.margin = std::numeric_limits<double>::infinity();
    expect_refused([&] { obbsat::contact_pairs(poses, pairs.data(), 1, out, bad_margin); }, "margin");
    const obbsat::pose_records64 tiny(std::vector<rect_pose64>{{{0, 0}, {1, 1}, {1, 0}}, {{0, 0}, {1, 1}, {1e-200, 0}}});
    expect_refused([&] { obbsat::contact_pairs(tiny, pairs.data(), 1, out); }, "pose 1: rotation");
    const obbsat::rect_records64 crossed(std::vector<rect64>{{{0, 1}, {1, 1}, {1, 0}, {0, 0}},
                                                             {{0, 0}, {1, 1}, {1, 0}, {0, 1}}});
    expect_refused([&] { obbsat::contact_pairs(crossed, pairs.data(), 1, out); }, "rectangle 1: corners");
    expect_refused([&] { obbsat::distance_pairs(crossed, pairs, {}); }, "rectangle 1: corners");
    const obbsat::pose_records64 one(std::vector<rect_pose64>{rows[0]});
    expect_refused([&] { obbsat::contact_stream(poses, one, out); }, "differ in length");
    // An output over the pairs themselves.
    std::vector<pair_index> shared(64, pair_index{0, 1});
    EXPECT_THROW(obbsat::contact_pairs(poses, shared.data(), 1, reinterpret_cast<contact64*>(shared.data())),
                 obbsat::invalid_input);
    obbsat::contact_options64 on_scalar;
    on_scalar.use = backend::scalar;
    EXPECT_EQ(obbsat::contact_pairs(poses, pairs.data(), 1, out, on_scalar), backend::scalar);
    EXPECT_EQ(out[0].point_count, 2u);
}

}  // namespace
