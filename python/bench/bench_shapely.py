"""obbsat against shapely 1.8 on the same rectangles: Polygon.intersects per
pair on a subset of a scene's candidate pairs (with the agreement of every
method), and an STRtree scene query (all intersecting pairs) beside
obbsat.find_pairs(method="exact"), pair by pair.

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
    # STRtree candidates by bounding box, then intersects. obbsat: find_pairs
    # with method exact. The two pair sets are compared pair by pair.
    n = args.tree_rects
    small_rects, _ = obbsat.testing.make_scene(rects=n, pairs=10 * n, seed=2)
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
        return found

    warnings.simplefilter("ignore", shapely.errors.ShapelyDeprecationWarning)
    tree_pairs, tree_time = timed(tree_query)
    tree_set = set(tree_pairs)
    print(f"\nscene of {n} rectangles: STRtree query + intersects {tree_time:.2f} s, {len(tree_set)} pairs")
    print("| obbsat.find_pairs(exact) | ms | speedup | pairs | found by both | only shapely | only obbsat |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for threads in (1, 2):
        obbsat.find_pairs(small_rects, threads=threads)
        best = None
        for _ in range(5):
            hits, t = timed(lambda: obbsat.find_pairs(small_rects, method="exact", threads=threads))
            best = t if best is None else min(best, t)
        hit_set = set(map(tuple, hits.tolist()))
        print(f"| {threads} thread{'s' if threads > 1 else ''} | {best * 1e3:.1f} | {tree_time / best:.0f}x | "
              f"{len(hit_set)} | {len(tree_set & hit_set)} | {len(tree_set - hit_set)} | {len(hit_set - tree_set)} |")
    for i, j in sorted(tree_set ^ hit_set)[:5]:
        side = "shapely" if (i, j) in tree_set else "obbsat"
        print(f"  only {side}: ({i}, {j})\n    {small_rects[i].tolist()}\n    {small_rects[j].tolist()}")


if __name__ == "__main__":
    main()
