// Fuzz target: every backend this CPU runs, for every method and through every
// batch entry point (collide_pairs over rect_records and over rect_soa, and
// collide_stream), must give exactly the verdicts of the method's scalar
// reference on any finite input, and the scene query with method exact must
// report exactly the pairs the exact oracle calls colliding. The first
// difference is printed (with the two rectangles in hex floats for a pair)
// and stops the run.
//
// Input format (see decode_rect): one byte for the number of rectangles, one
// byte of flags, then each rectangle as a kind byte and its payload; the bytes
// left over are pairs of indices (each taken modulo the number of rectangles).
#include "fuzz_bytes.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::point;
using obbsat::rect;
using obbsat::fuzz::byte_source;
using obbsat::fuzz::finite_from_bits;

constexpr std::size_t max_rects = 48;
constexpr std::uint8_t flag_check_bad_index = 0x01;
constexpr std::uint8_t untouched = 0xee;

point finite_point(float x, float y) {
    return point{finite_from_bits(obbsat::fuzz::bits_of(x)), finite_from_bits(obbsat::fuzz::bits_of(y))};
}

// Eight raw 32-bit patterns: reaches subnormals, the largest magnitudes and
// every mix of scales, but rarely two rectangles near each other.
rect raw_rect(byte_source& in) {
    float v[8];
    for (float& c : v) {
        c = finite_from_bits(in.u32());
    }
    return rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}

// Small integers times a power of two: exact touching, shared edges and
// corners, and degenerate quads, at a scale from 2^-32 to 2^31.
rect integer_rect(byte_source& in, int exponent) {
    float v[8];
    for (float& c : v) {
        c = std::ldexp(static_cast<float>(static_cast<std::int8_t>(in.byte())), exponent);
    }
    return rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}

// A true rotated rectangle by center, half extents and angle: what scenes hold.
rect pose_rect(byte_source& in) {
    const std::uint8_t center_kind = in.byte();
    point center{};
    if ((center_kind & 1) != 0) {
        center = point{finite_from_bits(in.u32()), finite_from_bits(in.u32())};
    } else {
        const int exponent = (center_kind >> 1) % 64 - 32;
        const auto cx = static_cast<std::int16_t>(in.u16());
        const auto cy = static_cast<std::int16_t>(in.u16());
        center = point{std::ldexp(static_cast<float>(cx), exponent),
                       std::ldexp(static_cast<float>(cy), exponent)};
    }
    const int extent_exponent = in.byte() % 64 - 40;
    const point half{std::ldexp(static_cast<float>(in.u16()), extent_exponent),
                     std::ldexp(static_cast<float>(in.u16()), extent_exponent)};
    const float angle = static_cast<float>(in.u16()) * (6.2831853f / 65536.0f);
    const rect r = obbsat::corners_of(obbsat::pose{center, half, angle});
    // Corners of a pose near the largest floats may round to infinity.
    return rect{finite_point(r.ul.x, r.ul.y), finite_point(r.ur.x, r.ur.y),
                finite_point(r.lr.x, r.lr.y), finite_point(r.ll.x, r.ll.y)};
}

// An earlier rectangle with each coordinate moved by a few representable
// floats: pairs on the edge between touching and separated.
rect nudged_rect(byte_source& in, const std::vector<rect>& earlier) {
    const rect base = earlier[in.byte() % earlier.size()];
    float v[8] = {base.ul.x, base.ul.y, base.ur.x, base.ur.y, base.lr.x, base.lr.y, base.ll.x, base.ll.y};
    for (float& c : v) {
        c = obbsat::fuzz::nudged(c, static_cast<std::int8_t>(in.byte()) / 16);
    }
    return rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}

rect decode_rect(byte_source& in, const std::vector<rect>& earlier) {
    const std::uint8_t kind = in.byte();
    switch (kind % 4) {
        case 0: return raw_rect(in);
        case 1: return integer_rect(in, (kind >> 2) - 32);
        case 2: return pose_rect(in);
        default: return earlier.empty() ? integer_rect(in, 0) : nudged_rect(in, earlier);
    }
}

std::string hex(float value) {
    char text[48];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(value));
    return text;
}

std::string describe(const rect& r) {
    const point corners[4] = {r.ul, r.ur, r.lr, r.ll};
    const char* names[4] = {"UL", "UR", "LR", "LL"};
    std::string out;
    for (int k = 0; k < 4; ++k) {
        out += std::string(k == 0 ? "" : " ") + names[k] + " (" + hex(corners[k].x) + ", " +
               hex(corners[k].y) + ")";
    }
    return out;
}

[[noreturn]] void stop(const std::string& what) {
    std::fprintf(stderr, "fuzz_backends: %s\n", what.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

struct batch {
    std::vector<rect> rects;
    std::vector<pair_index> pairs;
    obbsat::rect_records records;
    obbsat::rect_soa soa;
    obbsat::rect_soa stream_a;
    obbsat::rect_soa stream_b;
};

std::string pair_text(const batch& in, std::size_t i) {
    const pair_index p = in.pairs[i];
    return "pair " + std::to_string(i) + " (rectangles " + std::to_string(p.a) + ", " +
           std::to_string(p.b) + ")\n  A " + describe(in.rects[p.a]) + "\n  B " +
           describe(in.rects[p.b]);
}

void expect_same(const batch& in, method m, backend b, const char* path, backend ran,
                 const std::vector<std::uint8_t>& expected, const std::vector<std::uint8_t>& got) {
    const std::string where = std::string(path) + ", method " + obbsat::method_name(m) +
                              ", backend " + obbsat::backend_name(b);
    if (ran != b) {
        stop(where + ": ran backend " + obbsat::backend_name(ran));
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (got[i] != expected[i]) {
            stop(where + ": reference " + std::to_string(expected[i]) + ", backend " +
                 std::to_string(got[i]) + " on " + pair_text(in, i));
        }
    }
}

// A pair list with one index past the end must be refused before any
// verdict is written, on both stores.
void expect_bad_index_refused(const batch& in, method m, backend b) {
    std::vector<pair_index> pairs = in.pairs;
    const auto past_end = static_cast<std::uint32_t>(in.rects.size());
    pairs.insert(pairs.begin() + static_cast<std::ptrdiff_t>(pairs.size() / 2), pair_index{0, past_end});
    obbsat::collide_options options;
    options.test = m;
    options.use = b;
    std::vector<std::uint8_t> got(pairs.size(), untouched);
    for (int store = 0; store < 2; ++store) {
        bool refused = false;
        try {
            if (store == 0) {
                obbsat::collide_pairs(in.records, pairs.data(), pairs.size(), got.data(), options);
            } else {
                obbsat::collide_pairs(in.soa, pairs.data(), pairs.size(), got.data(), options);
            }
        } catch (const obbsat::invalid_input&) {
            refused = true;
        }
        if (!refused) {
            stop(std::string("an index past the end was accepted, backend ") + obbsat::backend_name(b));
        }
        for (const std::uint8_t v : got) {
            if (v != untouched) {
                stop(std::string("a refused batch wrote verdicts, backend ") + obbsat::backend_name(b));
            }
        }
    }
}

batch decode(const std::uint8_t* data, std::size_t size, std::uint8_t& flags) {
    byte_source in(data, size);
    const std::size_t count = 1 + in.byte() % max_rects;
    flags = in.byte();
    batch out;
    for (std::size_t i = 0; i < count; ++i) {
        out.rects.push_back(decode_rect(in, out.rects));
    }
    while (!in.empty()) {
        const auto a = static_cast<std::uint32_t>(in.byte() % count);
        const auto b = static_cast<std::uint32_t>(in.byte() % count);
        out.pairs.push_back(pair_index{a, b});
    }
    if (out.pairs.empty()) {
        for (std::uint32_t a = 0; a < count; ++a) {
            for (std::uint32_t b = 0; b < count && b < 8; ++b) {
                out.pairs.push_back(pair_index{a, b});
            }
        }
    }
    out.records = obbsat::rect_records(out.rects);
    out.soa = obbsat::rect_soa(out.rects);
    std::vector<rect> a_side;
    std::vector<rect> b_side;
    for (const pair_index& p : out.pairs) {
        a_side.push_back(out.rects[p.a]);
        b_side.push_back(out.rects[p.b]);
    }
    out.stream_a = obbsat::rect_soa(a_side);
    out.stream_b = obbsat::rect_soa(b_side);
    return out;
}


}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<backend> backends = obbsat::runnable_backends();
    std::uint8_t flags = 0;
    const batch in = decode(data, size, flags);
    const std::size_t n = in.pairs.size();

    std::vector<std::uint8_t> exact_verdicts;
    std::vector<std::uint8_t> conservative_verdicts;
    std::vector<std::uint8_t> got(n);
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        const obbsat::reference_fn reference = obbsat::method_reference(m);
        std::vector<std::uint8_t> expected(n);
        for (std::size_t i = 0; i < n; ++i) {
            expected[i] = reference(in.rects[in.pairs[i].a], in.rects[in.pairs[i].b]) ? 1 : 0;
        }
        if (m == method::exact) {
            exact_verdicts = expected;
        } else if (m == method::conservative) {
            conservative_verdicts = expected;
        }
        for (const backend b : backends) {
            obbsat::collide_options options;
            options.test = m;
            options.use = b;
            got.assign(n, untouched);
            expect_same(in, m, b, "collide_pairs over rect_records",
                        obbsat::collide_pairs(in.records, in.pairs.data(), n, got.data(), options),
                        expected, got);
            got.assign(n, untouched);
            expect_same(in, m, b, "collide_pairs over rect_soa",
                        obbsat::collide_pairs(in.soa, in.pairs.data(), n, got.data(), options),
                        expected, got);
            got.assign(n, untouched);
            expect_same(in, m, b, "collide_stream",
                        obbsat::collide_stream(in.stream_a, in.stream_b, got.data(), options),
                        expected, got);
            if ((flags & flag_check_bad_index) != 0) {
                expect_bad_index_refused(in, m, b);
            }
        }
    }
    // Method conservative promises never to miss a collision.
    for (std::size_t i = 0; i < n; ++i) {
        if (exact_verdicts[i] == 1 && conservative_verdicts[i] == 0) {
            stop("method conservative says apart where the exact oracle says they collide: " +
                 pair_text(in, i));
        }
    }
    // The scene query with method exact, over the rectangles read in place, on
    // every backend: exactly the pairs i < j the oracle calls colliding.
    std::vector<obbsat::pair_index> colliding;
    for (std::uint32_t i = 0; i < in.rects.size(); ++i) {
        for (std::uint32_t j = i + 1; j < in.rects.size(); ++j) {
            if (obbsat::oracle::intersects(in.rects[i], in.rects[j])) {
                colliding.push_back(obbsat::pair_index{i, j});
            }
        }
    }
    for (const backend b : backends) {
        obbsat::collide_options options;
        options.test = method::exact;
        options.use = b;
        const std::vector<obbsat::pair_index> found = obbsat::find_pairs(in.rects, options);
        bool same = found.size() == colliding.size();
        for (std::size_t k = 0; same && k < found.size(); ++k) {
            same = found[k].a == colliding[k].a && found[k].b == colliding[k].b;
        }
        if (!same) {
            stop("find_pairs(exact) on " + std::string(obbsat::backend_name(b)) + " reports " +
                 std::to_string(found.size()) + " pairs, the oracle " + std::to_string(colliding.size()));
        }
    }
    return 0;
}
