"""``read_topography``: which reader takes a file, and the checks every file gets first; ``write_profile``."""

from __future__ import annotations

import io
import re
from pathlib import Path

import numpy as np

from memstribo.errors import DataFileError, InputError, MemstriboError
from memstribo.surfaces.roughness import Profile
from memstribo.units import printable
from memstribo.surfaces.readers._common import _ST_EXTENSIONS, _TEXT, _unit_factor
from memstribo.surfaces.readers.containers import _read_container
from memstribo.surfaces.readers.instruments import _NotRead, _check_complete, _st_open, _st_topography
from memstribo.surfaces.readers.numpy_files import _read_npy
from memstribo.surfaces.readers.text import _decode_text, _plain_rows, _read_header_export, _read_plain_text, _text_reason

#: in a message: the formats memstribo reads
_SUPPORTED_SHORT = ("Supported: what SurfaceTopography reads (.di/.001, .tiff, .ibw, Dektak .opdx/.csv, .gwy, .x3p, "
                    "...), contact.engineering .zip, x-z or z text, .npy.")

#: text extensions: plain numbers go to SurfaceTopography first, then memstribo's units and checks; the one-line
#: 'Image Width' export (which SurfaceTopography reads as a 16384 x 1 map) is memstribo's own
_PLAIN_FIRST = _TEXT

#: largest text file read [bytes], checked by its size before reading (issue #41: a 1.9 GB file took 6.2 GB of
#: memory before its refusal): 1 GiB holds memstribo's 10 million points at 100 characters each
_TEXT_MAX_BYTES = 2**30


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
        or a length above 1 m, no lateral size (give ``physical_size``); a file that contradicts
        itself (an Igor note whose ScanPoints/ScanLines differ from the wave or whose scan size
        is not a positive finite length, a NanoScope image whose line counts do not fill its
        data block, a negative Gwyddion size, a text header naming the height column before x),
        numbers written with non-ASCII digits, float16 ``.npy`` arrays, a constant surface. One
        message, naming the file, the format(s) tried and what is supported; text from the file
        is shown with its control characters escaped.
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
    if not path.is_file():  # /dev/zero, a pipe, a socket: reading it could never end
        raise DataFileError(f"{shown} is not a regular file (a device, pipe or socket); give a measurement file.")
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
            if size > _TEXT_MAX_BYTES:
                raise DataFileError(f"{shown}: {size:,} bytes; memstribo reads text files of at most "
                                    f"{_TEXT_MAX_BYTES:,} bytes (1 GiB: 10 million points of 100 characters).")
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
