"""What every reader shares: the map type, length units, the limits of a measured surface and its checks."""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from memstribo.errors import DataFileError, InputError
from memstribo.surfaces.roughness import UNIFORM_RTOL, Profile
from memstribo.units import printable

#: length units accepted by ``unit`` and their size in metres
LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "μm": 1e-6, "nm": 1e-9, "A": 1e-10, "Å": 1e-10,
                "pm": 1e-12}

_TEXT = (".txt", ".csv", ".dat", ".xyz", ".asc")
_OWN = _TEXT + (".npy", ".zip")
#: instrument formats handed to SurfaceTopography (plus NanoScope's numbered extensions .001, .002, ...)
_ST_EXTENSIONS = (".di", ".spm", ".tif", ".tiff", ".opdx", ".opd", ".ibw", ".gwy", ".x3p", ".nc", ".sur", ".plu",
                  ".plux", ".mi", ".nid", ".nms", ".datx", ".sdf", ".stp", ".top", ".zon", ".frt", ".vk4", ".vk6",
                  ".vk7", ".lext", ".oir", ".poir", ".al3d", ".os3d", ".mdt", ".h5", ".mat", ".tmd", ".zmg",
                  ".dzi", ".jpk", ".ezd", ".nmm", ".mnt", ".bcr", ".bcrf", ".xyz")
SUPPORTED_EXTENSIONS = tuple(sorted(set(_OWN + _ST_EXTENSIONS))) + (".001 (NanoScope, any number)",)

#: x steps of a text profile that differ by less than this (relative) are rounding: the profile is uniform
_READER_UNIFORM_RTOL = 0.02

#: magnitude of Rq that suggests a wrong unit
_RQ_MIN, _RQ_MAX = 1e-12, 1e-3

#: largest height [m] of a measured surface, smallest lateral step and largest length [m]
_Z_MAX = 0.1
_DX_MIN, _LENGTH_MAX = 1e-12, 1.0

#: most points (pixels) of one profile or map memstribo reads (80 MB of heights)
MAX_POINTS = 10_000_000


@dataclass(frozen=True, eq=False)
class SurfaceMap:
    """A measured height map.

    Attributes
    ----------
    heights : numpy.ndarray
        Heights [m], shape (ny, nx); rows are scan lines along x.
    dx, dy : float
        Pixel sizes along x and y [m].
    name : str
        Short name.
    source : str
        Provenance: file, member, channel, calibration notes.
    channel : str
        Channel read.
    """

    heights: np.ndarray
    dx: float
    dy: float
    name: str = "map"
    source: str = ""
    channel: str = ""

    def __post_init__(self):
        h = np.array(self.heights, dtype=float)
        if h.ndim != 2 or min(h.shape) < 2:
            raise InputError(f"map '{self.name}': heights must have shape (ny, nx) with ny, nx >= 2 (got {h.shape}).")
        bad = int(np.count_nonzero(~np.isfinite(h)))
        if bad:
            raise DataFileError(f"map '{self.name}' has {bad} of {h.size} undefined (NaN/masked) pixels; memstribo does "
                                "not fill them silently: fill or crop them in your AFM software first.")
        peak = float(np.max(np.abs(h)))
        if peak > _Z_MAX:  # as a Profile refuses: heights that are not in metres
            raise InputError(f"map '{self.name}': heights reach {peak:.3g} m, more than {_Z_MAX:g} m: not a measured "
                             "surface, or the heights are not in metres.")
        for label, value in (("dx", self.dx), ("dy", self.dy)):
            if not (np.isfinite(value) and value > 0):
                raise InputError(f"map '{self.name}': {label} must be a positive length in m (got {value!r}).")
        h.setflags(write=False)
        object.__setattr__(self, "heights", h)
        object.__setattr__(self, "dx", float(self.dx))
        object.__setattr__(self, "dy", float(self.dy))

    @property
    def shape(self) -> tuple[int, int]:
        """(ny, nx)."""
        return self.heights.shape

    @property
    def physical_sizes(self) -> tuple[float, float]:
        """Scan size (nx dx, ny dy) [m]."""
        ny, nx = self.heights.shape
        return nx * self.dx, ny * self.dy

    def line_scans(self) -> list[Profile]:
        """One :class:`Profile` per row (scan line along x), unlevelled."""
        ny, nx = self.heights.shape
        x = np.arange(nx) * self.dx
        return [Profile(x=x, z=row, name=f"{self.name} line {i}", source=f"{self.source}; row {i}")
                for i, row in enumerate(self.heights)]


# --------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------


def _unit_factor(unit, what):
    if unit is None:
        return None
    key = str(unit).strip()
    if key not in LENGTH_UNITS:
        raise InputError(f"unknown length unit '{printable(unit)}' for {what}; allowed: "
                         f"{', '.join(sorted(set(LENGTH_UNITS)))}.")
    return LENGTH_UNITS[key]


def _check_magnitude(z, path, unit_used):
    zc = np.asarray(z, dtype=float)
    peak = float(np.max(np.abs(zc))) if zc.size else 0.0
    if peak > _Z_MAX:  # also keeps the squares below overflow
        raise DataFileError(f"{path}: heights read as {unit_used} reach {peak:.3g} m, more than {_Z_MAX:g} m: not a "
                            "measured surface, or the height unit is wrong. Give the file's unit with --unit "
                            "(m, mm, um, nm, A, pm).")
    if zc.size and np.ptp(zc) == 0:  # not a unit problem: nothing was measured
        raise DataFileError(f"{path}: every height is {float(zc.flat[0]):g} m: a constant surface has no roughness. "
                            "Allowed: measured heights that vary; check that the channel or column read is the "
                            "height.")
    if zc.ndim == 1:
        t = np.arange(zc.size) - (zc.size - 1) / 2
        r = zc - zc.mean()
        r = r - t * (np.dot(t, r) / np.dot(t, t))
    else:
        r = zc - zc.mean()
    rq = float(np.sqrt(np.mean(r ** 2)))
    if rq > _RQ_MAX or rq < _RQ_MIN:
        raise DataFileError(f"{path}: heights read as {unit_used} give Rq = {rq:.3g} m, outside the plausible range "
                            f"{_RQ_MIN:g}..{_RQ_MAX:g} m for a measured surface: the height unit is probably wrong. "
                            "Give the file's unit with --unit (m, mm, um, nm, A, pm).")


def _check_finite(array, path):
    bad = int(np.count_nonzero(~np.isfinite(array)))
    if bad:
        raise DataFileError(f"{path}: {bad} of {array.size} heights are NaN or undefined (masked); memstribo does not "
                            "fill them silently: fill or crop them in your AFM software, or give a complete profile.")


def _check_lateral(step, length, n, path, what="x step"):
    """A lateral step and length a measurement can have, and an array that fits in memory."""
    if n > MAX_POINTS:
        raise DataFileError(f"{path}: {n} points; memstribo reads at most {MAX_POINTS:,} per profile or map.")
    if not _DX_MIN <= step <= _LENGTH_MAX or length > _LENGTH_MAX:
        raise DataFileError(f"{path}: {what} {step:.3g} m over a length of {length:.3g} m is not a measured surface "
                            f"(allowed: steps of {_DX_MIN:g} m or more, {_LENGTH_MAX:g} m at most): the lateral unit "
                            "is probably wrong. Give the file's unit with --unit, or the size with --physical-size.")


def _profile_from_xz(x, z, path, name, source, unit, z_unit=None):
    """A Profile from x, z in the file's unit(s); uniform x (to rounding) is made exactly uniform."""
    factor = _unit_factor(unit or "m", str(path))
    z_factor = _unit_factor(z_unit, str(path)) if z_unit else factor
    x = np.asarray(x, dtype=float) * factor
    z = np.asarray(z, dtype=float) * z_factor
    if x.size < 3:
        raise DataFileError(f"{path}: {x.size} point(s); a profile needs at least 3 for any roughness statistic.")
    _check_finite(z, path)
    if not np.all(np.isfinite(x)):
        raise DataFileError(f"{path}: the x column has NaN or infinite values.")
    steps = np.diff(x)
    if np.any(steps == 0):
        row = int(np.flatnonzero(steps == 0)[0]) + 1
        raise DataFileError(f"{path}: x repeats at data row {row + 1} (duplicate position); x must increase strictly "
                            "from row to row (first column = position).")
    if np.any(steps < 0):
        row = int(np.flatnonzero(steps < 0)[0]) + 1
        raise DataFileError(f"{path}: x decreases at data row {row + 1}; x must increase strictly from row to row "
                            "(first column = position; sort the file or give one scan direction).")
    _check_lateral(float(steps.min()), float(x[-1] - x[0]), x.size, path)
    uniform = np.ptp(steps) <= _READER_UNIFORM_RTOL * steps.mean()
    if uniform:
        if np.ptp(steps) > UNIFORM_RTOL * steps.mean():
            source += "; x steps equal to within the file's rounding, made exactly uniform"
        x = x[0] + np.arange(x.size) * ((x[-1] - x[0]) / (x.size - 1))
    else:
        source += "; non-uniform x (statistics are point-wise; use --resample STEP for a uniform grid)"
    _check_magnitude(z, path, z_unit or unit or "m")
    return Profile(x=x, z=z, name=name, source=source)

def _check_unit_option(file_unit, unit, path):
    if file_unit is None:
        return unit or "m"
    file_unit = {"μm": "um", "µm": "um"}.get(file_unit, file_unit)
    if unit is not None and LENGTH_UNITS.get(unit) != LENGTH_UNITS.get(file_unit):
        raise DataFileError(f"{path} declares its heights in {printable(file_unit, 20)}; --unit ({unit}) is only for "
                            "files without a unit.")
    return file_unit

def _physical_sizes(physical_size, dim, path):
    """``physical_size`` (m, or text with units: '10 um' or '10 um, 5 um') as a tuple of ``dim`` lengths [m]."""
    from memstribo.units import to_si

    if isinstance(physical_size, str):
        parts = [p for p in re.split(r"\s*[,x;]\s*(?=[-+.\d])", physical_size.strip()) if p]
    elif isinstance(physical_size, (tuple, list)):
        parts = list(physical_size)
    else:
        parts = [physical_size]
    values = [to_si(p, "m", "--physical-size") for p in parts]
    if len(values) == 1:
        values = values * dim
    if len(values) != dim or not all(_DX_MIN <= v <= _LENGTH_MAX for v in values):
        raise InputError(f"--physical-size '{printable(physical_size, 40)}': give {dim} length(s) between "
                         f"{_DX_MIN:g} m and {_LENGTH_MAX:g} m ('10 um'" + (" or '10 um, 5 um')." if dim == 2 else ")."))
    return tuple(values)
