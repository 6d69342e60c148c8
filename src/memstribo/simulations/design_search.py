"""Design search: the gear pair with the widest safe torque window, by NSGA-II under uncertainty (issue #39).

Each candidate design (module, teeth or ratio, face width, pressure angle, addendum, coating; see
:mod:`memstribo.simulations.design_spec`) is first checked for its geometry (undercut, interference,
pointed tip, contact ratio, minimum tip thickness: no cycle runs for a design that fails). A feasible
design gets its **safe torque window**:

* the lower (stiction) edge is the lowest torque of the spec's log-spaced torques at which the running
  and the start-up stiction probabilities, over ``realisations`` roughness realisations, are below
  ``stiction_probability`` by the upper end of their 95 % Wilson interval (MODEL 7b, 7d, 7f). Each
  verdict is a map point (:func:`memstribo.simulations.design_map.map_point`: cheap cycles of ``steps``
  positions, with the map's convergence spot check, ``converged``); the edge is found by bisection over
  the torques (P(stiction) falls as the torque rises), at most ceil(log2(num + 1)) verdicts;
* the upper (fracture) edge is the torque at which the probability that a tooth breaks within ``cycles``
  pinion revolutions (:func:`memstribo.simulations.tooth_life.fracture_probability_within`, on the
  cycle's load with the lower edge's mean COF) reaches ``fracture_probability``, capped at the range's top;
* the window is the upper edge minus the lower, 0 where they cross. ``torque_window_high`` is the same
  with the lower edge at the torque below it (the edge lies between the two: the grid's resolution).

The mesh efficiency at the lower edge, the coating's life there (``cycles_to_failure``), and the pair's
footprint are the other objectives. The search is NSGA-II (pymoo), seeded; each evaluation is written
at once to ``OUT/evaluations/<id>.json``, so that an interrupted search, run again with ``resume``,
replays its generations from the disk (the same seed gives the same candidates) and computes only what
is missing. Evaluations run on Dask like the maps (``workers=1``: in this process).
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from memstribo.errors import InputError, MemstriboError
from memstribo.output import ensure_directory
from memstribo.quantities import attrs as quantity_attrs
from memstribo.references import cites
from memstribo.simulations.design_spec import (CONSTRAINT_NAMES, DesignSpec, complete, decode, design_key,
                                               design_parameters, geometry_constraints)

__all__ = ["DesignResult", "DESIGN_RESULTS", "OBJECTIVE_KEYS", "run_design", "evaluate_design", "footprint",
           "design_dataset", "front_figure", "brute_force", "explain_arguments", "default_design"]

MANIFEST = "design.json"
EVALUATIONS = "evaluations"
#: the numbers of one evaluated design (units in :mod:`memstribo.quantities`)
DESIGN_RESULTS = ("torque_window", "torque_window_high", "stiction_torque", "stiction_torque_bracket",
                  "fracture_torque", "stiction_probability", "stiction_probability_low", "stiction_probability_high",
                  "startup_stiction_probability", "startup_stiction_probability_high", "mesh_efficiency_median",
                  "mesh_efficiency_p05", "mesh_efficiency_p95", "cof_mean_median", "cycles_to_failure", "footprint",
                  "converged", "cycles_spent", "verdicts")
#: objective -> its result key
OBJECTIVE_KEYS = {"window": "torque_window", "efficiency": "mesh_efficiency_median",
                  "coating_life": "cycles_to_failure", "footprint": "footprint"}


@dataclass
class DesignResult:
    """What a design search did: the folder, its counts, the Pareto set (xarray) and the default design."""

    folder: Path
    dataset: Any
    default: dict
    best: dict | None
    n_evaluations: int
    n_computed: int
    n_reused: int
    n_infeasible: int
    n_failed: int
    cycles_spent: int
    cycles_total: int
    generations: int
    elapsed: float
    figures: list = field(default_factory=list)
    notes: list = field(default_factory=list)


def footprint(params, design) -> float:
    """Area of the pair's bounding rectangle [m^2]: (r_a1 + a + r_a2) x 2 max(r_a1, r_a2), a = m (z1 + z2) / 2."""
    z1, z2 = int(design.get("teeth_pinion", params["teeth_pinion"])), int(design.get("teeth_gear", params["teeth_gear"]))
    m = float(design.get("module", params["module"]))
    ha = float(design.get("addendum_coefficient", params["addendum_coefficient"]))
    ra1, ra2 = m * z1 / 2 + ha * m, m * z2 / 2 + ha * m
    return (ra1 + m * (z1 + z2) / 2 + ra2) * 2 * max(ra1, ra2)


# --- one design ------------------------------------------------------------------------------------------

def evaluate_design(params, design: dict, torques=(), realisations: int = 4, steps: int | None = None,
                    stiction_probability: float = 0.5, fracture_probability: float = 0.01, cycles: float = 1e9,
                    cycles_observed: float | None = None, coating_life: bool = False) -> dict[str, Any]:
    """The safe torque window, efficiency and coating life of one design (runs on a worker).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Base parameters; ``design``'s values are set on them.
    design : dict
        Design values (SI; ``coating``: a name or "none").
    torques : sequence of float
        Ascending drive torques [N*m] on which the stiction edge is located.
    realisations, steps : int
        Roughness realisations per verdict, positions per meshing cycle.
    stiction_probability, fracture_probability : float
        p_s (bound for the 95 % upper end of P(stiction), running and start-up) and p_f [-].
    cycles : float
        Required life [pinion revolutions] of the fracture edge.
    cycles_observed : float, optional
        Observed coating life that calibrates the damage coefficient (:func:`map_point`).
    coating_life : bool
        Compute the cycles to coating failure at the lower edge (one more verdict).

    Returns
    -------
    dict
        The keys of :data:`DESIGN_RESULTS` (SI; NaN where unknown) and ``note``.
    """
    from memstribo.simulations.design_map import map_point

    coating = design.get("coating")
    coating = None if coating in (None, "none") else str(coating)
    q = design_parameters(params, design).updated({"realisations": int(realisations)}, origin="design")
    wear = float(q["coating_wear"]) if coating else 1.0
    probe_params = q.updated({"damage_coefficient": None}, origin="design") if coating else q
    torques = [float(t) for t in torques]
    verdicts: dict[int, dict] = {}

    def verdict(k):
        if k not in verdicts:
            verdicts[k] = map_point(probe_params.updated({"drive_torque": torques[k]}, origin="design"), coating,
                                    wear, None, steps)
        return verdicts[k]

    def safe(k):
        v = verdict(k)
        startup = v.get("startup_stiction_probability_high", math.nan)
        return v["stiction_probability_high"] < stiction_probability and not startup >= stiction_probability

    lo, hi = -1, len(torques)  # torques[lo] sticks (or is below the range), torques[hi] is safe (or above it)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if safe(mid) else (mid, hi)
    edge = hi if hi < len(torques) else max(verdicts)
    chosen = verdict(edge)
    cof = chosen.get("cof_mean_median", math.nan)
    fracture = _fracture_torque(q, torques[0], torques[-1], cof, cycles, fracture_probability)
    lower = torques[hi] if hi < len(torques) else math.nan
    upper = min(fracture, torques[-1])
    window = max(0.0, upper - lower) if hi < len(torques) else 0.0
    bracket = torques[max(hi - 1, 0)] if hi < len(torques) else math.nan
    values = {"torque_window": window, "torque_window_high": max(0.0, upper - bracket) if math.isfinite(bracket)
              else 0.0, "stiction_torque": lower, "stiction_torque_bracket": bracket, "fracture_torque": fracture}
    for key in ("stiction_probability", "stiction_probability_low", "stiction_probability_high",
                "startup_stiction_probability", "startup_stiction_probability_high", "mesh_efficiency_median",
                "mesh_efficiency_p05", "mesh_efficiency_p95", "cof_mean_median", "converged"):
        values[key] = float(chosen.get(key, math.nan))
    values["cycles_to_failure"] = math.nan
    note = "" if hi < len(torques) else "sticks (95 % upper bound) at every torque of the range"
    if coating_life:
        if coating is None:
            values["cycles_to_failure"] = 0.0
        else:
            life = map_point(q.updated({"drive_torque": torques[edge]}, origin="design"), coating, wear, None, steps,
                             cycles_observed=cycles_observed)
            values["cycles_to_failure"] = float(life["cycles_to_failure"])
            note = "; ".join(n for n in (note, life.get("note", "")) if n)
            verdicts[-1] = life
    values["footprint"] = footprint(params, design)
    values["verdicts"] = float(len(verdicts))
    values["cycles_spent"] = float(len(verdicts) * int(realisations))
    values["torques_probed"] = [torques[k] for k in sorted(k for k in verdicts if k >= 0)]
    values["note"] = note
    return values


def _fracture_torque(params, low, high, cof, cycles, probability) -> float:
    """The drive torque [N*m] at which the pair's fracture probability within ``cycles`` reaches ``probability``
    (bisection on log T over [low/10, 10 high]; the ends where it is never or always reached)."""
    from memstribo.simulations.tooth_life import fracture_probability_within, synthetic_cycle, tooth_life

    cof = float(cof) if math.isfinite(cof) else 0.0

    def risk(torque):
        q = params.updated({"drive_torque": float(torque)}, origin="design")
        return fracture_probability_within(tooth_life(synthetic_cycle(q, cof=cof, steps=41), q), cycles)

    a, b = math.log(low / 10.0), math.log(high * 10.0)
    if risk(math.exp(b)) < probability:
        return math.exp(b)
    if risk(math.exp(a)) >= probability:
        return math.exp(a)
    for _ in range(40):
        mid = 0.5 * (a + b)
        a, b = (mid, b) if risk(math.exp(mid)) < probability else (a, mid)
        if b - a < 1e-4:
            break
    return math.exp(a)


# --- the search --------------------------------------------------------------------------------------------

def default_design(spec: DesignSpec, base) -> dict:
    """The base parameters' design (the thesis pair by default): each variable at its base value, bare
    silicon where "none" is a choice (else the first coating listed)."""
    design = {}
    for v in spec.variables:
        if v.name == "coating":
            design["coating"] = "none" if "none" in v.choices else v.choices[0]
        elif v.name == "ratio":
            design["teeth_gear"] = int(base["teeth_gear"])
        else:
            design[v.name] = base[v.name]
    if spec.ratio is not None:
        design["teeth_gear"] = int(base["teeth_gear"])
    if spec.centre_distance is not None:
        design["module"] = float(base["module"])
    return design


class _Evaluations:
    """The evaluations of one search folder: on disk, computed serially or on Dask, counted."""

    def __init__(self, spec, base, folder, client=None, scheduler=None, workers=None, progress=False):
        self.spec, self.base, self.folder = spec, base, ensure_directory(Path(folder) / EVALUATIONS)
        self.client, self.scheduler, self.workers, self.progress = client, scheduler, workers, progress
        self.cluster, self.own = None, False
        self.computed, self.reused = set(), set()
        self.options = dict(torques=[float(t) for t in spec.torques], realisations=spec.realisations,
                            steps=spec.steps, stiction_probability=spec.stiction_probability,
                            fracture_probability=spec.fracture_probability, cycles=spec.cycles,
                            cycles_observed=spec.cycles_observed, coating_life="coating_life" in spec.objectives)

    def _path(self, key):
        return self.folder / f"{key}.json"

    def _read(self, key):
        path = self._path(key)
        if not path.exists():
            return None
        try:
            return json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None  # torn: compute again

    def get(self, designs: list[dict], label="") -> list[dict]:
        """The records of ``designs`` (computing the missing ones; each written as soon as it is done)."""
        from memstribo.simulations.study import _write_json_atomic

        keys = [design_key(d) for d in designs]
        todo = {}
        for key, design in zip(keys, designs):
            if key in todo:
                continue
            record = self._read(key)
            if record is not None and record.get("error"):  # failed in an earlier run: run it again (as a map does)
                record = None
            if record is not None:
                if key not in self.computed:
                    self.reused.add(key)
                continue
            g = geometry_constraints(self.spec, self.base, design)
            if np.any(g > 0):  # infeasible: no cycle runs
                _write_json_atomic(self._path(key), {"id": key, "design": design, "constraints": g.tolist(),
                                                     "feasible": False, "error": None,
                                                     "values": {"footprint": footprint(self.base, design)}})
                self.computed.add(key)
                continue
            todo[key] = design
        if todo:
            self._compute(todo, label)
        return [self._read(key) for key in keys]

    def _compute(self, todo: dict, label: str) -> None:
        from tqdm.auto import tqdm

        from memstribo.simulations.study import _write_json_atomic, evaluate_point

        bar = tqdm(total=len(todo), unit="design", desc=label or self.spec.name, file=sys.stderr,
                   disable=not self.progress, dynamic_ncols=True)

        def write(key, outcome):
            g = geometry_constraints(self.spec, self.base, todo[key])
            _write_json_atomic(self._path(key), {"id": key, "design": todo[key], "constraints": g.tolist(),
                                                 "feasible": True, **outcome})
            self.computed.add(key)
            bar.update(1)

        try:
            if self.workers == 1 and self.client is None and self.scheduler is None:
                for key, design in todo.items():
                    write(key, evaluate_point(evaluate_design, self.base, {"design": design, **self.options}))
                return
            from distributed import as_completed

            client = self._client()
            futures = {client.submit(evaluate_point, evaluate_design, self.base, {"design": d, **self.options},
                                     key=f"memstribo-design-{k}-{os.getpid()}-{time.time_ns()}", pure=False): k
                       for k, d in todo.items()}
            for future in as_completed(list(futures), loop=client.loop):
                key = futures.pop(future)
                try:
                    outcome = future.result()
                except Exception as exc:  # a bug in one design: record it, carry on
                    outcome = {"values": {}, "error": f"{type(exc).__name__}: {exc}"}
                write(key, outcome)
                future.release()
        finally:
            bar.close()

    def _client(self):
        if self.client is None:
            from memstribo.simulations.study import _connect, require_dask

            require_dask("memstribo design (workers > 1)")
            self.client, self.cluster = _connect(self.scheduler, self.workers)
            self.own = True
        return self.client

    def close(self):
        if self.own:
            self.client.close()
            if self.cluster is not None:
                self.cluster.close()


def _objectives(spec: DesignSpec, base, records: list[dict]) -> tuple[np.ndarray, np.ndarray]:
    """(F, G) of the records for pymoo: objectives to minimise, constraints (<= 0 met; computed again from each
    design, cheap, so that a record written by another version of the checks still fits)."""
    from memstribo.simulations.design_spec import OBJECTIVES

    rows = []
    for record in records:
        values = record.get("values") or {}
        row = []
        for name in spec.objectives:
            value = values.get(OBJECTIVE_KEYS[name])
            value = math.nan if value is None else float(value)
            if name == "coating_life" and math.isfinite(value):
                value = math.log10(max(value, 1.0))
            row.append(OBJECTIVES[name][0] * value if math.isfinite(value) else 0.0)
        rows.append(row)
    g = np.array([geometry_constraints(spec, base, r["design"]) for r in records], dtype=float)
    return np.array(rows, dtype=float), g


@cites("deb_2002", "blank_2020")
def run_design(spec: DesignSpec, out: str | Path, params=None, *, client=None, scheduler: str | None = None,
               workers: int | None = None, resume: bool = False, progress: bool = False,
               figures: bool = True) -> DesignResult:
    """Run the design search of ``spec``: NSGA-II over its variables, evaluations written to ``out``.

    Writes ``OUT/design.json`` (manifest), ``OUT/evaluations/<id>.json`` (one per design), ``OUT/pareto.nc`` and
    ``.csv`` (the Pareto set), ``OUT/evaluations.nc``/``.csv`` (every design evaluated, the default design first)
    and ``OUT/figures/design_front.png``/``.svg``. ``resume`` continues an interrupted search in ``out``: its
    generations replay from the disk (seeded), only missing evaluations run.

    Raises
    ------
    InputError
        ``out`` holding another search, or this one without ``resume``; pymoo not installed.
    """
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.study import _hash, check_or_write_manifest

    try:
        from pymoo.algorithms.moo.nsga2 import NSGA2
    except ImportError:
        raise InputError("memstribo design searches with pymoo, an optional part of memstribo: install it with "
                         "pip install 'memstribo[design]'.") from None
    start = time.perf_counter()
    if workers is not None and (not isinstance(workers, int) or isinstance(workers, bool) or workers < 1):
        raise InputError(f"workers = {workers!r}: give a positive integer.")
    params = params if params is not None else get_parameter_values()
    base = params.updated(spec.parameters, origin=f"design spec {spec.source}")
    folder = ensure_directory(out)
    spec_dict = json.loads(json.dumps(asdict(spec), default=str))
    # the spec's file name is not part of the search: a spec moved or named otherwise resumes the same folder
    run_hash = _hash({"spec": {k: v for k, v in spec_dict.items() if k != "source"}, "parameters": params.to_dict()})
    check_or_write_manifest(folder / MANIFEST, folder, resume, run_hash, {
        "format": 1, "name": spec.name, "source": spec.source, "hash": run_hash, "spec": spec_dict,
        "parameter_set": params.name}, what="design search", differs="another spec or parameters")
    evaluations = _Evaluations(spec, base, folder, client, scheduler, workers, progress)
    try:
        default = evaluations.get([default_design(spec, base)], "default design")[0]
        archive = _search(spec, base, evaluations, NSGA2)
    finally:
        evaluations.close()
    records = [default] + [r for r in archive.values() if r["id"] != default["id"]]
    return _finish(spec, base, folder, records, default, evaluations, start, figures)


def _search(spec, base, evaluations, algorithm_class) -> dict:
    """NSGA-II by ask and tell; every generation's designs from :class:`_Evaluations`. Returns id -> record."""
    from pymoo.core.evaluator import Evaluator
    from pymoo.core.problem import Problem
    from pymoo.core.repair import Repair
    from pymoo.problems.static import StaticProblem
    from pymoo.termination import get_termination

    lows = np.array([v.bounds[0] for v in spec.variables])
    highs = np.array([v.bounds[1] for v in spec.variables])

    class OnGrid(Repair):  # integers, steps and choices: the population holds the designs evaluated
        def _do(self, problem, X, **kwargs):
            return np.array([[v.coordinate(v.value(x)) for v, x in zip(spec.variables, row)] for row in X])

    problem = Problem(n_var=len(lows), n_obj=len(spec.objectives), n_ieq_constr=len(CONSTRAINT_NAMES),
                      xl=lows, xu=highs)
    algorithm = algorithm_class(pop_size=spec.population, repair=OnGrid(), eliminate_duplicates=True)
    algorithm.setup(problem, termination=get_termination("n_gen", spec.generations), seed=spec.seed, verbose=False)
    archive: dict[str, dict] = {}
    generation = 0
    while algorithm.has_next():
        population = algorithm.ask()
        if population is None or len(population) == 0:  # no new design left (a small grid, all visited)
            break
        designs = [decode(spec, x, base) for x in population.get("X")]
        generation += 1
        records = evaluations.get(designs, f"generation {generation}/{spec.generations}")
        for record in records:
            archive.setdefault(record["id"], {**record, "generation": generation})
        f, g = _objectives(spec, base, records)
        Evaluator().eval(StaticProblem(problem, F=f, G=g), population)
        algorithm.tell(infills=population)
    return archive


def pareto_mask(f: np.ndarray) -> np.ndarray:
    """True for the rows of ``f`` (objectives to minimise) that no other row dominates."""
    n = len(f)
    keep = np.ones(n, dtype=bool)
    for i in range(n):
        others = np.delete(np.arange(n), i)
        dominated = np.all(f[others] <= f[i], axis=1) & np.any(f[others] < f[i], axis=1)
        keep[i] = not dominated.any()
    return keep


def _finish(spec, base, folder, records, default, evaluations, start, figures) -> DesignResult:
    from memstribo.output import provenance_attributes, write_dataset

    feasible = [r for r in records[1:] if r.get("feasible") and not r.get("error")]
    notes = []
    if feasible:
        f, _ = _objectives(spec, base, feasible)
        front = [r for r, keep in zip(feasible, pareto_mask(f)) if keep]
        front.sort(key=lambda r: -float(r["values"].get("torque_window", 0.0)))
    else:
        front = []
        notes.append("no feasible design evaluated without an error: no Pareto set")
    provenance = provenance_attributes(base, extra={
        "title": spec.name, "stage": "design search", "design_spec": spec.source,
        "design_objectives": json.dumps(list(spec.objectives)), "design_seed": spec.seed,
        "design_population": spec.population, "design_generations": spec.generations,
        "design_realisations": spec.realisations, "design_steps": "mesh_steps" if spec.steps is None else spec.steps,
        "design_torques": json.dumps([float(t) for t in spec.torques])})
    pareto = design_dataset(front, spec)
    write_dataset(pareto, folder, "pareto", provenance=provenance)
    everything = design_dataset(records, spec)
    write_dataset(everything, folder, "evaluations", provenance=provenance)
    written = front_figure(everything, pareto, spec, folder / "figures") if figures and front else []
    all_records = [evaluations._read(p.stem) for p in sorted(evaluations.folder.glob("*.json"))]
    all_records = [r for r in all_records if r]
    spent = sum(float((evaluations._read(k) or {}).get("values", {}).get("cycles_spent", 0)) for k in
                evaluations.computed)
    total = sum(float(r.get("values", {}).get("cycles_spent", 0)) for r in all_records)
    failed = [r for r in all_records if r.get("error")]
    notes += [f"design {r['id']}: {r['error']}" for r in failed[:5]]
    unconverged = [r for r in front if r["values"].get("converged") == 0.0]
    if unconverged:
        notes.append(f"{len(unconverged)} of {len(front)} Pareto designs not converged at {spec.steps or 'mesh_steps'} "
                     "steps (MODEL 7d): confirm them with memstribo design --explain N (memstribo mesh refines itself)")
    return DesignResult(folder, pareto, default, front[0] if front else None, len(all_records),
                        len(evaluations.computed), len(evaluations.reused),
                        sum(1 for r in all_records if not r.get("feasible")), len(failed), int(spent), int(total),
                        spec.generations, time.perf_counter() - start, written, notes)


# --- outputs -----------------------------------------------------------------------------------------------

def design_dataset(records: list[dict], spec: DesignSpec):
    """The designs as an :class:`xarray.Dataset` over the dimension ``design``: each variable (SI; ``coating``
    as text, ``teeth_gear`` and ``module`` where derived), every result of :data:`DESIGN_RESULTS`, ``feasible``,
    ``design_id``, ``generation``, ``note`` and ``error``."""
    import xarray as xr

    from memstribo.simulations.study import _unit_of

    names = [v.name for v in spec.variables if v.name != "ratio"]
    for derived in ("teeth_gear", "module"):
        if derived not in names and any(derived in r["design"] for r in records):
            names.append(derived)
    data = {}
    for name in names:
        column = [r["design"].get(name) for r in records]
        if name == "coating":
            data[name] = (("design",), np.array([str(c) for c in column], dtype=object),
                          {"units": "", "long_name": "coating"})
        else:
            data[name] = (("design",), np.array([math.nan if c is None else float(c) for c in column]),
                          {"units": _unit_of(name) or "1", "long_name": name.replace("_", " ")})
    for key in DESIGN_RESULTS:
        column = [(r.get("values") or {}).get(key) for r in records]
        data[key] = (("design",), np.array([math.nan if c is None else float(c) for c in column]), quantity_attrs(key))
    data["feasible"] = (("design",), np.array([float(bool(r.get("feasible"))) for r in records]),
                        quantity_attrs("feasible"))
    data["generation"] = (("design",), np.array([float(r.get("generation", 0)) for r in records]),
                          quantity_attrs("generation"))
    for key, source in (("design_id", "id"), ("error", "error")):
        data[key] = (("design",), np.array([str(r.get(source) or "") for r in records], dtype=object),
                     quantity_attrs(key))
    data["note"] = (("design",), np.array([str((r.get("values") or {}).get("note", "")) for r in records],
                                          dtype=object), quantity_attrs("note"))
    dataset = xr.Dataset({k: xr.Variable(*v) for k, v in data.items()},
                         coords={"design": ("design", np.arange(len(records)))})
    dataset.attrs["title"] = spec.name
    return dataset


def front_figure(everything, pareto, spec: DesignSpec, folder) -> list:
    """The front: every feasible design evaluated (grey), the Pareto set (coloured by mesh efficiency; hollow where
    not converged), the default design (star) and the widest window (red ring), on the first two objectives (one
    objective: window against footprint)."""
    from memstribo.output import new_figure, save_figure

    axes_keys = [OBJECTIVE_KEYS[o] for o in spec.objectives][:2]
    if len(axes_keys) < 2:
        axes_keys = axes_keys + ["footprint" if axes_keys[0] != "footprint" else "torque_window"]
    scale = {"torque_window": (1e9, "torque window [nN m]"), "footprint": (1e12, "footprint [µm²]"),
             "mesh_efficiency_median": (1.0, "mesh efficiency (median) [-]"),
             "cycles_to_failure": (1.0, "cycles to coating failure")}
    fig, ax = new_figure(figsize=(6.0, 4.4), constrained_layout=True)
    (fx, lx), (fy, ly) = scale[axes_keys[0]], scale[axes_keys[1]]
    ok = everything["feasible"].values == 1
    ax.plot(everything[axes_keys[0]].values[ok] * fx, everything[axes_keys[1]].values[ok] * fy, ".", color="0.7",
            label="designs evaluated")
    points = ax.scatter(pareto[axes_keys[0]].values * fx, pareto[axes_keys[1]].values * fy, c=pareto[
        "mesh_efficiency_median"].values, cmap="viridis", edgecolors="k", zorder=3, label="Pareto set")
    fig.colorbar(points, ax=ax).set_label("mesh efficiency (median)")
    ax.plot(everything[axes_keys[0]].values[0] * fx, everything[axes_keys[1]].values[0] * fy, "*", color="C3",
            markersize=14, markeredgecolor="k", label="default design", zorder=4)
    loose = pareto["converged"].values == 0  # MODEL 7d: not converged at the search's steps, drawn hollow
    if loose.any():
        ax.plot(pareto[axes_keys[0]].values[loose] * fx, pareto[axes_keys[1]].values[loose] * fy, "o", color="w",
                markeredgecolor="k", markersize=7, zorder=3.5, label="Pareto, not converged")
    ax.plot(pareto[axes_keys[0]].values[0] * fx, pareto[axes_keys[1]].values[0] * fy, "o", markersize=14,
            markerfacecolor="none", markeredgecolor="C3", label="widest window (Pareto design 0)", zorder=4)
    for i in range(pareto.sizes["design"]):
        ax.annotate(str(i), (pareto[axes_keys[0]].values[i] * fx, pareto[axes_keys[1]].values[i] * fy),
                    textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel(lx)
    ax.set_ylabel(ly)
    ax.set_title(f"{spec.name}: Pareto front", fontsize=10)
    ax.legend(fontsize=7, loc="best")
    return save_figure(fig, folder, "design_front")


def brute_force(spec: DesignSpec, out: str | Path, params=None, *, workers: int | None = 1) -> dict:
    """Evaluate every design of the spec's grid (all variables integer, stepped or categorical) in ``out``'s
    evaluation store (shared with a search there): the record with the widest torque window, and the count."""
    import itertools

    from memstribo.parameters import get_parameter_values

    grids = []
    for v in spec.variables:
        if v.kind == "choice":
            grids.append(list(v.choices))
        elif v.kind == "int":
            grids.append(list(range(int(v.low), int(v.high) + 1)))
        elif v.step:
            grids.append([v.value(v.low + k * v.step) for k in range(int(round((v.high - v.low) / v.step)) + 1)])
        else:
            raise InputError(f"brute force needs a grid: give {v.name} a step.")
    base = (params if params is not None else get_parameter_values()).updated(spec.parameters, origin="design")
    evaluations = _Evaluations(spec, base, out, workers=workers)
    designs = [complete(spec, dict(zip([v.name for v in spec.variables], combo)), base)
               for combo in itertools.product(*grids)]
    try:
        records = evaluations.get(designs, "brute force")
    finally:
        evaluations.close()
    windows = [float((r.get("values") or {}).get("torque_window", -1.0) or 0.0) if r.get("feasible") else -1.0
               for r in records]
    best = int(np.argmax(windows))
    return {"best": records[best], "window": windows[best], "designs": len(records)}


def explain_arguments(folder: str | Path, index: int) -> tuple[list[str], dict]:
    """The ``memstribo mesh`` command line that gives Pareto design ``index``'s verdict at its lower edge
    (``--set`` of its variables and drive torque, ``--coating``, ``--steps``, ``--realisations``), and its row."""
    import xarray as xr

    path = Path(folder) / "pareto.nc"
    if not path.exists():
        raise InputError(f"no Pareto set in '{folder}' (pareto.nc): run the search first (same --out).")
    with xr.open_dataset(path) as dataset:
        dataset = dataset.load()
    n = dataset.sizes["design"]
    if not 0 <= index < n:
        raise InputError(f"--explain {index}: the Pareto set in '{folder}' has designs 0 to {n - 1}.")
    row = {k: dataset[k].values[index].item() if hasattr(dataset[k].values[index], "item") else
           dataset[k].values[index] for k in dataset.data_vars}
    manifest = json.loads((Path(folder) / MANIFEST).read_text(encoding="utf-8"))
    spec = manifest["spec"]
    argv = ["mesh"]
    for key in ("module", "face_width", "pressure_angle", "addendum_coefficient", "teeth_pinion", "teeth_gear"):
        if key in row:
            value = int(row[key]) if key.startswith("teeth") else repr(float(row[key]))
            argv += ["--set", f"{key}={value}"]
    torque = row["stiction_torque"] if math.isfinite(row["stiction_torque"]) else spec["torque_max"]
    argv += ["--set", f"drive_torque={float(torque)!r}", "--realisations", str(spec["realisations"]), "--no-refine"]
    if spec.get("steps"):
        argv += ["--steps", str(spec["steps"])]
    if row.get("coating") not in (None, "none"):
        argv += ["--coating", str(row["coating"])]
    for key, value in (spec.get("parameters") or {}).items():
        argv += ["--set", f"{key}={value}"]
    return argv, row
