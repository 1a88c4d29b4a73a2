// A small SVG writer: elements with attributes, nested by open/close, text
// escaped for XML, numbers written so that every renderer reads them.
//
// Numbers: an SVG coordinate must be a plain finite decimal. Callers place
// their geometry in the picture's own units first; a value that is not finite
// or lies beyond +-1e7 here is a bug in that placement, reported by throwing
// std::logic_error rather than by writing a picture that renders wrongly.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace obbsat::svg {

/// `text` with &, <, >, " and ' replaced by their XML entities.
std::string escape_xml(std::string_view text);

/// `value` as a short decimal (at most two decimals, no exponent); throws
/// std::logic_error unless |value| <= 1e7.
std::string coordinate(double value);

/// The attributes of one element, in the order they are set.
class attributes {
public:
    /// name="value", the value escaped.
    attributes& set(std::string_view name, std::string_view value);
    /// name="coordinate(value)".
    attributes& set(std::string_view name, double value);

    const std::string& text() const { return text_; }

private:
    std::string text_;
};

/// An SVG document built front to back; finish() checks every element is closed.
class writer {
public:
    /// Starts <svg> of the given size in user units (pixels).
    writer(double width, double height);

    /// <tag attrs>; must be matched by close().
    void open(std::string_view tag, const attributes& attrs = attributes());
    /// Closes the innermost open element.
    void close();
    /// <tag attrs/>.
    void leaf(std::string_view tag, const attributes& attrs);
    /// <tag attrs>text</tag>, the text escaped.
    void text(std::string_view tag, const attributes& attrs, std::string_view content);
    /// A comment (for people reading the file); "--" in it is broken up.
    void comment(std::string_view content);

    /// Closes <svg> and returns the document; throws std::logic_error if an
    /// element opened with open() is still open.
    std::string finish();

private:
    void indent();

    std::string out_;
    std::vector<std::string> open_tags_;
};

}  // namespace obbsat::svg
