"""Text profiles and maps: plain x-z (or z) text with per-axis units, and the one-line export with an image header."""

from __future__ import annotations

import codecs
import io
import re
import unicodedata

import numpy as np

from memstribo.errors import DataFileError
from memstribo.units import printable
from memstribo.surfaces.readers._common import LENGTH_UNITS, MAX_POINTS, SurfaceMap, _check_finite, _check_lateral, _check_magnitude, _check_unit_option, _physical_sizes, _profile_from_xz, _unit_factor
from memstribo.surfaces.readers.instruments import _NotRead, _QuietLogs, _st_open

_HEADER_SHAPE = re.compile(r"\((\d+)\s*x\s*(\d+)\)")
#: header lines of the one-line export whose values memstribo reads as numbers
_EXPORT_NUMBERS = ("image width", "image height", "real width", "real height")


def _read_header_export(text, path, name, unit):
    """The one-line export: 'key : value' header lines, then all nx*ny heights (row-major)."""
    lines = text.splitlines()
    header = {}
    start = None
    for i, line in enumerate(lines):
        if " : " in line or line.strip().endswith(":"):
            key, _, value = line.partition(":")
            header[key.strip().lower()] = value.strip()
            if key.strip().lower() in _EXPORT_NUMBERS:  # int() and float() read '\uff11\uff12\uff18' as 128
                _check_ascii_digits(line, path, every_line=True, first_line=i + 1)
        elif line.strip():
            start = i
            break
    if start is not None:
        _check_ascii_digits("\n".join(lines[start:]), path, every_line=True, first_line=start + 1)
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
    _check_ascii_digits(text, path)
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


def _non_ascii_digit(line):
    """The first decimal digit of ``line`` that is not ASCII 0-9 (float() reads '\uff11\uff12' and '\u0661\u0662' as 12), or None."""
    return next((c for c in line if not c.isascii() and c.isdecimal()), None)


def _check_ascii_digits(text, path, every_line=False, first_line=1):
    """Refuse numbers written with non-ASCII digits: a data row (a row of numbers once its digits are read as
    ASCII) or, with ``every_line``, any line. Comment lines and words elsewhere in a header may hold them."""
    if text.isascii():
        return
    for number, line in enumerate(text.split("\n"), start=first_line):
        digit = _non_ascii_digit(line)
        if digit is None or line.lstrip().startswith("#"):
            continue
        ascii_line = "".join(str(unicodedata.decimal(c)) if not c.isascii() and c.isdecimal() else c for c in line)
        if every_line or _NUMBER_ROW.match(ascii_line.strip()):
            raise DataFileError(f"{path}: line {number} holds the non-ASCII digit '{digit}' (U+{ord(digit):04X} "
                                f"{unicodedata.name(digit, 'DIGIT')}); numbers in a measurement file are written with "
                                "the ASCII digits 0-9 (memstribo does not read other digits as numbers): convert the "
                                "file's digits to 0-9.")


# ASCII digits only: Python's float() also reads full-width (U+FF10..) and Arabic-Indic digits
_NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?|[-+]?(?:nan|inf|infinity)"
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


#: first words of a column name that say which quantity the column holds
_POSITION_NAMES = {"x", "position", "pos", "distance", "lateral", "length", "scan", "width"}
_HEIGHT_NAMES = {"z", "height", "heights", "h", "depth", "topography", "topo", "elevation", "zsensor"}


def _column_kind(field):
    """'x' or 'z' for a column name whose first word names a position or a height, else None."""
    word = next((w for w in re.split(r"[^A-Za-z]+", field) if w), "").lower()
    return "x" if word in _POSITION_NAMES else "z" if word in _HEIGHT_NAMES else None


def _check_column_order(header, fields, path):
    """Refuse a column-header line naming the height before the position: memstribo reads the columns by place
    (first x, then the height) and would give each the other's unit, or read the heights as positions."""
    if len(fields) == 2 and (_column_kind(fields[0]), _column_kind(fields[1])) == ("z", "x"):
        raise DataFileError(f"{path}: the header line '{printable(header, 60)}' names the height column first and "
                            "the position second; memstribo reads the first column as x (position) and the second "
                            "as the height, each with its own unit. Allowed: x first ('x [um], z [nm]'): swap the "
                            "columns and their names.")


def _header_units(header, path):
    """Units of the x and z columns named in a column-header line ('x [um], z [nm]'), or (None, None)."""
    if not header:
        return None, None
    fields = [f for f in re.split(r"\s*[,;\t]\s*", header.strip().strip(",;")) if f]
    if len(fields) != 2:
        bracketed = [f.strip() for f in re.findall(r"[^\[\]()]*[\[(][^\])]*[\])]", header)]
        fields = bracketed if len(bracketed) == 2 else header.split()
    _check_column_order(header, fields, path)
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
