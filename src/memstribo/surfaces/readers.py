"""Read measured surfaces: instrument files -> :class:`~memstribo.surfaces.roughness.Profile` or :class:`SurfaceMap`.

Every format SurfaceTopography reads goes through it first (imported lazily, it takes
seconds), with the file's channels, units and sizes: instrument files, and text or CSV files
with an instrument header such as a Bruker Dektak CSV export. memstribo reads these itself
(see data/afm/README.md, "Reader notes and pitfalls"):

- plain numeric x-z (or z) text/CSV (``#`` comments, whitespace, commas or semicolons, one
  optional line of column names whose units, ``x [um], z [nm]``, are honoured per axis) and
  ``.npy`` (n x 2 or 2 x n) profiles: own strict readers (SurfaceTopography would silently
  skip unreadable leading rows and ignore such a header); heights in metres unless ``unit``
  says otherwise; text in UTF-8 with or without BOM, UTF-16, Latin-1, any line ends;
- the one-line text export with an 11-line header ("Name : ... (128x128)", "Z Unit : nm"),
  e.g. ``topography_in_nanometers.txt``: own reader (SurfaceTopography returns a 16384 x 1 map);
- contact.engineering containers (``.zip`` with ``meta.yml``): every member is opened on its
  own; the member's own calibration is used, *not* meta.yml's ``height_scale`` on top of it
  (that would apply the NanoScope scale twice); meta.yml gives the unit of unit-less members;
- Park TIFF and every other SurfaceTopography map: SurfaceTopography's ``heights()`` is
  indexed [x, y]; memstribo stores (ny, nx) with rows = scan lines along x;
- Asylum ``.ibw``: pixel size ScanSize / points (SurfaceTopography uses ScanSize / (points - 1)).

A file that no reader takes gets one message: why it is not x-z text, what SurfaceTopography
said for its format (one clause, never its list of every reader), what is supported. Text
from the file is shown with control characters escaped. TIFF and Igor files cut short are
refused even where the cut spares the heights.

Every problem raises :class:`~memstribo.errors.DataFileError` naming the file and what is allowed.
"""

from __future__ import annotations

import codecs
import io
import logging
import re
import warnings
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from memstribo.errors import DataFileError, InputError, MemstriboError
from memstribo.surfaces.roughness import UNIFORM_RTOL, Profile
from memstribo.units import printable

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
    try:
        nx, ny = int(width), int(height)
    except ValueError:
        raise DataFileError(f"{path}: header 'Image Width'/'Image Height' must be whole numbers, got "
                            f"'{printable(width, 20)}' x '{printable(height, 20)}'.") from None
    if not (2 <= nx and 2 <= ny and nx * ny <= MAX_POINTS):
        raise DataFileError(f"{path}: the header says {nx} x {ny} pixels; memstribo reads maps of 2 x 2 to "
                            f"{MAX_POINTS:,} pixels.")
    try:
        values = np.array(" ".join(lines[start:]).split(), dtype=float)
    except ValueError:
        raise DataFileError(f"{path}: the height data after the header are not all numbers.") from None
    if values.size != nx * ny:
        raise DataFileError(f"{path}: the header says {nx} x {ny} pixels but {values.size} heights follow "
                            "(a truncated or edited file?).")
    file_unit = header.get("z unit")
    unit = _check_unit_option(file_unit, unit, path)
    factor = _unit_factor(unit, str(path))

    def length(key, n):
        text_value = header.get(key)
        m = re.match(r"([0-9.eE+-]+)\s*(\S+)", text_value or "")
        try:
            size = float(m.group(1)) * _unit_factor(m.group(2), f"{path} header '{key}'") if m else None
        except ValueError:
            size = None
        if size is None:
            raise DataFileError(f"{path}: header line '{key}' missing or unreadable; cannot tell the pixel size.")
        _check_lateral(size / n, size, nx * ny, path, what=f"pixel size ('{key}')")
        return size / n

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
        raise DataFileError(f"{path} declares its heights in {printable(file_unit, 20)}; --unit ({unit}) is only for "
                            "files without a unit.")
    return file_unit


def _decode_text(data: bytes, path):
    """The text of a text file (UTF-8 with or without BOM, UTF-16 with BOM, Latin-1), lines ending in '\\n'.

    Returns None for binary data (NUL bytes or control characters): not a text file.
    """
    if data.startswith(codecs.BOM_UTF8):
        data = data[len(codecs.BOM_UTF8):]
        encoding = "utf-8"
    elif data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        if len(data) % 2:
            raise DataFileError(f"{path}: UTF-16 text with an odd number of bytes: the file is truncated.")
        encoding = "utf-16"
    elif len(data) >= 4 and data[1::2][:64].count(0) > 24 and data[0::2][:64].count(0) == 0:
        encoding = "utf-16-le"  # UTF-16 without a byte-order mark
    else:
        encoding = "utf-8"
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError:
        if encoding != "utf-8":
            return None
        text = data.decode("latin-1")
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    bad = next((i for i, c in enumerate(text) if not (c.isprintable() or c in "\n\t\f\v")), None)
    if bad is None:
        return text
    if encoding == "utf-8" and "\x00" not in text:
        # readable text with terminal control sequences (ESC, BEL, ...) in it: not a measurement export
        line = text.count("\n", 0, bad) + 1
        raise DataFileError(f"{path}: line {line} holds control characters ({printable(text[bad], 10)}, e.g. terminal "
                            "escape sequences); a text profile holds numbers, '#' comments and one line of column "
                            "names.")
    return None


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?(?:nan|inf|infinity)"
_NUMBER_ROW = re.compile(rf"^\s*(?:{_NUMBER})(?:\s*[,;\t ]\s*(?:{_NUMBER}))*\s*[,;]*\s*$", re.IGNORECASE)
_SPLIT = re.compile(r"\s*[,;\s]\s*")
_UNIT_WORDS = {"meter": "m", "meters": "m", "metre": "m", "metres": "m", "millimeter": "mm", "millimeters": "mm",
               "millimetre": "mm", "micrometer": "um", "micrometers": "um", "micrometre": "um", "micron": "um",
               "microns": "um", "nanometer": "nm", "nanometers": "nm", "nanometre": "nm", "angstrom": "A",
               "angstroms": "A", "picometer": "pm", "picometers": "pm"}


def _plain_rows(text):
    """(header line or None, data lines) of plain numeric text, or None if it is not plain numeric text.

    Plain numeric text: '#' comment lines and blank lines anywhere, at most one line of column
    names before the data, then only rows of 1 or 2 numbers (the x-z and z formats memstribo
    reads itself). Anything else (instrument headers, 3 or more columns) is another format.
    """
    header, rows, comment = None, [], None
    for line in text.split("\n"):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            if not rows and header is None:
                comment = stripped.lstrip("#").strip()
            continue
        if _NUMBER_ROW.match(stripped):
            rows.append(stripped)
        elif not rows and header is None:
            header = stripped
        else:
            return None
    if not rows:
        return None
    widths = {len([f for f in _SPLIT.split(r.rstrip(",;")) if f]) for r in rows[:50]}
    if not widths <= {1, 2}:
        return None
    if header is None and comment:
        # a comment right before the data naming both columns' units in brackets: '# x [um], z [nm]'
        units = re.findall(r"[\[(]\s*([A-Za-z\u00b5\u03bc\u00c5]+)\s*[\])]", comment)
        if len(units) == 2 and all(u in LENGTH_UNITS for u in units):
            header = comment
    return header, rows


def _header_units(header, path):
    """Units of the x and z columns named in a column-header line ('x [um], z [nm]'), or (None, None)."""
    if not header:
        return None, None
    fields = [f for f in re.split(r"\s*[,;\t]\s*", header.strip().strip(",;")) if f]
    if len(fields) != 2:
        bracketed = [f.strip() for f in re.findall(r"[^\[\]()]*[\[(][^\])]*[\])]", header)]
        fields = bracketed if len(bracketed) == 2 else header.split()
    units = []
    for field in fields[:2]:
        found = re.search(r"[\[(]\s*([^\])]*?)\s*[\])]", field)
        token = found.group(1) if found else None
        if token is None:
            words = re.split(r"[\s_/:=-]+", field)
            token = next((w for w in words[1:] if w in LENGTH_UNITS or w.lower() in _UNIT_WORDS), None)
        if token is not None:
            key = token.strip()
            key = _UNIT_WORDS.get(key.lower(), key)
            if key not in LENGTH_UNITS:
                raise DataFileError(f"{path}: column '{printable(field, 40)}' of the header line has unit "
                                    f"'{printable(token, 20)}', not a length; allowed: m, mm, um, nm, A, pm.")
            token = key
        units.append(token)
    if len(units) == 2 and (units[0] is None) != (units[1] is None):
        which = "x" if units[0] is None else "height"
        raise DataFileError(f"{path}: the header line '{printable(header, 60)}' gives a unit for one column only; "
                            f"give the {which} column's unit as well ('x [um], z [nm]'), or none and use --unit.")
    return (units + [None, None])[:2] if len(units) == 2 else (None, None)


def _read_plain_text(text, plain, path, name, unit, physical_size=None):
    """Plain numeric x-z (or z) text: SurfaceTopography reads it first (its numbers); memstribo then applies what
    SurfaceTopography does not keep, the header's per-axis units (``x [um], z [nm]``) and the x origin of a uniform
    scan, and its own checks (x strictly increasing, finite heights, plausible sizes). Text SurfaceTopography
    refuses (a z-only column, odd delimiters, ...) is read by memstribo's own parser, the fallback."""
    header, rows = plain
    try:
        reader = _st_open(io.BytesIO(text.encode("utf-8")), path, ".txt")
        with _QuietLogs():
            topography = reader.topography()
            if topography.dim != 1:
                raise _NotRead("not a line scan")
            x, z = topography.positions_and_heights()
    except MemoryError:
        raise
    except Exception:  # SurfaceTopography refused it: memstribo's own reader
        return _read_plain(header, rows, path, name, unit, physical_size=physical_size)
    first = [f for f in _SPLIT.split(rows[0].strip().rstrip(",;").strip()) if f]
    if len(first) != 2 or len(x) != len(rows):  # not the x-z table memstribo would read: its own reader decides
        return _read_plain(header, rows, path, name, unit, physical_size=physical_size)
    x = np.asarray(x, dtype=float)
    x = x - x[0] + float(first[0])  # a uniform line scan of SurfaceTopography starts at 0; keep the file's origin
    try:
        x_file = np.array([float(_SPLIT.split(row.strip().rstrip(",;").strip())[0]) for row in rows])
    except ValueError:
        x_file = None
    scale = float(np.max(np.abs(x_file))) if x_file is not None and x_file.size else 0.0
    if x_file is None or not np.allclose(x, x_file, rtol=0.0, atol=1e-9 * max(scale, 1e-300)):
        # SurfaceTopography reordered or regularised the positions (reversed, repeated or uneven x): memstribo's
        # own reader says what is wrong with the file
        return _read_plain(header, rows, path, name, unit, physical_size=physical_size)
    array = np.column_stack([x, np.ma.filled(np.ma.asarray(z, dtype=float), np.nan)])
    return _read_plain(header, rows, path, name, unit, physical_size=physical_size, array=array,
                       reader="read by SurfaceTopography")


def _read_plain(header, rows, path, name, unit, declared_unit=None, physical_size=None, array=None,
                reader="read by memstribo"):
    """Plain x-z (or z) numeric text: memstribo's own strict reader, or the x-z ``array`` SurfaceTopography read
    from it (then only the header's units and the checks are memstribo's)."""
    x_unit, z_unit = _header_units(header, path)
    if x_unit is not None:
        if unit is not None and (LENGTH_UNITS[unit] != LENGTH_UNITS[x_unit] or LENGTH_UNITS[unit] != LENGTH_UNITS[z_unit]):
            raise DataFileError(f"{path}: the header line gives the units (x in {x_unit}, heights in {z_unit}); "
                                f"--unit ({unit}) is only for files without units.")
        unit_note = f"x in {x_unit}, heights in {z_unit} (from the header line)"
    else:
        x_unit = z_unit = _check_unit_option(declared_unit, unit, path) if declared_unit else (unit or "m")
        unit_note = x_unit
    if array is not None:
        if physical_size is not None:
            raise DataFileError(f"{path}: the x column gives the profile length; --physical-size is only for files "
                                "without one.")
        return _profile_from_xz(array[:, 0], array[:, 1], path, name, f"{path} (x-z text, {unit_note}, {reader})",
                                x_unit, z_unit)
    widths = set()
    table = []
    for i, row in enumerate(rows):
        fields = [f for f in _SPLIT.split(row.strip().rstrip(",;").strip()) if f]
        widths.add(len(fields))
        if len(widths) > 1:
            raise DataFileError(f"{path}: data row {i + 1} has {len(fields)} column(s), the rows before it "
                                f"{len(fields) == 1 and 2 or 1}; a text profile has the same columns on every row "
                                "(a truncated file?).")
        table.append([float(f) for f in fields])
    array = np.array(table, dtype=float)
    if array.shape[1] == 1:
        z = array[:, 0]
        if physical_size is None:
            raise DataFileError(f"{path}: one column of heights and no x; give the profile length with "
                                "--physical-size (e.g. '10 um'), or add an x column.")
        length = _physical_sizes(physical_size, 1, path)[0]
        x = np.arange(z.size) * (length / z.size) / _unit_factor(x_unit, str(path))
        return _profile_from_xz(x, z, path, name, f"{path} (z text, {unit_note}; length {length:g} m given)",
                                x_unit, z_unit)
    if physical_size is not None:
        raise DataFileError(f"{path}: the x column gives the profile length; --physical-size is only for files "
                            "without one.")
    return _profile_from_xz(array[:, 0], array[:, 1], path, name, f"{path} (x-z text, {unit_note})", x_unit, z_unit)


def _text_reason(text, path):
    """Why ``text`` is not plain x-z text (for the message when no reader takes the file)."""
    if text is None:
        return "binary data, not text"
    lines = [(i + 1, line.strip()) for i, line in enumerate(text.split("\n"))
             if line.strip() and not line.strip().startswith("#")]
    if not lines:
        return "no data rows"
    bad = [(i, line) for i, line in lines if not _NUMBER_ROW.match(line)]
    if len(bad) > 1 or (bad and bad[0] != lines[0]):
        i, line = bad[1] if len(bad) > 1 and bad[0] == lines[0] else bad[0]
        return (f"line {i} '{printable(line, 40)}' is not numbers separated by spaces, tabs, commas or "
                "semicolons")
    return f"{len(_SPLIT.split(lines[-1][1]))} columns; a text profile has 2 (x, height) or 1 (height)"


def _read_text(data: bytes, path, name, unit, declared_unit=None, physical_size=None):
    """A text member of a container (or a text file SurfaceTopography does not take): own readers only."""
    text = _decode_text(data, path)
    if text is None:
        raise DataFileError(f"{path}: not a readable x-z text profile (binary data, not text).")
    if "image width" in text[:2000].lower():
        return _read_header_export(text, path, name, unit)
    plain = _plain_rows(text)
    if plain is None:
        raise DataFileError(f"{path}: not a readable x-z text profile ({_text_reason(text, path)}).")
    return _read_plain(*plain, path, name, unit, declared_unit, physical_size)


def _read_npy(path, name, unit):
    try:
        array = np.load(path, allow_pickle=False)
    except Exception:  # numpy raises several types for corrupt files
        raise DataFileError(f"{path}: not a readable .npy file (corrupt, truncated or holding Python objects).") from None
    array = np.asarray(array, dtype=float) if getattr(array, "dtype", None) is not None and array.dtype.kind in "fiu" else None
    if array is None or array.ndim != 2 or 2 not in array.shape:
        raise DataFileError(f"{path}: a .npy profile must be a numeric array of shape (n, 2) or (2, n) holding x and "
                            "height (in m unless --unit says otherwise).")
    table = array if array.shape[1] == 2 and array.shape[0] != 2 else array.T
    return _profile_from_xz(table[:, 0], table[:, 1], path, name, f"{path} (numpy x-z array, {unit or 'm'})", unit)


def _st_module():
    try:
        import SurfaceTopography.IO as st_io
    except ImportError as exc:  # pragma: no cover - declared dependency
        raise DataFileError(f"reading instrument files needs the SurfaceTopography package ({exc}).") from None
    return st_io


def _format_names(suffix):
    """SurfaceTopography's names of the formats that use ``suffix`` (e.g. '.csv' -> 'Plain text (x,y,z ...)')."""
    st_io = _st_module()
    names = []
    for reader in st_io.readers:
        extensions = getattr(reader, "_file_extensions", None) or []
        if suffix.lstrip(".").lower() in [e.lower() for e in extensions]:
            names.append(getattr(reader, "_name", reader.__name__))
    return names


class _QuietLogs:
    """Silence the readers' own logging (tifffile logs every bad tag) and their warnings."""

    def __enter__(self):
        self._warnings = warnings.catch_warnings()
        self._warnings.__enter__()
        warnings.simplefilter("ignore")
        logging.disable(logging.CRITICAL)
        return self

    def __exit__(self, *exc):
        logging.disable(logging.NOTSET)
        self._warnings.__exit__(*exc)
        return False


def _st_reason(exc, suffix):
    """One short clause on why SurfaceTopography did not read a file (never its full reader list)."""
    message = str(exc)
    tried = re.findall(r"tried (\w+):\s*\n\s*([^\n]*)", message)
    st_io = _st_module()
    own = {r.__name__: getattr(r, "_name", r.__name__) for r in st_io.readers
           if suffix.lstrip(".").lower() in [e.lower() for e in (getattr(r, "_file_extensions", None) or [])]}
    for reader_name, reason in tried:
        if reader_name in own:
            return f"as {own[reader_name]}: {printable(reason.strip().rstrip('.'), 140)}"
    if tried or type(exc).__name__ == "CannotDetectFileFormat":
        expected = f" (a {suffix} file should be {' or '.join(own.values())})" if own else ""
        return f"none of its {len(st_io.readers)} formats recognises the content{expected}"
    return f"{type(exc).__name__}: {printable(message.splitlines()[0].strip().rstrip('.') if message else '', 140)}"


def _st_open(source, path, suffix):
    """SurfaceTopography's reader of a path or stream; its failures become one short DataFileError."""
    st_io = _st_module()
    try:
        with _QuietLogs():
            return st_io.open_topography(source)
    except MemoryError:
        raise
    except Exception as exc:
        raise _NotRead(_st_reason(exc, suffix)) from None


class _NotRead(Exception):
    """SurfaceTopography did not read the file (the reason, one clause)."""


def _select_channel(reader, channel, path):
    channels = reader.channels
    names = [f"{printable(c.name, 40)} (ch{c.index})" for c in channels]
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
    raise DataFileError(f"{path}: no channel '{printable(channel, 40)}'. Channels: {', '.join(names)} (give a name "
                        "or chN).")


def _height_unit(c):
    unit = c.unit
    if isinstance(unit, tuple):
        return unit[1]
    return unit


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


def _st_topography(reader, path, name, channel, unit, fix_ibw=False, physical_size=None):
    c = _select_channel(reader, channel, path)
    file_unit = _height_unit(c)
    if isinstance(c.unit, tuple) and file_unit is None:
        raise DataFileError(f"{path}: channel '{printable(c.name, 40)}' (ch{c.index}) is not a height channel (it has "
                            "no length unit). Choose a height channel with --channel.")
    unit_used = _check_unit_option(file_unit, unit, path) if file_unit else (unit or "m")
    kwargs = {} if file_unit else {"unit": unit_used}
    dim = c.dim if c.dim in (1, 2) else 2
    if c.physical_sizes is None or (np.ndim(c.physical_sizes) and any(s is None for s in c.physical_sizes)):
        if physical_size is None:
            what = "profile length" if dim == 1 else "scan size"
            raise DataFileError(f"{path}: the file does not give its lateral size; give the {what} with "
                                f"--physical-size (e.g. '10 um'" + (" or '10 um, 5 um')." if dim == 2 else ")."))
        sizes = _physical_sizes(physical_size, dim, path)
        kwargs["physical_sizes"] = sizes[0] if dim == 1 else sizes
    elif physical_size is not None:
        raise DataFileError(f"{path}: the file gives its lateral size; --physical-size is only for files without one.")
    if c.nb_grid_pts is not None and int(np.prod(c.nb_grid_pts)) > MAX_POINTS:
        raise DataFileError(f"{path}: channel '{printable(c.name, 40)}' has {int(np.prod(c.nb_grid_pts)):,} pixels; "
                            f"memstribo reads at most {MAX_POINTS:,}.")
    with _QuietLogs():
        topography = reader.topography(channel_index=c.index, **kwargs)
        if topography.has_undefined_data:
            n_bad = int(np.count_nonzero(np.ma.getmaskarray(topography.heights())))
            raise DataFileError(f"{path}: channel '{printable(c.name, 40)}' has {n_bad} undefined (masked/NaN) pixels; "
                                "memstribo does not fill them silently: fill or crop them in your AFM software first.")
        topography = topography.to_unit("m")
        heights = np.asarray(topography.heights(), dtype=float)
    _check_finite(heights, path)
    source = f"{path}, channel '{c.name}' (ch{c.index}), read by SurfaceTopography, {unit_used}"
    if "physical_sizes" in kwargs:
        source += f"; lateral size {kwargs['physical_sizes']} m given with --physical-size"
    if topography.dim == 1:
        if topography.is_uniform:
            n = heights.size
            x = np.arange(n) * (topography.physical_sizes[0] / n)
        else:
            x, heights = topography.positions_and_heights()
        x = np.asarray(x, dtype=float)
        if x.size < 3:
            raise DataFileError(f"{path}: {x.size} point(s); a profile needs at least 3 for any roughness statistic.")
        steps = np.diff(x)
        if np.any(steps <= 0):
            raise DataFileError(f"{path}: the positions do not increase strictly (repeated or reversed x).")
        _check_lateral(float(steps.min()), float(x[-1] - x[0]), x.size, path)
        _check_magnitude(heights, path, unit_used)
        return Profile(x=x, z=heights, name=name, source=source)
    nx, ny = topography.nb_grid_pts
    sx, sy = topography.physical_sizes
    dx, dy = sx / nx, sy / ny
    if fix_ibw:
        raw = (c.info or {}).get("raw_metadata", {})
        try:
            dx = float(raw.get("FastScanSize", raw["ScanSize"])) / int(raw.get("ScanPoints", nx))
            dy = float(raw.get("SlowScanSize", raw["ScanSize"])) / int(raw.get("ScanLines", ny))
            source += "; pixel size ScanSize/points from the Igor header (SurfaceTopography uses ScanSize/(points-1))"
        except (KeyError, ValueError, TypeError, ZeroDivisionError):
            source += "; no ScanSize in the Igor header: pixel size as SurfaceTopography gives it"
    if min(nx, ny) < 2:
        raise DataFileError(f"{path}: a {nx} x {ny} map; memstribo needs at least 2 x 2 pixels.")
    for label, step, size in (("pixel size dx", dx, nx * dx), ("pixel size dy", dy, ny * dy)):
        _check_lateral(step, size, nx * ny, path, what=label)
    heights = heights.T  # SurfaceTopography indexes [x, y]; rows must be scan lines along x
    _check_magnitude(heights, path, unit_used)
    return SurfaceMap(heights=heights, dx=dx, dy=dy, name=name, source=source, channel=c.name)


def _check_complete(path, suffix, size):
    """Refuse an instrument file cut short, even where the cut spares the heights (it is damaged)."""
    with open(path, "rb") as handle:
        head = handle.read(64)
    if suffix in (".tif", ".tiff") and head[:2] in (b"II", b"MM"):
        try:
            import tifffile

            with _QuietLogs(), tifffile.TiffFile(str(path)) as tif:
                ends = []
                for page in tif.pages:
                    for tag in page.tags.values():
                        if getattr(tag, "valuebytecount", 0) > 4:  # values of 4 bytes or less sit in the tag itself
                            ends.append(tag.valueoffset + tag.valuebytecount)
                    offsets, counts = page.dataoffsets, page.databytecounts
                    ends.extend(o + c for o, c in zip(offsets, counts))
        except Exception:
            return  # SurfaceTopography's own reading decides
        if ends and max(ends) > size:
            raise DataFileError(f"{path}: the TIFF file is truncated ({size:,} bytes; its tags and strips need "
                                f"{max(ends):,}). Copy the file again from the instrument.")
    elif suffix == ".ibw" and len(head) >= 64:
        import struct

        version_le = struct.unpack("<h", head[:2])[0]
        order = "<" if version_le in (1, 2, 3, 5) else ">"
        version = struct.unpack(order + "h", head[:2])[0]
        if version == 5:
            fields = struct.unpack(order + "hh4l4l4l3l", head[:64])
            wfm, formula, note, data_units = fields[2], fields[3], fields[4], fields[5]
            dim_units, dim_labels, indices, options = sum(fields[6:10]), sum(fields[10:14]), fields[14], 0
            need = 64 + wfm + formula + note + data_units + dim_units + dim_labels + indices + options
            if need > size:
                raise DataFileError(f"{path}: the Igor binary wave is truncated ({size:,} bytes; its header declares "
                                    f"{need:,}). Copy the file again from the instrument.")


#: in a message: the formats memstribo reads
_SUPPORTED_SHORT = ("Supported: what SurfaceTopography reads (.di/.001, .tiff, .ibw, Dektak .opdx/.csv, .gwy, .x3p, "
                    "...), contact.engineering .zip, x-z or z text, .npy.")


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


def _read_container(path, name, channel, unit, physical_size=None):
    try:
        archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, OSError, EOFError, ValueError) as exc:
        raise DataFileError(f"{path}: not a readable zip container ({printable(exc, 100)}).") from None
    with archive:
        members = [m for m in archive.namelist() if not m.endswith("/") and not m.lower().startswith("license")
                   and m != "meta.yml"]
        if not members:
            raise DataFileError(f"{path}: the zip holds no measurement files.")
        meta = _container_meta(archive)
        member_text, _, channel_text = (channel or "").partition("::")
        shown = [printable(m, 60) for m in members[:10]] + (["..."] if len(members) > 10 else [])
        if member_text:
            chosen = [m for m in members if m == member_text] or [m for m in members if member_text.lower() in m.lower()]
            if len(chosen) != 1:
                what = "matches several members" if chosen else "matches no member"
                raise DataFileError(f"{path}: channel '{printable(channel, 60)}' {what}. Members: {', '.join(shown)} "
                                    "(give a member name or a unique part of it; add '::CHANNEL' for a channel "
                                    "inside it).")
            member = chosen[0]
        else:
            afm = [m for m in members if _is_afm_member(m)]
            member = (afm or members)[0]
        if archive.getinfo(member).file_size > _MEMBER_MAX_BYTES:
            raise DataFileError(f"{path}: member '{printable(member, 60)}' unpacks to "
                                f"{archive.getinfo(member).file_size:,} bytes; memstribo reads members of at most "
                                f"{_MEMBER_MAX_BYTES:,}.")
        try:
            data = archive.read(member)
        except (zipfile.BadZipFile, OSError, EOFError, ValueError, NotImplementedError, RuntimeError) as exc:
            raise DataFileError(f"{path}: member '{printable(member, 60)}' cannot be unpacked "
                                f"({printable(exc, 100)}); the zip is damaged.") from None
    member_path = f"{path}::{printable(member, 80)}"
    member_name = f"{Path(path).name}/{printable(member, 80)}"
    declared = (meta.get(member) or {}).get("unit")
    declared = declared if isinstance(declared, str) else None
    if member.lower().endswith(_TEXT):
        profile = _read_text(data, member_path, member_name, unit, declared_unit=declared,
                             physical_size=physical_size)
        extra = f"; unit {declared} from meta.yml" if declared else ""
        if isinstance(profile, SurfaceMap):
            return profile
        return profile.replace(source=profile.source + extra)
    try:
        reader = _st_open(io.BytesIO(data), member_path, Path(member).suffix.lower())
    except _NotRead as exc:
        raise DataFileError(f"{member_path}: SurfaceTopography cannot read this member ({exc}).") from None
    result = _st_topography(reader, member_path, member_name, channel_text or None, unit,
                            physical_size=physical_size)
    note = "; the member's own Z calibration (meta.yml's height_scale is not applied again)"
    if isinstance(result, SurfaceMap):
        return SurfaceMap(heights=result.heights, dx=result.dx, dy=result.dy, name=result.name,
                          source=result.source + note, channel=f"{member}::{result.channel}")
    return result.replace(source=result.source + note)


#: largest zip member memstribo unpacks (a crafted zip can unpack to far more than it holds)
_MEMBER_MAX_BYTES = 2 * 2**30

#: text extensions: plain numbers go to SurfaceTopography first, then memstribo's units and checks; the one-line
#: 'Image Width' export (which SurfaceTopography reads as a 16384 x 1 map) is memstribo's own
_PLAIN_FIRST = _TEXT


def read_topography(path, channel=None, unit=None, physical_size=None):
    """Read a measured surface: a profile or a height map, in metres.

    Every format SurfaceTopography reads goes through it (instrument files, and text or CSV
    files with an instrument header such as a Bruker Dektak CSV export), with the file's
    channels, units and sizes. Plain numeric x-z text goes to SurfaceTopography first as well;
    memstribo then applies the per-axis units of its column-header line (``x [um], z [nm]``) and
    its checks. memstribo's own readers are the fallback for text SurfaceTopography refuses (a
    z-only column), and read the one-line text export with an 'Image Width'/'Image Height'
    header (which SurfaceTopography reads as a 16384 x 1 map) and ``.npy`` x-z arrays. Text is read in UTF-8 (with or without BOM),
    UTF-16 (with BOM) or Latin-1, with LF, CRLF or CR line endings.

    Parameters
    ----------
    path : str or pathlib.Path
        Instrument file (NanoScope .di/.001, Park .tiff, Asylum .ibw, Dektak .opdx or .csv,
        Gwyddion, x3p, ... through SurfaceTopography), a contact.engineering ``.zip``
        container, an x-z text/CSV profile (``#`` comments, one optional line of column
        names), an ``.npy`` x-z array or a one-line text export with an
        'Image Width'/'Image Height' header.
    channel : str, optional
        Channel name (``"Height"``) or index (``"ch3"``, ``"3"``); for a ``.zip``, a member
        name or a unique part of it, optionally ``"MEMBER::CHANNEL"``. Default: the file's
        height channel (ch0) or the container's AFM member.
    unit : str, optional
        Unit of x and heights in files that do not declare one (text, .npy): m (default),
        mm, um, nm, A, pm.
    physical_size : float, str or tuple, optional
        Lateral size [m] (or text with a unit, ``"10 um"``; two for a map, ``"10 um, 5 um"``)
        of a file that does not give one (a map without scan size, a z-only text profile).

    Returns
    -------
    Profile or SurfaceMap
        Heights [m], not levelled.

    Raises
    ------
    DataFileError
        Missing, empty, unreadable, truncated or corrupt file, unknown format, unknown
        channel, undefined (NaN/masked) pixels, repeated or decreasing x, fewer than 3 points,
        heights whose Rq (> 1 mm or < 1 pm) suggests a wrong unit, a lateral step below 1 pm
        or a length above 1 m, no lateral size (give ``physical_size``). One message, naming
        the file, the format(s) tried and what is supported; text from the file is shown with
        its control characters escaped.
    """
    path = Path(path)
    shown = printable(path, 200)
    if unit is not None:
        _unit_factor(unit, "--unit")
    try:
        return _read(path, shown, channel, unit, physical_size)
    except (MemoryError, MemstriboError, KeyboardInterrupt):
        raise
    except RecursionError:
        raise DataFileError(f"{shown}: the file's structure is nested too deeply to read; it is damaged.") from None
    except Exception as exc:  # a reader failed in a way it does not report itself: a damaged file
        raise DataFileError(f"{shown}: could not read the file ({type(exc).__name__}: {printable(exc, 120)}); it "
                            "may be damaged or truncated.") from None


def _read(path, shown, channel, unit, physical_size):
    if not path.exists():
        raise DataFileError(f"file not found: {shown}")
    if path.is_dir():
        raise DataFileError(f"{shown} is a folder; give a measurement file.")
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise DataFileError(f"{shown}: cannot read the file ({exc.strerror}).") from None
    if size == 0:
        raise DataFileError(f"{shown}: the file is empty (0 bytes).")
    suffix = path.suffix.lower()
    name = printable(path.name, 80)
    if suffix == ".zip":
        return _read_container(path, name, channel, unit, physical_size)
    if suffix == ".npy":
        result = _read_npy(path, name, unit)
    else:
        result = None
        text = None
        if suffix in _PLAIN_FIRST:
            if size > _MEMBER_MAX_BYTES:
                raise DataFileError(f"{shown}: {size:,} bytes; memstribo reads text files of at most "
                                    f"{_MEMBER_MAX_BYTES:,} bytes.")
            try:
                data = path.read_bytes()
            except OSError as exc:
                raise DataFileError(f"{shown}: cannot read the file ({exc.strerror}).") from None
            text = _decode_text(data, shown)
            head = text[:2000].lower() if text is not None else ""
            if "image width" in head and "image height" in head:
                result = _read_header_export(text, shown, name, unit)
            elif text is not None:
                plain = _plain_rows(text)
                if plain is not None:
                    result = _read_plain_text(text, plain, shown, name, unit, physical_size=physical_size)
        if result is None:
            known = suffix in _ST_EXTENSIONS or suffix in _TEXT or bool(re.fullmatch(r"\.\d{3}", suffix))
            if known:
                _check_complete(path, suffix, size)
            # text re-encoded to UTF-8 with LF line ends, so that a BOM or CR line ends do not stop the reader
            source = io.BytesIO(text.encode("utf-8")) if text is not None else str(path)
            try:
                reader = _st_open(source, shown, suffix)
            except _NotRead as exc:
                if suffix in _TEXT:
                    raise DataFileError(f"{shown}: not a readable x-z text profile ({_text_reason(text, shown)}), nor "
                                        f"a format SurfaceTopography reads ({exc}). {_SUPPORTED_SHORT}") from None
                if not known:
                    raise DataFileError(f"{shown}: unknown format '{printable(suffix or '(no extension)', 20)}'. "
                                        "Supported: .di/.001 (NanoScope), .tiff (Park), .ibw (Asylum), .opdx/.csv "
                                        "(Dektak), .gwy, .x3p, .sur, .plu and the other formats SurfaceTopography "
                                        "reads, .zip (contact.engineering), x-z text (.txt .csv .dat .asc) and .npy; "
                                        f"SurfaceTopography: {exc}.") from None
                raise DataFileError(f"{shown}: could not read the file: SurfaceTopography {exc}. It is damaged, "
                                    f"truncated or not what its extension says. {_SUPPORTED_SHORT}") from None
            return _st_topography(reader, shown, name, channel, unit, fix_ibw=suffix == ".ibw",
                                  physical_size=physical_size)
    if channel is not None:
        allowed = {"default", "0", "ch0", str(getattr(result, "channel", "")).lower()}
        if str(channel).lower() not in allowed:
            raise DataFileError(f"{shown}: no channel '{printable(channel, 40)}'; this file has one channel: "
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
    from memstribo.output import ensure_directory

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
    from memstribo.output import atomic_write

    try:
        atomic_write(path, lambda tmp: np.savetxt(tmp, np.column_stack([profile.x, profile.z]), fmt="%.17g",
                                                  delimiter=delimiter, header=header))
    except OSError as exc:
        raise InputError(f"cannot write '{path}': {exc.strerror}.") from None
    return path
