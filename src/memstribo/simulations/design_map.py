"""Design maps: the stiction verdict of an ensemble over a grid of design parameters.

A design map sweeps two or more design parameters (drive torque, face width, module,
teeth, roughness, coating, worn fraction Omega, ...) on a grid. Every grid point is an
*ensemble verdict* (:func:`memstribo.simulations.mesh.simulate_ensemble`, MODEL 7b): ``realisations``
meshing cycles on independent roughness realisations give the stiction probability and the
5/50/95 % quantiles of the stiction margin, the mean COF and the mesh efficiency. Coated
points with a known damage coefficient c1 (parameter ``damage_coefficient``) or an observed
coating life (``[map] cycles_observed``) also get the cycles to coating failure and to
returning stiction (:func:`memstribo.physics.damage.run_damage`).

The points run as independent tasks on dask.distributed (like :mod:`memstribo.simulations.study`, whose
helpers this module reuses): each finished point is written at once, atomically, to
``OUT/points/<id>.json``; ``resume=True`` computes only the missing points and reruns the
failed ones. At the end ``OUT/map.nc`` (NetCDF, CF attributes and provenance) holds the map
with **one dimension per swept parameter**, ``OUT/map.csv`` the same as a table, and
``OUT/figures/`` the filled contours of stiction probability (with the 50 % boundary),
efficiency and coating life.

Spec file (TOML)::

    [parameters]                    # optional: base overrides for every point
    load_case = "torque"

    [map]
    name = "torque x face width"
    realisations = 4                # roughness realisations per point (default 4)
    steps = 21                      # optional: positions per meshing cycle
    plot = ["drive_torque", "face_width"]   # optional: the two axes of the figures
    cycles_observed = 1e6           # optional: observed coating life, calibrates c1
    wear_sweep = [0, 0.25, 0.5, 0.75, 1]     # optional: Omega states for the critical wear
    uncertainty = 64                # optional: P(stiction) over realisations x constants from their priors
                                    # (MODEL 7d, memstribo.uncertainty): samples per point, realisations each

    [map.fixed]                     # optional: the same for every point
    coating = "OTS"

    [map.grid]                      # the axes, in the order written
    drive_torque = {start = "5e-8 N*m", stop = "2e-7 N*m", num = 4}
    face_width = ["1 um", "2 um", "4 um"]
"""

from __future__ import annotations

import functools
import json
import math
import os
import sys
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from memstribo.errors import InputError, MemstriboError, did_you_mean
from memstribo.output import ensure_directory
from memstribo.quantities import attrs as quantity_attrs
from memstribo.quantities import unit as quantity_unit
from memstribo.units import printable

__all__ = ["MapSpec", "MapResult", "MAP_RESULTS", "load_map_spec", "map_spec", "design_map", "map_point",
           "map_dataset", "map_figures"]

MANIFEST = "map.json"
FORMAT_VERSION = 1
DEFAULT_REALISATIONS = 4
DEFAULT_WEAR_SWEEP = (0.0, 0.25, 0.5, 0.75, 1.0)
#: most points of one map (each point is an ensemble of meshing cycles)
MAX_MAP_POINTS = 10_000

#: the results of one map point: name -> (unit, long name)
#: The results of a map point (units and meanings in :mod:`memstribo.quantities`): the ensemble verdict under
#: the names of :func:`memstribo.simulations.mesh.ensemble_summary`, and the coating's life.
MAP_RESULTS = ("stiction_probability", "stiction_margin_median", "stiction_margin_p05", "stiction_margin_p95",
               "cof_mean_median", "cof_mean_p05", "cof_mean_p95", "mesh_efficiency_median", "mesh_efficiency_p05",
               "mesh_efficiency_p95", "realisations", "cycles_to_failure", "cycles_to_stiction", "critical_wear",
               "stiction_probability_low", "stiction_probability_high", "stiction_probability_nominal",
               "uncertainty_samples", "converged", "step_change_margin", "grid_change_margin",
               # the start-up verdict over the realisations (MODEL 7f, issue #35)
               "startup_stiction_probability", "startup_stiction_probability_low",
               "startup_stiction_probability_high", "startup_margin_median", "startup_margin_p05",
               "startup_margin_p95")

_MAP_KEYS = {"name", "realisations", "steps", "plot", "cycles_observed", "wear_sweep", "grid", "fixed",
             "uncertainty"}


@dataclass(frozen=True)
class MapSpec:
    """A design map: the grid axes and how each point is computed.

    Attributes
    ----------
    name : str
        Title of the map.
    axes : tuple of (str, list)
        The swept keys (model parameters or ``coating``, ``wear``, ``seed``, ``roughness``,
        ``steps``) and their values as written (units allowed: ``"2 um"``), in grid order.
    fixed : dict
        Keys set the same at every point.
    parameters : dict
        Base parameter overrides (``[parameters]``).
    realisations : int
        Roughness realisations per point.
    steps : int or None
        Positions along the path of contact (None: the parameter ``mesh_steps``).
    plot : tuple of str
        The two axes of the figures (default: the first two numeric axes).
    cycles_observed : float or None
        Observed coating life [meshing cycles] that calibrates c1.
    wear_sweep : tuple of float
        Worn fractions Omega [-] whose stiction margins give the critical wear of coated points.
    uncertainty : int
        Samples (realisations x constant sets) of each point's P(stiction) over the uncertain
        constants (MODEL 7d; 0: the realisations at nominal constants only).
    source : str
        Where the spec comes from (file name or "python").
    """

    name: str
    axes: tuple[tuple[str, list], ...]
    fixed: dict[str, Any] = field(default_factory=dict)
    parameters: dict[str, Any] = field(default_factory=dict)
    realisations: int = DEFAULT_REALISATIONS
    steps: int | None = None
    plot: tuple[str, ...] = ()
    cycles_observed: float | None = None
    wear_sweep: tuple[float, ...] = DEFAULT_WEAR_SWEEP
    uncertainty: int = 0
    source: str = "python"

    @property
    def shape(self) -> tuple[int, ...]:
        """Number of values along each axis."""
        return tuple(len(values) for _, values in self.axes)

    @property
    def dims(self) -> tuple[str, ...]:
        """The swept keys (the dimensions of the map)."""
        return tuple(key for key, _ in self.axes)


@dataclass(frozen=True)
class MapResult:
    """What a map run did.

    Attributes
    ----------
    folder : pathlib.Path
        The output folder.
    n_points, n_computed, n_reused, n_failed, n_retried : int
        Points of the map, computed by this run, found finished on disk, failed, and rerun
        after failing in an earlier run.
    elapsed : float
        Wall time of this run [s].
    dataset : xarray.Dataset
        The map, one dimension per axis (also in ``map.nc``/``map.csv``).
    errors : dict
        ``{point id: message}`` of the failed points.
    figures : list of pathlib.Path
        The figures written.
    notes : list of str
        What could not be computed and why (e.g. coating life without c1).
    """

    folder: Path
    n_points: int
    n_computed: int
    n_reused: int
    n_failed: int
    n_retried: int
    elapsed: float
    dataset: Any
    errors: dict[str, str]
    figures: list = field(default_factory=list)
    notes: list = field(default_factory=list)


# --- spec ----------------------------------------------------------------------------------------

def map_spec(table: Mapping[str, Any], parameters: Mapping[str, Any] | None = None,
             source: str = "python") -> MapSpec:
    """Build a :class:`MapSpec` from the ``[map]`` table of a spec file (as a dict), validated whole.

    Raises
    ------
    InputError
        Unknown keys (with a did-you-mean), wrong types, an empty grid, a key both fixed and
        swept, a plot axis that is not a numeric axis, more than 10 000 points.
    """
    from memstribo.simulations.study import _check_scalar, _expand_values
    from memstribo.units import to_si

    where = f"map spec {printable(source, 200)}"
    if not isinstance(table, Mapping):
        raise InputError(f"{where}: [map] must be a table.")
    from memstribo.checks import refuse_unknown_keys

    refuse_unknown_keys(table, _MAP_KEYS, where, "key(s) {keys} in [map]")
    grid, fixed = table.get("grid", {}), table.get("fixed", {})
    if not isinstance(grid, Mapping) or not isinstance(fixed, Mapping):
        raise InputError(f"{where}: [map.grid] and [map.fixed] must be tables.")
    if not grid:
        raise InputError(f"{where}: no axes: give a [map.grid] table (e.g. drive_torque = [...], "
                         "face_width = [...]).")
    name = table.get("name", "design map")
    if not isinstance(name, str) or not name.strip() or len(name) > 200:
        raise InputError(f"{where}: name must be a short text (1 to 200 characters), got {printable(repr(name), 60)}.")
    for key, value in fixed.items():
        _check_scalar(key, value, f"{where} [map.fixed]")
    both = sorted(set(grid) & set(fixed))
    if both:
        raise InputError(f"{where}: {both} both in [map.grid] and [map.fixed]; give each key once.")
    axes = tuple((str(key), _expand_values(key, values, f"{where} [map.grid]")) for key, values in grid.items())
    n_points = math.prod(len(values) for _, values in axes)
    if n_points > MAX_MAP_POINTS:
        raise InputError(f"{where}: {n_points:,} points; a map holds at most {MAX_MAP_POINTS:,}.")
    realisations = table.get("realisations", DEFAULT_REALISATIONS)
    if not isinstance(realisations, int) or isinstance(realisations, bool) or not 1 <= realisations <= 10_000:
        raise InputError(f"{where}: realisations = {printable(repr(realisations), 40)}: give an integer from 1 "
                         "to 10000.")
    steps = table.get("steps")
    if steps is not None and (not isinstance(steps, int) or isinstance(steps, bool) or not 2 <= steps <= 100_000):
        raise InputError(f"{where}: steps = {printable(repr(steps), 40)} must be an integer from 2 to 100000.")
    cycles = table.get("cycles_observed")
    if cycles is not None:
        try:
            cycles = to_si(cycles, "", "cycles_observed")
        except InputError as exc:
            raise InputError(f"{where}: cycles_observed: {exc}") from None
        if not math.isfinite(cycles) or cycles <= 0:
            raise InputError(f"{where}: cycles_observed = {cycles!r}: give a number of meshing cycles > 0.")
    wears = table.get("wear_sweep", list(DEFAULT_WEAR_SWEEP))
    if (not isinstance(wears, list) or len(wears) < 2
            or not all(isinstance(w, (int, float)) and not isinstance(w, bool) and 0 <= w <= 1 for w in wears)):
        raise InputError(f"{where}: wear_sweep = {printable(repr(wears), 60)}: give a list of at least two worn "
                         "fractions from 0 to 1.")
    uncertainty = table.get("uncertainty", 0)
    if (not isinstance(uncertainty, int) or isinstance(uncertainty, bool) or not 0 <= uncertainty <= 100_000
            or (uncertainty and uncertainty < realisations)):
        raise InputError(f"{where}: uncertainty = {printable(repr(uncertainty), 40)}: give the samples per point "
                         f"(realisations x constant sets), at least realisations ({realisations}) and at most "
                         "100000, or 0 for none.")
    numeric = [key for key, values in axes if _is_numeric(key) and len(values) >= 2]
    plot = table.get("plot")
    if plot is None:
        plot = numeric[:2]
    elif (not isinstance(plot, list) or not 1 <= len(plot) <= 2 or not all(isinstance(p, str) for p in plot)
          or len(set(plot)) != len(plot)):
        raise InputError(f"{where}: plot = {printable(repr(plot), 60)}: give one or two axis names, e.g. "
                         "[\"drive_torque\", \"face_width\"].")
    for key in plot:
        if key not in numeric:
            raise InputError(f"{where}: plot axis '{printable(key, 40)}' is not a numeric axis of [map.grid] with "
                             f"two or more values; axes: {numeric}.{did_you_mean(key, numeric)}")
    return MapSpec(name=name, axes=axes, fixed=dict(fixed), parameters=dict(parameters or {}),
                   realisations=realisations, steps=steps, plot=tuple(plot), cycles_observed=cycles,
                   wear_sweep=tuple(float(w) for w in wears), uncertainty=int(uncertainty), source=source)


def load_map_spec(path: str | Path) -> MapSpec:
    """Read a map spec TOML file (``[map]`` table, optional ``[parameters]``), validated whole."""
    from memstribo.parameters import read_config

    config = read_config(path)
    if "map" not in config:
        raise InputError(f"map spec '{printable(path, 200)}' has no [map] table; see 'memstribo map --help'.")
    others = sorted(set(config) - {"map", "parameters", "meta"})
    if others:
        raise InputError(f"map spec '{printable(path, 200)}' has {others} table(s); a map spec holds [map] and "
                         "[parameters] only.")
    return map_spec(config["map"], config.get("parameters"), source=str(path))


def _is_numeric(key: str) -> bool:
    from memstribo.parameters import SPECS

    return (key in SPECS and SPECS[key].kind in ("float", "int")) or key in ("wear", "seed", "steps")


def _study_of(spec: MapSpec):
    """The map's points as a :class:`memstribo.simulations.study.StudySpec` (grid order: last axis fastest)."""
    import itertools

    from memstribo.simulations.study import StudySpec

    fixed = dict(spec.fixed)
    if spec.steps is not None and "steps" not in fixed and "steps" not in spec.dims:
        fixed["steps"] = spec.steps
    points = tuple({**fixed, **dict(zip(spec.dims, combination))}
                   for combination in itertools.product(*(values for _, values in spec.axes)))
    parameters = {**spec.parameters, "realisations": spec.realisations}
    return StudySpec(name=spec.name, function="map", points=points, parameters=parameters, source=spec.source)


# --- one point ------------------------------------------------------------------------------------------

def map_point(params, coating: str | None = None, wear: float = 1.0, roughness: str | None = None,
              steps: int | None = None, *, cycles_observed: float | None = None,
              wear_sweep=DEFAULT_WEAR_SWEEP, uncertainty: int = 0) -> dict[str, Any]:
    """The ensemble verdict of one map point (and the coating life where it is known).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        The point's parameters; ``realisations`` sets the size of the ensemble.
    coating : str or None
        Coating name; None for bare silicon.
    wear : float
        Worn fraction Omega of the gear's coating [-] (1 for bare silicon).
    roughness : str or None
        Path of a measured profile or AFM map; None for the synthetic roughness.
    steps : int or None
        Positions along the path of contact.
    cycles_observed : float, optional
        Observed coating life [meshing cycles] that calibrates c1.
    wear_sweep : sequence of float
        Worn fractions [-] whose stiction margins give the critical wear.
    uncertainty : int
        Samples of P(stiction) over realisations x the uncertain constants
        (:func:`memstribo.uncertainty.study.uncertainty_study`, no sensitivity); 0: the realisations
        at nominal constants only.

    Returns
    -------
    dict
        The keys of :data:`MAP_RESULTS` (SI; NaN where unknown) and ``note`` (text). The
        probability always comes with its 95 % interval (``stiction_probability_low``, ``_high``,
        Wilson); with ``uncertainty`` it is over realisations x constants and
        ``stiction_probability_nominal`` keeps the realisations' at nominal constants.
    """
    from memstribo.simulations import mesh
    from memstribo.simulations.study import _read_roughness

    coating_object = None
    if coating is not None:
        from memstribo.physics.coating import get_coating

        coating_object = get_coating(coating, params)
    surface = _read_roughness(roughness)
    summaries, first = [], None
    for k in range(int(params["realisations"])):
        dataset = mesh.simulate_mesh(params, surface, steps=steps, coating=coating_object, wear=wear,
                                     realisation=k)
        summary = mesh.summarize(dataset)
        summary["realisation"] = k
        summary["seed"] = [int(params["roughness_seed"]), k]
        summaries.append(summary)
        if k == 0:
            first = dataset
    from memstribo.uncertainty.intervals import ensemble_interval

    ensemble = ensemble_interval(mesh.ensemble_summary(summaries))
    values: dict[str, Any] = {key: ensemble[key] for key in MAP_RESULTS if key in ensemble}
    values["stiction_probability_nominal"] = ensemble["stiction_probability"]
    for kind in ("stiction", "startup_stiction"):  # the running and start-up verdicts' intervals (MODEL 7d, 7f)
        if f"{kind}_probability_ci" in ensemble:
            values[f"{kind}_probability_low"], values[f"{kind}_probability_high"] = ensemble[f"{kind}_probability_ci"]
    values["uncertainty_samples"] = 0
    if uncertainty:
        from memstribo.uncertainty.study import uncertainty_study

        study = uncertainty_study(params, surface, samples=int(uncertainty), realisations=int(params["realisations"]),
                                  steps=steps, coating=coating, wear=wear, sensitivity=False)
        values["stiction_probability"] = study["stiction_probability"]
        values["stiction_probability_low"], values["stiction_probability_high"] = study["stiction_probability_ci"]
        values["uncertainty_samples"] = study["samples"]
    values.update(_converged(params, surface, steps, coating_object, wear, summaries[0], first))
    values.update(cycles_to_failure=math.nan, cycles_to_stiction=math.nan, critical_wear=math.nan)
    note = ""
    if coating is None:
        note = "bare silicon: no coating life"
    elif params["damage_coefficient"] is None and cycles_observed is None:
        note = "coating life unknown: set the parameter damage_coefficient or [map] cycles_observed"
    else:
        from memstribo.simulations import coating_wear as coating_module
        from memstribo.physics import damage

        try:
            # the point's first cycle (realisation 0, its own wear) is one of the sweep's states when its
            # wear is in wear_sweep: reused, not computed again (the same call, the same numbers)
            sweep = coating_module.wear_sweep(params, coating_object, list(wear_sweep), roughness=surface,
                                              steps=steps, known={float(wear): first})
            outcome = damage.run_damage(params, first, wear_sweep=sweep, cycles_observed=cycles_observed,
                                        figures=False)
            summary = outcome.summary
            values["cycles_to_failure"] = float(summary.get("cycles_to_failure", math.nan))
            stiction = summary.get("cycles_to_stiction")
            values["cycles_to_stiction"] = math.nan if stiction is None else float(stiction)
            crit = summary.get("critical_wear")
            values["critical_wear"] = math.nan if crit is None else float(crit)
            if crit is None:
                note = "stiction does not return up to the largest worn fraction of wear_sweep"
        except MemstriboError as exc:
            note = f"coating life not computed: {exc}"
    values["note"] = note
    return values


map_point.units = {key: quantity_unit(key) for key in MAP_RESULTS}


def _converged(params, surface, steps, coating, wear, first, dataset=None) -> dict:
    """``converged`` (1.0 or 0.0, NaN where unchecked) and the changes of the point's first realisation at twice
    the steps and at twice the grid's resolution (MODEL 7d; :func:`memstribo.simulations.mesh.convergence.check_cycle`).
    Unchecked where ``mesh_step_refinements`` or ``mesh_grid_refinements`` is 0. ``dataset``: that cycle, so that
    each comparison is first the spot check (the whole finer cycle only where it fails, :mod:`.mesh.spot`)."""
    if not (params["mesh_step_refinements"] and params["mesh_grid_refinements"]):
        return {"converged": math.nan, "step_change_margin": math.nan, "grid_change_margin": math.nan}
    from memstribo.simulations.mesh.convergence import check_cycle

    check = check_cycle(params, surface, steps=steps, coating=coating, wear=wear, baseline=first, dataset=dataset)
    return {"converged": float(check["converged"]), "step_change_margin": check["step_change_margin"],
            "grid_change_margin": check["grid_change_margin"]}


# --- running ---------------------------------------------------------------------------------------------

def design_map(spec: MapSpec, out: str | Path, params=None, *, client=None, scheduler: str | None = None,
               workers: int | None = None, resume: bool = False, progress: bool = False,
               figures: bool = True) -> MapResult:
    """Compute a design map on Dask, point by point, resumable; write ``map.nc``, ``map.csv`` and figures.

    Parameters
    ----------
    spec : MapSpec
        The map (see :func:`load_map_spec` or :func:`map_spec`).
    out : str or pathlib.Path
        Output folder: ``map.json`` (manifest), ``points/<id>.json``, ``map.nc``, ``map.csv``,
        ``figures/``.
    params : memstribo.parameters.Parameters, optional
        Base parameters (default: the thesis set).
    client : distributed.Client, optional
        An existing Dask client to run the points on (it is not closed).
    scheduler : str, optional
        Address of an existing Dask scheduler (``tcp://host:8786``), when no ``client``.
    workers : int, optional
        Worker processes of the LocalCluster started when neither ``client`` nor ``scheduler``
        is given (default: the number of cores).
    resume : bool
        Finish a map started in ``out``: compute only the missing points, rerun the failed ones.
    progress : bool
        Progress bar (tqdm) over the points on stderr.
    figures : bool
        Write the figures.

    Returns
    -------
    MapResult

    Raises
    ------
    InputError
        A bad point, ``out`` holding another map, or ``out`` holding this map without ``resume``.
    """
    from memstribo.simulations.study import require_dask

    require_dask("memstribo map")
    from memstribo.output import provenance_attributes, write_dataset
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.study import _finished_points, _hash, POINTS_FOLDER, prepare_points
    from memstribo.simulations.study import points_references

    start = time.perf_counter()
    params = params if params is not None else get_parameter_values()
    if workers is not None and (not isinstance(workers, int) or isinstance(workers, bool) or workers < 1):
        raise InputError(f"workers = {workers!r}: give a positive integer.")
    study = _study_of(spec)
    points = prepare_points(study, params)
    base = params.updated(study.parameters, origin=f"map spec {spec.source}")
    folder = ensure_directory(out)
    options = {"cycles_observed": spec.cycles_observed, "wear_sweep": list(spec.wear_sweep)}
    if spec.uncertainty:  # only then: the hash of a map without it stays what it was
        options["uncertainty"] = int(spec.uncertainty)
    map_hash = _hash({"function": "map_point", "points": [[p.id, p.inputs] for p in points], "options": options,
                      "parameters": params.to_dict(), "base": study.parameters, "axes": spec.axes})
    manifest_path = folder / MANIFEST
    from memstribo.simulations.study import check_or_write_manifest

    check_or_write_manifest(manifest_path, folder, resume, map_hash, {
        "format": FORMAT_VERSION, "name": spec.name, "source": spec.source, "hash": map_hash,
        "axes": [[key, values] for key, values in spec.axes], "parameter_set": params.name,
        "base_overrides": study.parameters, "options": options,
        "points": [{"id": p.id, "index": p.index, "inputs": p.inputs} for p in points],
    }, what="map", differs="other axes, points or parameters")
    ensure_directory(folder / POINTS_FOLDER)
    ids = {p.id for p in points}
    finished = _finished_points(folder, ids)
    done = {pid for pid, record in finished.items() if not record.get("error")}
    n_retried = len(finished) - len(done)
    todo = [p for p in points if p.id not in done]
    function = functools.partial(map_point, **options)
    if todo:
        _compute(spec, function, todo, folder, len(points), len(done), client, scheduler, workers, progress)
    records = _finished_points(folder, ids)
    missing = ids - set(records)
    if missing:
        raise InputError(f"{len(missing)} point(s) have no result file in '{folder / POINTS_FOLDER}'; rerun with "
                         "--resume.")
    ordered = [records[p.id] for p in points]
    dataset = map_dataset(ordered, spec, points)
    cited = points_references(ordered)  # recorded on the workers, returned with each point
    provenance = provenance_attributes(base, extra={
        "title": spec.name, "stage": "design map", "models_cited": ", ".join(cited) or "none recorded",
        "map_axes": json.dumps(list(spec.dims)),
        "map_realisations": spec.realisations, "map_spec": spec.source,
        "map_cycles_observed": "none" if spec.cycles_observed is None else spec.cycles_observed,
        "map_wear_sweep": json.dumps(list(spec.wear_sweep))})
    write_dataset(dataset, folder, "map", provenance=provenance)
    written, notes = [], _notes(dataset)
    if figures:
        written, figure_notes = map_figures(dataset, folder / "figures", spec.plot)
        notes += figure_notes
    errors = {r["id"]: r["error"] for r in ordered if r.get("error")}
    return MapResult(folder, len(points), len(todo), len(done), len(errors), n_retried,
                     time.perf_counter() - start, dataset, errors, written, notes)


def _compute(spec, function, todo, folder, total, already, client, scheduler, workers, progress) -> None:
    """Submit the points to Dask; write each one at once as it finishes (any order)."""
    from distributed import as_completed
    from tqdm.auto import tqdm

    from memstribo.simulations.study import POINTS_FOLDER, _connect, _write_json_atomic, evaluate_point

    cluster = None
    own = client is None
    if own:
        client, cluster = _connect(scheduler, workers)
    bar = tqdm(total=total, initial=already, unit="point", desc=spec.name, file=sys.stderr,
               disable=not progress, dynamic_ncols=True)
    try:
        futures = {}
        # the longest points first (and with the highest priority): the last tasks are then the short
        # ones, so that no worker waits long for another's long point at the end of the map
        ordered = sorted(todo, key=lambda point: -_point_cost(point, function))
        for rank, point in enumerate(ordered):
            future = client.submit(evaluate_point, function, point.params, point.options,
                                   key=f"memstribo-map-{point.id}-{os.getpid()}-{time.time_ns()}", pure=False,
                                   priority=len(ordered) - rank)
            futures[future] = point
        for future in as_completed(list(futures), loop=client.loop):
            point = futures.pop(future)
            try:
                outcome = future.result()
            except Exception as exc:  # a bug in a point: record it, carry on
                outcome = {"values": {}, "error": f"{type(exc).__name__}: {exc}", "seconds": None}
            record = {"id": point.id, "index": point.index, "inputs": point.inputs, **outcome}
            _write_json_atomic(folder / POINTS_FOLDER / f"{point.id}.json", record)
            future.release()
            bar.update(1)
    finally:
        bar.close()
        if own:
            client.close()
            if cluster is not None:
                cluster.close()


def _point_cost(point, function=None) -> float:
    """Relative cost of a map point, for the order of the tasks: rows x steps x meshing cycles.

    The contact solves dominate a meshing cycle, one per nanoblock row and step; a coated point
    whose coating life is computed adds one cycle per worn fraction of ``wear_sweep`` other than
    its own (that one is its first realisation's cycle, reused). Only the
    order of the tasks depends on it, never a result.
    """
    try:
        params = point.params
        rows = max(1, int(float(params["face_width"]) // float(params["adhesive_width"])))
        steps = point.options.get("steps") or params["mesh_steps"]
        cycles = int(params["realisations"])
        if point.options.get("coating"):
            options = getattr(function, "keywords", {}) or {}
            if params["damage_coefficient"] is not None or options.get("cycles_observed") is not None:
                states = {float(w) for w in options.get("wear_sweep", DEFAULT_WEAR_SWEEP)}
                cycles += len(states - {float(point.options.get("wear", 0.0))})  # the point's own: reused
        return float(rows * int(steps) * cycles)
    except (KeyError, TypeError, ValueError, MemstriboError):
        return 1.0


# --- the dataset ---------------------------------------------------------------------------------------

def map_dataset(records: list[dict], spec: MapSpec, points: list | None = None):
    """The map as an :class:`xarray.Dataset` with one dimension per axis of ``spec``.

    Numeric axes are coordinates in SI (with ``units``); ``coating`` and ``roughness`` axes
    are text coordinates. Every result of :data:`MAP_RESULTS` is a variable over all axes
    (NaN where a point failed or a value is unknown); ``error`` and ``note`` hold text.
    """
    import xarray as xr

    from memstribo.parameters import SPECS
    from memstribo.simulations.study import STUDY_KEYS, _unit_of
    from memstribo.units import to_si

    shape, dims = spec.shape, spec.dims
    coords = {}
    for key, values in spec.axes:
        unit = _unit_of(key)
        description = SPECS[key].description if key in SPECS else STUDY_KEYS.get(key, ("", key))[1]
        if _is_numeric(key):
            array = np.array([to_si(v, unit, key) for v in values], dtype=float)
        else:
            array = np.array([str(v) for v in values], dtype=object)
        coords[key] = (key, array, {"units": unit, "long_name": description})
    data = {}
    for key in MAP_RESULTS:
        flat = [r.get("values", {}).get(key) for r in records]
        array = np.array([np.nan if v is None else float(v) for v in flat], dtype=float).reshape(shape)
        data[key] = (dims, array, quantity_attrs(key))
    for key in ("note", "error"):
        source = [(r.get("values", {}).get("note") if key == "note" else r.get("error")) or "" for r in records]
        data[key] = (dims, np.array(source, dtype=object).reshape(shape), quantity_attrs(key))
    data["point_id"] = (dims, np.array([r["id"] for r in records], dtype=object).reshape(shape),
                        quantity_attrs("point_id"))
    dataset = xr.Dataset({k: xr.Variable(*v) for k, v in data.items()},
                         coords={k: xr.Variable(*v) for k, v in coords.items()})
    dataset.attrs["title"] = spec.name
    return dataset


def _notes(dataset) -> list[str]:
    notes = []
    if "converged" in dataset:  # MODEL 7d: a point that is not converged says so (hollow markers in the figures)
        flags = np.asarray(dataset["converged"].values, dtype=float)
        checked = int(np.isfinite(flags).sum())
        if checked:
            notes.append(f"{int((flags == 0).sum())} of {checked} checked point(s) not converged (margin or mean COF "
                         "change by 2 % or more at twice the steps or the grid): hollow markers in the figures")
    for text in dict.fromkeys(str(v) for v in np.ravel(dataset["note"].values)):
        if text and not text.startswith("bare silicon"):
            count = int((dataset["note"].values == text).sum())
            notes.append(f"{count} point(s): {text}")
    return notes


# --- figures ----------------------------------------------------------------------------------------------

_FIGURES = (
    ("stiction_probability", "stiction probability [-]", "design_map_stiction"),
    ("mesh_efficiency_median", "mesh efficiency, median [-]", "design_map_efficiency"),
    ("cycles_to_failure", "log10 cycles to coating failure", "design_map_coating_life"),
)


_PREFIXES = ((1e-15, "f"), (1e-12, "p"), (1e-9, "n"), (1e-6, "µ"), (1e-3, "m"), (1.0, ""))


def _display(dataset, key: str) -> tuple[float, str]:
    """(factor from SI, axis label): ``face_width`` in µm, ``drive_torque`` in nN*m, ..."""
    unit = dataset[key].attrs.get("units", "")
    name = key.replace("_", " ")
    if not unit or unit == "1":
        return 1.0, name
    values = np.abs(np.asarray(dataset[key].values, dtype=float))
    largest = float(values.max()) if values.size else 1.0
    factor, prefix = 1.0, ""
    if unit in ("m", "N", "N*m", "Pa", "J") and 0 < largest < 1:
        for scale, symbol in _PREFIXES:
            if largest >= scale:
                factor, prefix = scale, symbol
    return 1.0 / factor, f"{name} [{prefix}{unit}]"


def map_figures(dataset, folder: str | Path, plot=(), *, stem_prefix: str = "", max_panels: int = 6):
    """Filled contours of the map over the ``plot`` axes: stiction probability, efficiency, coating life.

    The stiction probability figure draws the 50 % boundary (where the map crosses it). Other
    axes of the map give one panel per value combination (at most ``max_panels``; the rest are
    left out with a note). One plot axis gives line plots instead of contours.

    Parameters
    ----------
    dataset : xarray.Dataset
        From :func:`map_dataset`.
    folder : str or pathlib.Path
        Where the PNG and SVG files go.
    plot : sequence of str
        One or two numeric axes (default: the first two numeric axes with two or more values).
    stem_prefix : str
        Prefix of the file names (``design_map_stiction`` etc. follow it).
    max_panels : int
        Most panels per figure.

    Returns
    -------
    (list of pathlib.Path, list of str)
        Files written, and notes on figures left out.
    """
    import itertools

    from memstribo.output import new_figure, save_figure

    plot = list(plot) or [d for d in dataset["stiction_probability"].dims
                          if dataset[d].dtype.kind == "f" and dataset.sizes[d] >= 2][:2]
    if not plot:
        return [], ["no figure: the map has no numeric axis with two or more values"]
    others = [d for d in dataset["stiction_probability"].dims if d not in plot]
    combos = list(itertools.product(*(range(dataset.sizes[d]) for d in others)))
    notes = []
    if len(combos) > max_panels:
        notes.append(f"figures show the first {max_panels} of {len(combos)} combinations of {others}")
        combos = combos[:max_panels]
    written = []
    for key, title, stem in _FIGURES:
        values = dataset[key]
        if key == "cycles_to_failure":
            finite = np.isfinite(values.values) & (values.values > 0)
            if not finite.any():
                continue
            values = np.log10(values.where(finite))
        levels = _levels(values.values)
        n = len(combos)
        fig, axes = new_figure(1, n, figsize=(4.2 * n + 0.8, 3.6), squeeze=False, constrained_layout=True)
        mappable = None
        for ax, combo in zip(axes[0], combos):
            selection = dict(zip(others, combo))
            panel = values.isel(selection).transpose(*plot)
            caption = ", ".join(f"{d} = {_coord_text(dataset, d, i)}" for d, i in selection.items())
            band = None
            if key == "stiction_probability" and "stiction_probability_low" in dataset:
                band = tuple(dataset[b].isel(selection).transpose(*plot)
                             for b in ("stiction_probability_low", "stiction_probability_high"))
            flags = dataset["converged"].isel(selection).transpose(*plot).values if "converged" in dataset else None
            mappable = _draw_panel(ax, dataset, panel, plot, key, levels, band, flags)
            ax.set_title(caption or dataset.attrs.get("title", ""), fontsize=9)
        if mappable is not None and len(plot) == 2:
            bar = fig.colorbar(mappable, ax=list(axes[0]), format="%.4g")
            bar.set_label(title)
        fig.suptitle(f"{dataset.attrs.get('title', 'design map')}: {title}", fontsize=10)
        written += save_figure(fig, folder, f"{stem_prefix}{stem}")
    return written, notes


def _coord_text(dataset, dim: str, index: int) -> str:
    value = dataset[dim].values[index]
    unit = dataset[dim].attrs.get("units", "")
    if isinstance(value, (float, np.floating)):
        return f"{float(value):.3g} {unit}".strip()
    return str(value)


def _levels(values) -> np.ndarray:
    """11 contour levels over every finite value of ``values`` (the same for all panels)."""
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    if finite.size and finite.min() < finite.max():
        return np.linspace(finite.min(), finite.max(), 11)
    centre = float(finite[0]) if finite.size else 0.0
    half = 0.5 * (abs(centre) + 1e-12)
    return np.linspace(centre - half, centre + half, 3)


def _draw_panel(ax, dataset, panel, plot, key, levels=None, band=None, flags=None):
    """One panel: contours over two axes (lines over one), the points marked, hollow where not converged."""
    x_factor, x_label = _display(dataset, plot[0])
    x = dataset[plot[0]].values.astype(float) * x_factor
    if len(plot) == 1:
        ax.plot(x, panel.values, marker="o")
        bad = np.asarray(flags, dtype=float) == 0 if flags is not None else np.zeros(x.shape, dtype=bool)
        if bad.any():
            ax.plot(x[bad], np.asarray(panel.values)[bad], "o", markerfacecolor="white", markeredgecolor="k",
                    markersize=7, label="not converged")
            ax.legend(loc="best", fontsize=7)
        if key == "stiction_probability":
            ax.axhline(0.5, color="k", linestyle="--", linewidth=0.8, label="50 %")
            if band is not None:  # the 95 % interval of each point's probability
                ax.fill_between(x, band[0].values, band[1].values, color="C0", alpha=0.25, lw=0,
                                label="95 % interval")
            ax.set_ylim(-0.05, 1.05)
        ax.set_xlabel(x_label)
        ax.set_ylabel(key.replace("_", " "))
        _scale(ax.set_xscale, x)
        return None
    y_factor, y_label = _display(dataset, plot[1])
    y = dataset[plot[1]].values.astype(float) * y_factor
    z = np.ma.masked_invalid(panel.values.T)  # rows: y, columns: x
    if key == "stiction_probability":
        levels = np.linspace(0.0, 1.0, 11)
        mappable = ax.contourf(x, y, z, levels=levels, cmap="RdYlGn_r", vmin=0.0, vmax=1.0)
        if z.count() and z.min() < 0.5 < z.max():
            lines = ax.contour(x, y, z, levels=[0.5], colors="k", linewidths=1.5)
            ax.clabel(lines, fmt={0.5: "50 %"}, fontsize=8)
        if band is not None:  # the band of the 50 % boundary: where either end of the 95 % interval crosses 0.5
            for bound in band:
                zb = np.ma.masked_invalid(bound.values.T)
                if zb.count() and zb.min() < 0.5 < zb.max():
                    ax.contour(x, y, zb, levels=[0.5], colors="k", linewidths=0.9, linestyles="--")
    else:
        mappable = ax.contourf(x, y, z, levels=levels, cmap="viridis")
    _mark_points(ax, x, y, flags)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    _scale(ax.set_xscale, x)
    _scale(ax.set_yscale, y)
    return mappable


def _mark_points(ax, x, y, flags=None) -> None:
    """The computed points: small dots where converged (or unchecked), hollow circles where not (MODEL 7d).

    ``flags``: the points' ``converged`` over (x, y) (1, 0 or NaN), or None."""
    xx, yy = np.meshgrid(x, y)
    bad = (np.asarray(flags, dtype=float).T == 0) if flags is not None else np.zeros(xx.shape, dtype=bool)
    ax.plot(xx[~bad], yy[~bad], "k.", markersize=2)
    if bad.any():
        ax.plot(xx[bad], yy[bad], "o", markerfacecolor="none", markeredgecolor="k", markersize=6,
                label="not converged")
        ax.legend(loc="best", fontsize=7)


def _scale(setter, values) -> None:
    values = np.asarray(values, dtype=float)
    if values.size >= 2 and np.all(values > 0) and values.max() / values.min() >= 100:
        setter("log")
