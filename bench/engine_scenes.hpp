// Scenes shaped like a physics engine's workloads, for the engine_frame/ and
// engine_cold/ rows (bench_engine.cpp): each a deterministic sequence of
// frames of poses, stepped one frame at a time. Generation uses IEEE basic
// arithmetic and std::sqrt only (rotations from the rational parametrisation
// of the unit circle, composed and renormalised), as make_pose_scene does, so
// a scene and box count give the same bytes on every machine.
//
//   stacks         Pyramids of unit boxes (Box2D's pyramid benchmark: a base
//                  of 20 boxes, each row one box shorter and offset by half a
//                  box, on a ground box), laid out on a grid of pyramids.
//                  Neighbours overlap by 2 mm (a resting contact's slop);
//                  every frame each box sits at its rest pose plus a jitter
//                  of at most 0.5 mm in x and y and 0.5 mrad in rotation,
//                  drawn anew (it does not accumulate). Grounds do not move.
//   tumbler        Drums of radius 26 with 2000 boxes (half extents 0.2 to
//                  0.35) and 32 wall segments each, turning 0.02 rad per
//                  frame. A box is carried along the wall at its own radius
//                  (rotating with the drum) up to a release height drawn per
//                  cycle on the rising side, then flies: thrown with the
//                  wall's speed plus an inward push, under gravity (0.01 per
//                  frame squared), spinning at up to 0.2 rad per frame, until
//                  it reaches its radius again, moving outward, and is carried
//                  again. Boxes pass through each other (no contact response):
//                  the motion only has to change many contacts every frame.
//   spawn_despawn  A uniform make_pose_scene (2 colliding pairs per box), every
//                  box drifting at its own velocity (up to 0.01 per frame in x
//                  and y); every frame 1% of the rows, drawn at random, are
//                  removed (the others keep their order) and as many new boxes
//                  are appended, at random places in the scene's square. The
//                  count stays the same; the rows after the first removed one
//                  hold other boxes than the frame before.
//                  Each box has an id (counted up as boxes are made, the
//                  ids of removed boxes never come back), which the
//                  engine_frame rows pass (box_view::with_ids).
//   spawn_despawn_filtered
//                  spawn_despawn's frames (the same rows, ids and changes)
//                  with pair filters that travel with their rows
//                  (box_view::with_filters): a category of one of 4 bits,
//                  a mask refusing one category for 1 box in 8, a group of 2
//                  to 4 boxes for 1 box in 16, drawn from the box's id; and
//                  every frame 0.1% of the boxes, drawn at random, take new
//                  filter values. The engine_frame row passes ids and filters.
//   spawn_swap_remove
//                  spawn_despawn's scene and motion, where each removed row
//                  takes the last row in its place (swap-remove, as an ECS
//                  stores its components) before as many new boxes are
//                  appended: the rows that stay do not keep their order,
//                  about 1% of them move. Ids as in spawn_despawn.
//   drift          The same uniform drifting scene with no box removed or
//                  added: spawn_despawn's frames without the change of rows,
//                  the baseline its frame rows compare with.
//   drift_ids      drift's frames with ids (each box's id its row, the same
//                  every frame), passed by the engine_frame row: a frame with
//                  no change of rows that pays, as spawn_despawn's do, for
//                  matching the ids against the last frame's.
//   teleports      The same uniform drifting scene; every frame 2% of the
//                  boxes, drawn at random, jump to a random place in the
//                  scene's square.
#pragma once

#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_records.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace obbsat_bench {

enum class engine_scene {
    stacks,
    tumbler,
    spawn_despawn,
    spawn_despawn_filtered,
    spawn_swap_remove,
    drift,
    drift_ids,
    teleports
};

inline constexpr engine_scene engine_scenes[] = {
    engine_scene::stacks,       engine_scene::tumbler,           engine_scene::spawn_despawn,
    engine_scene::spawn_despawn_filtered, engine_scene::spawn_swap_remove, engine_scene::drift,
    engine_scene::drift_ids,    engine_scene::teleports};

/// "stacks", "tumbler", "spawn_despawn", "spawn_despawn_filtered", "spawn_swap_remove", "drift", "drift_ids" or "teleports".
const char* engine_scene_name(engine_scene scene);

/// One run through a scene's frames, from frame 0.
class engine_sequence {
public:
    virtual ~engine_sequence() = default;
    /// The poses of the current frame; valid until the next step.
    virtual const obbsat::pose_records& poses() const = 0;
    /// Moves to the next frame.
    virtual void step() = 0;
    /// The ids of the current frame's rows, one per row, when the scene
    /// gives its boxes ids (spawn_despawn, drift_ids); nullptr otherwise.
    virtual const std::vector<std::uint64_t>* ids() const { return nullptr; }
    /// The pair filters of the current frame's rows (spawn_despawn_filtered),
    /// valid until the next step; none given otherwise.
    virtual obbsat::pair_filters filters() const { return {}; }
};

/// Frame 0 of `scene` with `boxes` boxes (walls and grounds counted).
std::unique_ptr<engine_sequence> make_engine_sequence(engine_scene scene, std::size_t boxes);

}  // namespace obbsat_bench
