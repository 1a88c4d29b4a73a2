// Collects rects and tagged pairs until a suite holds the pairs it was asked for.
#pragma once

#include <obbsat/suites/suite.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace obbsat::suites::detail {

class suite_builder {
public:
    suite_builder(suite& out, std::size_t wanted_pairs);

    /// True once the suite holds every pair it was asked for.
    bool full() const { return out_.pairs.size() >= wanted_; }
    /// Pairs still wanted.
    std::size_t remaining() const { return wanted_ - out_.pairs.size(); }

    /// Appends a rect; returns its index.
    std::uint32_t add_rect(const rect& r);
    /// Appends the pair (a, b) with `tag`, unless the suite is full.
    void add_pair(std::uint32_t a, std::uint32_t b, const std::string& tag);
    /// Appends both rects and the pair (a, b), unless the suite is full.
    void add_two(const rect& a, const rect& b, const std::string& tag);

private:
    suite& out_;
    std::size_t wanted_;
    std::unordered_map<std::string, std::uint16_t> tag_index_;
};

}  // namespace obbsat::suites::detail
