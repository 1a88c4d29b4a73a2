"""A spatial join of rotated footprints at UTM coordinates, three ways:
geopandas.sjoin(predicate="intersects") of a frame with itself, shapely's
STRtree with intersects per candidate, and obbsat.geo.sjoin_pairs; the time of
each and whether they report the same pairs.

    python3 python/bench/bench_geopandas.py --rects 100000
    python3 python/bench/bench_geopandas.py --rects 1000000 --skip-strtree

The footprints are rectangles of 4 to 40 m sides at random angles, centres
uniform in a square of 40 m per footprint side to side (sqrt(N) * 40 m), at
easting 500 km, northing 5500 km, float64, drawn from --seed. All three
answer sjoin's question: every ordered pair (i, j) of rows whose closed
footprints share a point, (i, i) included. Pairs are compared as sets of
positions.
"""

import argparse
import time
import warnings

import numpy as np

import geopandas
import shapely
from shapely.strtree import STRtree

import obbsat
import obbsat.geo

ORIGIN = np.array([500_000.0, 5_500_000.0])


def footprints(count, seed):
    """float64 (count, 8) corners UL, UR, LR, LL at UTM-like coordinates."""
    rng = np.random.default_rng(seed)
    side = np.sqrt(count) * 40.0
    centers = ORIGIN + rng.uniform(0, side, size=(count, 1, 2))
    half = rng.uniform(2.0, 20.0, size=(count, 1, 2))
    angle = rng.uniform(0, np.pi, size=(count, 1))
    unit = np.array([[-1, 1], [1, 1], [1, -1], [-1, -1]], dtype=np.float64)
    local = unit[None] * half
    c, s = np.cos(angle), np.sin(angle)
    corners = np.stack([c * local[..., 0] - s * local[..., 1], s * local[..., 0] + c * local[..., 1]], axis=-1)
    return (corners + centers).reshape(count, 8)


def timed(call):
    start = time.perf_counter()
    result = call()
    return result, time.perf_counter() - start


def geopandas_pairs(table):
    joined = geopandas.sjoin(table, table, how="inner", predicate="intersects")
    return set(zip(joined.index.tolist(), joined["index_right"].tolist()))


def strtree_pairs(polygons):
    tree = STRtree(polygons)
    found = set()
    for i, polygon in enumerate(polygons):
        for j in tree.query_items(polygon):
            if polygon.intersects(polygons[j]):
                found.add((i, int(j)))
    return found


def float64_is_exact():
    """Whether find_pairs decides float64 corners as given (two squares 1 mm
    apart at easting 500 km are apart) or rounds them to float32 (they touch)."""
    x = ORIGIN[0]
    squares = np.array([[x, 10, x + 10, 10, x + 10, 0, x, 0],
                        [x + 10.001, 10, x + 20, 10, x + 20, 0, x + 10.001, 0]])
    return len(obbsat.find_pairs(squares, method="exact")) == 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rects", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--skip-strtree", action="store_true", help="leave out the STRtree loop (slow at 1M)")
    args = parser.parse_args()
    warnings.simplefilter("ignore")

    print(f"geopandas {geopandas.__version__}, shapely {shapely.__version__}, obbsat {obbsat.__version__} "
          f"on {obbsat.resolved_backend()}; spatial index {type(geopandas.GeoSeries([]).sindex).__name__}")
    exact64 = float64_is_exact()
    print("find_pairs on float64 corners: " + ("exact for the doubles" if exact64 else
          "rounds them to float32 (0.5 m steps at these coordinates): pairs closer than that can differ"))

    corners = footprints(args.rects, args.seed)
    polygons, build = timed(lambda: obbsat.geo.to_shapely(corners))
    table = geopandas.GeoDataFrame({"row": np.arange(len(corners))}, geometry=polygons)
    print(f"{len(corners)} footprints, {len(polygons)} shapely polygons built in {build:.2f} s")

    rows = []
    reference, took = timed(lambda: geopandas_pairs(table))
    rows.append(("geopandas.sjoin(predicate='intersects')", took, reference))
    if not args.skip_strtree:
        found, took = timed(lambda: strtree_pairs(polygons))
        rows.append(("shapely STRtree + intersects", took, found))
    converted, convert_time = timed(lambda: obbsat.geo.corners_from_geoseries(table))
    assert np.array_equal(converted, corners)
    for threads in (1, 2):
        obbsat.geo.sjoin_pairs(converted, threads=threads)
        found, took = timed(lambda: obbsat.geo.sjoin_pairs(converted, threads=threads))
        rows.append((f"obbsat sjoin_pairs on corners, {threads} thread{'s' if threads > 1 else ''}", took,
                     set(zip(found[0].tolist(), found[1].tolist()))))
    found, took = timed(lambda: obbsat.geo.sjoin_pairs(table))
    rows.append(("obbsat sjoin_pairs on the GeoDataFrame, 1 thread", took, set(zip(found[0].tolist(),
                                                                                   found[1].tolist()))))
    print(f"corners_from_geoseries: {convert_time:.2f} s (included in the GeoDataFrame row)\n")

    base = rows[0][1]
    print("| join | s | vs sjoin | pairs (i, j), self pairs included | same as sjoin | only sjoin | only this |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, took, found in rows:
        print(f"| {name} | {took:.3f} | {base / took:.1f}x | {len(found)} | {len(found & reference)} | "
              f"{len(reference - found)} | {len(found - reference)} |")

    differ = set()
    for _, _, found in rows[1:]:
        differ |= found ^ reference
    if differ:
        print("\npairs not reported by all: how far GEOS has them overlap or apart")
        for i, j in sorted(differ)[:10]:
            if (i, j) in reference:
                area = polygons[i].intersection(polygons[j]).area
                print(f"  ({i}, {j}) in sjoin only: they overlap by {area:.3g} m^2")
            else:
                print(f"  ({i}, {j}) not in sjoin: {polygons[i].distance(polygons[j]):.3g} m apart")


if __name__ == "__main__":
    main()
