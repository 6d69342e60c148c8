"""Read measured surfaces: instrument files -> :class:`~memstribo.roughness.Profile` or :class:`SurfaceMap`.

Instrument formats go through SurfaceTopography (imported lazily, it takes seconds);
memstribo reads a few formats itself where SurfaceTopography's result would be wrong for
our use (see data/afm/README.md, "Reader notes and pitfalls"):

- plain x-z text/CSV (``#`` comments, whitespace or commas) and ``.npy`` (n x 2 or 2 x n)
  profiles: own readers; heights in metres unless ``unit`` says otherwise;
- the one-line text export with an 11-line header ("Name : ... (128x128)", "Z Unit : nm"),
  e.g. ``topography_in_nanometers.txt``: own reader (SurfaceTopography returns a 16384 x 1 map);
- contact.engineering containers (``.zip`` with ``meta.yml``): every member is opened on its
  own; the member's own calibration is used, *not* meta.yml's ``height_scale`` on top of it
  (that would apply the NanoScope scale twice); meta.yml gives the unit of unit-less members;
- Park TIFF and every other SurfaceTopography map: SurfaceTopography's ``heights()`` is
  indexed [x, y]; memstribo stores (ny, nx) with rows = scan lines along x;
- Asylum ``.ibw``: pixel size ScanSize / points (SurfaceTopography uses ScanSize / (points - 1)).

Every problem raises :class:`~memstribo.errors.DataFileError` naming the file and what is allowed.
"""

from __future__ import annotations

import io
import re
import warnings
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import DataFileError, InputError
from .roughness import UNIFORM_RTOL, Profile

__all__ = ["SurfaceMap", "read_topography", "write_profile", "SUPPORTED_EXTENSIONS", "LENGTH_UNITS"]

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
        raise InputError(f"unknown length unit '{unit}' for {what}; allowed: {', '.join(sorted(set(LENGTH_UNITS)))}.")
    return LENGTH_UNITS[key]


def _check_magnitude(z, path, unit_used):
    zc = np.asarray(z, dtype=float)
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


def _profile_from_xz(x, z, path, name, source, unit):
    """A Profile from x, z in the file's unit; uniform x (to rounding) is made exactly uniform."""
    factor = _unit_factor(unit or "m", str(path))
    x = np.asarray(x, dtype=float) * factor
    z = np.asarray(z, dtype=float) * factor
    _check_finite(z, path)
    if not np.all(np.isfinite(x)):
        raise DataFileError(f"{path}: the x column has NaN or infinite values.")
    if x.size < 3:
        raise DataFileError(f"{path}: {x.size} point(s); a profile needs at least 3 for any roughness statistic.")
    steps = np.diff(x)
    if np.any(steps <= 0):
        raise DataFileError(f"{path}: x must increase strictly from row to row (first column = position).")
    uniform = np.ptp(steps) <= _READER_UNIFORM_RTOL * steps.mean()
    if uniform:
        if np.ptp(steps) > UNIFORM_RTOL * steps.mean():
            source += "; x steps equal to within the file's rounding, made exactly uniform"
        x = x[0] + np.arange(x.size) * ((x[-1] - x[0]) / (x.size - 1))
    else:
        source += "; non-uniform x (statistics are point-wise; use --resample STEP for a uniform grid)"
    _check_magnitude(z, path, unit or "m")
    return Profile(x=x, z=z, name=name, source=source)


_HEADER_SHAPE = re.compile(r"\((\d+)\s*x\s*(\d+)\)")


def _read_header_export(text, path, name, unit):
    """The one-line export: 'key : value' header lines, then all nx*ny heights (row-major)."""
    lines = text.splitlines()
    header = {}
    start = None
    for i, line in enumerate(lines):
        if " : " in line or line.strip().endswith(":"):
            key, _, value = line.partition(":")
            header[key.strip().lower()] = value.strip()
        elif line.strip():
            start = i
            break
    width, height = header.get("image width"), header.get("image height")
    if start is None or width is None or height is None:
        raise DataFileError(f"{path}: a text header was found but no 'Image Width'/'Image Height' and data lines.")
    nx, ny = int(width), int(height)
    try:
        values = np.array(" ".join(lines[start:]).split(), dtype=float)
    except ValueError as exc:
        raise DataFileError(f"{path}: the height data after the header are not all numbers ({exc}).") from None
    if values.size != nx * ny:
        raise DataFileError(f"{path}: the header says {nx} x {ny} pixels but {values.size} heights follow.")
    file_unit = header.get("z unit")
    unit = _check_unit_option(file_unit, unit, path)
    factor = _unit_factor(unit, str(path))

    def length(key, n):
        text_value = header.get(key)
        m = re.match(r"([0-9.eE+-]+)\s*(\S+)", text_value or "")
        if not m:
            raise DataFileError(f"{path}: header line '{key}' missing or unreadable; cannot tell the pixel size.")
        return float(m.group(1)) * _unit_factor(m.group(2), f"{path} header '{key}'") / n

    heights = values.reshape(ny, nx) * factor
    _check_finite(heights, path)
    _check_magnitude(heights, path, unit)
    return SurfaceMap(heights=heights, dx=length("real width", nx), dy=length("real height", ny), name=name,
                      source=f"{path} (text export: header + {nx}x{ny} heights row-major, {unit}; own reader)",
                      channel=_HEADER_SHAPE.sub("", header.get("name", "default")).strip())


def _check_unit_option(file_unit, unit, path):
    if file_unit is None:
        return unit or "m"
    file_unit = {"μm": "um", "µm": "um"}.get(file_unit, file_unit)
    if unit is not None and LENGTH_UNITS.get(unit) != LENGTH_UNITS.get(file_unit):
        raise DataFileError(f"{path} declares its heights in {file_unit}; --unit ({unit}) is only for files "
                            "without a unit.")
    return file_unit


def _read_text(data: bytes, path, name, unit, declared_unit=None):
    text = data.decode("utf-8", errors="replace")
    first = next((line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")), "")
    if _HEADER_SHAPE.search(text[:2000]) or re.match(r"\s*[A-Za-z]", first):
        if "image width" in text[:2000].lower():
            return _read_header_export(text, path, name, unit)
    unit = _check_unit_option(declared_unit, unit, path) if declared_unit else (unit or "m")
    cleaned = text.replace(",", " ").replace(";", " ")
    if first and not re.match(r"\s*[-+.\d]", first):
        # one line of column names ("x,z") before the data: treat it as a comment
        cleaned = cleaned.replace(first.replace(",", " ").replace(";", " "), "#", 1)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            table = np.loadtxt(io.StringIO(cleaned), comments="#", ndmin=2)
    except (ValueError, UserWarning) as exc:
        raise DataFileError(f"{path}: not a readable x-z text profile ({exc}). Expected two columns (x, height) "
                            "separated by spaces, tabs or commas, '#' comment lines allowed.") from None
    if table.shape[0] == 0:
        raise DataFileError(f"{path}: no data rows.")
    if table.shape[1] != 2:
        raise DataFileError(f"{path}: {table.shape[1]} columns; a text profile needs exactly 2 (x, height).")
    return _profile_from_xz(table[:, 0], table[:, 1], path, name, f"{path} (x-z text, {unit})", unit)


def _read_npy(path, name, unit):
    try:
        array = np.load(path, allow_pickle=False)
    except Exception as exc:  # numpy raises several types for corrupt files
        raise DataFileError(f"{path}: not a readable .npy file ({exc}).") from None
    array = np.asarray(array, dtype=float) if array.dtype.kind in "fiu" else None
    if array is None or array.ndim != 2 or 2 not in array.shape:
        raise DataFileError(f"{path}: a .npy profile must be a numeric array of shape (n, 2) or (2, n) holding x and "
                            "height (in m unless --unit says otherwise).")
    table = array if array.shape[1] == 2 and array.shape[0] != 2 else array.T
    return _profile_from_xz(table[:, 0], table[:, 1], path, name, f"{path} (numpy x-z array, {unit or 'm'})", unit)


def _st_open(source, path):
    """SurfaceTopography reader of a path or stream, with errors turned into DataFileError."""
    try:
        from SurfaceTopography import open_topography
    except ImportError as exc:  # pragma: no cover - declared dependency
        raise DataFileError(f"reading {path} needs the SurfaceTopography package ({exc}).") from None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return open_topography(source)
    except Exception as exc:
        raise DataFileError(f"{path}: could not read the file ({type(exc).__name__}: {exc}). It may be corrupt or "
                            f"of a format SurfaceTopography does not know.") from None


def _select_channel(reader, channel, path):
    channels = reader.channels
    names = [f"{c.name} (ch{c.index})" for c in channels]
    if channel is None:
        return reader.default_channel
    text = str(channel).strip()
    m = re.fullmatch(r"(?:ch)?(\d+)", text, flags=re.IGNORECASE)
    if m:
        index = int(m.group(1))
        for c in channels:
            if c.index == index:
                return c
    matches = [c for c in channels if c.name.lower() == text.lower()]
    if matches:
        return matches[0]
    raise DataFileError(f"{path}: no channel '{channel}'. Channels: {', '.join(names)} (give a name or chN).")


def _height_unit(c):
    unit = c.unit
    if isinstance(unit, tuple):
        return unit[1]
    return unit


def _st_topography(reader, path, name, channel, unit, fix_ibw=False):
    c = _select_channel(reader, channel, path)
    file_unit = _height_unit(c)
    if isinstance(c.unit, tuple) and file_unit is None:
        raise DataFileError(f"{path}: channel '{c.name}' (ch{c.index}) is not a height channel (it has no length "
                            "unit). Choose a height channel with --channel.")
    unit_used = _check_unit_option(file_unit, unit, path) if file_unit else (unit or "m")
    kwargs = {} if file_unit else {"unit": unit_used}
    if c.physical_sizes is None:
        raise DataFileError(f"{path}: the file does not give the scan size; memstribo cannot read it.")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            topography = reader.topography(channel_index=c.index, **kwargs)
            if topography.has_undefined_data:
                n_bad = int(np.count_nonzero(np.ma.getmaskarray(topography.heights())))
                raise DataFileError(f"{path}: channel '{c.name}' has {n_bad} undefined (masked/NaN) pixels; memstribo "
                                    "does not fill them silently: fill or crop them in your AFM software first.")
            topography = topography.to_unit("m")
            heights = np.asarray(topography.heights(), dtype=float)
    except DataFileError:
        raise
    except Exception as exc:
        raise DataFileError(f"{path}: could not read channel '{c.name}' ({type(exc).__name__}: {exc}).") from None
    _check_finite(heights, path)
    source = f"{path}, channel '{c.name}' (ch{c.index}), read by SurfaceTopography, {unit_used}"
    if topography.dim == 1:
        if topography.is_uniform:
            n = heights.size
            x = np.arange(n) * (topography.physical_sizes[0] / n)
        else:
            x, heights = topography.positions_and_heights()
        _check_magnitude(heights, path, unit_used)
        return Profile(x=np.asarray(x, dtype=float), z=heights, name=name, source=source)
    nx, ny = topography.nb_grid_pts
    sx, sy = topography.physical_sizes
    dx, dy = sx / nx, sy / ny
    if fix_ibw:
        raw = (c.info or {}).get("raw_metadata", {})
        try:
            dx = float(raw.get("FastScanSize", raw["ScanSize"])) / int(raw.get("ScanPoints", nx))
            dy = float(raw.get("SlowScanSize", raw["ScanSize"])) / int(raw.get("ScanLines", ny))
            source += "; pixel size ScanSize/points from the Igor header (SurfaceTopography uses ScanSize/(points-1))"
        except (KeyError, ValueError, TypeError):
            source += "; no ScanSize in the Igor header: pixel size as SurfaceTopography gives it"
    heights = heights.T  # SurfaceTopography indexes [x, y]; rows must be scan lines along x
    _check_magnitude(heights, path, unit_used)
    return SurfaceMap(heights=heights, dx=dx, dy=dy, name=name, source=source, channel=c.name)


def _container_meta(archive):
    try:
        import yaml
    except ImportError:  # pragma: no cover - SurfaceTopography depends on PyYAML
        return {}

    class Loader(yaml.SafeLoader):
        pass

    Loader.add_constructor("tag:yaml.org,2002:python/tuple", lambda loader, node: tuple(loader.construct_sequence(node)))
    try:
        meta = yaml.load(archive.read("meta.yml"), Loader=Loader)
    except Exception:
        return {}
    units = {}
    for surface in (meta or {}).get("surfaces", []):
        for topo in surface.get("topographies", []):
            original = (topo.get("datafile") or {}).get("original")
            if original:
                units[original] = topo
    return units


def _is_afm_member(member):
    return re.search(r"\.(\d{3}|di|spm|ibw|tiff?|gwy|x3p|nc|opdx|sur|plu|mi|nid|datx)$", member, re.IGNORECASE)


def _read_container(path, name, channel, unit):
    try:
        archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, OSError) as exc:
        raise DataFileError(f"{path}: not a readable zip container ({exc}).") from None
    with archive:
        members = [m for m in archive.namelist() if not m.endswith("/") and not m.lower().startswith("license")
                   and m != "meta.yml"]
        if not members:
            raise DataFileError(f"{path}: the zip holds no measurement files.")
        meta = _container_meta(archive)
        member_text, _, channel_text = (channel or "").partition("::")
        if member_text:
            chosen = [m for m in members if m == member_text] or [m for m in members if member_text.lower() in m.lower()]
            if len(chosen) != 1:
                what = "matches several members" if chosen else "matches no member"
                raise DataFileError(f"{path}: channel '{channel}' {what}. Members: {', '.join(members)} (give a member "
                                    "name or a unique part of it; add '::CHANNEL' for a channel inside it).")
            member = chosen[0]
        else:
            afm = [m for m in members if _is_afm_member(m)]
            member = (afm or members)[0]
        data = archive.read(member)
    member_name = f"{Path(path).name}/{member}"
    declared = (meta.get(member) or {}).get("unit")
    if member.lower().endswith(_TEXT):
        profile = _read_text(data, f"{path}::{member}", member_name, unit, declared_unit=declared)
        extra = f"; unit {declared} from meta.yml" if declared else ""
        return profile.replace(source=profile.source + extra)
    reader = _st_open(io.BytesIO(data), f"{path}::{member}")
    result = _st_topography(reader, f"{path}::{member}", member_name, channel_text or None, unit)
    note = "; the member's own Z calibration (meta.yml's height_scale is not applied again)"
    if isinstance(result, SurfaceMap):
        return SurfaceMap(heights=result.heights, dx=result.dx, dy=result.dy, name=result.name,
                          source=result.source + note, channel=f"{member}::{result.channel}")
    return result.replace(source=result.source + note)


def read_topography(path, channel=None, unit=None):
    """Read a measured surface: a profile or a height map, in metres.

    Parameters
    ----------
    path : str or pathlib.Path
        Instrument file (NanoScope .di/.001, Park .tiff, Asylum .ibw, Dektak .opdx, Gwyddion,
        x3p, ... through SurfaceTopography), a contact.engineering ``.zip`` container, an x-z
        text/CSV profile (``#`` comments), an ``.npy`` x-z array or a one-line text export
        with an 'Image Width'/'Image Height' header.
    channel : str, optional
        Channel name (``"Height"``) or index (``"ch3"``, ``"3"``); for a ``.zip``, a member
        name or a unique part of it, optionally ``"MEMBER::CHANNEL"``. Default: the file's
        height channel (ch0) or the container's AFM member.
    unit : str, optional
        Unit of x and heights in files that do not declare one (text, .npy): m (default),
        mm, um, nm, A, pm.

    Returns
    -------
    Profile or SurfaceMap
        Heights [m], not levelled.

    Raises
    ------
    DataFileError
        Missing, unreadable or corrupt file, unknown format, unknown channel, undefined
        (NaN/masked) pixels, heights whose Rq (> 1 mm or < 1 pm) suggests a wrong unit.
    """
    path = Path(path)
    if unit is not None:
        _unit_factor(unit, "--unit")
    if not path.exists():
        raise DataFileError(f"file not found: {path}")
    if path.is_dir():
        raise DataFileError(f"{path} is a folder; give a measurement file.")
    suffix = path.suffix.lower()
    name = path.name
    if suffix == ".zip":
        return _read_container(path, name, channel, unit)
    if suffix == ".npy":
        result = _read_npy(path, name, unit)
    elif suffix in _TEXT:
        try:
            data = path.read_bytes()
        except OSError as exc:
            raise DataFileError(f"{path}: cannot read the file ({exc}).") from None
        result = _read_text(data, path, name, unit)
    elif suffix in _ST_EXTENSIONS or re.fullmatch(r"\.\d{3}", suffix):
        reader = _st_open(str(path), path)
        return _st_topography(reader, path, name, channel, unit, fix_ibw=suffix == ".ibw")
    else:
        raise DataFileError(f"{path}: unknown format '{suffix or '(no extension)'}'. Supported: "
                            f"{', '.join(SUPPORTED_EXTENSIONS)}.")
    if channel is not None:
        allowed = {"default", "0", "ch0", str(getattr(result, "channel", "")).lower()}
        if str(channel).lower() not in allowed:
            raise DataFileError(f"{path}: no channel '{channel}'; this file has one channel: "
                                f"'{getattr(result, 'channel', 'default') or 'default'}' (ch0).")
    return result


def write_profile(profile: Profile, path) -> Path:
    """Write a profile as x-z text in metres (``#`` header with name and provenance).

    The file reads back with :func:`read_topography` (same numbers to 17 significant digits).

    Parameters
    ----------
    profile : Profile
        The profile (x, z [m]).
    path : str or pathlib.Path
        Output file (``.txt`` or ``.csv``; folders are created).

    Returns
    -------
    pathlib.Path
        The path written.
    """
    from .output import ensure_directory

    if not isinstance(profile, Profile):
        raise InputError("write_profile needs a Profile (a map: write one of its line_scans()).")
    path = Path(path)
    if path.suffix.lower() not in (".txt", ".csv"):
        raise InputError(f"profile output '{path}' must end in .txt or .csv.")
    ensure_directory(path.parent)
    kind = "SYNTHETIC" if profile.synthetic else "measured"
    header = (f"{profile.name} ({kind})\nsource: {profile.source}\n"
              f"{profile.n_points} points; columns: x [m], height [m] (written by memstribo)")
    delimiter = "," if path.suffix.lower() == ".csv" else " "
    tmp = path.with_name(path.name + ".tmp")
    try:
        np.savetxt(tmp, np.column_stack([profile.x, profile.z]), fmt="%.17g", delimiter=delimiter, header=header)
        tmp.replace(path)
    except OSError as exc:
        raise InputError(f"cannot write '{path}': {exc.strerror}.") from None
    return path
