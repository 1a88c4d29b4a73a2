"""obbsat against shapely 1.8 on the same rectangles: Polygon.intersects per
pair on a subset of a scene's candidate pairs (with the agreement of every
method), and an STRtree scene query (all intersecting pairs) beside
obbsat.colliding_pairs on the scene's candidate list.

    python3 python/bench/bench_shapely.py --pairs 1000000 --subset 100000
"""

import argparse
import time
import warnings

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.strtree import STRtree

import obbsat


def timed(call):
    start = time.perf_counter()
    result = call()
    return result, time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=1_000_000)
    parser.add_argument("--subset", type=int, default=100_000)
    parser.add_argument("--tree-rects", type=int, default=50_000)
    args = parser.parse_args()

    rects, pairs = obbsat.testing.make_scene(rects=args.pairs // 2, pairs=args.pairs, seed=1)
    print(f"shapely {shapely.__version__}, obbsat {obbsat.__version__} on {obbsat.resolved_backend()}")
    polygons, build = timed(lambda: [Polygon(r.reshape(4, 2).astype(np.float64)) for r in rects])
    print(f"{len(rects)} shapely polygons built in {build:.2f} s")

    subset = pairs[: args.subset]
    truth, shapely_time = timed(lambda: np.array([polygons[a].intersects(polygons[b]) for a, b in subset]))
    print(f"\nPolygon.intersects, one call per pair, {len(subset)} pairs: {shapely_time:.3f} s "
          f"({len(subset) / shapely_time / 1e6:.3f} Mpairs/s)")
    print("| method | obbsat ms (1 thread) | speedup | agree with shapely | differ |")
    print("|---|---:|---:|---:|---:|")
    for method in obbsat.methods():
        obbsat.collide(rects, subset, method=method)
        verdicts, t = timed(lambda: obbsat.collide(rects, subset, method=method))
        agree = int((verdicts == truth).sum())
        print(f"| {method} | {t * 1e3:.2f} | {shapely_time / t:.0f}x | {agree} of {len(subset)} | "
              f"{len(subset) - agree} |")

    # The scene query: every intersecting pair of a smaller scene. shapely:
    # STRtree candidates by bounding box, then intersects. obbsat: the scene
    # generator's candidate pairs (centres closer than the radius), then
    # colliding_pairs; the answers are compared where both look.
    n = args.tree_rects
    small_rects, small_pairs = obbsat.testing.make_scene(rects=n, pairs=10 * n, seed=2)
    small_polygons = [Polygon(r.reshape(4, 2).astype(np.float64)) for r in small_rects]
    index_of = {id(p): i for i, p in enumerate(small_polygons)}

    def tree_query():
        tree = STRtree(small_polygons)
        found = []
        for i, p in enumerate(small_polygons):
            for q in tree.query(p):
                j = index_of[id(q)]
                if i < j and p.intersects(q):
                    found.append((i, j))
        return np.array(sorted(found), dtype=np.int64).reshape(-1, 2)

    warnings.simplefilter("ignore", shapely.errors.ShapelyDeprecationWarning)
    tree_pairs, tree_time = timed(tree_query)
    hits, obbsat_time = timed(lambda: obbsat.colliding_pairs(small_rects, small_pairs, method="exact"))
    tree_set = set(map(tuple, tree_pairs.tolist()))
    hit_set = set(map(tuple, hits.tolist()))
    print(f"\nscene of {n} rectangles: STRtree query + intersects {tree_time:.2f} s, {len(tree_set)} pairs; "
          f"obbsat.colliding_pairs(exact) on the {len(small_pairs)} candidate pairs {obbsat_time * 1e3:.1f} ms, "
          f"{len(hit_set)} pairs ({tree_time / obbsat_time:.0f}x)")
    candidates = set(map(tuple, small_pairs.astype(np.int64).tolist()))
    missed = (tree_set - hit_set) & candidates
    print(f"found by both: {len(tree_set & hit_set)}; only shapely: {len(tree_set - hit_set)}, of which "
          f"{len(missed)} among obbsat's candidate pairs (the rest: no candidate pair to decide); "
          f"only obbsat: {len(hit_set - tree_set)}")

if __name__ == "__main__":
    main()
