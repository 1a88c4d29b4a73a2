#include <obbsat/oracle/product_sum.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace obbsat::oracle {

namespace {

// A double as sign·m·2^e with an integer 0 <= m < 2^53.
struct binary_value {
    bool negative;
    std::uint64_t m;
    int e;
};

binary_value binary_of(double v) {
    int exponent = 0;
    const double fraction = std::frexp(std::fabs(v), &exponent);  // in [0.5, 1) or 0
    // fraction·2^53 is an integer below 2^53 for every double, subnormals included.
    const auto m = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
    return binary_value{v < 0.0, m, exponent - 53};
}

// An unsigned integer of six 32-bit limbs, least significant first: enough for
// a product of three 53-bit integers (below 2^159).
struct product_bits {
    std::uint32_t limb[6];
};

product_bits times(const product_bits& a, std::uint64_t m) {
    const std::uint64_t m_limbs[2] = {m & 0xffffffffu, m >> 32};
    product_bits out{};
    for (int j = 0; j < 2; ++j) {
        std::uint64_t carry = 0;
        for (int i = 0; i + j < 6; ++i) {
            const std::uint64_t t = static_cast<std::uint64_t>(a.limb[i]) * m_limbs[j] + out.limb[i + j] + carry;
            out.limb[i + j] = static_cast<std::uint32_t>(t);
            carry = t >> 32;
        }
    }
    return out;
}

// The bit positions a sum can reach: exponents of a product of three doubles
// lie in [3·(−1074 − 52), 3·971], the product's integer below 2^159, and 32
// terms add at most 5 bits of carry.
constexpr int lowest_exponent = 3 * (-1074 - 52);
constexpr int highest_bit = 3 * 971 + 159 + 5;
// One limb more than sign_of_product_sum's widest count (its `limb_count`).
constexpr int accumulator_limbs = (highest_bit - lowest_exponent) / 32 + 10;

// Positive and negative terms added apart, as magnitudes, then compared; only
// the limbs from `low` up are touched.
struct wide_sum {
    std::uint32_t positive[accumulator_limbs];
    std::uint32_t negative[accumulator_limbs];
};

void add_at(std::uint32_t* accumulator, int limb_count, const product_bits& value, int shift) {
    const int word = shift / 32;
    const int bit = shift % 32;
    std::uint64_t carry = 0;
    int i = 0;
    for (; i < 7; ++i) {
        const std::uint64_t low_part = i < 6 ? static_cast<std::uint64_t>(value.limb[i]) << bit : 0;
        const std::uint64_t high_part =
            (i > 0 && bit > 0) ? static_cast<std::uint64_t>(value.limb[i - 1]) >> (32 - bit) : 0;
        const std::uint64_t piece = (low_part & 0xffffffffu) | high_part;
        const std::uint64_t t = static_cast<std::uint64_t>(accumulator[word + i]) + piece + carry;
        accumulator[word + i] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
    }
    for (int k = word + i; carry != 0 && k < limb_count; ++k) {
        const std::uint64_t t = static_cast<std::uint64_t>(accumulator[k]) + carry;
        accumulator[k] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
    }
}

}  // namespace

int sign_of_product_sum(const product_term* terms, int count) {
    if (count < 0 || count > product_sum_max_terms) {
        throw std::invalid_argument("sign_of_product_sum: " + std::to_string(count) + " terms (at most " +
                                    std::to_string(product_sum_max_terms) + ")");
    }
    struct scaled_term {
        bool negative;
        product_bits bits;
        int e;
    };
    scaled_term scaled[product_sum_max_terms];
    int nonzero = 0;
    int low = 0;
    int high = 0;
    for (int t = 0; t < count; ++t) {
        product_bits bits{{1, 0, 0, 0, 0, 0}};
        bool negative = false;
        int e = 0;
        for (const double f : terms[t].factor) {
            if (!std::isfinite(f)) {
                throw std::invalid_argument("sign_of_product_sum: a factor is not finite");
            }
            const binary_value b = binary_of(f);
            bits = times(bits, b.m);
            negative = negative != b.negative;
            e += b.e;
        }
        if (bits.limb[0] == 0 && bits.limb[1] == 0 && bits.limb[2] == 0 && bits.limb[3] == 0 &&
            bits.limb[4] == 0 && bits.limb[5] == 0) {
            continue;
        }
        low = nonzero == 0 ? e : (e < low ? e : low);
        high = nonzero == 0 ? e : (e > high ? e : high);
        scaled[nonzero++] = scaled_term{negative, bits, e};
    }
    if (nonzero == 0) {
        return 0;
    }
    // Bit 0 of the accumulator stands for 2^low; the highest term reaches bit
    // (high − low) + 159, plus 5 bits of carry, plus the 7-limb window of add_at.
    const int limb_count = (high - low + 159 + 5) / 32 + 9;
    wide_sum sum;
    for (int k = 0; k < limb_count; ++k) {
        sum.positive[k] = 0;
        sum.negative[k] = 0;
    }
    for (int t = 0; t < nonzero; ++t) {
        add_at(scaled[t].negative ? sum.negative : sum.positive, limb_count, scaled[t].bits, scaled[t].e - low);
    }
    for (int k = limb_count - 1; k >= 0; --k) {
        if (sum.positive[k] != sum.negative[k]) {
            return sum.positive[k] > sum.negative[k] ? 1 : -1;
        }
    }
    return 0;
}

}  // namespace obbsat::oracle
