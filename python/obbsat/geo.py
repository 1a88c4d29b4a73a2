"""shapely and geopandas in and out: footprints as obbsat corners, and the
pairs ``geopandas.sjoin(predicate="intersects")`` relates, from one scene query.

A footprint is a shapely ``Polygon`` of four corners with no holes: its
exterior ring, as shapely stores it, holds five coordinates, the last equal
to the first. Its corners become one obbsat row ``UL, UR, LR, LL`` in ring
order: the ring's first coordinate is UL, the second UR, the third LR, the
fourth LL. obbsat's methods take the corners in either winding, so a ring
that runs clockwise and one that runs counter-clockwise over the same four
points give the same verdicts; nothing is reordered, and :func:`to_shapely`
gives back the same ring, coordinate for coordinate. The names UL ... LL
are positions in the cycle, not compass directions.

Every coordinate stays a float64. ``sjoin_pairs`` hands float64 corners to
:func:`obbsat.find_pairs`; with ``method="exact"`` the verdict is whether the
two closed quadrilaterals share a point (touching counts, as it does for
GEOS's ``intersects``).

shapely (1.8 or 2.x) is needed when a function here is called, not when
``obbsat`` or ``obbsat.geo`` is imported; geopandas only for GeoSeries and
GeoDataFrames.

>>> from shapely.geometry import Polygon
>>> corners = obbsat.geo.corners_from_shapely([Polygon([(0, 0), (2, 0), (2, 1), (0, 1)]),
...                                            Polygon([(2, 1), (3, 1), (3, 3), (2, 3)])])
>>> corners
array([[0., 0., 2., 0., 2., 1., 0., 1.],
       [2., 1., 3., 1., 3., 3., 2., 3.]])
>>> obbsat.geo.to_shapely(corners)[1].wkt
'POLYGON ((2 1, 3 1, 3 3, 2 3, 2 1))'
>>> obbsat.geo.sjoin_pairs(corners)          # as sjoin of a frame with itself: (0, 1) touch
(array([0, 0, 1, 1]), array([0, 1, 0, 1]))
"""

import sys as _sys

import numpy as _np

import obbsat as _obbsat

__all__ = ["corners_from_geoseries", "corners_from_shapely", "sjoin_pairs", "to_geoseries", "to_shapely"]

# The well-known binary of a 2D polygon with one ring of five points, as
# shapely writes it: byte order (1 byte), geometry type 3 (4 bytes), one ring
# (4), five points (4), then ten float64s. Anything else takes the slow path,
# which reads the geometry through shapely and names what is wrong with it.
_WKB_SIZE = 93
_WKB_HEAD = 13


def _shapely():
    """The shapely modules this file uses, or an ImportError that says what to install."""
    try:
        import shapely.geometry
        import shapely.wkb
    except ImportError as error:
        raise ImportError(
            "obbsat.geo needs shapely (1.8 or later): install python3-shapely (Debian) or `pip install shapely`"
        ) from error
    return shapely


def _geopandas():
    try:
        import geopandas
    except ImportError as error:
        raise ImportError(
            "obbsat.geo.to_geoseries needs geopandas: install python3-geopandas (Debian) or `pip install geopandas`"
        ) from error
    return geopandas


def _as_geoseries(geometries):
    """The GeoSeries behind ``geometries`` (a GeoDataFrame's active geometry
    column), or None for anything else. A GeoSeries can only exist once
    geopandas is imported, so it is never imported here."""
    geopandas = _sys.modules.get("geopandas")
    if geopandas is None:
        return None
    if isinstance(geometries, geopandas.GeoDataFrame):
        return geometries.geometry
    if isinstance(geometries, geopandas.GeoSeries):
        return geometries
    return None


def _describe(geometry, shapely):
    """Why ``geometry`` is not a footprint of four corners, or None when it is one."""
    if geometry is None:
        return "is None (a missing geometry), expected a Polygon of 4 corners"
    if not isinstance(geometry, shapely.geometry.base.BaseGeometry):
        return f"is a {type(geometry).__name__}, not a shapely geometry"
    kind = geometry.geom_type
    if geometry.is_empty:
        # shapely 1.8 calls an empty Polygon() a GeometryCollection.
        return f"is an empty geometry ({kind}), expected a Polygon of 4 corners"
    if kind != "Polygon":
        return f"is a {kind}, expected a Polygon of 4 corners"
    holes = len(geometry.interiors)
    if holes:
        return f"has {holes} interior ring{'s' if holes > 1 else ''} (holes), expected none"
    corners = len(geometry.exterior.coords) - 1
    if corners != 4:
        return f"has {corners} corners, expected 4"
    return None


def _rows(geometries, names, shapely):
    """float64 (N, 8): the exterior corners of every geometry, read in bulk
    from their well-known binary; a geometry that is not a 2D polygon of one
    five-point little-endian ring is read through shapely, or refused with a
    ValueError naming it."""
    count = len(geometries)
    parts = []
    slow = []
    base = shapely.geometry.base.BaseGeometry
    placeholder = bytes(_WKB_SIZE)
    for position, geometry in enumerate(geometries):
        blob = b""
        if isinstance(geometry, base):
            try:
                blob = geometry.wkb
            except Exception:  # some GEOS versions cannot write an empty geometry: the slow path names it
                pass
        if len(blob) != _WKB_SIZE:
            slow.append(position)
            blob = placeholder
        parts.append(blob)
    blobs = _np.frombuffer(b"".join(parts), dtype=_np.uint8).reshape(count, _WKB_SIZE)
    head = blobs[:, :_WKB_HEAD]
    counts = head[:, 1:].copy().view("<u4")     # type, rings, points
    fast = (head[:, 0] == 1) & (counts[:, 0] == 3) & (counts[:, 1] == 1) & (counts[:, 2] == 5)
    rows = blobs[:, _WKB_HEAD:].copy().view("<f8")[:, :8]
    for position in sorted(set(slow) | set(_np.flatnonzero(~fast).tolist())):
        geometry = geometries[position]
        reason = _describe(geometry, shapely)
        if reason is not None:
            # An earlier row whose corners are wrong is named first.
            _check_outline(rows[:position], names)
            raise ValueError(f"{names(position)} {reason}")
        # A polygon of four corners that was not 2D little-endian (a z
        # coordinate, say): its x and y as shapely reads them.
        ring = geometry.exterior.coords
        rows[position] = [value for point in ring[:4] for value in point[:2]]
    return rows


def _check_outline(rows, names):
    """ValueError naming the first row whose four corners are not four
    distinct finite points around an outline that does not cross or touch
    itself (shapely calls such a polygon invalid; obbsat would decide the hull
    of a self-crossing outline, GEOS something else). Orientations are
    computed in float64 on coordinate differences: a quad a rounding away from
    touching itself can go either way."""
    finite = _np.isfinite(rows).all(axis=1)
    if not finite.all():
        raise ValueError(f"{names(int(_np.flatnonzero(~finite)[0]))} has a coordinate that is NaN or infinite")
    points = rows.reshape(-1, 4, 2)
    for a, b in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)):
        same = (points[:, a] == points[:, b]).all(axis=1)
        if same.any():
            raise ValueError(f"{names(int(_np.flatnonzero(same)[0]))} repeats a corner: "
                             f"corners {a} and {b} are both {tuple(points[_np.flatnonzero(same)[0], a])}")
    for sides in (((0, 1), (2, 3)), ((1, 2), (3, 0))):
        meet = _sides_meet(points, *sides)
        if meet.any():
            first = int(_np.flatnonzero(meet)[0])
            raise ValueError(f"{names(first)} has an outline that crosses or touches itself "
                             f"(sides {sides[0]} and {sides[1]} meet)")


def _orientation(p, q, r):
    return _np.sign((q[:, 0] - p[:, 0]) * (r[:, 1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[:, 0] - p[:, 0]))


def _between(p, q, r):
    """Whether r, collinear with segment pq, lies on it (its box)."""
    return ((_np.minimum(p[:, 0], q[:, 0]) <= r[:, 0]) & (r[:, 0] <= _np.maximum(p[:, 0], q[:, 0]))
            & (_np.minimum(p[:, 1], q[:, 1]) <= r[:, 1]) & (r[:, 1] <= _np.maximum(p[:, 1], q[:, 1])))


def _sides_meet(points, first, second):
    """Per quad: whether the closed sides ``first`` and ``second`` (corner index pairs) share a point."""
    p, q = points[:, first[0]], points[:, first[1]]
    r, s = points[:, second[0]], points[:, second[1]]
    o1, o2 = _orientation(p, q, r), _orientation(p, q, s)
    o3, o4 = _orientation(r, s, p), _orientation(r, s, q)
    crossing = (o1 * o2 < 0) & (o3 * o4 < 0)
    touching = (((o1 == 0) & _between(p, q, r)) | ((o2 == 0) & _between(p, q, s))
                | ((o3 == 0) & _between(r, s, p)) | ((o4 == 0) & _between(r, s, q)))
    return crossing | touching


def _corners_and_labels(geometries, what="geometry"):
    """``(corners, labels)``: float64 (N, 8) corners and the index labels of
    a GeoSeries or GeoDataFrame (None for any other sequence, whose rows are
    named by position)."""
    shapely = _shapely()
    series = _as_geoseries(geometries)
    if series is not None:
        labels = series.index.to_numpy()
        values = list(series.array)
        names = lambda position: f"{what} {labels[position]!r} (position {position})"  # noqa: E731
    else:
        if isinstance(geometries, shapely.geometry.base.BaseGeometry) or isinstance(geometries, (str, bytes)):
            raise TypeError(f"{what}: expected a sequence of shapely Polygons, a GeoSeries or a GeoDataFrame, "
                            f"got one {type(geometries).__name__}")
        labels = None
        values = list(geometries)
        names = lambda position: f"{what} {position}"  # noqa: E731
    corners = _rows(values, names, shapely)
    _check_outline(corners, names)
    return corners, labels


def corners_from_shapely(geometries):
    """The corners of each footprint as obbsat takes them: float64 (N, 8),
    rows ``UL, UR, LR, LL`` (x, y each), the first four coordinates of each
    exterior ring in ring order, exactly as stored.

    ``geometries`` is a sequence (list, tuple, numpy object array) of shapely
    Polygons, or a GeoSeries, or a GeoDataFrame (its active geometry column).
    Each must be a Polygon whose exterior ring has four corners (five
    coordinates, closed, as shapely keeps every ring), four distinct points
    around an outline that neither crosses nor touches itself, with no
    interior ring and every coordinate finite. Either winding. A z coordinate
    is dropped. Raw coordinate lists are not taken: they are already corners
    (``np.asarray(...).reshape(-1, 8)``).

    Raises ``ValueError`` naming the first geometry that is not one and why:
    ``geometry 3 is a MultiPolygon, expected a Polygon of 4 corners`` (by
    position), or for a GeoSeries by index label and position, ``geometry
    'b' (position 1) has 5 corners, expected 4``. ``ImportError`` without
    shapely.

    Cost: one well-known-binary export per geometry (a few microseconds
    each in shapely 1.8), then numpy.

    >>> from shapely.geometry import Polygon, box
    >>> obbsat.geo.corners_from_shapely([box(0, 0, 2, 1)])     # box() runs counter-clockwise from (2, 0)
    array([[2., 0., 2., 1., 0., 1., 0., 0.]])
    >>> obbsat.geo.corners_from_shapely([Polygon([(0, 0), (1, 0), (1, 1), (0.5, 2), (0, 1)])])
    Traceback (most recent call last):
    ...
    ValueError: geometry 0 has 5 corners, expected 4
    """
    return _corners_and_labels(geometries)[0]


def corners_from_geoseries(geoseries):
    """:func:`corners_from_shapely` of a GeoSeries or a GeoDataFrame (its
    active geometry column), which names a bad row by its index label. Row
    ``i`` of the result is the footprint at position ``i`` (``.iloc[i]``).

    >>> import geopandas
    >>> from shapely.geometry import box, Point
    >>> obbsat.geo.corners_from_geoseries(geopandas.GeoSeries([box(0, 0, 1, 1)], index=["a"]))
    array([[1., 0., 1., 1., 0., 1., 0., 0.]])
    >>> obbsat.geo.corners_from_geoseries(geopandas.GeoSeries([box(0, 0, 1, 1), Point(0, 0)], index=["a", "b"]))
    Traceback (most recent call last):
    ...
    ValueError: geometry 'b' (position 1) is a Point, expected a Polygon of 4 corners
    """
    if _as_geoseries(geoseries) is None:
        raise TypeError(f"corners_from_geoseries: expected a GeoSeries or a GeoDataFrame, "
                        f"got {type(geoseries).__name__}")
    return _corners_and_labels(geoseries)[0]


def _corner_array(corners):
    """The corners as float64 (N, 8), checked finite."""
    array = _np.asarray(corners)
    if array.dtype.kind not in "fiu":
        raise TypeError(f"corners: expected real numbers, got dtype {array.dtype}")
    if not ((array.ndim == 2 and array.shape[1] == 8) or (array.ndim == 3 and array.shape[1:] == (4, 2))):
        raise ValueError(f"corners: expected shape (N, 8) or (N, 4, 2) (UL, UR, LR, LL), got {array.shape}")
    rows = _np.ascontiguousarray(array.reshape(len(array), 8), dtype=_np.float64)
    finite = _np.isfinite(rows).all(axis=1)
    if not finite.all():
        raise ValueError(f"corners: row {int(_np.flatnonzero(~finite)[0])} has a coordinate that is NaN or infinite")
    return rows


def to_shapely(corners):
    """A shapely Polygon per row of ``corners`` ((N, 8) or (N, 4, 2), UL,
    UR, LR, LL), as a list: the ring UL, UR, LR, LL, UL, each coordinate the
    float64 of the row (float32 input is widened exactly), so
    ``corners_from_shapely(to_shapely(c))`` is ``c`` bit for bit. Nothing
    about the shape is checked beyond finite coordinates.

    >>> [p.wkt for p in obbsat.geo.to_shapely(np.array([[0, 1, 2, 1, 2, 0, 0, 0]]))]
    ['POLYGON ((0 1, 2 1, 2 0, 0 0, 0 1))']
    """
    shapely = _shapely()
    rows = _corner_array(corners)
    blobs = _np.empty((len(rows), _WKB_SIZE), dtype=_np.uint8)
    blobs[:, 0] = 1
    blobs[:, 1:_WKB_HEAD] = _np.frombuffer(_np.array([3, 1, 5], dtype="<u4").tobytes(), dtype=_np.uint8)
    ring = _np.concatenate([rows, rows[:, :2]], axis=1).astype("<f8")
    blobs[:, _WKB_HEAD:] = ring.view(_np.uint8).reshape(len(rows), 80)
    loads = shapely.wkb.loads
    return [loads(blob.tobytes()) for blob in blobs]


def to_geoseries(corners, index=None, crs=None):
    """:func:`to_shapely` as a ``geopandas.GeoSeries`` with the given index
    and coordinate reference system (needs geopandas).

    >>> obbsat.geo.to_geoseries(np.array([[0, 1, 2, 1, 2, 0, 0, 0]]), index=["a"], crs="EPSG:32633").crs.to_epsg()
    32633
    """
    geopandas = _geopandas()
    return geopandas.GeoSeries(to_shapely(corners), index=index, crs=crs)


def sjoin_pairs(left, right=None, method="exact", backend="auto", threads=1):
    """The rows ``geopandas.sjoin(left, right, predicate="intersects")``
    relates, as two arrays ``(left_index, right_index)``: the footprints'
    corners (:func:`corners_from_shapely`) through one
    :func:`obbsat.find_pairs` query.

    ``left`` and ``right`` are what :func:`corners_from_shapely` takes (a
    GeoSeries, a GeoDataFrame, a sequence of Polygons), or float corner
    arrays (N, 8) / (N, 4, 2). For a GeoSeries or a GeoDataFrame the arrays
    hold its index labels (sjoin's ``index_right`` and the joined frame's
    index); for anything else, 0-based positions.

    With ``right``: every (i, j) of left row i and right row j that collide.
    Without: what ``sjoin(left, left)`` gives, every ordered pair of rows of
    ``left`` that collide, both (i, j) and (j, i), and (i, i) for every row (a
    footprint meets itself). Use :func:`obbsat.find_pairs` on the corners for
    the pairs i < j only. Either way the pairs come sorted by left position,
    then right position (sjoin's row order is not promised; compare as sets).

    ``method="exact"`` (the default) reports exactly the pairs of closed
    quadrilaterals that share a point, touching included, which is what
    GEOS's ``intersects`` answers for such polygons; the other corner
    methods (:func:`obbsat.methods`) trade that for speed. ``backend`` and
    ``threads`` as in :func:`obbsat.find_pairs`.

    >>> from shapely.geometry import box
    >>> import geopandas
    >>> left = geopandas.GeoDataFrame(geometry=[box(0, 0, 1, 1), box(5, 5, 6, 6)], index=["a", "b"])
    >>> right = geopandas.GeoSeries([box(1, 0, 2, 1), box(0.5, 0.5, 5, 5)], index=[10, 20])
    >>> obbsat.geo.sjoin_pairs(left, right)
    (array(['a', 'a', 'b'], dtype=object), array([10, 20, 20]))
    """
    left_corners, left_labels = _input(left, "left")
    if right is None:
        found = _obbsat.find_pairs(left_corners, method=method, backend=backend, threads=threads)
        rows = _np.arange(len(left_corners), dtype=_np.intp)
        first = found[:, 0].astype(_np.intp)
        second = found[:, 1].astype(_np.intp)
        left_rows = _np.concatenate([first, second, rows])
        right_rows = _np.concatenate([second, first, rows])
        order = _np.lexsort((right_rows, left_rows))
        left_rows, right_rows = left_rows[order], right_rows[order]
        right_labels = left_labels
    else:
        right_corners, right_labels = _input(right, "right")
        found = _obbsat.find_pairs(left_corners, right_corners, method=method, backend=backend, threads=threads)
        left_rows = found[:, 0].astype(_np.intp)
        right_rows = found[:, 1].astype(_np.intp)
    return (left_rows if left_labels is None else left_labels[left_rows],
            right_rows if right_labels is None else right_labels[right_rows])


def _input(rects, what):
    """``(corners, labels)`` of one side of :func:`sjoin_pairs`: a numeric
    array is taken as corners, anything else converted from shapely."""
    if isinstance(rects, _np.ndarray) and rects.dtype.kind in "fiu":
        return rects, None
    return _corners_and_labels(rects, what)
