from typing import Any, Literal

import dask.array as da
import numpy.typing as npt

from ._core import PoseRecords, PoseRecords64, RectRecords, RectRecords64

_Precision = Literal["float32", "float64"] | None

def shared_records(
    rects: npt.ArrayLike | RectRecords | PoseRecords | RectRecords64 | PoseRecords64,
    client: Any = ...,
    *,
    precision: _Precision = ...,
) -> Any: ...
def collide(
    rects: Any, pairs: da.Array, method: str | None = ..., backend: str | None = ..., threads: int = ..., client: Any = ...,
    *, precision: _Precision = ...
) -> da.Array: ...
def colliding_pairs(
    rects: Any, pairs: da.Array, method: str | None = ..., backend: str | None = ..., threads: int = ..., client: Any = ...,
    *, precision: _Precision = ...
) -> da.Array: ...
def find_pairs(
    boxes: Any,
    tile: float,
    against: Any = ...,
    *,
    method: str | None = ...,
    backend: str | None = ...,
    threads: int = ...,
    extent: tuple[float, float, float, float] | None = ...,
) -> da.Array: ...
