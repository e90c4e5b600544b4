"""OpenCRG road surfaces: the reference C library's answers, numpy-vectorised, on a Rust core."""

from os import PathLike
from typing import Callable, NamedTuple, Optional, Union, overload

import numpy as np
import numpy.typing as npt

from . import odr as odr

__version__: str

OPTIONS: list[str]
MODIFIERS: list[str]
EVALUATIONS: list[str]

ISO8608_N0: float
ISO8608_LIMITS: list[float]
ISO8608_CLASSES: str

BORDER_NONE: int
BORDER_EX_ZERO: int
BORDER_EX_KEEP: int
BORDER_REPEAT: int
BORDER_REFLECT: int
REFLINE_EXTRAPOLATE: int
REFLINE_CLOSE_TRACK: int
CURV_LATERAL: int
CURV_REFLINE: int
GRID_NAN_KEEP: int
GRID_NAN_SET_ZERO: int
GRID_NAN_KEEP_LAST: int

_Path = Union[str, PathLike[str]]
_Floats = npt.NDArray[np.float64]
_ArrayLike = npt.ArrayLike
_Setting = Union[int, float, bool]

class CrgError(Exception):
    """Base of the errors of this module."""

class FormatError(CrgError, ValueError):
    """A road file whose content is wrong (names the file, line and field)."""

class CheckError(CrgError):
    """A road refused by `Road.check()`."""

class RequestError(CrgError, ValueError):
    """A request refused before any work: a parameter out of range, a size beyond the memory limit, a setting or option the library does not take."""

class TooLargeError(RequestError, MemoryError):
    """A request that would take more memory than it may (max_memory=, or half of what the system has)."""

class OutOfRangeError(RequestError):
    """A value the request does not take: a parameter out of range, a setting or option refused, a road without what the request needs."""

_Memory = Union[int, str]

class ReferenceLine(NamedTuple):
    """The reference line at each cross section (read-only float64 arrays)."""

    u: _Floats
    x: _Floats
    y: _Floats
    phi: _Floats
    z: _Floats

class Road:
    """A road loaded from a CRG file (LRFI, LDFI, KRBI or KDBI), following its file references.

    ``compat``: ``"2.0.1"`` (releases 2.0.1/1.2.0) or ``"upstream"`` (the default); when
    not given, the environment variable ``OPENCRG_COMPAT`` decides, as in the C library.
    ``in_place``: whether a binary road's grid is read in place from its file (its values
    read where evaluation reaches them, through the system's file cache, into a bounded
    cache of ``cache`` bytes): ``True``, ``False``, a size such as ``"256M"`` from which on,
    or ``None`` (``OPENCRG_IN_PLACE``, else from 1 GiB on). A road read in place pickles as
    its file and how it was read, not its grid.
    Raises ``FileNotFoundError`` for a missing file and ``FormatError`` for a bad one.
    """

    def __init__(
        self,
        path: _Path,
        *,
        compat: Optional[str] = None,
        in_place: Union[bool, int, str, None] = None,
        cache: Union[int, str, None] = None,
    ) -> None: ...
    @property
    def in_place(self) -> bool:
        """Whether the grid is read in place from the file (else it is in memory)."""
    @staticmethod
    def from_bytes(data: bytes, name: str = "<bytes>", *, compat: Optional[str] = None) -> Road: ...
    def check(self) -> None:
        """Checks the road as crgCheck does; raises CheckError when it fails."""
    def apply_modifiers(self) -> None:
        """Applies the modifiers to the data (contact points follow)."""
    def set_modifier(self, name: str, value: _Setting) -> None:
        """Sets one modifier (see MODIFIERS); it acts at the next apply_modifiers()."""
    def remove_modifier(self, name: str) -> None: ...
    def clear_modifiers(self) -> None: ...
    @property
    def modifiers(self) -> dict[str, _Setting]: ...
    @property
    def options(self) -> dict[str, _Setting]: ...
    def write(self, path: _Path, format: str = "KDBI") -> None:
        """Writes the road in KDBI, KRBI, LDFI or LRFI."""
    @property
    def u_range(self) -> tuple[float, float]: ...
    @property
    def v_range(self) -> tuple[float, float]: ...
    @property
    def increments(self) -> tuple[float, float]: ...
    @property
    def closed_track(self) -> Optional[tuple[float, float]]: ...
    @property
    def closed_track_report(self) -> tuple[bool, float, float]:
        """(closed, u begin, u end) as the C API reports them: the u range found the last time
        the line could be closed ((0.0, 0.0) if never), also when modifiers have since opened it."""
    @property
    def compat(self) -> str: ...
    @property
    def path(self) -> str: ...
    @property
    def format(self) -> str: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def grid(self) -> npt.NDArray[np.float32]:
        """Elevation grid (cross sections x long sections), NaN kept, read-only."""
    @property
    def v(self) -> _Floats:
        """v of each long section."""
    @property
    def reference_line(self) -> ReferenceLine: ...
    @property
    def header(self) -> dict[str, object]:
        """comments, road_crg, options, modifiers, mpro, references, format, channels."""
    @overload
    def uv_to_z(self, u: float, v: float, **options: _Setting) -> float: ...
    @overload
    def uv_to_z(self, u: _ArrayLike, v: _ArrayLike, **options: _Setting) -> _Floats: ...
    @overload
    def xy_to_z(self, x: float, y: float, **options: _Setting) -> float: ...
    @overload
    def xy_to_z(self, x: _ArrayLike, y: _ArrayLike, **options: _Setting) -> _Floats: ...
    @overload
    def uv_to_xy(self, u: float, v: float, **options: _Setting) -> tuple[float, float]: ...
    @overload
    def uv_to_xy(self, u: _ArrayLike, v: _ArrayLike, **options: _Setting) -> tuple[_Floats, _Floats]: ...
    @overload
    def xy_to_uv(self, x: float, y: float, **options: _Setting) -> tuple[float, float]: ...
    @overload
    def xy_to_uv(self, x: _ArrayLike, y: _ArrayLike, **options: _Setting) -> tuple[_Floats, _Floats]: ...
    @overload
    def uv_to_pk(self, u: float, v: float, **options: _Setting) -> tuple[float, float]: ...
    @overload
    def uv_to_pk(self, u: _ArrayLike, v: _ArrayLike, **options: _Setting) -> tuple[_Floats, _Floats]: ...
    @overload
    def xy_to_pk(self, x: float, y: float, **options: _Setting) -> tuple[float, float]: ...
    @overload
    def xy_to_pk(self, x: _ArrayLike, y: _ArrayLike, **options: _Setting) -> tuple[_Floats, _Floats]: ...
    @overload
    def uv_to_normal(self, u: float, v: float, **options: _Setting) -> tuple[float, float, float, float]: ...
    @overload
    def uv_to_normal(
        self, u: _ArrayLike, v: _ArrayLike, **options: _Setting
    ) -> tuple[_Floats, _Floats, _Floats, _Floats]: ...
    @overload
    def xy_to_normal(self, x: float, y: float, **options: _Setting) -> tuple[float, float, float, float]: ...
    @overload
    def xy_to_normal(
        self, x: _ArrayLike, y: _ArrayLike, **options: _Setting
    ) -> tuple[_Floats, _Floats, _Floats, _Floats]: ...

    def to_mesh(
        self, u: tuple[float, float] | None = None, v: tuple[float, float] | None = None,
        max_error: float | None = None, *, max_memory: _Memory | None = None, **options: _Setting
    ) -> dict[str, np.ndarray]:
        """The surface at the grid nodes, or simplified within max_error (m): positions, normals, texcoords, triangles, u, v (numpy)."""
    def write_mesh(
        self, path: str | PathLike[str], u: tuple[float, float] | None = None,
        v: tuple[float, float] | None = None, max_error: float | None = None, *,
        max_memory: _Memory | None = None, **options: _Setting
    ) -> None:
        """Writes the surface mesh (simplified within max_error when given) as .obj, .stl, .ply or .glb."""
    def roughness(self, tracks: list[float] | None = None, segment: float = 100.0) -> list[dict[str, object]]:
        """IRI (m/km, whole track and per segment) and ISO 8608 PSD class of wheel tracks at v."""
    def cut(self, u: tuple[float, float], v: tuple[float, float] | None = None) -> Road:
        """The part between u = (from, to) (and v): the grid nodes inside, the surface where it was."""
    def flip(self) -> Road:
        """The same road driven the other way (u reversed, v mirrored), the surface where it was."""
    def append(self, other: Road, *, max_memory: _Memory | None = None) -> Road:
        """`other` continuing this road from its end point, heading and height."""
    def resample(
        self, u_inc: float | None = None, v_inc: float | None = None, *, max_memory: _Memory | None = None
    ) -> Road:
        """The surface on a new grid, each node evaluated by the library."""
    def filter(
        self,
        *,
        gauss: float | None = None,
        median: int | None = None,
        limit: tuple[float, float] | None = None,
        fill_nan: bool = False,
        max_memory: _Memory | None = None,
    ) -> Road:
        """The grid filtered by exactly one of gauss (sigma, m), median (N x N), limit, fill_nan."""
    def slope(self, action: str) -> Road:
        """The slope moved: "extract" (grid to line), "apply" (line to grid) or "remove"."""
    def banking(self, action: str) -> Road:
        """The banking moved: "extract", "apply" or "remove"."""
    @property
    def global_origin(self) -> tuple[float, float, float, float]:
        """(x, y, z, phi): the local frame in the projected frame; setting it moves the frame, not the road."""
    @global_origin.setter
    def global_origin(self, origin: tuple[float, float, float, float]) -> None: ...
    @property
    def map_projection(self) -> dict[str, object] | None:
        """The $ROAD_CRG_MPRO section resolved (ellipsoids, transformation, projection), or None."""
    @overload
    def xyz_to_enh(self, x: float, y: float, z: float) -> tuple[float, float, float]: ...
    @overload
    def xyz_to_enh(self, x: _ArrayLike, y: _ArrayLike, z: _ArrayLike) -> tuple[_Floats, _Floats, _Floats]: ...
    @overload
    def enh_to_xyz(self, e: float, n: float, h: float) -> tuple[float, float, float]: ...
    @overload
    def enh_to_xyz(self, e: _ArrayLike, n: _ArrayLike, h: _ArrayLike) -> tuple[_Floats, _Floats, _Floats]: ...
    @overload
    def xyz_to_llh(self, x: float, y: float, z: float) -> tuple[float, float, float]: ...
    @overload
    def xyz_to_llh(self, x: _ArrayLike, y: _ArrayLike, z: _ArrayLike) -> tuple[_Floats, _Floats, _Floats]: ...
    @overload
    def llh_to_xyz(self, lat: float, lon: float, alt: float) -> tuple[float, float, float]: ...
    @overload
    def llh_to_xyz(self, lat: _ArrayLike, lon: _ArrayLike, alt: _ArrayLike) -> tuple[_Floats, _Floats, _Floats]: ...

@overload
def iri(profile: _ArrayLike, dx: float) -> float:
    """The International Roughness Index (m/km, ASTM E1926) of elevations dx m apart."""
@overload
def iri(profile: _ArrayLike, dx: float, segment: float) -> tuple[float, _Floats]:
    """The IRI and the IRI of each segment (m) from the first sample (NaN: no step in it)."""

def psd(profile: _ArrayLike, dx: float) -> dict[str, object]:
    """Displacement PSD (Welch, third-octave bands) of elevations dx m apart and its ISO 8608 class."""

def generate(
    points: _ArrayLike | _Path,
    width: float,
    u_inc: float,
    v_inc: float,
    surface: Callable[[_Floats, _Floats], _ArrayLike] | Road | None = None,
    *,
    max_memory: _Memory | None = None,
) -> Road:
    """A road along a smooth line through the points (x, y[, z]); surface(u, v) on arrays of shape (nu, nv)."""

def import_points(
    cloud: _ArrayLike | _Path,
    u_inc: float,
    v_inc: float,
    *,
    refline: _ArrayLike | _Path | None = None,
    width: float | None = None,
    max_edge: float | None = None,
    fill_nan: bool = False,
    crop: tuple[tuple[float, float], tuple[float, float]] | None = None,
    max_memory: _Memory | None = None,
) -> Road:
    """A road from a point cloud (n, 3), gridded along refline (or a line fitted through the cloud); crop ((x0, x1), (y0, y1)) keeps the points within it."""

def read_points(path: _Path) -> _Floats:
    """The points of a CSV/XYZ, PLY or LAS/LAZ file, shape (n, 2) or (n, 3)."""

def compare(a: Road, b: Road) -> dict[str, object]:
    """b's surface against a's at a's grid nodes: max_difference, signed, at (u, v, x, y), rms, compared, only_in_a."""

def write_fmu(
    road: Union[str, PathLike[str]],
    path: Union[str, PathLike[str]],
    wheels: int = 4,
    fmi: int = 2,
    binaries: Optional[Union[str, PathLike[str]]] = None,
    *,
    road_outside: bool = False,
) -> dict[str, object]:
    """The road (a CRG file, or an OpenDRIVE map with its CRG files) packed as an FMU in
    `path`: FMI 2.0 or 3.0, model exchange and co-simulation, answering height, normal
    and friction under `wheels` wheels. FMU binaries from `binaries`, else
    $OPENCRG_FMU_BINARIES, else the package's own (wheels carry the Linux x86-64 one).
    With `road_outside`, a CRG file is named by its absolute path, not packed (the FMU's
    parameter roadFile names another). Returns identifier, resources, platforms, variables."""

class ContactPoint:
    """A point of evaluation: its own options and x/y search history.

    Answers equal the C library's calls made point by point, in order, on one contact
    point; NaN where a point is refused.
    """

    def __init__(self, road: Road, *, history: Optional[int] = None, **options: _Setting) -> None: ...
    @property
    def road(self) -> Road: ...
    @property
    def options(self) -> dict[str, _Setting]: ...
    @property
    def refused(self) -> Union[bool, npt.NDArray[np.bool_]]:
        """Which points the last evaluation refused: for numbers whether the C API's call
        refuses the point (its values are then NaN; a NaN answered is no refusal); for
        arrays a boolean array of their shape, true where a point was answered NaN."""
    def set_option(self, name: str, value: _Setting) -> None: ...
    def remove_option(self, name: str) -> None: ...
    def reset_options(self) -> None: ...
    def set_history(self, size: int) -> None: ...
    @overload
    def uv_to_z(self, u: float, v: float) -> float: ...
    @overload
    def uv_to_z(self, u: _ArrayLike, v: _ArrayLike) -> _Floats: ...
    @overload
    def xy_to_z(self, x: float, y: float) -> float: ...
    @overload
    def xy_to_z(self, x: _ArrayLike, y: _ArrayLike) -> _Floats: ...
    @overload
    def uv_to_xy(self, u: float, v: float) -> tuple[float, float]: ...
    @overload
    def uv_to_xy(self, u: _ArrayLike, v: _ArrayLike) -> tuple[_Floats, _Floats]: ...
    @overload
    def xy_to_uv(self, x: float, y: float) -> tuple[float, float]: ...
    @overload
    def xy_to_uv(self, x: _ArrayLike, y: _ArrayLike) -> tuple[_Floats, _Floats]: ...
    @overload
    def uv_to_pk(self, u: float, v: float) -> tuple[float, float]: ...
    @overload
    def uv_to_pk(self, u: _ArrayLike, v: _ArrayLike) -> tuple[_Floats, _Floats]: ...
    @overload
    def xy_to_pk(self, x: float, y: float) -> tuple[float, float]: ...
    @overload
    def xy_to_pk(self, x: _ArrayLike, y: _ArrayLike) -> tuple[_Floats, _Floats]: ...
    @overload
    def uv_to_normal(self, u: float, v: float) -> tuple[float, float, float, float]: ...
    @overload
    def uv_to_normal(self, u: _ArrayLike, v: _ArrayLike) -> tuple[_Floats, _Floats, _Floats, _Floats]: ...
    @overload
    def xy_to_normal(self, x: float, y: float) -> tuple[float, float, float, float]: ...
    @overload
    def xy_to_normal(self, x: _ArrayLike, y: _ArrayLike) -> tuple[_Floats, _Floats, _Floats, _Floats]: ...
