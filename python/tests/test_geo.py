"""obbsat.geo: shapely footprints to corners and back, and sjoin_pairs against geopandas.sjoin."""

import doctest
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest

import obbsat

shapely_geometry = pytest.importorskip("shapely.geometry")
geopandas = pytest.importorskip("geopandas")
Point, Polygon, box = shapely_geometry.Point, shapely_geometry.Polygon, shapely_geometry.box
MultiPolygon, LineString = shapely_geometry.MultiPolygon, shapely_geometry.LineString

import obbsat.geo  # noqa: E402  (after the skips: the module itself imports without shapely)

# An easting and northing in metres, as UTM zone coordinates are: float32
# steps there are 0.5 m, so a millimetre gap exists only in float64.
UTM = np.array([500_000.0, 5_500_000.0])


def rotated_footprints(rng, n, spread, origin=(0.0, 0.0), size=(2.0, 30.0)):
    """float64 (n, 8) corners UL, UR, LR, LL of random rotated rectangles,
    centres in a square of side ``spread`` at ``origin``."""
    centers = np.asarray(origin) + rng.uniform(0, spread, size=(n, 1, 2))
    half = rng.uniform(size[0] / 2, size[1] / 2, size=(n, 1, 2))
    angle = rng.uniform(0, 2 * np.pi, size=(n, 1))
    unit = np.array([[-1, 1], [1, 1], [1, -1], [-1, -1]], dtype=np.float64)
    local = unit[None] * half
    c, s = np.cos(angle), np.sin(angle)
    corners = np.stack([c * local[..., 0] - s * local[..., 1], s * local[..., 0] + c * local[..., 1]], axis=-1)
    return (corners + centers).reshape(n, 8)


def frame(corners, labels=None):
    return geopandas.GeoDataFrame({"row": np.arange(len(corners))}, geometry=obbsat.geo.to_shapely(corners),
                                  index=labels)


def sjoin_set(left, right):
    """The (left label, right label) pairs geopandas.sjoin(predicate="intersects") reports."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        joined = geopandas.sjoin(left, right, how="inner", predicate="intersects")
    return set(zip(joined.index.tolist(), joined["index_right"].tolist()))


def pair_set(found):
    return set(zip(found[0].tolist(), found[1].tolist()))


def float64_is_exact():
    """Whether obbsat.find_pairs decides float64 corners as given: two
    squares 1 mm apart at a UTM easting are apart in float64 and touch once
    rounded to float32 (whose step there is 0.5 m)."""
    x = UTM[0]
    squares = np.array([[x, 10, x + 10, 10, x + 10, 0, x, 0],
                        [x + 10.001, 10, x + 20, 10, x + 20, 0, x + 10.001, 0]], dtype=np.float64)
    return len(obbsat.find_pairs(squares, method="exact")) == 0


needs_float64 = pytest.mark.skipif(
    not float64_is_exact(),
    reason="obbsat.find_pairs rounds float64 corners to float32 in this build (two squares 1 mm apart at "
           "easting 500000 collide): the UTM scenes need find_pairs deciding float64 corners exactly")


# Conversions

def test_round_trip_is_bit_exact_at_utm_coordinates():
    corners = rotated_footprints(np.random.default_rng(1), 500, 5000.0, origin=UTM)
    polygons = obbsat.geo.to_shapely(corners)
    assert all(p.geom_type == "Polygon" and len(p.exterior.coords) == 5 for p in polygons)
    back = obbsat.geo.corners_from_shapely(polygons)
    assert back.dtype == np.float64 and back.shape == (500, 8)
    assert np.array_equal(back.view(np.uint64), corners.view(np.uint64))
    # (N, 4, 2) and float32 input give the same polygons (float32 widened exactly).
    again = obbsat.geo.corners_from_shapely(obbsat.geo.to_shapely(corners.reshape(-1, 4, 2)))
    assert np.array_equal(again, corners)
    small = corners.astype(np.float32) - np.float32(0)
    assert np.array_equal(obbsat.geo.corners_from_shapely(obbsat.geo.to_shapely(small)), small.astype(np.float64))


def test_corners_follow_the_ring_in_either_winding():
    ring = [(0.0, 0.0), (3.0, 1.0), (2.0, 4.0), (-1.0, 3.0)]
    for coords in (ring, ring[::-1]):
        polygon = Polygon(coords)
        corners = obbsat.geo.corners_from_shapely([polygon])
        assert corners.tolist() == [[v for point in coords for v in point]]
        assert list(obbsat.geo.to_shapely(corners)[0].exterior.coords) == coords + coords[:1]


def test_winding_does_not_change_the_exact_verdicts():
    rng = np.random.default_rng(2)
    corners = rotated_footprints(rng, 300, 60.0, size=(1.0, 8.0)).astype(np.float32).astype(np.float64)
    reversed_winding = corners.reshape(-1, 4, 2)[:, ::-1].reshape(-1, 8)
    mixed = np.where((np.arange(300) % 2 == 0)[:, None], corners, reversed_winding)
    pairs = obbsat.find_pairs(corners, method="exact")
    assert len(pairs) > 50
    assert np.array_equal(obbsat.find_pairs(reversed_winding, method="exact"), pairs)
    assert np.array_equal(obbsat.find_pairs(mixed, method="exact"), pairs)


def test_z_coordinates_are_dropped():
    polygon = Polygon([(0, 0, 5), (2, 0, 5), (2, 1, 6), (0, 1, 6)])
    assert obbsat.geo.corners_from_shapely([polygon]).tolist() == [[0, 0, 2, 0, 2, 1, 0, 1]]


def test_empty_inputs():
    assert obbsat.geo.corners_from_shapely([]).shape == (0, 8)
    assert obbsat.geo.to_shapely(np.zeros((0, 8))) == []
    left, right = obbsat.geo.sjoin_pairs([])
    assert len(left) == 0 and len(right) == 0
    left, right = obbsat.geo.sjoin_pairs([box(0, 0, 1, 1)], [])
    assert len(left) == 0 and len(right) == 0


BAD_GEOMETRIES = {
    "none": (None, "is None"),
    "point": (Point(0, 0), "is a Point, expected a Polygon of 4 corners"),
    "line": (LineString([(0, 0), (1, 1)]), "is a LineString"),
    "multipolygon": (MultiPolygon([box(0, 0, 1, 1), box(2, 2, 3, 3)]), "is a MultiPolygon"),
    "empty": (Polygon(), r"is an empty geometry \(\w+\)"),
    "hole": (Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (2, 1), (2, 2), (1, 2)]]),
             r"has 1 interior ring \(holes\)"),
    "five corners": (Polygon([(0, 0), (1, 0), (1, 1), (0.5, 2), (0, 1)]), "has 5 corners, expected 4"),
    "triangle": (Polygon([(0, 0), (1, 0), (0, 1)]), "has 3 corners, expected 4"),
    "repeated corner": (Polygon([(0, 0), (1, 0), (1, 0), (0, 1)]), r"repeats a corner: corners 1 and 2"),
    "bow tie": (Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]), "has an outline that crosses or touches itself"),
    "collinear": (Polygon([(0, 0), (1, 0), (2, 0), (3, 0)]), "has an outline that crosses or touches itself"),
    "not finite": (Polygon([(0, 0), (1, 0), (1, np.nan), (0, 1)]), "has a coordinate that is NaN or infinite"),
    "not geometry": ("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))", "is a str, not a shapely geometry"),
}


@pytest.mark.parametrize("kind", sorted(BAD_GEOMETRIES))
def test_bad_geometry_is_named_by_position(kind):
    bad, reason = BAD_GEOMETRIES[kind]
    geometries = [box(0, 0, 1, 1), box(2, 0, 3, 1), bad, box(4, 0, 5, 1)]
    with pytest.raises(ValueError, match=r"^geometry 2 " + reason):
        obbsat.geo.corners_from_shapely(geometries)
    with pytest.raises(ValueError, match=r"^right 2 " + reason):
        obbsat.geo.sjoin_pairs(geometries[:2], geometries)


@pytest.mark.parametrize("kind", sorted(set(BAD_GEOMETRIES) - {"not geometry"}))
def test_bad_geometry_is_named_by_index_label(kind):
    bad, reason = BAD_GEOMETRIES[kind]
    series = geopandas.GeoSeries([box(0, 0, 1, 1), bad, box(4, 0, 5, 1)], index=["a", "b", "c"])
    with pytest.raises(ValueError, match=r"^geometry 'b' \(position 1\) " + reason):
        obbsat.geo.corners_from_geoseries(series)
    frame_ = geopandas.GeoDataFrame({"v": [1, 2, 3]}, geometry=series.values, index=[7, 8, 9])
    with pytest.raises(ValueError, match=r"^left 8 \(position 1\) " + reason):
        obbsat.geo.sjoin_pairs(frame_)


def test_a_valid_geometry_next_to_a_bad_one_is_not_blamed():
    # The bad row is found wherever it sits, also after many good ones.
    geometries = [box(i, 0, i + 1, 1) for i in range(1000)] + [box(0, 0, 1, 1).buffer(1)]
    with pytest.raises(ValueError, match=r"^geometry 1000 has \d+ corners, expected 4"):
        obbsat.geo.corners_from_shapely(geometries)


def test_the_first_bad_row_is_named_whatever_is_wrong_with_it():
    geometries = [box(0, 0, 1, 1), BAD_GEOMETRIES["bow tie"][0], Point(0, 0)]
    with pytest.raises(ValueError, match=r"^geometry 1 has an outline that crosses"):
        obbsat.geo.corners_from_shapely(geometries)
    with pytest.raises(ValueError, match=r"^geometry 0 is a Point"):
        obbsat.geo.corners_from_shapely(geometries[::-1])


def test_wrong_containers_and_arrays():
    with pytest.raises(TypeError, match="sequence of shapely Polygons"):
        obbsat.geo.corners_from_shapely(box(0, 0, 1, 1))
    with pytest.raises(TypeError, match="expected a GeoSeries or a GeoDataFrame, got list"):
        obbsat.geo.corners_from_geoseries([box(0, 0, 1, 1)])
    with pytest.raises(ValueError, match=r"expected shape \(N, 8\) or \(N, 4, 2\)"):
        obbsat.geo.to_shapely(np.zeros((3, 6)))
    with pytest.raises(ValueError, match="row 1 has a coordinate that is NaN or infinite"):
        obbsat.geo.to_shapely(np.array([[0, 1, 2, 1, 2, 0, 0, 0], [0, 1, 2, np.inf, 2, 0, 0, 0]]))


def test_geodataframe_uses_its_geometry_column_and_labels():
    corners = np.array([[0, 1, 2, 1, 2, 0, 0, 0], [5, 6, 6, 6, 6, 5, 5, 5], [2, 1, 3, 1, 3, 0, 2, 0]], float)
    table = frame(corners, labels=["x", "y", "z"])
    assert np.array_equal(obbsat.geo.corners_from_geoseries(table), corners)
    assert np.array_equal(obbsat.geo.corners_from_shapely(table.geometry), corners)
    series = obbsat.geo.to_geoseries(corners, index=["x", "y", "z"], crs="EPSG:32633")
    assert series.crs.to_epsg() == 32633 and list(series.index) == ["x", "y", "z"]
    left, right = obbsat.geo.sjoin_pairs(table)
    assert list(zip(left, right)) == [("x", "x"), ("x", "z"), ("y", "y"), ("z", "x"), ("z", "z")]


# sjoin_pairs against geopandas.sjoin

def small_scene(seed, n):
    """Footprints near the origin whose coordinates are float32 values, so
    that rounding to float32 changes nothing, with exactly touching pairs:
    integer boxes side by side and corner to corner."""
    rng = np.random.default_rng(seed)
    rotated = rotated_footprints(rng, n, 80.0, size=(1.0, 10.0)).astype(np.float32).astype(np.float64)
    grid = np.array([[x, y + 2, x + 2, y + 2, x + 2, y, x, y] for x in range(0, 12, 2) for y in range(90, 96, 2)],
                    dtype=np.float64)
    return np.concatenate([rotated, grid])


@pytest.mark.parametrize("seed", [3, 4, 5])
def test_self_join_equals_geopandas_sjoin_near_the_origin(seed):
    corners = small_scene(seed, 400)
    labels = [f"r{i}" for i in range(len(corners))]
    table = frame(corners, labels)
    expected = sjoin_set(table, table)
    found = obbsat.geo.sjoin_pairs(table)
    assert pair_set(found) == expected
    assert len(found[0]) == len(expected)          # no pair twice
    assert len(expected) > len(corners) + 100      # more than the self pairs
    # Positions for a list of polygons and for a corner array, sorted.
    by_position = obbsat.geo.sjoin_pairs(list(table.geometry))
    assert {(labels[i], labels[j]) for i, j in pair_set(by_position)} == expected
    assert np.array_equal(np.lexsort((by_position[1], by_position[0])), np.arange(len(by_position[0])))
    from_array = obbsat.geo.sjoin_pairs(corners)
    assert np.array_equal(from_array[0], by_position[0]) and np.array_equal(from_array[1], by_position[1])


@pytest.mark.parametrize("seed", [6, 7])
def test_cross_join_equals_geopandas_sjoin_near_the_origin(seed):
    corners = small_scene(seed, 500)
    left = frame(corners[:250], labels=np.arange(250) * 10)
    right = frame(corners[250:], labels=[f"p{i}" for i in range(len(corners) - 250)])
    expected = sjoin_set(left, right)
    assert len(expected) > 30
    assert pair_set(obbsat.geo.sjoin_pairs(left, right)) == expected
    assert pair_set(obbsat.geo.sjoin_pairs(left, right.geometry)) == expected
    swapped = obbsat.geo.sjoin_pairs(right, left)
    assert pair_set(swapped) == {(j, i) for i, j in expected}


def test_method_and_threads_reach_find_pairs():
    corners = small_scene(8, 300)
    exact = pair_set(obbsat.geo.sjoin_pairs(corners))
    assert pair_set(obbsat.geo.sjoin_pairs(corners, threads=2)) == exact
    assert pair_set(obbsat.geo.sjoin_pairs(corners, method="conservative")) >= exact
    with pytest.raises(ValueError, match="nonsense"):
        obbsat.geo.sjoin_pairs(corners, method="nonsense")


def utm_scene(seed):
    """Footprints at UTM coordinates: random rotated ones, plus rotated pairs
    that share an edge exactly (touching), and the same pairs with the second
    moved 1 mm away along the edge's normal (apart by 1 mm)."""
    rng = np.random.default_rng(seed)
    rotated = rotated_footprints(rng, 1500, 1500.0, origin=UTM)
    sides = []
    for k in range(40):
        corners = rotated_footprints(rng, 1, 1.0, origin=UTM + [2000.0 + 40 * k, 0.0]).reshape(4, 2)
        ul, ur, lr, ll = corners
        along = (ur - lr) * 0.8
        touching = np.array([ur, ur + (ur - ul), lr + (ur - ul), lr])   # shares the side UR-LR exactly
        normal = (ur - ul) / np.hypot(*(ur - ul))
        apart = touching + normal * 0.001
        sides += [corners, touching + [0.0, 0.0], apart, (corners + along)]
    return np.concatenate([rotated, np.array(sides).reshape(-1, 8)])


@needs_float64
@pytest.mark.parametrize("seed", [9, 10])
def test_self_join_equals_geopandas_sjoin_at_utm_coordinates(seed):
    corners = utm_scene(seed)
    table = frame(corners, labels=np.arange(len(corners)) + 1000)
    expected = sjoin_set(table, table)
    assert len(expected) > len(corners) + 1000
    found = pair_set(obbsat.geo.sjoin_pairs(table))
    assert found == expected, (sorted(found - expected)[:5], sorted(expected - found)[:5])
    # The touching pairs are in, the 1 mm gaps out.
    base = 1500 + 1000
    for k in range(40):
        first, touching, apart = base + 4 * k, base + 4 * k + 1, base + 4 * k + 2
        assert (first, touching) in found
        assert (first, apart) not in found


@needs_float64
def test_cross_join_equals_geopandas_sjoin_at_utm_coordinates():
    corners = utm_scene(11)
    left, right = frame(corners[::2]), frame(corners[1::2], labels=np.arange(len(corners[1::2])) * 3)
    assert pair_set(obbsat.geo.sjoin_pairs(left, right)) == sjoin_set(left, right)


def test_utm_millimetre_gap_on_this_build():
    """What a millimetre gap at UTM coordinates gives depends on the build:
    decided on float64 corners it is a gap; rounded to float32 (0.5 m steps)
    the two squares touch. Either way sjoin_pairs reports what find_pairs does."""
    x = UTM[0]
    squares = [box(x, 0, x + 10, 10), box(x + 10.001, 0, x + 20, 10)]
    found = pair_set(obbsat.geo.sjoin_pairs(squares))
    assert ((0, 1) in found) == (not float64_is_exact())
    assert {(0, 0), (1, 1)} <= found


# Docs and optional dependencies

def test_docstring_examples():
    result = doctest.testmod(obbsat.geo, extraglobs={"np": np, "obbsat": obbsat}, verbose=False)
    assert result.attempted > 10
    assert result.failed == 0


BLOCK_MODULES = """
import sys
class Block:
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in ("shapely", "geopandas"):
            raise ImportError(f"No module named {name!r} (blocked)")
        return None
sys.meta_path.insert(0, Block())
"""


def run_python(code):
    return subprocess.run([sys.executable, "-c", BLOCK_MODULES + textwrap.dedent(code)],
                          capture_output=True, text=True, timeout=120)


def test_import_obbsat_needs_no_shapely():
    result = run_python("""
        import obbsat
        assert "obbsat.geo" not in sys.modules and "shapely" not in sys.modules
        assert obbsat.find_pairs(__import__("numpy").zeros((2, 8))).shape == (1, 2)
        import obbsat.geo
        print("imported")
    """)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "imported"


@pytest.mark.parametrize("call", ["corners_from_shapely([])", "to_shapely([[0] * 8])", "sjoin_pairs([])",
                                  "to_geoseries([[0] * 8])"])
def test_without_shapely_a_call_says_what_to_install(call):
    result = run_python(f"""
        import obbsat
        try:
            obbsat.geo.{call}
        except ImportError as error:
            print(error)
    """)
    assert result.returncode == 0, result.stderr
    assert "obbsat.geo" in result.stdout and "needs" in result.stdout and "pip install" in result.stdout


def test_without_geopandas_to_geoseries_says_so():
    code = BLOCK_MODULES.replace('("shapely", "geopandas")', '("geopandas",)') + textwrap.dedent("""
        import obbsat
        print(obbsat.geo.corners_from_shapely(obbsat.geo.to_shapely([[0, 1, 1, 1, 1, 0, 0, 0]])).tolist())
        try:
            obbsat.geo.to_geoseries([[0] * 8])
        except ImportError as error:
            print(error)
    """)
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "[[0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0]]"
    assert "needs geopandas" in lines[1]
