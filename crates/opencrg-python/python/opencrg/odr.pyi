"""OpenDRIVE maps with OpenCRG surfaces: height, normal and friction at world points."""

from os import PathLike
from typing import Union, overload

import numpy as np
import numpy.typing as npt

_Path = Union[str, PathLike[str]]
_Floats = npt.NDArray[np.float64]
_ArrayLike = npt.ArrayLike

class Map:
    """An OpenDRIVE map ready to answer at world points (picklable: it is read again)."""

    def __init__(self, path: _Path) -> None:
        """Reads the map in `path` (its CRG files relative to its folder)."""
    @property
    def path(self) -> str: ...
    @property
    def road_ids(self) -> list[str]:
        """The roads' ids, in the file's order (`ground`'s `road` indexes this list)."""
    @property
    def road_lengths(self) -> list[float]: ...
    @property
    def junctions(self) -> int: ...
    def check(self) -> list[str]:
        """The checker's findings, one text each (empty when clean)."""
    def ground(self, x: _ArrayLike, y: _ArrayLike) -> dict[str, object]:
        """`z`, `friction`, `s`, `t` (NaN off every road), `road` (-1 off every road), `lane`,
        each a float or int for scalar inputs, else an array of the inputs' shape."""
    @overload
    def normal(self, x: float, y: float) -> tuple[float, float, float]: ...
    @overload
    def normal(self, x: _ArrayLike, y: _ArrayLike) -> tuple[_Floats, _Floats, _Floats]: ...
    def to_mesh(
        self, max_error: float | None = None, roads: list[str] | None = None, lanes: list[str] | None = None,
        *, max_memory: int | str | None = None
    ) -> dict[str, object]:
        """The drivable surface as numpy arrays: positions, normals, texcoords, triangles, per vertex
        friction, road, lane, s, t; groups (one dict per lane of a lane section)."""
    def write_mesh(
        self, path: _Path, max_error: float | None = None, roads: list[str] | None = None,
        lanes: list[str] | None = None, *, max_memory: int | str | None = None
    ) -> None:
        """Writes the mesh of to_mesh as .glb, .obj, .ply or .stl."""
    @overload
    def st_to_xyz(self, road: str, s: float, t: float) -> tuple[float, float, float]: ...
    @overload
    def st_to_xyz(self, road: str, s: _ArrayLike, t: _ArrayLike) -> tuple[_Floats, _Floats, _Floats]: ...
