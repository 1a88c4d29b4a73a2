from typing import Any

import dask.array as da
import numpy.typing as npt

from ._core import PoseRecords, RectRecords

def shared_records(rects: npt.ArrayLike | RectRecords | PoseRecords, client: Any = ...) -> Any: ...
def collide(
    rects: Any, pairs: da.Array, method: str | None = ..., backend: str | None = ..., threads: int = ..., client: Any = ...
) -> da.Array: ...
def colliding_pairs(
    rects: Any, pairs: da.Array, method: str | None = ..., backend: str | None = ..., threads: int = ..., client: Any = ...
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
