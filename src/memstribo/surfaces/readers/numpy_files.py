"""NumPy ``.npy`` files: x-z profiles (n x 2 or 2 x n) and 2D height maps, checked from the header before loading.

The header (shape, dtype) is read first, so a file that claims more points than memstribo reads
is refused with its name and shape before any memory is allocated; integer heights (counts, not
metres), complex numbers and float16 (about 3 digits; below 6e-5 only multiples of 6e-8) are
refused rather than converted; a constant map (all zero, say) has no roughness and is refused.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from memstribo.errors import DataFileError
from memstribo.surfaces.readers._common import MAX_POINTS, _Z_MAX, _check_finite, _profile_from_xz
from memstribo.units import printable

__all__ = ["read_height_array"]


def _header(path):
    """(shape, dtype) of a ``.npy`` file from its header alone; DataFileError if there is none."""
    try:
        with open(path, "rb") as handle:
            version = np.lib.format.read_magic(handle)
            if version == (1, 0):
                shape, _, dtype = np.lib.format.read_array_header_1_0(handle)
            else:
                shape, _, dtype = np.lib.format.read_array_header_2_0(handle)
    except (ValueError, OSError, EOFError, SyntaxError):
        raise DataFileError(f"{path}: not a readable .npy file (no NumPy header: corrupt or truncated).") from None
    return tuple(int(n) for n in shape), np.dtype(dtype)


def _load(path, integers_allowed, what):
    """The array of a ``.npy`` file after its header is checked: size, numeric kind."""
    shape, dtype = _header(path)
    points = int(np.prod(shape, dtype=float)) if shape else 1
    if points > MAX_POINTS:
        raise DataFileError(f"{path}: the .npy header declares an array of shape {' x '.join(map(str, shape))} "
                            f"({points:.3g} values); memstribo reads at most {MAX_POINTS:,} points per profile or "
                            "map.")
    if dtype.kind == "c":
        raise DataFileError(f"{path}: the .npy array is complex ({dtype}); {what} are real numbers: save the real "
                            "part (np.real) if that is the height.")
    allowed = "f" + ("iu" if integers_allowed else "")
    if dtype.kind not in allowed:
        hint = (" Integers are counts, not metres: convert to floating-point heights in m (e.g. "
                "heights * z_scale) before saving." if dtype.kind in "iub" else "")
        raise DataFileError(f"{path}: the .npy array holds {dtype} values; {what} must be floating-point numbers."
                            + hint)
    if dtype == np.float16:
        raise DataFileError(f"{path}: the .npy array holds float16 values: 11 significant bits (about 3 decimal "
                            "digits) and, below 6e-5, only multiples of 6e-8: heights of nanometres in metres round "
                            f"to 0 or to steps of 60 nm. Allowed: {what} saved as float32 or float64.")
    try:
        return np.load(path, allow_pickle=False)
    except MemoryError:
        raise
    except Exception:  # numpy raises several types for corrupt files
        raise DataFileError(f"{path}: not a readable .npy file (corrupt, truncated or holding Python objects).") from None


def _read_npy(path, name, unit):
    """An x-z profile from a ``.npy`` array of shape (n, 2) or (2, n), in m unless ``unit`` says otherwise."""
    array = _load(path, integers_allowed=True, what="x and heights")
    array = np.asarray(array, dtype=float) if array.dtype.kind in "fiu" else None
    if array is None or array.ndim != 2 or 2 not in array.shape:
        raise DataFileError(f"{path}: a .npy profile must be a numeric array of shape (n, 2) or (2, n) holding x and "
                            "height (in m unless --unit says otherwise).")
    table = array if array.shape[1] == 2 and array.shape[0] != 2 else array.T
    return _profile_from_xz(table[:, 0], table[:, 1], path, name, f"{path} (numpy x-z array, {unit or 'm'})", unit)


def read_height_array(path) -> np.ndarray:
    """A 2D map of heights [m] from a ``.npy`` file, checked before and after loading.

    Parameters
    ----------
    path : str or pathlib.Path
        A NumPy ``.npy`` file holding one 2D floating-point array of heights in metres, shape
        (ny, nx), at least 2 x 2.

    Returns
    -------
    numpy.ndarray
        The heights [m] as float64, shape (ny, nx).

    Raises
    ------
    DataFileError
        Not a regular file; no .npy header; a header declaring more than ``MAX_POINTS`` values
        (named with the file and its shape, before anything is loaded); integer, boolean,
        complex or float16 values (too few digits for nm heights in m); not 2D or smaller than
        2 x 2; NaN or infinite heights; a constant (e.g. all-zero) map, which has no roughness;
        heights above 0.1 m (heights that are not in metres).
    """
    path = Path(path)
    shown = printable(path, 200)
    if not path.exists():
        raise DataFileError(f"file not found: {shown}")
    if not path.is_file():
        raise DataFileError(f"{shown} is not a regular file (a folder, device or pipe); give a .npy file.")
    array = _load(shown, integers_allowed=False, what="heights [m]")
    if array.ndim != 2 or min(array.shape) < 2:
        raise DataFileError(f"{shown}: a .npy map must hold a 2D array of heights [m] with at least 2 x 2 points, "
                            f"got shape {array.shape}.")
    heights = np.asarray(array, dtype=float)
    _check_finite(heights, shown)
    if np.ptp(heights) == 0:
        raise DataFileError(f"{shown}: every height is {heights.flat[0]:g} m: a constant map has no roughness (a "
                            "contact solved on it is a flat one, whatever the measurement was). Allowed: measured "
                            "heights that vary; check that the array saved is the height channel, in m.")
    peak = float(np.max(np.abs(heights)))
    if peak > _Z_MAX:
        raise DataFileError(f"{shown}: heights reach {peak:.3g} m, more than {_Z_MAX:g} m: not a measured surface, or "
                            "the heights are not in metres (a .npy map holds heights in m: multiply by the unit's "
                            "size, e.g. 1e-9 for nm, before saving).")
    return heights
