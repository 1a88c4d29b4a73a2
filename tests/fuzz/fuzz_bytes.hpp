// Reading a fuzzer's bytes as typed values. Every read succeeds: past the end
// of the input it yields zeros, so any byte string decodes to exactly one
// input and a crash found by the fuzzer replays from its file alone.
#pragma once

#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace obbsat::fuzz {

class byte_source {
public:
    byte_source(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    bool empty() const { return position_ >= size_; }
    std::size_t remaining() const { return empty() ? 0 : size_ - position_; }

    std::uint8_t byte() { return empty() ? 0 : data_[position_++]; }

    std::uint16_t u16() {
        const unsigned low = byte();
        const unsigned high = byte();
        return static_cast<std::uint16_t>(low | (high << 8));
    }

    std::uint32_t u32() {
        const std::uint32_t low = u16();
        const std::uint32_t high = u16();
        return low | (high << 16);
    }

    /// The next `count` bytes (fewer at the end of the input) as text.
    std::string_view text(std::size_t count) {
        const std::size_t taken = count < remaining() ? count : remaining();
        const std::string_view out(reinterpret_cast<const char*>(data_) + position_, taken);
        position_ += taken;
        return out;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t position_ = 0;
};

inline float float_from_bits(std::uint32_t bits) {
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

inline std::uint32_t bits_of(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

/// A finite float for any 32 bits. Finite patterns (subnormals and the
/// largest magnitudes included) are kept as they are; an infinity becomes
/// the largest float of its sign, and a NaN loses the top bit of its exponent,
/// which leaves a value in [1, 2) of the same sign with the payload as fraction.
inline float finite_from_bits(std::uint32_t bits) {
    constexpr std::uint32_t exponent_mask = 0x7f800000u;
    constexpr std::uint32_t fraction_mask = 0x007fffffu;
    constexpr std::uint32_t sign_mask = 0x80000000u;
    if ((bits & exponent_mask) != exponent_mask) {
        return float_from_bits(bits);
    }
    if ((bits & fraction_mask) == 0) {
        return (bits & sign_mask) != 0 ? -FLT_MAX : FLT_MAX;
    }
    return float_from_bits(bits & ~0x40000000u);
}

/// `value` moved by `steps` representable floats (negative: towards -FLT_MAX),
/// stopping at +-FLT_MAX; +0 and -0 count as one value.
inline float nudged(float value, int steps) {
    const std::uint32_t bits = bits_of(value);
    const std::int64_t magnitude = static_cast<std::int64_t>(bits & 0x7fffffffu);
    std::int64_t ordered = (bits & 0x80000000u) != 0 ? -magnitude : magnitude;
    ordered += steps;
    constexpr std::int64_t largest = 0x7f7fffff;  // the bits of FLT_MAX
    if (ordered > largest) {
        ordered = largest;
    }
    if (ordered < -largest) {
        ordered = -largest;
    }
    if (ordered < 0) {
        return float_from_bits(0x80000000u | static_cast<std::uint32_t>(-ordered));
    }
    return float_from_bits(static_cast<std::uint32_t>(ordered));
}

}  // namespace obbsat::fuzz
