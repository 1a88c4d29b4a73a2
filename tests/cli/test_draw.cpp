// obbsat draw, run as a user runs it: the SVG it writes is parsed (a small XML
// reader below) and checked against the methods' references and the exact
// oracles called in process, for corners (--rects) and poses (--poses); bad
// usage and bad input leave no file behind.
#include "program_runner.hpp"

#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using obbsat::method;
using obbsat::point;
using obbsat::rect;
using obbsat::rect_pose;

using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;

// ---------------------------------------------------------------------------
// A small XML reader: enough of XML for the SVG the program writes, and
// strict about what it reads (balanced tags, quoted attributes, one root).

struct xml_element {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::vector<std::size_t> children;  // indices into xml_document::elements
    std::string text;                   // the text of the element and all its descendants
};

struct xml_document {
    std::vector<xml_element> elements;  // elements[0] is the root

    std::string attribute(std::size_t e, const std::string& name) const {
        const auto found = elements[e].attributes.find(name);
        return found == elements[e].attributes.end() ? std::string() : found->second;
    }

    bool has_class(std::size_t e, const std::string& css_class) const {
        std::istringstream words(attribute(e, "class"));
        std::string word;
        while (words >> word) {
            if (word == css_class) {
                return true;
            }
        }
        return false;
    }

    // Every element below `e` (not `e` itself), in document order.
    std::vector<std::size_t> descendants(std::size_t e) const {
        std::vector<std::size_t> out;
        for (const std::size_t child : elements[e].children) {
            out.push_back(child);
            const std::vector<std::size_t> below = descendants(child);
            out.insert(out.end(), below.begin(), below.end());
        }
        return out;
    }

    std::vector<std::size_t> descendants_with_class(std::size_t e, const std::string& css_class) const {
        std::vector<std::size_t> out;
        for (const std::size_t d : descendants(e)) {
            if (has_class(d, css_class)) {
                out.push_back(d);
            }
        }
        return out;
    }
};

std::string decode_entities(const std::string& text) {
    static const std::pair<const char*, char> entities[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        bool replaced = false;
        if (text[i] == '&') {
            for (const auto& [entity, c] : entities) {
                const std::string name(entity);
                if (text.compare(i, name.size(), name) == 0) {
                    out += c;
                    i += name.size();
                    replaced = true;
                    break;
                }
            }
            if (!replaced) {
                throw std::runtime_error("xml: unknown entity at " + std::to_string(i));
            }
            continue;
        }
        out += text[i++];
    }
    return out;
}

bool is_name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == ':' ||
           c == '.';
}

// Parses `text`; throws std::runtime_error on anything unbalanced or malformed.
xml_document parse_xml(const std::string& text) {
    xml_document doc;
    std::vector<std::size_t> open;
    bool root_closed = false;
    std::size_t i = 0;
    const auto fail = [&](const std::string& why) {
        throw std::runtime_error("xml: " + why + " at byte " + std::to_string(i));
    };
    const auto skip_blanks = [&] {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) {
            ++i;
        }
    };
    const auto read_name = [&] {
        const std::size_t begin = i;
        while (i < text.size() && is_name_char(text[i])) {
            ++i;
        }
        if (i == begin) {
            fail("expected a name");
        }
        return text.substr(begin, i - begin);
    };
    while (i < text.size()) {
        if (text[i] != '<') {
            const std::size_t end = text.find('<', i);
            const std::string piece = decode_entities(text.substr(i, end - i));
            if (open.empty()) {
                if (piece.find_first_not_of(" \t\r\n") != std::string::npos) {
                    fail("text outside the root element");
                }
            }
            for (const std::size_t e : open) {
                doc.elements[e].text += piece;
            }
            i = end == std::string::npos ? text.size() : end;
            continue;
        }
        if (text.compare(i, 5, "<?xml") == 0) {
            const std::size_t end = text.find("?>", i);
            if (end == std::string::npos || !doc.elements.empty()) {
                fail("bad declaration");
            }
            i = end + 2;
            continue;
        }
        if (text.compare(i, 4, "<!--") == 0) {
            const std::size_t end = text.find("-->", i + 4);
            if (end == std::string::npos) {
                fail("unterminated comment");
            }
            i = end + 3;
            continue;
        }
        if (text.compare(i, 2, "</") == 0) {
            i += 2;
            const std::string name = read_name();
            skip_blanks();
            if (i >= text.size() || text[i] != '>') {
                fail("bad closing tag");
            }
            ++i;
            if (open.empty() || doc.elements[open.back()].name != name) {
                fail("closing tag </" + name + "> does not match");
            }
            open.pop_back();
            root_closed = open.empty();
            continue;
        }
        ++i;
        if (root_closed) {
            fail("a second root element");
        }
        xml_element element;
        element.name = read_name();
        while (true) {
            skip_blanks();
            if (i >= text.size()) {
                fail("unterminated tag");
            }
            if (text[i] == '>' || text.compare(i, 2, "/>") == 0) {
                break;
            }
            const std::string name = read_name();
            skip_blanks();
            if (i + 1 >= text.size() || text[i] != '=' || text[i + 1] != '"') {
                fail("attribute " + name + " without a quoted value");
            }
            i += 2;
            const std::size_t end = text.find('"', i);
            if (end == std::string::npos) {
                fail("unterminated attribute value");
            }
            if (!element.attributes.emplace(name, decode_entities(text.substr(i, end - i))).second) {
                fail("attribute " + name + " given twice");
            }
            i = end + 1;
        }
        const bool self_closing = text[i] == '/';
        i += self_closing ? 2 : 1;
        const std::size_t index = doc.elements.size();
        if (!open.empty()) {
            doc.elements[open.back()].children.push_back(index);
        } else if (index != 0) {
            fail("a second root element");
        }
        doc.elements.push_back(element);
        if (self_closing) {
            root_closed = open.empty();
        } else {
            open.push_back(index);
        }
    }
    if (!open.empty()) {
        throw std::runtime_error("xml: <" + doc.elements[open.back()].name + "> is never closed");
    }
    if (doc.elements.empty()) {
        throw std::runtime_error("xml: no element");
    }
    return doc;
}

// ---------------------------------------------------------------------------
// What a drawing shows, read back from the SVG.

struct panel_reading {
    std::string id;
    std::string title;
    std::string caption;
    bool frame_says_apart;
    std::vector<std::string> separating_axes;  // data-axis of each separating-axis element
    bool has_inset;
    std::string inset_text;
    std::string legend;
};

std::vector<panel_reading> read_panels(const xml_document& doc) {
    std::vector<panel_reading> panels;
    for (const std::size_t e : doc.descendants(0)) {
        if (doc.elements[e].name != "g" || doc.attribute(e, "id").rfind("panel-", 0) != 0) {
            continue;
        }
        panel_reading panel;
        panel.id = doc.attribute(e, "id");
        const auto titles = doc.descendants_with_class(e, "title");
        if (titles.size() != 1) {
            throw std::runtime_error(panel.id + ": expected one title, found " + std::to_string(titles.size()));
        }
        panel.title = doc.elements[titles[0]].text;
        for (const std::size_t c : doc.descendants_with_class(e, "caption")) {
            panel.caption += doc.elements[c].text;
        }
        for (const std::size_t c : doc.descendants_with_class(e, "legend")) {
            panel.legend += doc.elements[c].text;
        }
        panel.frame_says_apart = doc.has_class(e, "verdict-apart");
        if (panel.frame_says_apart == doc.has_class(e, "verdict-collide")) {
            throw std::runtime_error(panel.id + ": the panel must say exactly one verdict");
        }
        for (const std::size_t s : doc.descendants_with_class(e, "separating-axis")) {
            panel.separating_axes.push_back(doc.attribute(s, "data-axis"));
        }
        const auto insets = doc.descendants_with_class(e, "inset");
        panel.has_inset = !insets.empty();
        for (const std::size_t s : insets) {
            panel.inset_text += doc.elements[s].text;
        }
        panels.push_back(panel);
    }
    return panels;
}

// Every number in a geometric attribute of the document.
std::vector<double> geometry_numbers(const xml_document& doc) {
    static const char* const names[] = {"x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r",
                                        "width", "height", "dy", "points", "font-size", "stroke-width"};
    std::vector<double> numbers;
    for (const xml_element& element : doc.elements) {
        for (const char* name : names) {
            const auto found = element.attributes.find(name);
            if (found == element.attributes.end()) {
                continue;
            }
            std::string text = found->second;
            for (char& c : text) {
                c = c == ',' ? ' ' : c;
            }
            std::istringstream in(text);
            std::string word;
            while (in >> word) {
                char* end = nullptr;
                const double value = std::strtod(word.c_str(), &end);
                if (end != word.c_str() + word.size()) {
                    throw std::runtime_error(std::string("not a number in ") + name + ": '" + word + "'");
                }
                numbers.push_back(value);
            }
        }
    }
    return numbers;
}

// ---------------------------------------------------------------------------
// Inputs.

std::string hex(float v) {
    char text[40];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(v));
    return text;
}

std::string rect_line(const rect& r) {
    return hex(r.ul.x) + "," + hex(r.ul.y) + "," + hex(r.ur.x) + "," + hex(r.ur.y) + "," + hex(r.lr.x) +
           "," + hex(r.lr.y) + "," + hex(r.ll.x) + "," + hex(r.ll.y) + "\n";
}

rect box(float x0, float x1, float y0, float y1) {
    return rect{point{x0, y1}, point{x1, y1}, point{x1, y0}, point{x0, y0}};
}

rect rotated(double cx, double cy, double w, double h, double degrees) {
    const double radians = degrees * 3.14159265358979323846 / 180.0;
    const double c = std::cos(radians), s = std::sin(radians);
    const auto corner = [&](double x, double y) {
        return point{static_cast<float>(cx + c * x - s * y), static_cast<float>(cy + s * x + c * y)};
    };
    return rect{corner(-w / 2, h / 2), corner(w / 2, h / 2), corner(w / 2, -h / 2), corner(-w / 2, -h / 2)};
}

// The pairs the drawing is meant for, one of each kind a person asks about.
struct labelled_pair {
    const char* kind;
    rect a;
    rect b;
};

std::vector<labelled_pair> interesting_pairs() {
    const float far = 1e6f;
    const float far_next = std::nextafter(far, 2e6f);
    return {
        {"touching tiles", box(0, 1, 0, 1), box(1, 2, 0, 1)},
        {"crossed", box(-5, 5, -0.5f, 0.5f), box(-0.5f, 0.5f, -5, 5)},
        {"one-ulp gap far from the origin", box(far - 10, far, far, far + 10), box(far_next, far + 10, far, far + 10)},
        {"clearly separated, rotated", rotated(0, 0, 4, 2, 30), rotated(6, 3, 3, 1.5, -20)},
        // A trapezoid whose slanted edge alone separates it from a small square:
        // no article axis does, so the exact methods show an edge normal.
        {"separated by a slanted edge", rect{point{0, 1}, point{4, 1}, point{4, 0}, point{1, 0}},
         box(0, 0.3f, 0, 0.3f)},
    };
}

const char* contact_name(obbsat::oracle::contact c) {
    switch (c) {
        case obbsat::oracle::contact::separated: return "separated";
        case obbsat::oracle::contact::touching: return "touching";
        case obbsat::oracle::contact::overlapping: return "overlapping";
    }
    return "?";
}

class draw_test : public ::testing::Test {
protected:
    void SetUp() override {
        std::string rects, pairs = "# i,j\n";
        for (std::size_t i = 0; i < cases_.size(); ++i) {
            rects += rect_line(cases_[i].a) + rect_line(cases_[i].b);
            pairs += std::to_string(2 * i) + "," + std::to_string(2 * i + 1) + "\n";
        }
        write_file(s_.file("rects.csv"), rects);
        write_file(s_.file("pairs.csv"), pairs);
    }

    // Draws `select` with `method_name`, expecting success, and reads the panels.
    std::vector<panel_reading> draw(const std::string& select, const std::string& method_name) {
        const run_result r = s_.run("draw --rects rects.csv --pairs pairs.csv --select " + select +
                                    " --method " + method_name + " --out pairs.svg");
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "");
        const xml_document doc = parse_xml(read_file(s_.file("pairs.svg")));
        EXPECT_EQ(doc.elements[0].name, "svg");
        return read_panels(doc);
    }

    const std::vector<labelled_pair> cases_ = interesting_pairs();
    scratch s_;
};

// ---------------------------------------------------------------------------
// What the panels say.

TEST_F(draw_test, one_panel_per_pair_with_the_verdict_of_each_method_and_the_exact_class) {
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        SCOPED_TRACE(obbsat::method_name(m));
        const std::vector<panel_reading> panels = draw("0-4", obbsat::method_name(m));
        ASSERT_EQ(panels.size(), cases_.size());
        for (std::size_t i = 0; i < cases_.size(); ++i) {
            SCOPED_TRACE(cases_[i].kind);
            const panel_reading& panel = panels[i];
            EXPECT_EQ(panel.id, "panel-" + std::to_string(i));
            const bool collides = obbsat::method_reference(m)(cases_[i].a, cases_[i].b);
            const obbsat::oracle::contact exact = obbsat::oracle::classify(cases_[i].a, cases_[i].b);
            const std::string verdict = collides ? "collide" : "apart";
            EXPECT_NE(panel.title.find(std::string(obbsat::method_name(m)) + " says " + verdict + ";"),
                      std::string::npos)
                << panel.title;
            EXPECT_NE(panel.title.find(std::string("exact class: ") + contact_name(exact)), std::string::npos)
                << panel.title;
            const bool agrees = collides == (exact != obbsat::oracle::contact::separated);
            EXPECT_EQ(panel.title.find("agrees with the exact answer") != std::string::npos, agrees)
                << panel.title;
            EXPECT_EQ(panel.title.find("DISAGREES") != std::string::npos, !agrees) << panel.title;
            EXPECT_EQ(panel.frame_says_apart, !collides);
            // A separating axis is drawn iff the method says apart, and only one.
            EXPECT_EQ(panel.separating_axes.size(), collides ? 0u : 1u);
            EXPECT_NE(panel.caption.find("A rect " + std::to_string(2 * i) + ": " +
                                         rect_line(cases_[i].a).substr(0, rect_line(cases_[i].a).size() - 1)),
                      std::string::npos)
                << panel.caption;
        }
    }
}

TEST_F(draw_test, method_exact_shows_an_edge_normal_when_no_article_axis_separates) {
    const std::vector<panel_reading> exact_panels = draw("3,4", "exact");
    ASSERT_EQ(exact_panels.size(), 2u);
    ASSERT_EQ(exact_panels[0].separating_axes.size(), 1u);
    EXPECT_EQ(exact_panels[0].separating_axes[0], "1");
    ASSERT_EQ(exact_panels[1].separating_axes.size(), 1u);
    EXPECT_EQ(exact_panels[1].separating_axes[0], "n");
    // The article's axes cannot see that slanted edge: sat4 and conservative,
    // which test only those axes, report a false collision.
    for (const char* name : {"sat4", "conservative"}) {
        SCOPED_TRACE(name);
        const std::vector<panel_reading> panels = draw("3,4", name);
        ASSERT_EQ(panels.size(), 2u);
        ASSERT_EQ(panels[0].separating_axes.size(), 1u);
        EXPECT_EQ(panels[0].separating_axes[0], "1");
        EXPECT_TRUE(panels[1].separating_axes.empty());
        EXPECT_NE(panels[1].title.find("DISAGREES: a false collision"), std::string::npos) << panels[1].title;
    }
}

TEST_F(draw_test, a_zoomed_inset_shows_grazing_contacts_only) {
    const std::vector<panel_reading> panels = draw("0-3", "exact");
    ASSERT_EQ(panels.size(), 4u);
    EXPECT_TRUE(panels[0].has_inset) << "touching tiles";
    EXPECT_NE(panels[0].inset_text.find("outlines meet"), std::string::npos) << panels[0].inset_text;
    EXPECT_FALSE(panels[1].has_inset) << "crossed";
    EXPECT_TRUE(panels[2].has_inset) << "one-ulp gap";
    EXPECT_NE(panels[2].inset_text.find("zoom"), std::string::npos) << panels[2].inset_text;
    EXPECT_NE(panels[2].inset_text.find("gap 0.0625"), std::string::npos) << panels[2].inset_text;
    EXPECT_FALSE(panels[3].has_inset) << "clearly separated";
}

TEST_F(draw_test, the_inset_appears_below_a_gap_of_one_percent_of_the_pair_size) {
    // Unit tiles side by side: the pair is 2 + gap wide.
    std::string rects;
    for (const float gap : {0.018f, 0.022f, 0.0f, 1e-7f}) {
        rects += rect_line(box(0, 1, 0, 1)) + rect_line(box(1 + gap, 2 + gap, 0, 1));
    }
    write_file(s_.file("rects.csv"), rects);
    write_file(s_.file("pairs.csv"), "0,1\n2,3\n4,5\n6,7\n");
    const std::vector<panel_reading> panels = draw("0-3", "sat4");
    ASSERT_EQ(panels.size(), 4u);
    EXPECT_TRUE(panels[0].has_inset) << "gap 0.9% of the pair";
    EXPECT_FALSE(panels[1].has_inset) << "gap 1.1% of the pair";
    EXPECT_TRUE(panels[2].has_inset) << "touching";
    EXPECT_TRUE(panels[3].has_inset) << "gap of one ulp";
}

TEST_F(draw_test, panels_follow_the_selection_and_pair_numbers_skip_comment_lines) {
    write_file(s_.file("pairs.csv"), "# first\n2,3\n\n# second\n4,5\n0,1\n");
    const std::vector<panel_reading> panels = draw("2,0-1", "sat4");
    ASSERT_EQ(panels.size(), 3u);
    EXPECT_EQ(panels[0].id, "panel-2");
    EXPECT_EQ(panels[1].id, "panel-0");
    EXPECT_EQ(panels[2].id, "panel-1");
    EXPECT_NE(panels[0].title.find("A = rect 0, B = rect 1"), std::string::npos) << panels[0].title;
    EXPECT_NE(panels[1].title.find("A = rect 2, B = rect 3"), std::string::npos) << panels[1].title;
    EXPECT_NE(panels[2].title.find("A = rect 4, B = rect 5"), std::string::npos) << panels[2].title;
}

TEST_F(draw_test, coordinates_stay_small_and_finite_for_huge_tiny_and_degenerate_inputs) {
    const float huge = 3e38f;
    const float tiny = 1e-44f;  // subnormal
    const std::vector<rect> rects = {
        box(-huge, huge, -huge, huge),
        box(huge / 2, huge, -1, 1),
        box(0, tiny, 0, tiny),
        box(tiny, 2 * tiny, 0, tiny),
        box(5, 5, 7, 7),                                         // a point
        box(5, 5, 7, 7),                                         // the same point
        rect{point{0, 0}, point{1e30f, 1}, point{1e30f, 1}, point{0, 0}},  // a segment
        box(-1e-30f, 1e30f, 2, 3),
        rotated(1e30, -1e30, 1e25, 1e24, 10),
        rotated(1e30 + 1e25, -1e30, 1e25, 1e24, 10),
        // sat4 separates these on axis 1 = (1e19, 0) with B's float scalars
        // overflowing to +infinity: B's extent lies at infinity.
        box(-5e18f, 5e18f, 0, 1),
        box(1e20f, 2e20f, 0, 1),
    };
    std::string text;
    for (const rect& r : rects) {
        text += rect_line(r);
    }
    write_file(s_.file("rects.csv"), text);
    write_file(s_.file("pairs.csv"), "0,1\n2,3\n4,5\n6,7\n8,9\n1,0\n10,11\n");
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        SCOPED_TRACE(obbsat::method_name(m));
        const std::vector<panel_reading> panels = draw("0-6", obbsat::method_name(m));
        ASSERT_EQ(panels.size(), 7u);
        if (m == method::sat4) {
            EXPECT_NE(panels[6].legend.find("apart (scalars overflow)"), std::string::npos) << panels[6].legend;
            EXPECT_EQ(panels[6].separating_axes, std::vector<std::string>{"1"});
        }
        const xml_document doc = parse_xml(read_file(s_.file("pairs.svg")));
        const std::vector<double> numbers = geometry_numbers(doc);
        EXPECT_GT(numbers.size(), 100u);
        for (const double v : numbers) {
            ASSERT_TRUE(std::isfinite(v) && std::fabs(v) <= 1e5) << v;
        }
    }
}

// Any four finite corners are a quadrilateral to draw: a corner far out on
// one side of an otherwise small quad, self-crossing quads, segments and
// points, at the ends of the float range and with subnormal coordinates, each
// against each, with every method.
TEST(draw_any_corners, degenerate_self_crossing_and_extreme_quads_draw_with_finite_coordinates) {
    const float huge = 3e38f;
    const float tiny = 1e-45f;  // the smallest subnormal
    const std::vector<rect> rects = {
        rect{point{1e17f, 0}, point{2, 0}, point{2, 1}, point{0, 1}},
        rect{point{1, 0.5f}, point{3, 0.5f}, point{3, 1.5f}, point{1, 1.5f}},
        rect{point{0, 0}, point{1, 0}, point{0, 0}, point{0, 0}},
        rect{point{0, -1e-30f}, point{0, -1}, point{-1, 0}, point{1, 1e-30f}},
        box(0, 0, 0, 0),
        box(huge, huge, huge, huge),
        box(tiny, tiny, -tiny, -tiny),
        rect{point{-huge, -huge}, point{huge, huge}, point{huge, huge}, point{-huge, -huge}},
        rect{point{-huge, huge}, point{huge, -huge}, point{huge, huge}, point{-huge, -huge}},
        rect{point{0, 0}, point{tiny, 0}, point{0, tiny}, point{tiny, tiny}},
        rect{point{huge, tiny}, point{-huge, tiny}, point{tiny, -huge}, point{tiny, huge}},
        rect{point{-huge, 0}, point{tiny, 0}, point{tiny, tiny}, point{-huge, tiny}},
        // A grazing contact near the origin between quads reaching 3e38: the
        // inset magnifies it about 1e46 times, edges from far outside cross it.
        rect{point{1e-38f, -3e38f}, point{-1e-30f, FLT_MAX}, point{-1e-30f, -tiny}, point{1e-38f, 0.5f}},
        rect{point{1e-30f, -1}, point{1e6f, 1e6f}, point{1, -tiny}, point{-3e38f, -3e38f}},
    };
    std::string rect_text;
    for (const rect& r : rects) {
        rect_text += rect_line(r);
    }
    std::string pair_text;
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < rects.size(); ++i) {
        for (std::size_t j = 0; j < rects.size(); ++j) {
            pair_text += std::to_string(i) + "," + std::to_string(j) + "\n";
            ++pairs;
        }
    }
    const scratch s;
    write_file(s.file("rects.csv"), rect_text);
    write_file(s.file("pairs.csv"), pair_text);
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        SCOPED_TRACE(obbsat::method_name(m));
        const run_result r = s.run("draw --rects rects.csv --pairs pairs.csv --select 0-" +
                                   std::to_string(pairs - 1) + " --method " + obbsat::method_name(m) +
                                   " --out pairs.svg");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "");
        const xml_document doc = parse_xml(read_file(s.file("pairs.svg")));
        EXPECT_EQ(read_panels(doc).size(), pairs);
        for (const double v : geometry_numbers(doc)) {
            ASSERT_TRUE(std::isfinite(v) && std::fabs(v) <= 1e5) << v;
        }
    }
}

// ---------------------------------------------------------------------------
// Poses: the same picture over --poses, with the pose test's axes.

std::string pose_line(const rect_pose& p) {
    return hex(p.center.x) + "," + hex(p.center.y) + "," + hex(p.half_extents.x) + "," + hex(p.half_extents.y) +
           "," + hex(p.rotation.x) + "," + hex(p.rotation.y) + "\n";
}

rect_pose pose(float cx, float cy, float hx, float hy, float c, float s) {
    return rect_pose{{cx, cy}, {hx, hy}, {c, s}};
}

struct labelled_pose_pair {
    const char* kind;
    rect_pose a;
    rect_pose b;
    const char* exact_separating_axis;  // the axis method exact shows, "" for none
};

std::vector<labelled_pose_pair> interesting_pose_pairs() {
    const float diagonal = 0.70710677f;
    return {
        {"touching tiles", pose(0.5f, 0.5f, 0.5f, 0.5f, 1, 0), pose(1.5f, 0.5f, 0.5f, 0.5f, 1, 0), ""},
        {"crossed, rotations of length 5", pose(0, 0, 1, 0.1f, 3, 4), pose(0, 0, 1, 0.1f, -4, 3), ""},
        {"one-ulp gap far from the origin", pose(1e6f, 1e6f, 5, 5, 1, 0), pose(1000010.0625f, 1e6f, 5, 5, 1, 0),
         "A.x"},
        // Only B's diagonal axis separates: on A's axes B's extents overlap A's.
        {"apart across B's diagonal", pose(0, 0, 1, 1, 1, 0), pose(1.9f, 1.9f, 1, 1, diagonal, diagonal), "B.x"},
        {"a point on a segment", pose(0, 0, 2, 0, 1, 0), pose(1, 0, 0, 0, 1, 0), ""},
    };
}

class draw_poses_test : public ::testing::Test {
protected:
    void SetUp() override {
        std::string poses, pairs = "# i,j\n";
        for (std::size_t i = 0; i < cases_.size(); ++i) {
            poses += pose_line(cases_[i].a) + pose_line(cases_[i].b);
            pairs += std::to_string(2 * i) + "," + std::to_string(2 * i + 1) + "\n";
        }
        write_file(s_.file("poses.csv"), poses);
        write_file(s_.file("pairs.csv"), pairs);
    }

    // Draws `select` with `method_name` (none: the default), expecting success;
    // the document, for the panels and what they hold.
    xml_document draw(const std::string& select, const std::string& method_name = "") {
        const run_result r = s_.run("draw --poses poses.csv --pairs pairs.csv --select " + select +
                                    (method_name.empty() ? "" : " --method " + method_name) + " --out poses.svg");
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "");
        xml_document doc = parse_xml(read_file(s_.file("poses.svg")));
        EXPECT_EQ(doc.elements[0].name, "svg");
        return doc;
    }

    const std::vector<labelled_pose_pair> cases_ = interesting_pose_pairs();
    scratch s_;
};

TEST_F(draw_poses_test, one_panel_per_pair_with_the_verdict_of_each_method_and_the_exact_class) {
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        SCOPED_TRACE(obbsat::method_name(m));
        const std::vector<panel_reading> panels = read_panels(draw("0-4", obbsat::method_name(m)));
        ASSERT_EQ(panels.size(), cases_.size());
        for (std::size_t i = 0; i < cases_.size(); ++i) {
            SCOPED_TRACE(cases_[i].kind);
            const panel_reading& panel = panels[i];
            EXPECT_EQ(panel.id, "panel-" + std::to_string(i));
            const bool collides = obbsat::pose_method_reference(m)(cases_[i].a, cases_[i].b);
            const obbsat::oracle::contact exact = obbsat::oracle::classify(cases_[i].a, cases_[i].b);
            const std::string verdict = collides ? "collide" : "apart";
            EXPECT_NE(panel.title.find(std::string(obbsat::method_name(m)) + " says " + verdict + ";"),
                      std::string::npos)
                << panel.title;
            EXPECT_NE(panel.title.find(std::string("exact class: ") + contact_name(exact)), std::string::npos)
                << panel.title;
            const bool agrees = collides == (exact != obbsat::oracle::contact::separated);
            EXPECT_EQ(panel.title.find("agrees with the exact answer") != std::string::npos, agrees)
                << panel.title;
            EXPECT_NE(panel.title.find("A = pose " + std::to_string(2 * i) + ", B = pose " +
                                       std::to_string(2 * i + 1)),
                      std::string::npos)
                << panel.title;
            EXPECT_EQ(panel.frame_says_apart, !collides);
            EXPECT_EQ(panel.separating_axes.size(), collides ? 0u : 1u);
            // The caption holds each pose as a line of a pose file.
            const std::string line_a = pose_line(cases_[i].a);
            EXPECT_NE(panel.caption.find("A pose " + std::to_string(2 * i) + ": " +
                                         line_a.substr(0, line_a.size() - 1)),
                      std::string::npos)
                << panel.caption;
            // The legend lists the pose test's four axes.
            for (const char* axis : {"A.x  A's (c, s)", "A.y  A's (-s, c)", "B.x  B's (c, s)", "B.y  B's (-s, c)"}) {
                EXPECT_NE(panel.legend.find(axis), std::string::npos) << axis << "\n" << panel.legend;
            }
        }
    }
}

TEST_F(draw_poses_test, the_separating_axis_is_drawn_with_both_projections) {
    const xml_document doc = draw("0-4", "exact");
    const std::vector<panel_reading> panels = read_panels(doc);
    ASSERT_EQ(panels.size(), cases_.size());
    for (std::size_t i = 0; i < cases_.size(); ++i) {
        SCOPED_TRACE(cases_[i].kind);
        const std::string want = cases_[i].exact_separating_axis;
        EXPECT_EQ(panels[i].separating_axes, want.empty() ? std::vector<std::string>{} : std::vector<std::string>{want});
    }
    // A's projection and B's, each one bar along the axis.
    std::size_t separating_groups = 0;
    for (const std::size_t e : doc.descendants(0)) {
        if (!doc.has_class(e, "separating-axis")) {
            continue;
        }
        ++separating_groups;
        EXPECT_EQ(doc.descendants_with_class(e, "extent-a").size(), 1u);
        EXPECT_EQ(doc.descendants_with_class(e, "extent-b").size(), 1u);
    }
    EXPECT_EQ(separating_groups, 2u);
    // The gap along A.x is exactly one float step at 1e6; along B's diagonal
    // it is 1.9·√2 − 1 − √2 (the float diagonal is not quite √2/2).
    EXPECT_NE(panels[2].legend.find("A.x  A's (c, s)  gap 0.0625"), std::string::npos) << panels[2].legend;
    EXPECT_NE(panels[3].legend.find("B.x  B's (c, s)  gap 0.273"), std::string::npos) << panels[3].legend;
}

TEST_F(draw_poses_test, local_is_the_default_and_replays_its_own_float_steps) {
    const std::vector<panel_reading> panels = read_panels(draw("2,3"));
    ASSERT_EQ(panels.size(), 2u);
    EXPECT_NE(panels[0].title.find("local says apart"), std::string::npos) << panels[0].title;
    EXPECT_NE(panels[0].legend.find("axes of local (float)"), std::string::npos) << panels[0].legend;
    EXPECT_EQ(panels[0].separating_axes, std::vector<std::string>{"A.x"});
    EXPECT_EQ(panels[1].separating_axes, std::vector<std::string>{"B.x"});
}

TEST_F(draw_poses_test, a_zoomed_inset_shows_grazing_contacts_only) {
    const std::vector<panel_reading> panels = read_panels(draw("0-4", "exact"));
    ASSERT_EQ(panels.size(), 5u);
    EXPECT_TRUE(panels[0].has_inset) << "touching tiles";
    EXPECT_NE(panels[0].inset_text.find("outlines meet"), std::string::npos) << panels[0].inset_text;
    EXPECT_FALSE(panels[1].has_inset) << "crossed";
    EXPECT_TRUE(panels[2].has_inset) << "one-ulp gap";
    EXPECT_NE(panels[2].inset_text.find("gap 0.0625"), std::string::npos) << panels[2].inset_text;
    EXPECT_FALSE(panels[3].has_inset) << "clearly separated";
    EXPECT_NE(panels[4].legend.find("A is a segment (hy = 0)"), std::string::npos) << panels[4].legend;
    EXPECT_NE(panels[4].legend.find("B is a point (hx = hy = 0)"), std::string::npos) << panels[4].legend;
    EXPECT_NE(panels[1].legend.find("A: |(c, s)| = 5 scales it"), std::string::npos) << panels[1].legend;
}

// Any valid pose draws: zero half extents, values at both ends of the float
// range (subnormals included), rotation vectors far from unit length, tiny
// poses far from the origin, each against each, with every method on poses.
TEST(draw_any_poses, extreme_and_degenerate_poses_draw_with_finite_coordinates) {
    const float huge = FLT_MAX;
    const float tiny = 1e-45f;  // the smallest subnormal
    const std::vector<rect_pose> poses = {
        pose(0, 0, 0, 0, 1, 0),
        pose(0, 0, 1, 0, 1, 0),
        pose(0, 0, 0, 1, 0.6f, 0.8f),
        pose(huge, huge, huge, huge, huge, -huge),
        pose(-3e38f, 3e38f, 3e38f, 1, 1, 0),
        pose(0, 0, 3e38f, 3e38f, tiny, 0),
        pose(tiny, -tiny, tiny, tiny, tiny, tiny),
        pose(0, 0, tiny, 0, tiny, -tiny),
        pose(1e30f, -1e30f, 1e-30f, 1e-30f, 1, 0),
        pose(1e30f, -1e30f, 1e-30f, 0, 0.6f, 0.8f),
        pose(1, 1, 1, 1, 1e20f, 1e-20f),
        pose(1, 1, 1e-20f, 1e20f, 1e-20f, 1e20f),
        pose(0.5f, 0.5f, 0.5f, 0.5f, 3, 4),
        pose(-1, 2, 2, 0, -1e-30f, 1),
        pose(5, 7, 0, 0, 1e38f, 1e38f),
        pose(5, 7, 0, 0, -1, 0),
    };
    std::string pose_text;
    for (const rect_pose& p : poses) {
        pose_text += pose_line(p);
    }
    std::string pair_text;
    std::vector<obbsat::oracle::contact> exact;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        for (std::size_t j = 0; j < poses.size(); ++j) {
            pair_text += std::to_string(i) + "," + std::to_string(j) + "\n";
            exact.push_back(obbsat::oracle::classify(poses[i], poses[j]));
        }
    }
    const scratch s;
    write_file(s.file("poses.csv"), pose_text);
    write_file(s.file("pairs.csv"), pair_text);
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        SCOPED_TRACE(obbsat::method_name(m));
        const run_result r = s.run("draw --poses poses.csv --pairs pairs.csv --select 0-" +
                                   std::to_string(exact.size() - 1) + " --method " + obbsat::method_name(m) +
                                   " --out poses.svg");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "");
        const xml_document doc = parse_xml(read_file(s.file("poses.svg")));
        const std::vector<panel_reading> panels = read_panels(doc);
        ASSERT_EQ(panels.size(), exact.size());
        for (std::size_t i = 0; i < panels.size(); ++i) {
            EXPECT_NE(panels[i].title.find(std::string("exact class: ") + contact_name(exact[i])), std::string::npos)
                << panels[i].title;
        }
        for (const double v : geometry_numbers(doc)) {
            ASSERT_TRUE(std::isfinite(v) && std::fabs(v) <= 1e5) << v;
        }
    }
}

TEST_F(draw_poses_test, bad_usage_and_bad_input_exit_2_and_write_nothing) {
    write_file(s_.file("keep.svg"), "old");
    write_file(s_.file("rects.csv"), rect_line(box(0, 1, 0, 1)) + rect_line(box(1, 2, 0, 1)));
    write_file(s_.file("bad_poses.csv"), "0,0,1,1,1,0\n0,0,1,-1,1,0\n");
    write_file(s_.file("far_pairs.csv"), "0,1\n0,10\n");
    const std::vector<std::string> before = s_.entries();
    struct bad_case {
        std::string args;
        std::string message;
    };
    const std::string tail = "--pairs pairs.csv --select 0 --out keep.svg";
    const std::vector<bad_case> cases = {
        {"--rects rects.csv --poses poses.csv " + tail, "draw: --rects and --poses both given"},
        {tail, "draw: missing required option --rects or --poses"},
        {"--poses poses.csv --method sat4 " + tail,
         "draw: --method sat4 does not run on poses (--poses); the methods on poses are conservative, exact, "
         "local"},
        {"--rects rects.csv --method local " + tail, "draw: --method local does not run on corners (--rects)"},
        {"--poses poses.csv --pairs pairs.csv --select 10 --out keep.svg",
         "--select: pair 10 is out of range: pairs.csv holds 5 pairs"},
        {"--poses bad_poses.csv " + tail, "bad_poses.csv:2: "},
        {"--poses poses.csv --pairs far_pairs.csv --select 0 --out keep.svg", "far_pairs.csv:2: "},
        {"--poses nothere.csv " + tail, "nothere.csv"},
        {"--poses poses.csv --pairs poses.csv --select 0 --out keep.svg", "name the same input"},
    };
    for (const bad_case& c : cases) {
        SCOPED_TRACE(c.args);
        const run_result r = s_.run("draw " + c.args);
        EXPECT_EQ(r.status, 2);
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_EQ(s_.entries(), before);
        EXPECT_EQ(read_file(s_.file("keep.svg")), "old");
    }
}

TEST_F(draw_poses_test, help_names_both_kinds_of_file) {
    const run_result r = s_.run("draw --help");
    EXPECT_EQ(r.status, 0);
    for (const char* word : {"--rects", "--poses", "A.x", "obbsat draw --poses"}) {
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
    }
}

TEST(draw_xml_reader, rejects_what_a_renderer_would_reject) {
    EXPECT_NO_THROW(parse_xml("<?xml version=\"1.0\"?>\n<svg a=\"1 &amp; 2\"><g><t>x</t></g><!-- c --></svg>\n"));
    EXPECT_EQ(parse_xml("<svg a=\"1 &amp; 2\"/>").elements[0].attributes.at("a"), "1 & 2");
    EXPECT_EQ(parse_xml("<svg><t>a<u>b</u>c</t></svg>").elements[1].text, "abc");
    for (const char* bad : {"<svg><g></svg>", "<svg></g>", "<svg>", "<svg/><g/>", "<svg a=1/>",
                            "<svg a=\"1\" a=\"2\"/>", "<svg>&nbsp;</svg>", "x<svg/>", ""}) {
        EXPECT_THROW(parse_xml(bad), std::runtime_error) << bad;
    }
}

// ---------------------------------------------------------------------------
// Help, bad usage and bad input: exit status 2, a message, no file.

TEST_F(draw_test, help_lists_the_options_and_an_example) {
    const run_result r = s_.run("draw --help");
    EXPECT_EQ(r.status, 0);
    for (const char* word : {"--rects", "--pairs", "--select", "--method", "--out", "example:"}) {
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
    }
    const run_result top = s_.run("--help");
    EXPECT_NE(top.out.find("draw"), std::string::npos);
}

TEST_F(draw_test, bad_usage_and_bad_input_exit_2_and_write_nothing) {
    write_file(s_.file("keep.svg"), "old");
    const std::vector<std::string> before = s_.entries();
    struct bad_case {
        std::string args;
        std::string message;
    };
    const std::string files = "--rects rects.csv --pairs pairs.csv ";
    const std::vector<bad_case> cases = {
        {files + "--out keep.svg", "missing required option --select"},
        {files + "--select 5 --out keep.svg", "--select: pair 5 is out of range: pairs.csv holds 5 pairs"},
        {files + "--select 0,9-12 --out keep.svg", "--select: pair 9 is out of range"},
        {files + "--select 3-1 --out keep.svg", "--select: range '3-1' runs backwards"},
        {files + "--select 1,,2 --out keep.svg", "--select: '' is not a pair number"},
        {files + "--select x --out keep.svg", "--select: 'x' is not a pair number"},
        {files + "--select 1,0-2 --out keep.svg", "--select: pair 1 is chosen twice"},
        {files + "--select 0-5000 --out keep.svg", "--select: more than 1024 pairs"},
        {files + "--select 0 --method fast --out keep.svg", "--method: unknown method 'fast'"},
        {files + "--select 0", "missing required option --out"},
        {"--rects nothere.csv --pairs pairs.csv --select 0 --out keep.svg", "nothere.csv"},
    };
    for (const bad_case& c : cases) {
        SCOPED_TRACE(c.args);
        const run_result r = s_.run("draw " + c.args);
        EXPECT_EQ(r.status, 2);
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_EQ(s_.entries(), before);
        EXPECT_EQ(read_file(s_.file("keep.svg")), "old");
    }
}

TEST_F(draw_test, a_bad_line_in_either_file_is_named_by_file_and_line) {
    write_file(s_.file("bad_rects.csv"), "0,1,1,1,1,0,0,0\n0,1,1,1,1,0,0,0\n0,1,1,1,1,0,0\n");
    write_file(s_.file("bad_pairs.csv"), "0,1\n# fine\n0,70\n");
    const std::vector<std::string> before = s_.entries();
    const run_result rects = s_.run("draw --rects bad_rects.csv --pairs pairs.csv --select 0 --out out.svg");
    EXPECT_EQ(rects.status, 2);
    EXPECT_EQ(rects.err.rfind("obbsat: bad_rects.csv:3: ", 0), 0u) << rects.err;
    // The bad pair line comes after the selected pair: the whole file is read.
    const run_result pairs = s_.run("draw --rects rects.csv --pairs bad_pairs.csv --select 0 --out out.svg");
    EXPECT_EQ(pairs.status, 2);
    EXPECT_EQ(pairs.err.rfind("obbsat: bad_pairs.csv:3: ", 0), 0u) << pairs.err;
    EXPECT_EQ(s_.entries(), before);
}

}  // namespace
