#include "draw/accuracy_svg.hpp"

#include "accuracy/accuracy_text.hpp"
#include "draw/svg_writer.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <vector>

namespace obbsat::accuracy {

namespace {

constexpr double width = 760.0;
constexpr double height = 500.0;
constexpr double plot_left = 90.0;
constexpr double plot_right = 600.0;
constexpr double plot_top = 70.0;
constexpr double plot_bottom = 420.0;
constexpr double label_height = 15.0;
// Wide enough for a label in a 12px sans-serif font: a bound, not a measure.
constexpr double label_char_width = 6.5;

svg::attributes text_at(const std::string& css_class, double x, double y, const char* anchor) {
    svg::attributes attrs;
    attrs.set("class", css_class).set("x", x).set("y", y).set("text-anchor", anchor);
    return attrs;
}

void line(svg::writer& out, double x1, double y1, double x2, double y2, const char* css_class) {
    out.leaf("line", svg::attributes().set("class", css_class).set("x1", x1).set("y1", y1).set("x2", x2).set("y2", y2));
}

// A tick step of 1, 2 or 5 times a power of ten giving about five ticks up to `top`.
double tick_step(double top) {
    const double raw = top / 5.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double factor : {1.0, 2.0, 5.0}) {
        if (factor * magnitude >= raw) {
            return factor * magnitude;
        }
    }
    return 10.0 * magnitude;
}

struct placed_label {
    double x0, x1, y0, y1;  // the box the text covers
};

bool overlaps(const placed_label& a, const placed_label& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

}  // namespace

std::string accuracy_svg(const accuracy_report& report) {
    // Horizontal scale: 0 .. a round number above the fastest method.
    double fastest = 0.0;
    for (const method_result& m : report.methods) {
        if (std::isfinite(m.mpairs_per_second)) {
            fastest = std::max(fastest, m.mpairs_per_second);
        }
    }
    const double x_step = tick_step(fastest > 0.0 ? fastest * 1.05 : 1.0);
    const double x_top = x_step * std::ceil((fastest > 0.0 ? fastest * 1.05 : 1.0) / x_step);
    auto x_of = [&](double speed) {
        const double clamped = std::isfinite(speed) ? std::clamp(speed, 0.0, x_top) : 0.0;
        return plot_left + (plot_right - plot_left) * clamped / x_top;
    };

    // Vertical scale: decades from the floor up to the decade above the worst rate.
    // Rows on poses are scored on other families than rows on corners: the
    // floor's claim holds for the row with the fewest pairs.
    std::uint64_t pairs = 0;
    std::uint64_t fewest_pairs = 0;
    double worst = 0.0;
    for (const method_result& m : report.methods) {
        pairs = std::max(pairs, m.total.pairs);
        if (m.total.pairs > 0 && (fewest_pairs == 0 || m.total.pairs < fewest_pairs)) {
            fewest_pairs = m.total.pairs;
        }
        worst = std::max(worst, m.total.error_rate());
    }
    const int floor_decade =
        static_cast<int>(std::floor(std::log10(1.0 / static_cast<double>(std::max<std::uint64_t>(pairs, 1))))) - 1;
    const int top_decade =
        std::max(floor_decade + 2, worst > 0.0 ? static_cast<int>(std::ceil(std::log10(worst))) : 0);
    auto y_of_decade = [&](double decade) {
        return plot_bottom - (plot_bottom - plot_top) * (decade - floor_decade) /
                                 static_cast<double>(top_decade - floor_decade);
    };
    auto y_of = [&](double rate) {
        return rate > 0.0 ? y_of_decade(std::log10(rate)) : y_of_decade(floor_decade);
    };

    svg::writer out(width, height);
    out.text("style", svg::attributes(),
             "\n"
             "text { font-family: sans-serif; font-size: 12px; fill: #222; }\n"
             ".title { font-size: 15px; font-weight: bold; }\n"
             ".axis-title { font-size: 13px; }\n"
             ".grid { stroke: #ddd; stroke-width: 1; }\n"
             ".frame { stroke: #444; stroke-width: 1; fill: none; }\n"
             ".floor { stroke: #2a7; stroke-width: 1.5; stroke-dasharray: 6 4; }\n"
             ".floor-label { fill: #2a7; }\n"
             ".point { fill: #c33; stroke: #611; stroke-width: 1; }\n"
             ".point.zero { fill: #2a7; stroke: #153; }\n"
             ".leader { stroke: #888; stroke-width: 0.8; }\n");
    out.leaf("rect", svg::attributes().set("x", 0.0).set("y", 0.0).set("width", width).set("height", height).set("fill", "white"));

    char title[200];
    if (report.pose_families.empty()) {
        std::snprintf(title, sizeof title,
                      "obbsat methods: speed against error (%" PRIu64 " hard-case pairs, %zu families)",
                      pairs, report.families.size());
    } else {
        std::snprintf(title, sizeof title,
                      "obbsat methods: speed against error (%zu families of rects, %zu of poses)",
                      report.families.size(), report.pose_families.size());
    }
    out.text("text", text_at("title", width / 2.0, 28.0, "middle"), title);
    char subtitle[200];
    std::snprintf(subtitle, sizeof subtitle,
                  "speed: %s scene, %zu pairs over %zu rects, %s%s%s, %u thread, %s",
                  report.timing_scene.density, report.timing_scene.pairs, report.timing_scene.rects,
                  report.timing_scene.store, report.pose_families.empty() ? "" : " or ",
                  report.pose_families.empty() ? "" : report.timing_scene.pose_store,
                  report.timing_scene.threads, backend_name(report.used));
    out.text("text", text_at("subtitle", width / 2.0, 48.0, "middle"), subtitle);

    // Grid and tick labels.
    for (double x = 0.0; x <= x_top * (1.0 + 1e-9); x += x_step) {
        line(out, x_of(x), plot_top, x_of(x), plot_bottom, "grid");
        char tick[32];
        std::snprintf(tick, sizeof tick, "%g", x);
        out.text("text", text_at("tick", x_of(x), plot_bottom + 18.0, "middle"), tick);
    }
    for (int decade = floor_decade + 1; decade <= top_decade; ++decade) {
        const double y = y_of_decade(decade);
        line(out, plot_left, y, plot_right, y, "grid");
        out.text("text", text_at("tick", plot_left - 8.0, y + 4.0, "end"), "1e" + std::to_string(decade));
    }
    const double floor_y = y_of(0.0);
    line(out, plot_left, floor_y, plot_right, floor_y, "floor");
    out.text("text", text_at("tick floor-label", plot_left - 8.0, floor_y + 4.0, "end"), "0");
    const std::string floor_text = "no errors (below 1 in " + std::to_string(fewest_pairs) + ")";
    out.text("text", text_at("floor-label", plot_left + 6.0, floor_y - 6.0, "start"), floor_text);
    out.leaf("rect", svg::attributes()
                         .set("class", "frame")
                         .set("x", plot_left)
                         .set("y", plot_top)
                         .set("width", plot_right - plot_left)
                         .set("height", plot_bottom - plot_top));
    out.text("text", text_at("axis-title", (plot_left + plot_right) / 2.0, plot_bottom + 44.0, "middle"),
             "throughput, Mpairs/s (1 thread) \u2192 faster");
    out.text("text",
             text_at("axis-title", 24.0, (plot_top + plot_bottom) / 2.0, "middle")
                 .set("transform", "rotate(-90 24 " + svg::coordinate((plot_top + plot_bottom) / 2.0) + ")"),
             "error rate over all families (log scale) \u2192 worse");

    // Points, then labels: each label takes the first place, nearest its
    // point first, right of it before left, that overlaps no point, no
    // other label and not the floor's caption; a label moved off its point's
    // line gets a leader line.
    std::vector<placed_label> placed;
    placed.push_back(placed_label{plot_left + 6.0,
                                  plot_left + 6.0 + label_char_width * static_cast<double>(floor_text.size()),
                                  floor_y - 17.0, floor_y - 3.0});
    for (const method_result& m : report.methods) {
        const std::string name = m.label();
        const double rate = m.total.error_rate();
        const double px = x_of(m.mpairs_per_second);
        const double py = y_of(rate);
        out.leaf("circle", svg::attributes()
                               .set("class", rate == 0.0 ? "point zero" : "point")
                               .set("data-method", name)
                               .set("cx", px)
                               .set("cy", py)
                               .set("r", 6.0));
        placed.push_back(placed_label{px - 7.0, px + 7.0, py - 7.0, py + 7.0});
    }
    for (const method_result& m : report.methods) {
        const std::string name = m.label();
        const double rate = m.total.error_rate();
        char speed[32];
        std::snprintf(speed, sizeof speed, "%.0f", m.mpairs_per_second);
        const std::string content = name + " (" + format_rate(rate) + ", " + speed + " Mpairs/s)";
        const double box_width = label_char_width * static_cast<double>(content.size());
        const double px = x_of(m.mpairs_per_second);
        const double py = y_of(rate);
        auto box_at = [&](bool left, double baseline) {
            const double x0 = left ? px - 10.0 - box_width : px + 10.0;
            return placed_label{x0, x0 + box_width, baseline - 11.0, baseline + 3.0};
        };
        auto fits = [&](const placed_label& box) {
            return box.x0 >= plot_left + 2.0 && box.x1 <= width - 4.0 && box.y0 >= plot_top - 10.0 &&
                   box.y1 <= plot_bottom - 1.0 &&
                   std::none_of(placed.begin(), placed.end(),
                                [&](const placed_label& other) { return overlaps(box, other); });
        };
        bool left = false;
        double baseline = py + 4.0;
        bool found = false;
        for (int step = 0; step <= 24 && !found; ++step) {
            for (const double direction : {-1.0, 1.0}) {
                for (const bool try_left : {false, true}) {
                    const double candidate = py + 4.0 + direction * label_height * step;
                    if (!found && fits(box_at(try_left, candidate))) {
                        left = try_left;
                        baseline = candidate;
                        found = true;
                    }
                }
                if (step == 0) {
                    break;  // step 0 has one position per side
                }
            }
        }
        const placed_label box = box_at(left, baseline);
        placed.push_back(box);
        if (std::fabs(baseline - (py + 4.0)) > 1.0) {
            line(out, px, py, left ? box.x1 : box.x0, baseline - 4.0, "leader");
        }
        out.text("text", text_at("label", left ? box.x1 : box.x0, baseline, left ? "end" : "start").set("data-method", name),
                 content);
    }
    return out.finish();
}

}  // namespace obbsat::accuracy
