"""Parameter studies on dask.distributed: grids or lists of points, resumable.

A study is a list of *points*; each point is a set of overrides (model parameters such as
``normal_load`` or ``module``, plus the study keys ``coating``, ``wear``, ``roughness``,
``seed`` and ``steps``) applied to a base parameter set. A *point function* turns the
parameters of one point into a dict of scalar results (SI units). The default point
function, ``"mesh"``, is the meshing-cycle summary of :func:`memstribo.simulations.mesh.simulate_mesh`
and :func:`memstribo.simulations.mesh.summarize` (the keys of ``memstribo mesh --json``).

The points run on a dask.distributed cluster: an embedded ``LocalCluster`` (processes, one
thread each, no dashboard) or an existing cluster given by its scheduler address. Results do
not depend on the scheduler or the number of workers: every point is a pure function of its
parameters (random roughness is seeded by the point's ``roughness_seed``) and holds no global
state.

Every finished point is written at once to ``OUT/points/<id>.json`` (temporary file,
``fsync``, atomic rename); ``OUT/study.json`` (the manifest) lists every point and a hash of
the study. After an interruption, even ``kill -9``, rerunning with ``resume=True`` computes
only the points that have no file yet, and runs the failed points again: no finished point
is lost and none is computed twice. At the end
``OUT/results.nc`` and ``OUT/results.csv`` gather all points (dimension ``point``); a study
that is a grid only also gets ``OUT/results_grid.nc``/``.csv`` with one dimension per swept
key (:func:`grid_dataset`).

Spec file (TOML)::

    [parameters]                    # optional: base overrides for every point
    mesh_steps = 40

    [study]
    name = "load sweep"
    function = "mesh"               # a name of POINT_FUNCTIONS (memstribo's own point functions)

    [study.fixed]                   # optional: overrides for every point
    coating = "OTS"

    [study.grid]                    # every combination, in the order written
    normal_load = ["25 uN", "100 uN", "300 uN"]
    wear = {start = 0.0, stop = 1.0, num = 6}

    [[study.points]]                # and/or an explicit list of points
    normal_load = "50 uN"
    module = "4 um"
"""

from __future__ import annotations

import hashlib
import itertools
import json
import logging
import os
import socket
import sys
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from memstribo.checks import point_wear
from memstribo.errors import InputError, MemstriboError, did_you_mean
from memstribo.output import dumps_json, ensure_directory, to_jsonable
from memstribo.quantities import attrs_or
from memstribo.units import printable

__all__ = ["StudySpec", "StudyResult", "STUDY_KEYS", "POINT_FUNCTIONS", "MAX_STUDY_POINTS", "load_study_spec",
           "study_spec", "prepare_points", "run_study", "evaluate_point", "mesh_point", "gear_point", "slide_point",
           "register_point_function", "resolve_function", "function_name", "study_dataset", "grid_dataset",
           "points_references"]

#: Keys of a point that are not model parameters, with their unit and meaning.
STUDY_KEYS: dict[str, tuple[str, str]] = {
    "coating": ("", "coating name (e.g. 'OTS'), or 'none' for bare silicon"),
    "wear": ("", "worn fraction Omega of the gear's coating, 0 to 1 (needs a coating)"),
    "roughness": ("", "roughness: 'synthetic' (default) or the path of a measured profile/AFM file"),
    "seed": ("", "seed of the synthetic roughness (sets the parameter roughness_seed)"),
    "steps": ("", "number of positions along the path of contact (default: the model's)"),
}

#: Options of the embedded LocalCluster that keep it quiet: no dashboard, and the scheduler's HTTP
#: server (which distributed starts even without a dashboard, by default on port 8787, with a
#: "Port 8787 is already in use" warning when another cluster holds it) on a free port of
#: 127.0.0.1 chosen by the system (port 0: nothing to warn about, nothing exposed beyond this host).
LOCAL_CLUSTER_QUIET: dict[str, Any] = {"dashboard_address": None,
                                       "scheduler_kwargs": {"dashboard_address": "127.0.0.1:0"},
                                       "silence_logs": logging.ERROR}

#: Dask's nannies export MALLOC_TRIM_THRESHOLD_=65536, which also fixes glibc's mmap threshold at 128 kB: every array
#: of over 16 384 values is then mapped afresh, and a meshing cycle costs 44 % more CPU (0.481 -> 0.694 s,
#: bench/results-map.txt entry 7); None unsets it (Dask's thread limits of 1 stay; your own cluster: docs/studies.md).
#: Dask's sampling profiler is off: 2-worker speed-up 1.86 without it, 1.78-1.84 with it (CPU; docs/uncertainty.md).
LOCAL_CLUSTER_ENVIRON: dict[str, Any] = {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
                                         "distributed.worker.profile.enabled": False}

#: How long to wait for an existing Dask scheduler before giving up.
CONNECT_TIMEOUT = "10s"

#: most points in one study (each holds its parameters: about 10 kB; the results more)
MAX_STUDY_POINTS = 100_000

POINTS_FOLDER = "points"
MANIFEST = "study.json"
FORMAT_VERSION = 1


@dataclass(frozen=True)
class StudySpec:
    """A study: which point function to run on which points.

    Attributes
    ----------
    name : str
        Title of the study.
    function : str or callable
        Point function: a name of :data:`POINT_FUNCTIONS` (the only choice of a spec file), or
        through the Python API any importable module-level function.
    points : tuple of dict
        The points, each ``{key: value}`` with values as written (units allowed: ``"25 uN"``).
    parameters : dict
        Base parameter overrides applied to every point before its own.
    source : str
        Where the spec comes from (file name or "python").
    grid : tuple of str
        The keys of the grid axes, in grid order, when the points are a grid only (no listed
        points); the results then also come back with one dimension per axis
        (``results_grid.nc``, :func:`grid_dataset`).
    """

    name: str
    function: Any
    points: tuple[dict[str, Any], ...]
    parameters: dict[str, Any] = field(default_factory=dict)
    source: str = "python"
    grid: tuple[str, ...] = ()


@dataclass(frozen=True)
class StudyResult:
    """What a study run did.

    Attributes
    ----------
    folder : pathlib.Path
        The output folder.
    n_points : int
        Points in the study.
    n_computed : int
        Points computed by this run.
    n_reused : int
        Points found finished on disk (``resume``) and not computed again.
    n_failed : int
        Points whose function raised an error (recorded in their file, see ``errors``).
    n_retried : int
        Points that had failed in an earlier run and were run again by this one (``resume``).
    elapsed : float
        Wall time of this run [s].
    dataset : xarray.Dataset
        All points: inputs and results over dimension ``point`` (also in results.nc/.csv).
    errors : dict
        ``{point id: message}`` of the failed points.
    """

    folder: Path
    n_points: int
    n_computed: int
    n_reused: int
    n_failed: int
    elapsed: float
    dataset: Any
    errors: dict[str, str]
    n_retried: int = 0


# --- spec ----------------------------------------------------------------------------------------

def _check_scalar(key: str, value: Any, where: str) -> None:
    """A point value is one number, string or boolean (not a table, not a list)."""
    if isinstance(value, (Mapping, list, tuple)):
        kind = "table" if isinstance(value, Mapping) else "list"
        raise InputError(f"{where}: '{printable(key)}' = {printable(repr(value), 60)}: a point value is one number or "
                         f"string, not a {kind}.")
    if not isinstance(value, (str, int, float, bool)):
        raise InputError(f"{where}: '{printable(key)}' has a value of type {type(value).__name__}; give a number or "
                         "a string.")


def _expand_values(key: str, values: Any, where: str) -> list[Any]:
    if isinstance(values, Mapping):
        unknown = set(values) - {"start", "stop", "num"}
        if unknown or not {"start", "stop", "num"} <= set(values):
            raise InputError(f"{where}: range '{printable(key)}' must be a table {{start, stop, num}}, got "
                             f"{printable(repr(dict(values)), 80)}.")
        unit = _unit_of(key)
        from memstribo.units import to_si

        try:
            start = to_si(values["start"], unit, key)
            stop = to_si(values["stop"], unit, key)
        except InputError as exc:
            raise InputError(f"{where}: range '{printable(key)}': {exc}") from None
        num = values["num"]
        if not isinstance(num, int) or isinstance(num, bool) or not 1 <= num <= MAX_STUDY_POINTS:
            raise InputError(f"{where}: range '{printable(key)}' needs num = an integer from 1 to "
                             f"{MAX_STUDY_POINTS:,}, got {printable(repr(num), 40)}.")
        return [float(v) for v in np.linspace(start, stop, num)]
    if isinstance(values, list):
        if not values:
            raise InputError(f"{where}: '{printable(key)}' has an empty list of values.")
        if len(values) > MAX_STUDY_POINTS:
            raise InputError(f"{where}: '{printable(key)}' lists {len(values):,} values; at most {MAX_STUDY_POINTS:,}.")
        for value in values:
            _check_scalar(key, value, where)
        return list(values)
    _check_scalar(key, values, where)
    return [values]


def _unit_of(key: str) -> str:
    from memstribo.parameters import SPECS

    if key in STUDY_KEYS:
        return STUDY_KEYS[key][0]
    if key in SPECS:
        return SPECS[key].unit
    return ""


def study_spec(study: Mapping[str, Any], parameters: Mapping[str, Any] | None = None,
               source: str = "python") -> StudySpec:
    """Build a :class:`StudySpec` from the ``[study]`` table of a spec file (as a dict).

    ``study["function"]`` is a name of :data:`POINT_FUNCTIONS` (default ``"mesh"``); through
    the Python API (``source="python"``) it may also be a callable (a module-level function,
    so that the Dask workers can import it). A spec file never names code to import.

    Raises
    ------
    InputError
        Unknown keys, wrong types, empty grids, more than :data:`MAX_STUDY_POINTS` points,
        neither a grid nor a list of points, or a function that is not a registered name.
    """
    where = f"study spec {printable(source, 200)}"
    if not isinstance(study, Mapping):
        raise InputError(f"{where}: [study] must be a table.")
    allowed = {"name", "function", "fixed", "grid", "points"}
    unknown = sorted(str(k) for k in set(study) - allowed)
    if unknown:
        raise InputError(f"{where}: unknown key(s) {[printable(k) for k in unknown]} in [study]; allowed: "
                         f"{sorted(allowed)}.{did_you_mean(unknown[0], allowed)}")
    fixed = study.get("fixed", {})
    grid = study.get("grid", {})
    listed = study.get("points", [])
    if not isinstance(grid, Mapping) or not isinstance(listed, list) or not isinstance(fixed, Mapping):
        raise InputError(f"{where}: [study.grid] and [study.fixed] must be tables, [[study.points]] a list of tables.")
    name = study.get("name", "study")
    if not isinstance(name, str) or not name.strip() or len(name) > 200:
        raise InputError(f"{where}: name must be a short text (1 to 200 characters), got {printable(repr(name), 60)}.")
    if not grid and not listed:
        raise InputError(f"{where}: no points: give a [study.grid] table and/or [[study.points]] tables.")
    for key, value in fixed.items():
        _check_scalar(key, value, f"{where} [study.fixed]")
    axes = [(key, _expand_values(key, values, where)) for key, values in grid.items()]
    n_points = int(np.prod([len(values) for _, values in axes], dtype=float)) if axes else 0
    n_points += len(listed)
    if n_points > MAX_STUDY_POINTS:
        raise InputError(f"{where}: {n_points:,} points; a study holds at most {MAX_STUDY_POINTS:,} (split it, or use "
                         "fewer grid values).")
    points: list[dict[str, Any]] = []
    if axes:
        for combination in itertools.product(*(values for _, values in axes)):
            points.append({**fixed, **dict(zip((key for key, _ in axes), combination))})
    for entry in listed:
        if not isinstance(entry, Mapping):
            raise InputError(f"{where}: every [[study.points]] entry must be a table, got {printable(repr(entry), 60)}.")
        for key, value in entry.items():
            _check_scalar(key, value, f"{where} [[study.points]]")
        points.append({**fixed, **entry})
    function = study.get("function", "mesh")
    if callable(function):  # the Python API (a TOML file holds no callables)
        pass
    elif not isinstance(function, str):
        raise InputError(f"{where}: function must be the name of a point function, one of {sorted(POINT_FUNCTIONS)}, "
                         f"got {printable(repr(function), 60)}.")
    elif function not in POINT_FUNCTIONS:
        hint = did_you_mean(function, POINT_FUNCTIONS)
        code = (" A study spec names one of memstribo's point functions, never code to import; a function of your "
                "own runs through the Python API (study_spec({'function': my_function, ...}), run_study)."
                if ":" in function or "." in function else "")
        raise InputError(f"{where}: unknown point function '{printable(function, 60)}'; use one of "
                         f"{sorted(POINT_FUNCTIONS)}.{hint}{code}")
    grid_keys = tuple(str(key) for key, _ in axes) if axes and not listed else ()
    return StudySpec(name=name, function=function, points=tuple(points),
                     parameters=dict(parameters or {}), source=source, grid=grid_keys)


def load_study_spec(path: str | Path) -> StudySpec:
    """Read a study spec TOML file (``[study]`` table, optional ``[parameters]``), validated whole."""
    from memstribo.parameters import read_config

    config = read_config(path)
    if "study" not in config:
        raise InputError(f"study spec '{printable(path, 200)}' has no [study] table; see 'memstribo study --help'.")
    if "run" in config:
        raise InputError(f"study spec '{printable(path, 200)}' has a [run] table; a study spec holds [study] and "
                         "[parameters] only.")
    return study_spec(config["study"], config.get("parameters"), source=str(path))


# --- points ----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _Point:
    id: str
    index: int
    inputs: dict[str, Any]          # as written in the spec
    params: Any                     # Parameters with the point's overrides
    options: dict[str, Any]         # coating, wear, roughness, steps (SI, validated)


def _point_options(raw: Mapping[str, Any], where: str, base_folder: Path | None) -> tuple[dict, dict]:
    """Split a point into parameter overrides and study options (validated)."""
    from memstribo.parameters import SPECS
    from memstribo.units import to_si

    overrides, options = {}, {}
    for key, value in raw.items():
        if key in STUDY_KEYS:
            options[key] = value
        elif key in SPECS:
            overrides[key] = value
        else:
            raise InputError(f"{where}: unknown key '{key}': neither a model parameter nor one of "
                             f"{sorted(STUDY_KEYS)}.{did_you_mean(key, list(SPECS) + list(STUDY_KEYS))}")
    if "seed" in options:
        overrides["roughness_seed"] = options.pop("seed")
    clean: dict[str, Any] = {}
    coating = options.get("coating", "none")
    if coating is None or str(coating).strip().lower() in ("none", "bare", ""):
        clean["coating"] = None
    else:
        from memstribo.physics.coating import available_coatings

        known = available_coatings()
        if not isinstance(coating, str) or coating not in known:
            raise InputError(f"{where}: unknown coating '{printable(coating, 40)}'; use one of {known} or 'none'."
                             f"{did_you_mean(str(coating), known)}")
        clean["coating"] = coating
    if "wear" in options:
        wear = to_si(options["wear"], "", "wear")
        if not 0.0 <= wear <= 1.0:
            raise InputError(f"{where}: wear = {options['wear']!r} is outside 0 to 1 (the worn fraction Omega).")
        clean["wear"] = wear  # else: the point's coating_wear (checks.point_wear, once its parameters are known)
    if clean["coating"] is None and clean.get("wear", 1.0) != 1.0:
        raise InputError(f"{where}: wear = {clean['wear']:g} needs a coating (bare silicon is wear = 1).")
    roughness = options.get("roughness", "synthetic")
    if str(roughness).strip().lower() == "synthetic":
        clean["roughness"] = None
    else:
        path = Path(str(roughness)).expanduser()
        if not path.is_absolute() and base_folder is not None:
            path = base_folder / path
        if not path.is_file():
            raise InputError(f"{where}: roughness file '{printable(roughness, 200)}' does not exist.")
        clean["roughness"] = str(path.resolve())
    if "steps" in options:
        steps = options["steps"]
        if not isinstance(steps, int) or isinstance(steps, bool) or not 2 <= steps <= 100_000:
            raise InputError(f"{where}: steps = {printable(repr(steps), 40)} must be an integer >= 2 and <= 100000.")
        clean["steps"] = steps
    else:
        clean["steps"] = None
    return overrides, clean


def prepare_points(spec: StudySpec, params) -> list[_Point]:
    """Validate every point of ``spec`` against ``params`` (before anything runs).

    Raises
    ------
    InputError
        A point with an unknown key or a value outside its range (the message names the point).
    """
    base = params.updated(spec.parameters, origin=f"study spec {spec.source}") if spec.parameters else params
    base_folder = Path(spec.source).parent if spec.source != "python" else None
    points = []
    for index, raw in enumerate(spec.points):
        where = f"study point {index} ({_describe(raw)})"
        if spec.source != "python":
            where = f"study spec {printable(spec.source, 200)}: {where}"
        overrides, options = _point_options(raw, where, base_folder)
        try:
            point_params = base.updated(overrides, origin=f"study point {index}") if overrides else base
        except InputError as exc:
            raise InputError(f"{where}: {exc}") from None
        options = point_wear(options, raw, point_params, where)
        if options.get("steps") is not None and "mesh_window" in point_params:
            from memstribo.parameters import check_mesh_size

            try:
                check_mesh_size(options["steps"], point_params["mesh_window"], point_params["mesh_grid_spacing"],
                                what="steps")
            except InputError as exc:
                raise InputError(f"{where}: {exc}") from None
        digest = _hash({"inputs": raw, "parameters": point_params.to_dict(), "options": options})[:10]
        points.append(_Point(f"p{index:06d}-{digest}", index, dict(raw), point_params, options))
    return points


def _describe(raw: Mapping[str, Any]) -> str:
    return printable(", ".join(f"{k}={v}" for k, v in raw.items()), 120) or "base parameters"


def _hash(value: Any) -> str:
    text = json.dumps(to_jsonable(value), sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


# --- point functions ---------------------------------------------------------------------------------

def _read_roughness(path: str | None):
    if path is None:
        return None
    from memstribo.surfaces.readers import read_topography

    return read_topography(path)


def mesh_point(params, coating: str | None = None, wear: float = 1.0, roughness: str | None = None,
               steps: int | None = None) -> dict[str, float]:
    """The meshing-cycle summary of one study point (the default point function).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        The point's parameters.
    coating : str or None
        Coating name (:func:`memstribo.physics.coating.get_coating`); None for bare silicon.
    wear : float
        Worn fraction Omega of the gear's coating [-] (1 for bare silicon).
    roughness : str or None
        Path of a measured profile or AFM map; None for the default synthetic profile.
    steps : int or None
        Positions along the path of contact (None: the model's default).

    Returns
    -------
    dict
        :func:`memstribo.simulations.mesh.summarize` of the meshing cycle (SI units).
    """
    from memstribo.simulations import mesh

    coating_object = None
    if coating is not None:
        from memstribo.physics.coating import get_coating

        coating_object = get_coating(coating, params)
    dataset = mesh.simulate_mesh(params, _read_roughness(roughness), steps=steps, coating=coating_object,
                                 wear=wear)
    return mesh.summarize(dataset)


def gear_point(params, coating: str | None = None, wear: float = 1.0, roughness: str | None = None,
               steps: int | None = None) -> dict[str, Any]:
    """Gear geometry and the pitch-point Hertz contact of one point (``memstribo gear --json``; fast)."""
    if coating is not None or roughness is not None or steps is not None:
        raise InputError("point function 'gear' takes no coating, roughness or steps (it is the smooth pair).")
    from memstribo.physics.gear import gear_summary

    values, _ = gear_summary(params)
    return values


def slide_point(params, coating: str | None = None, wear: float = 1.0, roughness: str | None = None,
                steps: int | None = None) -> dict[str, Any]:
    """The fixed-load flat-friction slide of one point (``memstribo slide --json``): COF, forces, energies."""
    if coating is not None or steps is not None:
        raise InputError("point function 'slide' takes no coating or steps (set sliding_step for the step).")
    from memstribo.simulations import sliding

    return sliding.summarize(sliding.slide("fixed-load", params, _read_roughness(roughness))).to_dict()


#: memstribo's own point functions, by name: the only ones a study spec file may name.
#: ``register_point_function`` adds one through the Python API (in this process).
POINT_FUNCTIONS: dict[str, Callable] = {
    "mesh": mesh_point,
    "gear": gear_point,
    "slide": slide_point,
}


def _units_of_slide():
    from memstribo.simulations.sliding import UNITS

    return UNITS


_UNITS_OF = {"slide": _units_of_slide}


def register_point_function(name: str, function: Callable) -> None:
    """Make ``function`` available to study specs as ``name`` (Python API; this process only).

    ``function(params, coating=None, wear=1.0, roughness=None, steps=None) -> dict`` must be a
    module-level function that the Dask workers can import. Give it a ``units`` dict attribute
    to label the results.
    """
    if not isinstance(name, str) or not name.isidentifier():
        raise InputError(f"point function name {name!r} must be an identifier.")
    if not callable(function):
        raise InputError(f"point function {name!r} must be callable, got {type(function).__name__}.")
    POINT_FUNCTIONS[name] = function


def function_name(function) -> str:
    """A stable name of a point function (registry name, or ``module:qualname`` of a callable)."""
    if isinstance(function, str):
        return function
    return f"{getattr(function, '__module__', '?')}:{getattr(function, '__qualname__', repr(function))}"


def resolve_function(function) -> Callable:
    """The point function ``function``: a callable as it is, or a name of :data:`POINT_FUNCTIONS`.

    Names resolve only through the registry (memstribo's own modules): a string never makes
    memstribo import a module it names.
    """
    if callable(function):
        return function
    target = POINT_FUNCTIONS.get(function) if isinstance(function, str) else None
    if target is None:
        raise InputError(f"unknown point function '{printable(function, 60)}': use one of {sorted(POINT_FUNCTIONS)}."
                         f"{did_you_mean(str(function), POINT_FUNCTIONS)}")
    return target


def evaluate_point(function, params, options: Mapping[str, Any]) -> dict[str, Any]:
    """Run one point (on a worker): ``{"values": {...}, "error": None or message, "seconds": ..., ...}``.

    Model errors (:class:`memstribo.errors.MemstriboError`) are recorded, not raised, so that
    one impossible point (e.g. stiction at start-up) does not stop a study of thousands.
    ``references`` lists the keys of :data:`memstribo.references.REFERENCES` that the point's
    model functions cited (recorded in the worker's process, so they travel back with the result).
    """
    from memstribo.references import collect_references

    start = time.perf_counter()
    with collect_references() as used:
        try:
            name = function_name(function)
            function = resolve_function(function)
            values = function(params, **options)
            if not isinstance(values, Mapping):
                raise InputError(f"point function {name!r} returned {type(values).__name__}, not a dict.")
            values = {str(k): to_jsonable(v) for k, v in values.items()}
            error = None
        except MemstriboError as exc:
            values, error = {}, f"{type(exc).__name__}: {exc}"
    return {"values": values, "error": error, "seconds": time.perf_counter() - start,
            "host": socket.gethostname(), "pid": os.getpid(), "references": list(used)}


def points_references(records) -> list[str]:
    """The reference keys the points used (``references`` of their records), in order of first use.

    The keys are also added to this process's record (:func:`memstribo.references.record_references`),
    so that ``references.txt`` and the report of a run list them. Keys unknown to this version
    (a point file of another version) are left out.
    """
    from memstribo.references import REFERENCES, record_references

    keys = list(dict.fromkeys(key for record in records for key in (record.get("references") or ())
                              if key in REFERENCES))
    record_references(keys)
    return keys


# --- running -------------------------------------------------------------------------------------------

def _write_json_atomic(path: Path, value: Any) -> None:
    """One point's result, durable before the rename (fsync): a killed study loses no finished point."""
    from memstribo.output import atomic_write

    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as handle:
            handle.write(dumps_json(value))
            handle.flush()
            os.fsync(handle.fileno())

    atomic_write(path, write)


def _finished_points(folder: Path, ids: set[str]) -> dict[str, dict]:
    """Point files already on disk (complete ones only: a torn .tmp is ignored and removed)."""
    done = {}
    points_folder = folder / POINTS_FOLDER
    if not points_folder.is_dir():
        return done
    for path in points_folder.iterdir():
        if path.name.endswith(".tmp"):
            path.unlink(missing_ok=True)
            continue
        if path.suffix != ".json" or path.stem not in ids:
            continue
        try:
            record = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue  # unreadable: compute it again
        done[path.stem] = record
    return done


def require_dask(what: str = "this command") -> None:
    """Refuse clearly when dask.distributed is not installed (the optional extra ``parallel``).

    Raises
    ------
    InputError
        Naming ``what`` needs it and the command that installs it.
    """
    try:
        import dask  # noqa: F401
        import distributed  # noqa: F401
    except ImportError:
        raise InputError(f"{what} runs on dask.distributed, an optional part of memstribo: install it with "
                         "pip install 'memstribo[parallel]'.") from None


def _connect(scheduler: str | None, workers: int | None):
    """A dask.distributed Client: to ``scheduler`` or to a new quiet LocalCluster (:func:`local_cluster`)."""
    from distributed import Client

    if scheduler:
        try:
            return Client(scheduler, timeout=CONNECT_TIMEOUT, set_as_default=False), None
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError(f"cannot connect to the Dask scheduler at '{scheduler}': {exc}. "
                             "Start one with 'dask scheduler' (see docs/studies.md).") from None
    cluster = local_cluster(workers or os.cpu_count() or 1)
    return Client(cluster, set_as_default=False), cluster


def local_cluster(n_workers: int):
    """The LocalCluster that studies and maps start: ``n_workers`` processes of one thread each, quiet
    (:data:`LOCAL_CLUSTER_QUIET`), with glibc's own memory settings (:data:`LOCAL_CLUSTER_ENVIRON`; a
    MALLOC_TRIM_THRESHOLD_ already in this process's environment, yours or left by a Dask cluster started
    earlier in it, is still inherited)."""
    import dask
    from distributed import LocalCluster

    with dask.config.set(LOCAL_CLUSTER_ENVIRON):  # read when the nannies are made, here
        return LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True, **LOCAL_CLUSTER_QUIET)


def run_study(spec: StudySpec, out: str | Path, params=None, *, scheduler: str | None = None,
              workers: int | None = None, resume: bool = False, progress: bool = False) -> StudyResult:
    """Run the points of ``spec`` on Dask and write each one as soon as it is finished.

    Parameters
    ----------
    spec : StudySpec
        The study (see :func:`load_study_spec`).
    out : str or pathlib.Path
        Output folder: ``study.json`` (manifest), ``points/<id>.json``, ``results.nc``/``.csv``.
    params : memstribo.parameters.Parameters, optional
        Base parameters (default: the thesis set).
    scheduler : str, optional
        Address of an existing Dask scheduler (``tcp://host:8786``); default: a LocalCluster.
    workers : int, optional
        Worker processes of the LocalCluster (default: the number of cores).
    resume : bool
        Finish a study started in ``out`` (the spec and parameters must be the same).
    progress : bool
        Show a progress bar on stderr (points done, rate, time left).

    Raises
    ------
    InputError
        Bad spec or point, ``out`` holding another study, or ``out`` holding this study without ``resume``.
    """
    require_dask("memstribo study")
    from memstribo.parameters import get_parameter_values

    start = time.perf_counter()
    params = params if params is not None else get_parameter_values()
    if workers is not None and (not isinstance(workers, int) or workers < 1):
        raise InputError(f"workers = {workers!r}: give a positive integer.")
    function = resolve_function(spec.function)  # fail early on a bad name
    points = prepare_points(spec, params)
    folder = ensure_directory(out)
    study_hash = _hash({"function": function_name(spec.function), "points": [[p.id, p.inputs] for p in points],
                        "parameters": params.to_dict(), "base": spec.parameters})
    manifest_path = folder / MANIFEST
    check_or_write_manifest(manifest_path, folder, resume, study_hash, {
        "format": FORMAT_VERSION, "name": spec.name, "function": function_name(spec.function),
        "source": spec.source, "hash": study_hash, "parameter_set": params.name, "base_overrides": spec.parameters,
        "points": [{"id": p.id, "index": p.index, "inputs": p.inputs} for p in points],
    }, what="study", differs="other points, function or parameters")
    ensure_directory(folder / POINTS_FOLDER)
    by_id = {p.id: p for p in points}
    finished = _finished_points(folder, set(by_id))
    done = {pid: record for pid, record in finished.items() if not record.get("error")}
    n_retried = len(finished) - len(done)  # failed in an earlier run: run again (the model or inputs may be fixed)
    todo = [p for p in points if p.id not in done]
    n_computed = 0
    if todo:
        n_computed = _compute(spec, function, todo, folder, len(points), len(done), scheduler, workers, progress)
    records = _finished_points(folder, set(by_id))
    missing = sorted(set(by_id) - set(records))
    if missing:  # cannot happen unless files vanished while running
        raise InputError(f"{len(missing)} point(s) have no result file in '{folder / POINTS_FOLDER}'; rerun with --resume.")
    ordered = [records[p.id] for p in points]
    dataset = study_dataset(ordered, spec, points)
    from memstribo.output import provenance_attributes, write_dataset

    base = params.updated(spec.parameters, origin=f"study spec {spec.source}") if spec.parameters else params
    cited = points_references(ordered)  # recorded on the workers, returned with each point
    provenance = provenance_attributes(base, extra={"command": "memstribo study", "study_spec": str(spec.source),
                                                    "study_function": function_name(spec.function),
                                                    "models_cited": ", ".join(cited) or "none recorded"})
    write_dataset(dataset, folder, "results", provenance=provenance)
    if spec.grid:
        try:
            write_dataset(grid_dataset(dataset, spec), folder, "results_grid", provenance=provenance)
        except InputError:
            pass  # an axis repeats a value: the results stay over dimension 'point' only
    errors = {r["id"]: r["error"] for r in ordered if r.get("error")}
    return StudyResult(folder, len(points), n_computed, len(done), len(errors), time.perf_counter() - start,
                       dataset, errors, n_retried)


def _compute(spec, function, todo, folder, total, already, scheduler, workers, progress) -> int:
    from distributed import as_completed
    from tqdm.auto import tqdm

    client, cluster = _connect(scheduler, workers)
    bar = tqdm(total=total, initial=already, unit="point", desc=spec.name, file=sys.stderr,
               disable=not progress, dynamic_ncols=True)
    computed = 0
    try:
        futures = {}
        for point in todo:
            future = client.submit(evaluate_point, function, point.params, point.options,
                                   key=f"memstribo-{point.id}-{os.getpid()}", pure=False)
            futures[future] = point
        for future in as_completed(list(futures), loop=client.loop):
            point = futures.pop(future)  # release the result on the cluster once it is on disk
            try:
                outcome = future.result()
            except Exception as exc:  # a bug in the point function: record it, carry on
                outcome = {"values": {}, "error": f"{type(exc).__name__}: {exc}", "seconds": None}
            record = {"id": point.id, "index": point.index, "inputs": point.inputs, **outcome}
            _write_json_atomic(folder / POINTS_FOLDER / f"{point.id}.json", record)
            future.release()
            computed += 1
            bar.update(1)
    finally:
        bar.close()
        client.close()
        if cluster is not None:
            cluster.close()
    return computed


def study_dataset(records: list[dict], spec: StudySpec | None = None, points: list | None = None):
    """The points as an :class:`xarray.Dataset` over dimension ``point`` (inputs, then results).

    Inputs are in SI. With ``points`` (from :func:`prepare_points`), a point that does not set
    an input shows the value it ran with (the base parameter, the default coating, ...);
    without, the values written in the spec (NaN or "" where a point does not set one).
    """
    import xarray as xr

    from memstribo.parameters import SPECS
    from memstribo.units import to_si

    n = len(records)
    data: dict[str, Any] = {}
    input_keys = list(dict.fromkeys(k for r in records for k in r["inputs"]))
    for key in input_keys:
        raw = [r["inputs"].get(key) for r in records]
        if points is not None:
            raw = [_effective_input(key, point) for point in points]
        unit = _unit_of(key)
        if key in SPECS and SPECS[key].kind in ("float", "int") or key in ("wear", "seed", "steps"):
            values = np.array([np.nan if v is None else to_si(v, unit, key) for v in raw], dtype=float)
        else:
            values = np.array(["" if v is None else str(v) for v in raw], dtype=object)
        description = SPECS[key].description if key in SPECS else STUDY_KEYS.get(key, ("", key))[1]
        data[f"input_{key}"] = ("point", values, {"units": unit, "long_name": f"input: {description}"})
    output_keys = list(dict.fromkeys(k for r in records for k in r.get("values", {})))
    units = _result_units(spec)
    for key in output_keys:
        raw = [r.get("values", {}).get(key) for r in records]
        if all(isinstance(v, (int, float, bool)) or v is None for v in raw):
            values = np.array([np.nan if v is None else float(v) for v in raw], dtype=float)
        else:
            values = np.array([json.dumps(v) if not isinstance(v, str) else v for v in raw], dtype=object)
        data[key] = ("point", values, attrs_or(key, units.get(key, "")))
    data["error"] = ("point", np.array([r.get("error") or "" for r in records], dtype=object), attrs_or("error"))
    ids = np.array([r["id"] for r in records], dtype=object)
    dataset = xr.Dataset({k: xr.Variable(*v) for k, v in data.items()},
                         coords={"point": ("point", np.arange(n)), "point_id": ("point", ids)})
    dataset.attrs["title"] = spec.name if spec else "study"
    if spec is not None:
        dataset.attrs["point_function"] = function_name(spec.function)
    return dataset


def grid_dataset(dataset, spec: StudySpec):
    """The results of a grid study with one dimension per swept key instead of ``point``.

    ``dataset`` is :func:`study_dataset` of the study's points (in grid order, last axis
    fastest); the axes become coordinates (SI, from ``input_<key>``) and every other variable
    is reshaped onto them (a result named like an axis becomes ``result_<name>``).

    Raises
    ------
    InputError
        ``spec`` is not a pure grid (it lists points too).
    """
    import xarray as xr

    if not spec.grid:
        raise InputError("the study is not a pure grid (it lists points): its results have dimension 'point' only.")
    axes = list(spec.grid)
    values = {key: list(dict.fromkeys(dataset[f"input_{key}"].values.tolist())) for key in axes}
    shape = tuple(len(values[key]) for key in axes)
    if int(np.prod(shape)) != dataset.sizes["point"]:
        raise InputError("the study's grid axes do not match its points (repeated values on an axis?).")
    coords = {key: xr.Variable(key, np.asarray(values[key]), dict(dataset[f"input_{key}"].attrs)) for key in axes}
    data = {}
    for name, variable in dataset.data_vars.items():
        if name in {f"input_{key}" for key in axes}:
            continue
        target = f"result_{name}" if name in axes else name  # a result named like an axis (gear: module)
        data[target] = xr.Variable(tuple(axes), np.asarray(variable.values).reshape(shape), dict(variable.attrs))
    data["point_id"] = xr.Variable(tuple(axes), np.asarray(dataset["point_id"].values).reshape(shape),
                                   {"units": "", "long_name": "id of the point's file in points/"})
    grid = xr.Dataset(data, coords=coords)
    grid.attrs.update(dataset.attrs)
    return grid


def _effective_input(key: str, point) -> Any:
    """The value of input ``key`` that ``point`` ran with (SI or text)."""
    if key == "seed":
        return point.params["roughness_seed"]
    if key == "coating":
        return point.options["coating"] or "none"
    if key == "roughness":
        return point.options["roughness"] or "synthetic"
    if key == "steps":
        steps = point.options["steps"]
        if steps is None and "mesh_steps" in point.params:
            steps = point.params["mesh_steps"]
        return steps
    if key in STUDY_KEYS:
        return point.options.get(key)
    return point.params[key]


def _result_units(spec: StudySpec | None) -> dict[str, str]:
    """Units of the point function's results, where it declares them (``function.units``)."""
    if spec is None:
        return {}
    try:
        function = resolve_function(spec.function)
    except InputError:
        return {}
    units = getattr(function, "units", None)
    if units is None and spec.function in _UNITS_OF:
        units = _UNITS_OF[spec.function]()
    if units is None and spec.function == "mesh":
        try:
            from memstribo.simulations import mesh

            units = getattr(mesh, "SUMMARY_UNITS", None)
        except ImportError:
            units = None
    return dict(units or {})


def check_or_write_manifest(manifest_path, folder, resume, run_hash, manifest_new, what="study",
                            differs="other points, function or parameters") -> None:
    """Write a new study's (or map's) manifest, or check (InputError) that the folder's is this one, resumed."""
    if manifest_path.exists():
        try:
            manifest = json.loads(manifest_path.read_text(encoding="utf-8"))
        except ValueError:
            raise InputError(f"'{manifest_path}' is not a {what} manifest; choose another --out.") from None
        if not resume:
            raise InputError(f"'{folder}' already holds a {what}; add --resume to finish it or choose another --out.")
        if manifest.get("hash") != run_hash:
            raise InputError(f"--resume: '{folder}' holds a different {what} ({differs}); choose another --out.")
    else:
        _write_json_atomic(manifest_path, manifest_new)
