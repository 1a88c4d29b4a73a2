// A small JSON reader, enough for the accuracy report's JSON (obbsat accuracy
// --json): the program tests of the float and the double report share it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace obbsat::cli_test {

struct json {
    enum class kind { null, boolean, number, string, array, object } type = kind::null;
    bool flag = false;
    double value = 0.0;
    std::string text;
    std::vector<json> items;
    std::vector<std::pair<std::string, json>> members;

    const json& operator[](const std::string& key) const {
        for (const auto& [name, member] : members) {
            if (name == key) {
                return member;
            }
        }
        throw std::runtime_error("no member '" + key + "'");
    }
    bool has(const std::string& key) const {
        return std::any_of(members.begin(), members.end(), [&](const auto& m) { return m.first == key; });
    }
    std::uint64_t count() const { return static_cast<std::uint64_t>(value); }
};

class json_reader {
public:
    explicit json_reader(const std::string& text) : text_(text) {}

    json document() {
        json out = value();
        skip_blanks();
        if (at_ != text_.size()) {
            fail("text after the document");
        }
        return out;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(at_));
    }
    void skip_blanks() {
        while (at_ < text_.size() && std::strchr(" \t\r\n", text_[at_]) != nullptr) {
            ++at_;
        }
    }
    bool take(char c) {
        skip_blanks();
        if (at_ < text_.size() && text_[at_] == c) {
            ++at_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c)) {
            fail(std::string("expected '") + c + "'");
        }
    }
    bool take_word(const char* word) {
        const std::size_t n = std::strlen(word);
        if (text_.compare(at_, n, word) == 0) {
            at_ += n;
            return true;
        }
        return false;
    }
    std::string string_body() {
        expect('"');
        std::string out;
        while (at_ < text_.size() && text_[at_] != '"') {
            if (static_cast<unsigned char>(text_[at_]) < 0x20) {
                fail("control character in a string");
            }
            if (text_[at_] == '\\') {
                ++at_;
                if (at_ >= text_.size()) {
                    fail("unfinished escape");
                }
                const char e = text_[at_];
                if (e == 'u') {
                    if (at_ + 4 >= text_.size()) {
                        fail("short \\u escape");
                    }
                    out += static_cast<char>(std::stoi(text_.substr(at_ + 1, 4), nullptr, 16));
                    at_ += 4;
                } else if (std::strchr("\"\\/", e) != nullptr) {
                    out += e;
                } else if (e == 'n') {
                    out += '\n';
                } else if (e == 't') {
                    out += '\t';
                } else {
                    fail("unknown escape");
                }
                ++at_;
                continue;
            }
            out += text_[at_++];
        }
        if (at_ >= text_.size()) {
            fail("unfinished string");
        }
        ++at_;
        return out;
    }
    json value() {
        skip_blanks();
        json out;
        if (at_ >= text_.size()) {
            fail("missing value");
        }
        const char c = text_[at_];
        if (c == '{') {
            out.type = json::kind::object;
            ++at_;
            if (take('}')) {
                return out;
            }
            do {
                skip_blanks();
                std::string name = string_body();
                expect(':');
                out.members.emplace_back(std::move(name), value());
            } while (take(','));
            expect('}');
        } else if (c == '[') {
            out.type = json::kind::array;
            ++at_;
            if (take(']')) {
                return out;
            }
            do {
                out.items.push_back(value());
            } while (take(','));
            expect(']');
        } else if (c == '"') {
            out.type = json::kind::string;
            out.text = string_body();
        } else if (take_word("true")) {
            out.type = json::kind::boolean;
            out.flag = true;
        } else if (take_word("false")) {
            out.type = json::kind::boolean;
        } else if (take_word("null")) {
            out.type = json::kind::null;
        } else {
            const char* begin = text_.c_str() + at_;
            char* end = nullptr;
            out.value = std::strtod(begin, &end);
            if (end == begin) {
                fail("not a value");
            }
            out.type = json::kind::number;
            at_ += static_cast<std::size_t>(end - begin);
        }
        return out;
    }

    const std::string& text_;
    std::size_t at_ = 0;
};

}  // namespace obbsat::cli_test
