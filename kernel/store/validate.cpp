#include <obbsat/error.hpp>
#include <obbsat/oracle/orientation.hpp>
#include <obbsat/rect_soa.hpp>
#include <obbsat/validate.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace obbsat {

namespace {

// A side as the exact difference of two float corners would be, in double:
// a float difference is off by at most half a double ulp, and no square or
// product of two sides can overflow or fall into double's subnormal range.
struct side {
    double x;
    double y;
};

side side_from(point from, point to) {
    return side{static_cast<double>(to.x) - static_cast<double>(from.x),
                static_cast<double>(to.y) - static_cast<double>(from.y)};
}

double length(side s) { return std::sqrt(s.x * s.x + s.y * s.y); }

double dot(side a, side b) { return a.x * b.x + a.y * b.y; }

void require_tolerance(float tolerance) {
    if (!(tolerance >= 0.0f && tolerance < 1.0f)) {
        char text[64];
        std::snprintf(text, sizeof text, "%g", static_cast<double>(tolerance));
        throw invalid_input(std::string("rectangle tolerance ") + text +
                            " is outside [0, 1): it is a relative deviation");
    }
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

rect_check checked(const rect& r, float tolerance) {
    rect_check out;
    const float coordinates[coord_count] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y,
                                            r.lr.x, r.lr.y, r.ll.x, r.ll.y};
    for (unsigned k = 0; k < coord_count; ++k) {
        if (!std::isfinite(coordinates[k])) {
            out.problem = rect_problem::non_finite;
            out.where = coord_name(static_cast<coord>(k));
            return out;
        }
    }

    const point corners[4] = {r.ul, r.ur, r.lr, r.ll};
    static const char* const side_names[4] = {"side UL-UR", "side UR-LR", "side LR-LL", "side LL-UL"};
    for (unsigned k = 0; k < 4; ++k) {
        const point p = corners[k];
        const point q = corners[(k + 1) % 4];
        if (p.x == q.x && p.y == q.y) {
            out.problem = rect_problem::degenerate;
            out.where = side_names[k];
            return out;
        }
    }
    const int turn_at_ur = oracle::orientation(r.ul, r.ur, r.lr);
    if (turn_at_ur == 0 && oracle::orientation(r.ul, r.ur, r.ll) == 0) {
        out.problem = rect_problem::degenerate;
        out.where = "all four corners";
        return out;
    }
    out.turn = turn_at_ur > 0 ? winding::ccw : turn_at_ur < 0 ? winding::cw : winding::none;

    const side sides[4] = {side_from(r.ul, r.ur), side_from(r.ur, r.lr), side_from(r.lr, r.ll),
                           side_from(r.ll, r.ul)};
    const double lengths[4] = {length(sides[0]), length(sides[1]), length(sides[2]),
                               length(sides[3])};
    // Corner k + 1 joins side k and side k + 1.
    static const char* const corner_names[4] = {"corner UR", "corner LR", "corner LL", "corner UL"};
    static const char* const pair_names[2] = {"sides UL-UR and LR-LL", "sides UR-LR and LL-UL"};
    double worst = 0.0;
    const char* worst_where = "";
    for (unsigned k = 0; k < 4; ++k) {
        const unsigned next = (k + 1) % 4;
        const double cosine = std::fabs(dot(sides[k], sides[next])) / (lengths[k] * lengths[next]);
        if (cosine > worst) {
            worst = cosine;
            worst_where = corner_names[k];
        }
    }
    for (unsigned k = 0; k < 2; ++k) {
        const double longer = std::max(lengths[k], lengths[k + 2]);
        const double relative = std::fabs(lengths[k] - lengths[k + 2]) / longer;
        if (relative > worst) {
            worst = relative;
            worst_where = pair_names[k];
        }
    }
    if (worst > static_cast<double>(tolerance)) {
        out.problem = rect_problem::not_rectangle;
        out.deviation = worst;
        out.where = worst_where;
    }
    return out;
}

std::string explanation(const rect_check& c, float tolerance) {
    const std::string limit = "tolerance " + number(static_cast<double>(tolerance));
    switch (c.problem) {
        case rect_problem::none: return "valid";
        case rect_problem::non_finite: return std::string("coordinate ") + c.where + " is not finite";
        case rect_problem::degenerate:
            if (std::string(c.where) == "all four corners") {
                return "degenerate: all four corners lie on one line (zero area)";
            }
            return std::string("degenerate: ") + c.where + " has length zero";
        case rect_problem::not_rectangle:
            if (std::string(c.where).rfind("corner", 0) == 0) {
                return std::string("not a rectangle: ") + c.where + " is not a right angle (|cos| " +
                       number(c.deviation) + ", " + limit + ")";
            }
            return std::string("not a rectangle: ") + c.where + " differ in length (relative " +
                   number(c.deviation) + ", " + limit + ")";
    }
    return "unknown problem";
}

}  // namespace

const char* problem_name(rect_problem p) {
    switch (p) {
        case rect_problem::none: return "ok";
        case rect_problem::non_finite: return "non-finite coordinate";
        case rect_problem::degenerate: return "degenerate";
        case rect_problem::not_rectangle: return "not a rectangle";
    }
    return "unknown";
}

const char* winding_name(winding w) {
    switch (w) {
        case winding::none: return "none";
        case winding::ccw: return "ccw";
        case winding::cw: return "cw";
    }
    return "unknown";
}

rect_check check_rect(const rect& r, float tolerance) {
    require_tolerance(tolerance);
    return checked(r, tolerance);
}

validation_report validate(const rect* rects, std::size_t n, float tolerance) {
    require_tolerance(tolerance);
    validation_report report;
    for (std::size_t i = 0; i < n; ++i) {
        const rect_check c = checked(rects[i], tolerance);
        if (!c.ok()) {
            report.ok = false;
            report.index = i;
            report.check = c;
            report.message = "rectangle " + std::to_string(i) + ": " + explanation(c, tolerance);
            return report;
        }
        if (c.turn == winding::ccw) {
            ++report.ccw_count;
        } else if (c.turn == winding::cw) {
            ++report.cw_count;
        }
    }
    report.index = n;
    report.message = "all " + std::to_string(n) + " rectangles are valid (" +
                     std::to_string(report.ccw_count) + " counter-clockwise, " +
                     std::to_string(report.cw_count) + " clockwise)";
    return report;
}

}  // namespace obbsat
