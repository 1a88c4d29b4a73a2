#include "draw/svg_writer.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace obbsat::svg {

namespace {

// Far beyond any picture this program draws, far below where renderers lose
// precision (some work in float).
constexpr double coordinate_limit = 1e7;

}  // namespace

std::string escape_xml(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c; break;
        }
    }
    return out;
}

std::string coordinate(double value) {
    if (!(std::fabs(value) <= coordinate_limit)) {
        throw std::logic_error("svg coordinate out of range: " + std::to_string(value));
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    // Trim "12.50" to "12.5" and "12.00" to "12": the file is read by people too.
    std::string out(text);
    while (out.back() == '0') {
        out.pop_back();
    }
    if (out.back() == '.') {
        out.pop_back();
    }
    if (out == "-0") {
        out = "0";
    }
    return out;
}

attributes& attributes::set(std::string_view name, std::string_view value) {
    text_ += ' ';
    text_ += name;
    text_ += "=\"";
    text_ += escape_xml(value);
    text_ += '"';
    return *this;
}

attributes& attributes::set(std::string_view name, double value) {
    return set(name, std::string_view(coordinate(value)));
}

writer::writer(double width, double height) {
    out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    open("svg", attributes()
                    .set("xmlns", "http://www.w3.org/2000/svg")
                    .set("width", width)
                    .set("height", height)
                    .set("viewBox", "0 0 " + coordinate(width) + " " + coordinate(height)));
}

void writer::indent() { out_.append(2 * open_tags_.size(), ' '); }

void writer::open(std::string_view tag, const attributes& attrs) {
    indent();
    out_ += '<';
    out_ += tag;
    out_ += attrs.text();
    out_ += ">\n";
    open_tags_.emplace_back(tag);
}

void writer::close() {
    if (open_tags_.empty()) {
        throw std::logic_error("svg: close() without an open element");
    }
    const std::string tag = open_tags_.back();
    open_tags_.pop_back();
    indent();
    out_ += "</" + tag + ">\n";
}

void writer::leaf(std::string_view tag, const attributes& attrs) {
    indent();
    out_ += '<';
    out_ += tag;
    out_ += attrs.text();
    out_ += "/>\n";
}

void writer::text(std::string_view tag, const attributes& attrs, std::string_view content) {
    indent();
    out_ += '<';
    out_ += tag;
    out_ += attrs.text();
    out_ += '>';
    out_ += escape_xml(content);
    out_ += "</";
    out_ += tag;
    out_ += ">\n";
}

void writer::comment(std::string_view content) {
    std::string safe(content);
    for (std::size_t at = safe.find("--"); at != std::string::npos; at = safe.find("--", at)) {
        safe.replace(at, 2, "- -");
    }
    indent();
    out_ += "<!-- " + safe + " -->\n";
}

std::string writer::finish() {
    if (open_tags_.empty()) {
        throw std::logic_error("svg: finish() called twice");
    }
    if (open_tags_.size() != 1) {
        throw std::logic_error("svg: finish() with " + std::to_string(open_tags_.size() - 1) +
                               " element(s) still open");
    }
    close();
    return std::move(out_);
}

}  // namespace obbsat::svg
