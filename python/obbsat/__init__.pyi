from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

from . import testing as testing
from ._core import RectRecords as RectRecords
from ._core import UnsupportedBackendError as UnsupportedBackendError

__version__: str

_Out = TypeVar("_Out", npt.NDArray[np.bool_], npt.NDArray[np.uint8])

def methods() -> list[str]: ...
def backends(compiled: bool = ...) -> list[str]: ...
def resolved_backend(backend: str = ...) -> str: ...
def records(rects: npt.ArrayLike | RectRecords) -> RectRecords: ...
def collide(
    rects: npt.ArrayLike | RectRecords,
    pairs: npt.ArrayLike,
    method: str = ...,
    backend: str = ...,
    threads: int = ...,
    out: _Out | None = ...,
) -> npt.NDArray[np.bool_] | _Out: ...
def colliding_pairs(
    rects: npt.ArrayLike | RectRecords,
    pairs: npt.ArrayLike,
    method: str = ...,
    backend: str = ...,
    threads: int = ...,
) -> npt.NDArray[np.integer[Any]]: ...
def collide_stream(
    a: npt.ArrayLike,
    b: npt.ArrayLike,
    method: str = ...,
    backend: str = ...,
    threads: int = ...,
    out: _Out | None = ...,
) -> npt.NDArray[np.bool_] | _Out: ...
