from typing import Any, Literal, TypeVar, overload

import numpy as np
import numpy.typing as npt

from . import geo as geo
from . import testing as testing
from ._core import FindPairsStats as FindPairsStats
from ._core import PoseRecords as PoseRecords
from ._core import PoseRecords64 as PoseRecords64
from ._core import RectRecords as RectRecords
from ._core import RectRecords64 as RectRecords64
from ._core import UnsupportedBackendError as UnsupportedBackendError

__version__: str

_Out = TypeVar("_Out", npt.NDArray[np.bool_], npt.NDArray[np.uint8])
# None: float64 data in float64, everything else in float32.
_Precision = Literal["float32", "float64"] | None
# Every store records() builds: float32 and double, corners and poses.
_Store = RectRecords | PoseRecords | RectRecords64 | PoseRecords64
_S = TypeVar("_S", RectRecords, PoseRecords, RectRecords64, PoseRecords64)

def aligned(array: npt.ArrayLike, alignment: int = ...) -> np.ndarray: ...
def methods(poses: bool = ...) -> list[str]: ...
def backends(compiled: bool = ...) -> list[str]: ...
def resolved_backend(backend: str | None = ...) -> str: ...
@overload
def records(rects: _S, *, precision: _Precision = ...) -> _S: ...
@overload
def records(rects: npt.ArrayLike, *, precision: _Precision = ...) -> _Store: ...
def collide(
    rects: npt.ArrayLike | _Store,
    pairs: npt.ArrayLike,
    method: str | None = ...,
    backend: str | None = ...,
    threads: int = ...,
    out: _Out | None = ...,
    *,
    precision: _Precision = ...,
) -> npt.NDArray[np.bool_] | _Out: ...
def colliding_pairs(
    rects: npt.ArrayLike | _Store,
    pairs: npt.ArrayLike,
    method: str | None = ...,
    backend: str | None = ...,
    threads: int = ...,
    *,
    precision: _Precision = ...,
) -> npt.NDArray[np.integer[Any]]: ...
def collide_stream(
    a: npt.ArrayLike,
    b: npt.ArrayLike,
    method: str | None = ...,
    backend: str | None = ...,
    threads: int = ...,
    out: _Out | None = ...,
    *,
    precision: _Precision = ...,
) -> npt.NDArray[np.bool_] | _Out: ...
def corners_of_poses(
    poses: npt.ArrayLike | PoseRecords | PoseRecords64, backend: str | None = ..., *, precision: _Precision = ...
) -> npt.NDArray[np.float32] | npt.NDArray[np.float64]: ...
def find_pairs(
    boxes: npt.ArrayLike | _Store,
    against: npt.ArrayLike | _Store | None = ...,
    *,
    method: str | None = ...,
    backend: str | None = ...,
    threads: int = ...,
    categories: npt.ArrayLike | None = ...,
    masks: npt.ArrayLike | None = ...,
    groups: npt.ArrayLike | None = ...,
    against_categories: npt.ArrayLike | None = ...,
    against_masks: npt.ArrayLike | None = ...,
    against_groups: npt.ArrayLike | None = ...,
    precision: _Precision = ...,
) -> npt.NDArray[np.uint32]: ...

class PairFinder:
    def __init__(
        self,
        method: str | None = ...,
        backend: str | None = ...,
        threads: int = ...,
        *,
        events: bool = ...,
        precision: _Precision = ...,
    ) -> None: ...
    def find(
        self,
        boxes: npt.ArrayLike | _Store,
        against: npt.ArrayLike | _Store | None = ...,
        *,
        ids: npt.ArrayLike | None = ...,
        against_ids: npt.ArrayLike | None = ...,
        categories: npt.ArrayLike | None = ...,
        masks: npt.ArrayLike | None = ...,
        groups: npt.ArrayLike | None = ...,
        against_categories: npt.ArrayLike | None = ...,
        against_masks: npt.ArrayLike | None = ...,
        against_groups: npt.ArrayLike | None = ...,
    ) -> npt.NDArray[np.uint32]: ...
    def find_contacts(
        self,
        boxes: npt.ArrayLike | RectRecords | PoseRecords | RectRecords64 | PoseRecords64,
        against: npt.ArrayLike | RectRecords | PoseRecords | RectRecords64 | PoseRecords64 | None = ...,
        *,
        ids: npt.ArrayLike | None = ...,
        against_ids: npt.ArrayLike | None = ...,
        categories: npt.ArrayLike | None = ...,
        masks: npt.ArrayLike | None = ...,
        groups: npt.ArrayLike | None = ...,
        against_categories: npt.ArrayLike | None = ...,
        against_masks: npt.ArrayLike | None = ...,
        against_groups: npt.ArrayLike | None = ...,
    ) -> tuple[npt.NDArray[np.uint32], Contacts]: ...
    @property
    def stats(self) -> FindPairsStats: ...
    @property
    def events(self) -> bool: ...
    # Row pairs (uint32), or id pairs (uint64) when the last find() had ids.
    def began(self) -> npt.NDArray[np.uint32] | npt.NDArray[np.uint64]: ...
    def ended(self) -> npt.NDArray[np.uint32] | npt.NDArray[np.uint64]: ...

def bounds(
    boxes: npt.ArrayLike | _Store, *, precision: _Precision = ...
) -> npt.NDArray[np.float32]: ...

class Contacts:
    normals: npt.NDArray[np.float32]
    depths: npt.NDArray[np.float32]
    counts: npt.NDArray[np.uint8]
    points: npt.NDArray[np.float32]
    separations: npt.NDArray[np.float32]
    features: npt.NDArray[np.uint32]
    def __init__(self, columns: dict[str, Any]) -> None: ...
    def __len__(self) -> int: ...

class Distances:
    distance: npt.NDArray[np.float32]
    a: npt.NDArray[np.float32]
    b: npt.NDArray[np.float32]
    def __init__(self, columns: dict[str, Any]) -> None: ...
    def __len__(self) -> int: ...

def contacts(
    boxes: npt.ArrayLike | RectRecords | PoseRecords,
    pairs: npt.ArrayLike,
    *,
    margin: float = ...,
    backend: str | None = ...,
    threads: int = ...,
    precision: str | None = ...,
) -> Contacts: ...
def contacts_stream(
    a: npt.ArrayLike, b: npt.ArrayLike, *, margin: float = ..., backend: str | None = ..., threads: int = ...,
    precision: str | None = ...,
) -> Contacts: ...
def distances(
    boxes: npt.ArrayLike | RectRecords | PoseRecords, pairs: npt.ArrayLike, *, backend: str | None = ..., threads: int = ...,
    precision: str | None = ...,
) -> Distances: ...
def distances_stream(
    a: npt.ArrayLike, b: npt.ArrayLike, *, backend: str | None = ..., threads: int = ...,
    precision: str | None = ...,
) -> Distances: ...
def find_contacts(
    boxes: npt.ArrayLike | RectRecords | PoseRecords | RectRecords64 | PoseRecords64,
    *,
    method: str | None = ...,
    margin: float = ...,
    backend: str | None = ...,
    threads: int = ...,
    precision: str | None = ...,
) -> tuple[npt.NDArray[np.uint32], Contacts]: ...
