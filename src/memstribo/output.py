"""Writing results: labelled datasets (NetCDF + CSV), figures (PNG + SVG), JSON.

Results are :class:`xarray.Dataset` objects whose variables carry ``units`` and
``long_name`` attributes. These helpers write them so that nothing already computed is
lost: each file is written to a temporary name and renamed into place. Every NetCDF and
CSV file says what made it (:func:`provenance_attributes`: memstribo version, creation
time, parameters and overrides, load case, roughness source with its SHA-256) and follows
the CF conventions for its variables (``units`` in UDUNITS form, ``long_name``).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import re
from collections.abc import Mapping
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

import numpy as np

from memstribo.errors import InputError


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


def atomic_write(path: Path, write) -> Path:
    """Write ``path`` through ``write(tmp)`` into ``path.tmp`` and rename it: a reader (or a killed
    run) never sees a half-written file. The one atomic-write helper of memstribo."""
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    try:
        write(tmp)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
    return path


def atomic_write_text(path: Path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically (:func:`atomic_write`)."""
    return atomic_write(Path(path), lambda tmp: Path(tmp).write_text(text, encoding="utf-8"))


_atomic_write = atomic_write


def write_dataset(dataset, folder: str | Path, stem: str, csv: bool = True, *,
                  provenance: Mapping[str, Any] | None = None) -> list[Path]:
    """Write ``dataset`` to ``folder/stem.nc`` (NetCDF) and, if ``csv``, ``folder/stem.csv``.

    Every variable gets CF-style attributes: ``units`` in UDUNITS form (see
    :func:`udunits`; ``'1'`` for dimensionless) and a ``long_name`` (derived from the
    variable's name when missing). The global attributes are ``provenance`` (see
    :func:`provenance_attributes`; without it, the version, creation time and conventions
    only) merged with the dataset's own attributes. The dataset passed in is not changed.

    CSV column headers read ``name [unit]``; the file starts with a block of ``#`` lines
    holding the same provenance as the NetCDF file, so read it with
    ``pandas.read_csv(path, comment="#", index_col=0)`` or
    ``numpy.loadtxt(path, delimiter=",", comments="#", skiprows=...)``.
    The CSV holds the variables along the dataset's main dimension (see :func:`_table`);
    the NetCDF file holds everything.

    Parameters
    ----------
    dataset : xarray.Dataset
        Variables with ``units`` (and ideally ``long_name``) attributes.
    folder : str or pathlib.Path
        Output folder (created).
    stem : str
        File name without suffix.
    csv : bool
        Also write the CSV table.
    provenance : mapping, optional
        Global attributes from :func:`provenance_attributes`.

    Returns
    -------
    list of pathlib.Path
        The paths written.
    """
    folder = ensure_directory(folder)
    dataset = cf_dataset(dataset, provenance)
    encoding = netcdf_encoding(dataset)
    written = [_atomic_write(folder / f"{stem}.nc",
                             lambda tmp: dataset.to_netcdf(tmp, format="NETCDF4", encoding=encoding))]
    if csv:
        frame = _table(dataset).to_dataframe()
        frame.columns = [_column_label(dataset, name) for name in frame.columns]
        frame.index.names = [_column_label(dataset, name) for name in frame.index.names]
        header = _csv_header(dataset, f"{stem}.csv", f"{stem}.nc")

        def write_csv(tmp):
            with open(tmp, "w", encoding="utf-8", newline="") as handle:
                handle.write(header)
                frame.to_csv(handle, lineterminator="\n")

        written.append(_atomic_write(folder / f"{stem}.csv", write_csv))
    return written


# --- provenance and CF attributes --------------------------------------------------------------
CONVENTIONS = "CF-1.8"

#: Parameters that define the load case of a meshing cycle (also in ``load_case_parameters``).
LOAD_CASE_PARAMETERS = ("load_case", "normal_load", "drive_torque", "pinion_speed", "load_sharing", "face_width",
                        "coating_wear", "mesh_steps", "interface_model", "contact_adhesion", "realisations")

_DIMENSIONLESS = {"", "-", "1", "none", "dimensionless", "unitless", "[]", "[-]"}


def udunits(unit: str | None) -> str:
    """A unit string in the form UDUNITS-2 (and so CF) reads: ``'' -> '1'``, ``'Pa^1' -> 'Pa'``.

    Dimensionless units (``''``, ``'-'``, ``'dimensionless'``) become ``'1'``; pint's ``**``
    becomes ``^``; an exponent 1 is dropped; ``'m/s'``, ``'J/m^2'``, ``'N*m'`` and ``'rad/s'``
    are already UDUNITS and stay as they are.

    >>> [udunits(u) for u in ("", "Pa^1", "J/m**2", "N*m", "m")]
    ['1', 'Pa', 'J/m^2', 'N*m', 'm']
    """
    text = "" if unit is None else " ".join(str(unit).split())
    if text.lower() in _DIMENSIONLESS:
        return "1"
    text = text.replace("**", "^").replace(" ^", "^").replace("^ ", "^")
    text = re.sub(r"\^\+?1(?![0-9.])", "", text)
    return text or "1"


def _utc_now() -> str:
    return datetime.now(timezone.utc).replace(microsecond=0).isoformat().replace("+00:00", "Z")


def _version() -> str:
    from memstribo import __version__

    return __version__


def file_sha256(path: str | Path) -> str:
    """SHA-256 (hex) of a file's bytes."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def roughness_provenance(roughness) -> dict[str, str]:
    """Where a roughness profile came from: the file and its SHA-256, or "synthetic: seed N".

    Parameters
    ----------
    roughness : Profile, SurfaceMap, str or pathlib.Path
        A profile or map (its ``source`` names the file it was read from, or says
        "synthetic: ... seed N"), or the path of a measured file.

    Returns
    -------
    dict
        ``roughness_provenance`` (one line), ``roughness_source`` (the profile's own
        provenance text) and, for a file that exists, ``roughness_file`` and
        ``roughness_file_sha256``.
    """
    if isinstance(roughness, (str, Path)) and Path(roughness).is_file():
        path = Path(roughness)
        digest = file_sha256(path)
        return {"roughness_provenance": f"file {path}, sha256 {digest}", "roughness_source": str(path),
                "roughness_file": str(path), "roughness_file_sha256": digest}
    source = str(getattr(roughness, "source", roughness) or "")
    out = {"roughness_source": source}
    if getattr(roughness, "synthetic", False) or "synthetic" in source:
        seed = re.search(r"seed (\d+)", source)
        out["roughness_provenance"] = f"synthetic: seed {seed.group(1)}" if seed else "synthetic: seed not recorded"
        return out
    path = _leading_file(source)
    if path is not None:
        digest = file_sha256(path)
        out.update(roughness_provenance=f"file {path}, sha256 {digest}", roughness_file=str(path),
                   roughness_file_sha256=digest)
    else:
        out["roughness_provenance"] = f"measured, file not found from here: {source}"
    return out


def _leading_file(source: str) -> Path | None:
    """The longest start of ``source`` that names an existing file (readers write "PATH, channel ...")."""
    ends = [m.start() for m in re.finditer(r"[ ,;(]", source)] + [len(source)]
    for end in sorted(ends, reverse=True):
        candidate = source[:end].rstrip(" ,;")
        if candidate and Path(candidate).is_file():
            return Path(candidate)
    return None


#: Packages whose versions every provenance record names (the ones whose behaviour moves the numbers).
KEY_PACKAGES = ("numpy", "scipy", "numba", "xarray", "netCDF4", "SurfaceTopography", "matplotlib", "pint")


def _is_checkout(folder: Path) -> bool:
    """Whether ``folder`` is the root of a memstribo source tree (its pyproject.toml names memstribo)."""
    try:
        text = (folder / "pyproject.toml").read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    return re.search(r'^name\s*=\s*"memstribo"\s*$', text, re.MULTILINE) is not None


def checkout_root(cwd: str | Path | None = None) -> Path | None:
    """The root of the memstribo source tree in use, or None.

    The tree the package was imported from (an editable install or ``PYTHONPATH=src``) comes first;
    otherwise the current folder or one above it, when it is a memstribo checkout (a wheel installed
    with ``pip install .`` and run from the repository root). This is what finds ``data/afm/`` and
    the git commit.
    """
    package = Path(__file__).resolve().parents[2]
    if _is_checkout(package):
        return package
    here = Path(cwd) if cwd is not None else Path.cwd()
    for folder in (here, *here.parents):
        if _is_checkout(folder):
            return folder
    return None


_GIT_CACHE: dict[str, str] = {}


def git_commit(root: str | Path | None = None) -> str:
    """The git commit of the checkout at ``root`` (default :func:`checkout_root`), as text.

    ``"<40 hex digits>"``, with ``" (uncommitted changes)"`` appended when tracked files differ from
    it; ``"none: not run from a checkout of the repository"`` or ``"none: <why>"`` otherwise.
    """
    import subprocess

    root = Path(root) if root is not None else checkout_root()
    if root is None:
        return "none: not run from a checkout of the repository"
    key = str(root)
    if key not in _GIT_CACHE:
        try:
            head = subprocess.run(["git", "-C", key, "rev-parse", "HEAD"], capture_output=True, text=True,
                                  timeout=10)
            if head.returncode != 0 or not re.fullmatch(r"[0-9a-f]{40}", head.stdout.strip()):
                _GIT_CACHE[key] = "none: the checkout has no git history here"
            else:
                dirty = subprocess.run(["git", "-C", key, "status", "--porcelain", "--untracked-files=no"],
                                       capture_output=True, text=True, timeout=10).stdout.strip()
                _GIT_CACHE[key] = head.stdout.strip() + (" (uncommitted changes)" if dirty else "")
        except (OSError, subprocess.SubprocessError):
            _GIT_CACHE[key] = "none: git is not available"
    return _GIT_CACHE[key]


def package_versions(names=KEY_PACKAGES) -> dict[str, str]:
    """Installed version of each package in ``names`` ("not installed" when absent)."""
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for name in names:
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = "not installed"
    return out


_COMMAND_LINE: list[str] | None = None


def set_command_line(argv) -> None:
    """Record the command line of this process (the CLI's ``main`` calls it with ``["memstribo", *args]``)."""
    global _COMMAND_LINE
    _COMMAND_LINE = [str(a) for a in argv]


def command_line(argv=None) -> str:
    """The command line that runs, shell-quoted: ``argv``, else the one :func:`set_command_line` recorded,
    else ``sys.argv`` (the program shown as ``memstribo`` when it is the CLI)."""
    import shlex
    import sys

    argv = list(argv if argv is not None else _COMMAND_LINE if _COMMAND_LINE is not None else sys.argv)
    if not argv or argv == [""] or argv[0] in ("-c", "-"):
        return "python (no command line: called from Python)"
    program = Path(argv[0]).name
    if program in ("memstribo", "main.py", "__main__.py", "-m"):
        program = "memstribo"
    return " ".join([program, *(shlex.quote(str(a)) for a in argv[1:])])


def software_provenance() -> dict[str, Any]:
    """What ran: memstribo version, git commit (from a checkout), command line, Python and package versions.

    Returns
    -------
    dict
        ``memstribo_version``, ``git_commit`` (see :func:`git_commit`), ``command_line`` (see
        :func:`command_line`), ``python_version`` (``platform.python_version()``, implementation) and
        ``package_versions`` (name -> version of :data:`KEY_PACKAGES`).
    """
    import platform

    return {"memstribo_version": _version(), "git_commit": git_commit(), "command_line": command_line(),
            "python_version": f"{platform.python_version()} ({platform.python_implementation()})",
            "package_versions": package_versions()}


def provenance_attributes(params=None, *, roughness=None, extra: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """Global attributes saying what made a file: version, time, parameters, load case, roughness.

    Parameters
    ----------
    params : memstribo.parameters.Parameters, optional
        The parameters used. Every value goes into ``parameters`` (JSON text: name ->
        value [SI], UDUNITS unit, source); those that differ from the named parameter set,
        or were set by the user, into ``parameter_overrides`` with their origin (``--set``,
        ``config file ...``); the load case (:data:`LOAD_CASE_PARAMETERS`) into ``load_case_parameters`` (and its name into ``load_case``).
    roughness : Profile, SurfaceMap, path, or a list of them, optional
        The roughness used (see :func:`roughness_provenance`); a list gives JSON lists.
    extra : mapping, optional
        Further attributes (``stage``, ``models``, ``coating``, ...); dicts and lists are
        stored as JSON text.

    Returns
    -------
    dict
        Attribute name -> str, int or float, ready for NetCDF: ``Conventions``
        (``"CF-1.8"``), ``title``, ``source``, ``history``, ``date_created`` (ISO 8601,
        UTC), ``memstribo_version``, ``references``, ``models_cited``, ``git_commit``,
        ``command_line``, ``python_version``, ``package_versions`` (JSON text; see
        :func:`software_provenance`), and the above.
    """
    from memstribo.references import used_references

    version = _version()
    created = _utc_now()
    attrs: dict[str, Any] = {
        "Conventions": CONVENTIONS,
        "title": "memstribo results",
        "source": f"memstribo {version}",
        "history": f"{created} written by memstribo {version}",
        "date_created": created,
        "memstribo_version": version,
        "references": "N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and functionalized "
                      "gear microelectromechanical systems', PhD thesis, Cardiff University; see models_cited "
                      "and memstribo.references.REFERENCES",
        "models_cited": ", ".join(key for key, _ in used_references()) or "none recorded",
        **software_provenance(),
    }
    if params is not None:
        attrs.update(_parameter_attributes(params))
    if roughness is not None:
        if isinstance(roughness, (list, tuple)):
            items = [roughness_provenance(r) for r in roughness]
            for key in ("roughness_provenance", "roughness_source", "roughness_file", "roughness_file_sha256"):
                attrs[key] = json.dumps([item.get(key) for item in items], ensure_ascii=False)
        else:
            attrs.update(roughness_provenance(roughness))
    for key, value in (extra or {}).items():
        attrs[str(key)] = value
    return _netcdf_attributes(attrs)


def _parameter_attributes(params) -> dict[str, Any]:
    from memstribo.errors import MemstriboError
    from memstribo.parameters import SPECS, get_parameter_values

    def unit(name):
        spec = SPECS.get(name)
        return udunits(spec.unit) if spec is not None and spec.kind in ("float", "int") else ""

    def entry(name, key="source"):
        return {"value": to_jsonable(params[name]), "unit": unit(name), key: params.source(name)}

    try:
        base = get_parameter_values(params.name)
    except MemstriboError:
        base = None
    overrides = {name: entry(name, "origin") for name in params
                 if base is None or name not in base or base[name] != params[name]
                 or base.source(name) != params.source(name)}
    return {
        "parameter_set": str(params.name),
        "parameters": json.dumps({name: entry(name) for name in params}, allow_nan=False, ensure_ascii=False),
        "parameter_overrides": json.dumps(overrides, allow_nan=False, ensure_ascii=False),
        "load_case": str(params["load_case"]) if "load_case" in params else "",
        "load_case_parameters": json.dumps({name: {"value": to_jsonable(params[name]), "unit": unit(name)}
                                 for name in LOAD_CASE_PARAMETERS if name in params}, allow_nan=False,
                                ensure_ascii=False),
    }


def _netcdf_attributes(attrs: Mapping[str, Any]) -> dict[str, Any]:
    """Attribute values NetCDF can store: str, int, float (bool -> int, None -> "none", containers -> JSON)."""
    out = {}
    for key, value in attrs.items():
        if isinstance(value, (bool, np.bool_)):
            value = int(value)
        elif value is None:
            value = "none"
        elif isinstance(value, (dict, list, tuple)):
            value = json.dumps(to_jsonable(value), ensure_ascii=False)
        elif isinstance(value, Path):
            value = str(value)
        elif isinstance(value, np.generic):
            value = value.item()
        out[str(key)] = value
    return out


#: Attributes that always say when and by what the file was written (never the dataset's own).
_FIXED = ("Conventions", "date_created", "history", "memstribo_version", "git_commit", "command_line",
          "python_version", "package_versions")


def cf_dataset(dataset, provenance: Mapping[str, Any] | None = None):
    """A copy of ``dataset`` with CF attributes: UDUNITS ``units``, a ``long_name`` on every
    variable, and ``provenance`` (or the minimal :func:`provenance_attributes`) as global attributes."""
    from memstribo.quantities import known, quantity

    dataset = dataset.copy(deep=False)
    narrowed = {name: _cf_integer(variable, name) for name, variable in dataset.variables.items()}
    narrowed = {name: v for name, v in narrowed.items() if v is not dataset.variables[name]}
    if narrowed:
        dataset = dataset.assign({n: v for n, v in narrowed.items() if n not in dataset.coords})
        dataset = dataset.assign_coords({n: v for n, v in narrowed.items() if n in dataset.coords})
    for name in list(dataset.variables):
        variable = dataset.variables[name]
        attrs = dict(variable.attrs)
        if known(str(name)):  # the vocabulary's unit and long name where the variable has none
            attrs.setdefault("units", quantity(str(name)).unit)
            if not str(attrs.get("long_name", "")).strip():
                attrs["long_name"] = quantity(str(name)).long_name
        if variable.dtype.kind in "fiucb":
            attrs["units"] = udunits(attrs.get("units"))
        elif "units" in attrs:
            attrs.pop("units")
        if not str(attrs.get("long_name", "")).strip():
            attrs["long_name"] = str(name).replace("_", " ")
        variable.attrs = attrs
    provenance = dict(provenance) if provenance is not None else provenance_attributes()
    own = _netcdf_attributes(dataset.attrs)
    dataset.attrs = {**provenance, **{k: v for k, v in own.items() if k not in _FIXED}}
    return dataset


def netcdf_encoding(dataset) -> dict[str, dict[str, Any]]:
    """Per-variable NetCDF encodings that the CF checkers accept (CF-1.8 section 2.2 and 2.5.1).

    * coordinate variables get no ``_FillValue`` (CF 2.5.1: a coordinate has no missing values);
    * text variables are written as fixed-length character arrays (``char``, UTF-8, a dimension
      ``string<N>`` for N bytes) instead of NetCDF-4 variable-length strings, which CF-1.8 does not
      know; xarray reads them back as ``str`` (a missing entry, ``None``, as ``""``).

    64-bit integers are narrowed by :func:`cf_dataset` (CF-1.8 has no ``int64``).
    """
    encoding: dict[str, dict[str, Any]] = {}
    for name, variable in dataset.variables.items():
        entry: dict[str, Any] = {}
        if name in dataset.coords and variable.dtype.kind in "fc":
            entry["_FillValue"] = None
        if variable.dtype.kind in "UO":
            entry.update(dtype="S1", _Encoding="utf-8")  # xarray's own character dimension (string<N>)
            if name in dataset.coords:
                entry["_FillValue"] = None
        if entry:
            encoding[str(name)] = entry
    return encoding


def _cf_integer(variable, name):
    """``variable`` with a 64-bit integer dtype narrowed to ``int32`` (CF-1.8 knows no ``int64``)."""
    if variable.dtype.kind not in "iu" or variable.dtype.itemsize < 8:
        return variable
    values = np.asarray(variable.values)
    info = np.iinfo(np.int32)
    if values.size and (values.min() < info.min or values.max() > info.max):
        raise ValueError(f"integer variable {name!r} does not fit a 32-bit integer (CF-1.8 has no int64)")
    return variable.astype(np.int32)


def _csv_header(dataset, name: str, twin: str) -> str:
    """``#`` lines before the CSV table: the provenance of the NetCDF twin, then the columns."""
    attrs = dataset.attrs
    lines = [f"memstribo {attrs.get('memstribo_version', _version())}: {name} "
             f"(the same data with every attribute, and any per-block arrays: {twin})"]
    lines += [f"{key}: {value}" for key, value in attrs.items()]
    table = _table(dataset)
    for var in list(table.coords) + list(table.data_vars):
        v = table[var]
        lines.append(f"column {_column_label(dataset, var)}: {v.attrs.get('long_name', var)}")
    return "".join("# " + " ".join(str(line).splitlines()) + "\n" for line in lines)


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
#: SI prefixes of readable output; micro is "µ" (U+00B5) in text and figures alike (input accepts "u" too)
_PREFIXES = [(1e-18, "a"), (1e-15, "f"), (1e-12, "p"), (1e-9, "n"), (1e-6, "µ"), (1e-3, "m"), (1.0, ""),
             (1e3, "k"), (1e6, "M"), (1e9, "G"), (1e12, "T")]
# units that take SI prefixes in readable output
_PREFIXABLE = {"m", "N", "Pa", "J", "s", "N*m", "N/m", "J/m^2", "W"}


def format_quantity(value: float, unit: str = "") -> str:
    """``2.5e-05, "N"`` -> ``"25 µN"``: a number with an engineering prefix and its unit.

    Angles (``"rad"``) read in degrees: ``0.3491, "rad"`` -> ``"20 deg"``.
    """
    if value is None:
        return "-"
    unit = "" if unit == "1" else unit  # CF's dimensionless unit reads as a plain number
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if isinstance(value, (int, np.integer)) and not unit:
        return str(int(value))
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    if unit == "rad":
        return f"{math.degrees(value):.4g} deg"
    if unit in _PREFIXABLE and value != 0.0:
        magnitude = abs(value)
        factor, prefix = _PREFIXES[0]
        for f, p in _PREFIXES:
            if magnitude >= f * 0.9995:
                factor, prefix = f, p
        return f"{value / factor:.4g} {prefix}{unit}"
    return f"{value:.4g} {unit}".rstrip()


def engineering_scale(values, unit: str) -> tuple[float, str]:
    """``(factor, unit text)`` to draw ``values`` [``unit``, SI] as ``values / factor`` on an axis without an offset.

    A unit that takes SI prefixes gets one (``J`` -> ``nJ``, ``Pa`` -> ``GPa``, ``N`` -> ``µN``), chosen from the
    largest magnitude; another unit (``Pa^2``) gets a power of ten written into the label (``1e18 Pa^2``).

    >>> engineering_scale([5.6e-10, 7.6e-10], "J")
    (1e-12, 'pJ')
    >>> engineering_scale([5.6e-9, 7.6e-9], "J")
    (1e-09, 'nJ')
    """
    finite = np.abs(np.asarray(values, dtype=float))
    finite = finite[np.isfinite(finite) & (finite > 0)]
    if finite.size == 0:
        return 1.0, unit
    magnitude = float(finite.max())
    if unit in _PREFIXABLE:
        factor, prefix = _PREFIXES[0]
        for f, p in _PREFIXES:
            if magnitude >= f * 0.9995:
                factor, prefix = f, p
        return factor, f"{prefix}{unit}"
    exponent = 3 * int(math.floor(math.log10(magnitude) / 3))
    return (1.0, unit) if exponent == 0 else (10.0 ** exponent, f"1e{exponent} {unit}".strip())


def format_value(value: Any, unit: str = "") -> str:
    """Readable form of a result value: scalars with units, lists and dicts element-wise."""
    if isinstance(value, dict):
        return ", ".join(f"{k}: {format_value(v, unit)}" for k, v in value.items())
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(format_value(v, unit) for v in value) + "]"
    if isinstance(value, str):
        return value
    return format_quantity(value, unit)
