"""Instrument files through SurfaceTopography: open, pick the channel, convert to m, check, refuse truncated files."""

from __future__ import annotations

import logging
import re
import warnings

import numpy as np

from memstribo.errors import DataFileError
from memstribo.surfaces.roughness import Profile
from memstribo.units import printable
from memstribo.surfaces.readers._common import MAX_POINTS, SurfaceMap, _check_finite, _check_lateral, _check_magnitude, _check_unit_option, _physical_sizes

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


def _units(reader):
    """', whose units are ...' for a Gwyddion reader's data fields (from its raw metadata), or ''."""
    fields = [v.get("GwyDataField", {}) for k, v in (getattr(reader, "_metadata", None) or {}).items()
              if str(k).endswith("/data") and isinstance(v, dict)]
    units = sorted({str(f.get("si_unit_z", {}).get("GwySIUnit", {}).get("unitstr", "")) for f in fields
                    if isinstance(f.get("si_unit_z"), dict)})
    return f": its data have height unit(s) {', '.join(printable(u, 10) or '(none)' for u in units)}" if units else ""


def _check_scan_size(c, path):
    """The scan size the file states: finite and positive.

    SurfaceTopography reads a Gwyddion size 0 as 1 m and a negative one as its absolute value (as Gwyddion
    does); a negative size may stand for a mirrored axis, which memstribo would not know to undo: refused.
    """
    raw = (c.info or {}).get("raw_metadata", {}) or {}
    field = next((v.get("GwyDataField") for k, v in raw.items() if str(k).endswith("/data") and isinstance(v, dict)
                  and isinstance(v.get("GwyDataField"), dict)), None)
    stated = [(field[k], k) for k in ("xreal", "yreal") if k in field] if field else []
    stated += [(s, None) for s in np.atleast_1d(c.physical_sizes if c.physical_sizes is not None else [])
               if s is not None]
    for value, label in stated:
        if isinstance(value, (int, float, np.number)) and np.isfinite(value) and value > 0:
            continue
        shown = repr(float(value)) if isinstance(value, (int, float, np.number)) else repr(value)
        what = f" ({label})" if label else ""
        if isinstance(value, (int, float, np.number)) and value < 0:
            raise DataFileError(f"{path}: the file states a scan size of {shown}{what}, which is not a positive "
                                "length; memstribo does not take a negative size as its absolute value (it may stand "
                                "for a mirrored axis). Allowed: positive sizes; make the size positive in your AFM "
                                "software (and flip the data if the axis was mirrored).")
        raise DataFileError(f"{path}: the file states a scan size of {shown}{what}, which is not a positive length; "
                            "the file is damaged or was saved without its size (memstribo does not assume one).")


_NOTE_NUMBER = re.compile(r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")


def _ibw_pixel_size(raw, nx, ny, path):
    """(dx, dy) = (FastScanSize / ScanPoints, SlowScanSize / ScanLines) from an Asylum note, or None without ScanSize.

    The note must describe the wave: sizes positive and finite, ScanPoints and ScanLines (where given) equal to
    the wave's points per line and lines. A note that contradicts the wave (a cropped or resampled image whose
    note was kept) is refused: its pixel size would be wrong, and memstribo does not guess which is right.
    """
    fast = raw.get("FastScanSize", raw.get("ScanSize"))
    slow = raw.get("SlowScanSize", raw.get("ScanSize"))
    if fast is None or slow is None:
        return None
    sizes = []
    for key, text in (("FastScanSize" if "FastScanSize" in raw else "ScanSize", fast),
                      ("SlowScanSize" if "SlowScanSize" in raw else "ScanSize", slow)):
        text = str(text).strip()
        value = float(text) if _NOTE_NUMBER.fullmatch(text) else float("nan")
        if not (np.isfinite(value) and value > 0):
            raise DataFileError(f"{path}: the Igor note states '{key}: {printable(text, 20)}', not a positive finite "
                                "length in m; the file is damaged or was saved without its scan size (memstribo does "
                                f"not assume one). Allowed: a positive number of metres ('{key}: 2e-06').")
        sizes.append(value)
    counts = []
    for key, n, what in (("ScanPoints", nx, "points per line"), ("ScanLines", ny, "lines")):
        text = str(raw.get(key, n)).strip()
        m = re.fullmatch(r"([0-9]+)(?:\.0*)?", text)
        if m is None or int(m.group(1)) != n:
            raise DataFileError(f"{path}: the Igor note states '{key}: {printable(text, 20)}' but the wave holds {n} "
                                f"{what}: the note does not describe this wave (cropped or resampled?), and a pixel "
                                "size from it would be wrong; memstribo does not guess which is right. Allowed: "
                                f"ScanPoints and ScanLines equal to the wave's {nx} x {ny}; correct the note or export "
                                "the image again.")
        counts.append(n)
    return sizes[0] / counts[0], sizes[1] / counts[1]


def _check_nanoscope_counts(c, path):
    """A NanoScope image section's Samps/line x Number of lines must fill its data block exactly.

    SurfaceTopography takes the file's global counts when they fit the block instead, and scales the scan size
    by their ratio (a 10 um scan with 'Samps/line: 100000' is read as 25.6 nm); with counts that fill only part
    of the block it reads the first pixels. Both are the wrong geometry: refused.
    """
    raw = (c.info or {}).get("raw_metadata", {}) or {}
    if not all(k in raw for k in ("samps/line", "number of lines", "data length")):
        return
    try:
        nx, ny, length = int(raw["samps/line"]), int(raw["number of lines"]), int(raw["data length"])
        elsize = int((getattr(c, "tags", None) or {}).get("elsize", raw.get("bytes/pixel", 2)))
    except (TypeError, ValueError):
        return  # SurfaceTopography's own reading decides
    read = tuple(int(n) for n in c.nb_grid_pts) if c.nb_grid_pts is not None else (nx, ny)
    if read == (nx, ny) and nx * ny * elsize == length:
        return
    other = f" (SurfaceTopography would read {read[0]} x {read[1]})" if read != (nx, ny) else ""
    raise DataFileError(f"{path}: image '{printable(c.name, 40)}' (ch{c.index}) states Samps/line {nx} and Number "
                        f"of lines {ny} ({nx * ny:,} pixels of {elsize} bytes), but its data block holds {length:,} "
                        f"bytes{other}: the line counts contradict the data, so the pixel size cannot be trusted. "
                        "Allowed: Samps/line x Number of lines x bytes per pixel = data length; export the image "
                        "again.")


def _select_channel(reader, channel, path):
    channels = reader.channels
    if not channels:  # e.g. a Gwyddion file whose data fields have a height unit that is not a length (V)
        raise DataFileError(f"{path}: the file has no height channel (a channel whose heights are lengths){_units(reader)}; "
                            "memstribo reads heights in length units (m, nm, ...) only.")
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

def _st_topography(reader, path, name, channel, unit, fix_ibw=False, physical_size=None):
    c = _select_channel(reader, channel, path)
    file_unit = _height_unit(c)
    if isinstance(c.unit, tuple) and file_unit is None:
        raise DataFileError(f"{path}: channel '{printable(c.name, 40)}' (ch{c.index}) is not a height channel (it has "
                            "no length unit). Choose a height channel with --channel.")
    unit_used = _check_unit_option(file_unit, unit, path) if file_unit else (unit or "m")
    kwargs = {} if file_unit else {"unit": unit_used}
    dim = c.dim if c.dim in (1, 2) else 2
    _check_scan_size(c, path)
    _check_nanoscope_counts(c, path)
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
        pixel = _ibw_pixel_size((c.info or {}).get("raw_metadata", {}) or {}, nx, ny, path)
        if pixel is not None:
            dx, dy = pixel
            source += "; pixel size ScanSize/points from the Igor header (SurfaceTopography uses ScanSize/(points-1))"
        else:
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
