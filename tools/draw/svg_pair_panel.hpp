// One pair drawn as a panel: both quads with their corners, the four axes of
// the method's test through the pair's centre, the axis that separated them
// (with both extents as bars along it and the two facing extent ends as lines
// across), the verdict of the method against the exact class, a zoomed inset
// around a grazing contact, and the input values as hex floats.
//
// A pair of corner rectangles shows its quads as given, corners named UL UR
// LR LL, and the article's four axes (svg_pair_axes.hpp). A pair of poses
// shows each pose's rectangle from corners computed in double, measured from
// A's centre, so that a pose far smaller than its distance from the origin
// keeps its shape; each centre is marked, and the axes are the pose test's,
// A's x and y and B's x and y (svg_pose_axes.hpp).
//
// Every panel is scaled on its own so that the pair fills it, with positions
// computed in double relative to the pair's centre: coordinates written to the
// SVG are small finite numbers whatever the magnitude of the input.
//
// The SVG is meant to be read by tests too: the panel is <g id="panel-N"
// class="panel">, its title is <text class="title">, the separating axis is
// <g class="separating-axis">, the inset is <g class="inset">.
#pragma once

#include "draw/svg_writer.hpp"

#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstdint>
#include <string>

namespace obbsat::svg {

inline constexpr double panel_width = 640;
inline constexpr double panel_height = 446;

/// Colours shared by the panels and the picture's key.
inline constexpr const char* color_a = "#1f6fd1";
inline constexpr const char* color_b = "#9b30c8";
inline constexpr const char* color_collide = "#d62728";
inline constexpr const char* color_apart = "#2a9d3a";

/// Everything a panel shows about one pair.
struct pair_drawing {
    std::uint64_t pair_number;  ///< 0-based line of the pair file (non-comment lines)
    pair_index rects;           ///< the rectangle indices of A and B
    rect a;
    rect b;
    method test;
    bool collides;           ///< the method's verdict, as the library gave it
    oracle::contact exact;   ///< the exact class
};

/// Everything a panel shows about one pair of poses.
struct pose_pair_drawing {
    std::uint64_t pair_number;  ///< 0-based line of the pair file (non-comment lines)
    pair_index poses;           ///< the pose indices of A and B
    rect_pose a;
    rect_pose b;
    method test;
    bool collides;          ///< the method's verdict, as the library gave it
    oracle::contact exact;  ///< the exact class, by the pose oracle
};

/// Everything a panel shows about one pair of double poses (--precision double).
struct pose64_pair_drawing {
    std::uint64_t pair_number;
    pair_index poses;
    rect_pose64 a;
    rect_pose64 b;
    method test;
    bool collides;
    oracle::contact exact;  ///< by the double pose oracle
};

/// Everything a panel shows about one pair of double corners (--precision double).
struct rect64_pair_drawing {
    std::uint64_t pair_number;
    pair_index rects;
    rect64 a;
    rect64 b;
    method test;
    bool collides;
    oracle::contact exact;  ///< by the double oracle
};

/// "collide" or "apart".
const char* verdict_word(bool collides);

/// Draws the panel of `pair` with its top-left corner at (left, top).
void draw_pair_panel(writer& out, const pair_drawing& pair, double left, double top);

/// Draws the panel of a pair of poses with its top-left corner at (left, top).
void draw_pair_panel(writer& out, const pose_pair_drawing& pair, double left, double top);

/// Draws the panel of a pair of double poses, measured from A's centre (a
/// double), so that poses at UTM or larger coordinates keep their shape and a
/// gap of a few double ulps still gets its inset; the caption lists the doubles
/// as hex floats.
void draw_pair_panel(writer& out, const pose64_pair_drawing& pair, double left, double top);

/// Draws the panel of a pair of double corners, measured from A's UL corner.
void draw_pair_panel(writer& out, const rect64_pair_drawing& pair, double left, double top);

}  // namespace obbsat::svg
