"""Writing results: labelled datasets (NetCDF + CSV), figures (PNG + SVG), JSON.

Results are :class:`xarray.Dataset` objects whose variables carry ``units`` and
``long_name`` attributes. These helpers write them so that nothing already computed is
lost: each file is written to a temporary name and renamed into place.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any

import numpy as np

from .errors import InputError


def ensure_directory(path: str | Path) -> Path:
    """Create ``path`` (and parents) if needed; raise :class:`InputError` if impossible."""
    path = Path(path)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot create output folder '{path}': {exc.strerror}.") from None
    if not os.access(path, os.W_OK):
        raise InputError(f"output folder '{path}' is not writable.")
    return path


def _atomic_write(path: Path, write) -> Path:
    tmp = path.with_name(path.name + ".tmp")
    write(tmp)
    os.replace(tmp, path)
    return path


def write_dataset(dataset, folder: str | Path, stem: str, csv: bool = True) -> list[Path]:
    """Write ``dataset`` to ``folder/stem.nc`` (NetCDF) and, if ``csv``, ``folder/stem.csv``.

    Units stay as variable attributes in NetCDF; CSV column headers read ``name [unit]``.
    The CSV holds the variables along the dataset's main dimension (see :func:`_table`);
    the NetCDF file holds everything.
    Returns the paths written.
    """
    folder = ensure_directory(folder)
    written = [_atomic_write(folder / f"{stem}.nc", lambda tmp: dataset.to_netcdf(tmp, format="NETCDF4"))]
    if csv:
        frame = _table(dataset).to_dataframe()
        frame.columns = [_column_label(dataset, name) for name in frame.columns]
        frame.index.names = [_column_label(dataset, name) for name in frame.index.names]
        written.append(_atomic_write(folder / f"{stem}.csv", lambda tmp: frame.to_csv(tmp)))
    return written


def _table(dataset):
    """The part of ``dataset`` that is a table: variables along its main dimension.

    A CSV file is a table; variables with more dimensions (per-block loads over steps, say)
    would multiply its rows, so they stay in the NetCDF file only. The main dimension is
    the one most one-dimensional variables run along.
    """
    one_dimensional = [v for v in dataset.data_vars.values() if v.ndim == 1]
    if not one_dimensional or all(v.ndim <= 1 for v in dataset.data_vars.values()):
        return dataset
    dims = [v.dims[0] for v in one_dimensional]
    main = max(set(dims), key=dims.count)
    keep = [name for name, v in dataset.data_vars.items() if v.dims == (main,)]
    table = dataset[keep]
    return table.drop_vars([c for c in table.coords if table[c].dims not in ((main,), ())])


def _column_label(dataset, name) -> str:
    variable = dataset.variables.get(name)
    unit = variable.attrs.get("units", "") if variable is not None else ""
    return f"{name} [{unit}]" if unit else str(name)


def save_figure(figure, folder: str | Path, stem: str, formats=("png", "svg")) -> list[Path]:
    """Save a matplotlib ``figure`` as ``folder/stem.<fmt>`` for each format, then close it."""
    import matplotlib.pyplot as plt

    folder = ensure_directory(folder)
    written = []
    for fmt in formats:
        written.append(_atomic_write(folder / f"{stem}.{fmt}",
                                     lambda tmp, fmt=fmt: figure.savefig(tmp, format=fmt, dpi=150,
                                                                         bbox_inches="tight")))
    plt.close(figure)
    return written


def new_figure(*args, **kwargs):
    """``plt.subplots`` on the non-interactive Agg backend (safe without a display)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt.subplots(*args, **kwargs)


def to_jsonable(value: Any) -> Any:
    """Convert numpy scalars/arrays and nested containers to plain JSON types.

    Non-finite floats become ``None`` (JSON has no NaN); callers should avoid them.
    """
    if isinstance(value, dict):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [to_jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return [to_jsonable(v) for v in value.tolist()]
    if isinstance(value, (np.bool_, bool)):
        return bool(value)
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (np.floating, float)):
        value = float(value)
        return value if math.isfinite(value) else None
    if isinstance(value, Path):
        return str(value)
    return value


def dumps_json(value: Any) -> str:
    """One JSON object, SI values, no NaN."""
    return json.dumps(to_jsonable(value), indent=2, allow_nan=False)


# --- readable numbers (CLI tables, report) -------------------------------------------------
_PREFIXES = [(1e-18, "a"), (1e-15, "f"), (1e-12, "p"), (1e-9, "n"), (1e-6, "u"), (1e-3, "m"), (1.0, ""),
             (1e3, "k"), (1e6, "M"), (1e9, "G"), (1e12, "T")]
# units that take SI prefixes in readable output
_PREFIXABLE = {"m", "N", "Pa", "J", "s", "N*m", "N/m", "J/m^2", "W"}


def format_quantity(value: float, unit: str = "") -> str:
    """``2.5e-05, "N"`` -> ``"25 uN"``: a number with an engineering prefix and its unit."""
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if isinstance(value, (int, np.integer)) and not unit:
        return str(int(value))
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    if unit in _PREFIXABLE and value != 0.0:
        magnitude = abs(value)
        factor, prefix = _PREFIXES[0]
        for f, p in _PREFIXES:
            if magnitude >= f * 0.9995:
                factor, prefix = f, p
        return f"{value / factor:.4g} {prefix}{unit}"
    return f"{value:.4g} {unit}".rstrip()


def format_value(value: Any, unit: str = "") -> str:
    """Readable form of a result value: scalars with units, lists and dicts element-wise."""
    if isinstance(value, dict):
        return ", ".join(f"{k}: {format_value(v, unit)}" for k, v in value.items())
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(format_value(v, unit) for v in value) + "]"
    if isinstance(value, str):
        return value
    return format_quantity(value, unit)
