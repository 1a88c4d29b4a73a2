"""Seeded scenes for tests and benchmarks: not part of the collision API.

:func:`make_scene` returns the scenes the C++ tests, ``obbsat demo`` and the
C++ benchmarks generate (``obbsat::make_scene``), and :func:`make_pose_scene`
the whole scenes of the scene queries (``obbsat::make_pose_scene``, as
``obbsat gen --scene`` writes them), so a timing or a verdict from Python can
be set beside one from C++ on the same bytes.
"""

from . import _core

__all__ = ["make_pose_scene", "make_scene"]


def make_scene(rects=100_000, pairs=1_000_000, density="typical", seed=1):
    """A seeded scene shaped like a broadphase's output: ``rects`` rectangles
    (half extents in [0.5, 5], random orientations) and up to ``pairs``
    candidate pairs of nearby rectangles, sorted by first index.

    ``density`` (``"sparse"``, ``"typical"``, ``"dense"``) sets the share of
    candidates that collide: about 5%, 30% or 80%. The same arguments give the
    same bytes on every machine.

    Returns ``(corners, pairs)``: float32 ``(N, 8)`` and uint32 ``(M, 2)``.

    >>> corners, pairs = obbsat.testing.make_scene(rects=1000, pairs=5000, seed=7)
    >>> corners.shape, corners.dtype, pairs.shape, pairs.dtype
    ((1000, 8), dtype('float32'), (5000, 2), dtype('uint32'))
    """
    if rects < 0 or pairs < 0 or seed < 0:
        raise ValueError("rects, pairs and seed must be >= 0")
    return _core.make_scene(int(rects), int(pairs), density, int(seed))


def make_pose_scene(boxes=100_000, sizes="uniform", pairs_per_box=2.0, seed=1):
    """A seeded whole scene of poses for :func:`obbsat.find_pairs`: ``boxes``
    rectangles at random positions and orientations in a square (lower left
    corner at the origin) whose side gives about ``pairs_per_box`` colliding
    pairs per rectangle. ``sizes``: ``"uniform"`` (half extents in [0.5,
    1.5]) or ``"mixed"`` (sizes log-uniform over [0.2, 20], aspect ratio in
    [0.3, 1]). The same arguments give the same bytes on every machine.

    Returns float32 ``(N, 6)`` poses ``cx, cy, hx, hy, c, s``.

    >>> poses = obbsat.testing.make_pose_scene(boxes=1000, seed=7)
    >>> poses.shape, poses.dtype, 1000 < len(obbsat.find_pairs(poses, method="exact")) < 3000
    ((1000, 6), dtype('float32'), True)
    """
    if boxes < 0 or seed < 0:
        raise ValueError("boxes and seed must be >= 0")
    if not pairs_per_box > 0:
        raise ValueError(f"pairs_per_box must be > 0, not {pairs_per_box}")
    return _core.make_pose_scene(int(boxes), sizes, float(pairs_per_box), int(seed))
