#include "suite_builder.hpp"

#include <stdexcept>

namespace obbsat::suites::detail {

suite_builder::suite_builder(suite& out, std::size_t wanted_pairs) : out_(out), wanted_(wanted_pairs) {
    out_.pairs.reserve(wanted_pairs);
    out_.tags.reserve(wanted_pairs);
}

std::uint32_t suite_builder::add_rect(const rect& r) {
    if (out_.rects.size() >= 0xffffffffu) {
        throw std::length_error("obbsat::suites: more rects than a pair_index can address");
    }
    out_.rects.push_back(r);
    return static_cast<std::uint32_t>(out_.rects.size() - 1);
}

void suite_builder::add_pair(std::uint32_t a, std::uint32_t b, const std::string& tag) {
    if (full()) {
        return;
    }
    auto found = tag_index_.find(tag);
    if (found == tag_index_.end()) {
        if (out_.tag_names.size() > 0xffffu) {
            throw std::length_error("obbsat::suites: too many distinct tags");
        }
        found = tag_index_.emplace(tag, static_cast<std::uint16_t>(out_.tag_names.size())).first;
        out_.tag_names.push_back(tag);
    }
    out_.pairs.push_back(pair_index{a, b});
    out_.tags.push_back(found->second);
}

void suite_builder::add_two(const rect& a, const rect& b, const std::string& tag) {
    if (full()) {
        return;
    }
    const std::uint32_t ia = add_rect(a);
    const std::uint32_t ib = add_rect(b);
    add_pair(ia, ib, tag);
}

}  // namespace obbsat::suites::detail
