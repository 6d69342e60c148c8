"""The stiction verdict over what we do not know (MODEL 7d, issue 27).

:func:`uncertainty_study` samples roughness realisations (aleatory: parts differ) times sets of
the uncertain constants (epistemic: one true value nobody measured), both with low-discrepancy
designs, and reports

- P(stiction) at the nominal constants over the realisations, and over realisations x constants,
  each with its 95 % confidence interval (Wilson; :mod:`memstribo.uncertainty.intervals`);
- the 5/50/95 % quantiles of the margin (and of ``startup_margin`` where the cycle has it), of the
  mean COF and of its split;
- Sobol' first-order and total indices of the margin and of the mean COF (Saltelli's design and
  estimators, SALib, with bootstrap intervals); the roughness realisation is one more factor, so
  the ranking says whether the part-to-part spread or a constant decides;
- for each constant with a total index above 0.1 its critical value: where the median margin over
  the realisations crosses zero with the other constants at nominal (Brent's method), or "no
  crossing within the prior";
- one sentence a designer can act on.

Speed: a cycle is solved once per (realisation, constants that enter the contact solve or the block
mechanics); the bond energies are applied afterwards by :func:`memstribo.uncertainty.rescale.rescale_cycle`
(exact: the friction is linear in them). The cycles run on Dask when a client is given.
A sampled point that fails (an input the model refuses) or does not converge is counted and
reported, never dropped: the interval of P(stiction) covers both outcomes of every failed point.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites
from memstribo.uncertainty.decision import (REALISATION_FACTOR, SOLVED_REALISATIONS, _margin_function, clip_unit,
                                            critical_value, decision_analysis, decision_options)
from memstribo.uncertainty.intervals import sample_probability as _probability

__all__ = ["uncertainty_study", "critical_value", "sobol_indices", "REALISATION_FACTOR", "designer_sentence",
           "DEFAULT_REALISATIONS", "DEFAULT_BUDGET", "TARGET_HALF_WIDTH"]

#: realisations per constant set when not given
DEFAULT_REALISATIONS = 16
#: most samples (realisations x constant sets) that ``samples="auto"`` draws
DEFAULT_BUDGET = 1024
#: ``samples="auto"`` stops when the interval's half-width is below this [-]
TARGET_HALF_WIDTH = 0.05
#: bytes one stored cycle (reduced dataset) takes per step, for the memory estimate (about 45 variables)
BYTES_PER_CYCLE_STEP = 45 * 8


def _solve_cycle(params, roughness, steps, coating_name, wear, realisation):
    """One meshing cycle, reduced for the rescaling; the error text where the model refuses the point."""
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.simulations.mesh.solve_cache import keep_solves
    from memstribo.uncertainty.rescale import reduce_cycle

    keep_solves()  # rows whose contact inputs repeat (block constants, ends of priors) share their solve
    try:
        coating = None
        if coating_name:
            from memstribo.physics.coating import get_coating

            coating = get_coating(coating_name, params)
        return reduce_cycle(simulate_mesh(params, roughness, steps=steps, coating=coating, wear=wear,
                                          realisation=realisation))
    except InputError as exc:
        return str(exc)


class _Runner:
    """Cycles by (realisation, solve-relevant constants), solved once, rescaled for the bond energies."""

    def __init__(self, params, roughness, steps, coating_name, wear, client, progress):
        self.params, self.roughness, self.steps = params, roughness, steps
        self.coating_name, self.wear, self.client, self.progress = coating_name, wear, client, progress
        self.cache: dict = {}
        self.summary_cache: dict = {}
        self.ids: dict = {}
        self.solves = 0
        self.rescalings = 0
        self.solve_seconds = 0.0
        self.rescale_seconds = 0.0
        self._rescalable = None

    def rescalable(self) -> tuple[str, ...]:
        if self._rescalable is None:
            from memstribo.uncertainty.rescale import RESCALED

            # a coated cycle writes its vdW bonds over bare and coated blocks apart: both U_vdW rescale
            coated = bool(self.coating_name) and self.wear < 1.0
            self._rescalable = RESCALED + ("coating_vdw_bond_energy",) if coated else RESCALED
        return self._rescalable

    def _split(self, constants: Mapping):
        rescaled = {k: v for k, v in constants.items() if k in self.rescalable()}
        solved = {k: v for k, v in constants.items() if k not in self.rescalable()}
        return solved, rescaled

    def _key(self, realisation, solved):
        return (int(realisation), tuple(sorted((k, float(v)) for k, v in solved.items())))

    def _params(self, solved):
        return self.params.updated(solved, origin="uncertainty sample") if solved else self.params

    def adopt(self, cycles, realisations) -> int:
        """Take ``cycles`` {realisation: reduced cycle at the nominal constants} as solved; returns how many."""
        taken = [r for r in (cycles or {}) if 0 <= int(r) < realisations]
        for r in taken:
            self.cache[self._key(r, {})] = cycles[r]
        return len(taken)

    def summaries(self, points) -> list[dict]:
        """Summaries of ``points`` [(realisation, {constant: value})]; a failed point: {"failed": True, "error"}."""
        from memstribo.uncertainty.rescale import rescale_cycles

        todo = {}
        for realisation, constants in points:
            solved, _ = self._split(constants)
            key = self._key(realisation, solved)
            if key not in self.cache and key not in todo:
                todo[key] = (realisation, solved)
        if todo:
            start = time.perf_counter()
            keys = list(todo)
            args = []
            for key in keys:
                realisation, solved = todo[key]
                try:
                    args.append((self._params(solved), realisation))
                except InputError as exc:  # an inconsistent sample (e.g. blocks wider than the nanoblock)
                    args.append((str(exc), realisation))
            results = self._run([(p, r) for p, r in args if not isinstance(p, str)])
            it = iter(results)
            for key, (p, _) in zip(keys, args):
                self.cache[key] = p if isinstance(p, str) else next(it)
            self.solves += len(keys)
            self.solve_seconds += time.perf_counter() - start
        out: list = [None] * len(points)
        rescale: dict = {}  # cycle key -> (solve-relevant constants, [(index, bond energies)])
        for i, (realisation, constants) in enumerate(points):
            solved, rescaled = self._split(constants)
            key = self._key(realisation, solved)
            cycle = self.cache[key]
            if isinstance(cycle, str):
                out[i] = {"failed": True, "error": cycle, "realisation": realisation, "cycle_id": self._id(key)}
            elif rescaled:
                rescale.setdefault(key, (solved, []))[1].append((i, rescaled))
            else:
                out[i] = dict(self._summary(key))
                if "startup_margin" in cycle.attrs:
                    out[i].setdefault("startup_margin", float(cycle.attrs["startup_margin"]))
        start = time.perf_counter()
        for key, (solved, items) in rescale.items():  # every set of one cycle at once (rescale_cycles)
            results = rescale_cycles(self.cache[key], self._params(solved), [r for _, r in items],
                                     base=self._summary(key))
            self.rescalings += len(items)
            for (i, _), summary in zip(items, results):
                out[i] = summary
        self.rescale_seconds += time.perf_counter() - start
        for (realisation, constants), summary in zip(points, out):
            summary["realisation"] = realisation
            summary["cycle_id"] = self._id(self._key(realisation, self._split(constants)[0]))
        return out

    def _summary(self, key) -> dict:
        """``summarize`` of the cached cycle ``key``, computed once."""
        from memstribo.simulations.mesh import summarize

        if key not in self.summary_cache:
            self.summary_cache[key] = summarize(self.cache[key])
        return self.summary_cache[key]

    def _id(self, key) -> int:
        """A number per distinct cycle: the samples that share it share their contact solution."""
        return self.ids.setdefault(key, len(self.ids))

    def _run(self, args):
        n = len(args)
        common = (self.roughness, self.steps, self.coating_name, self.wear)
        if self.client is not None and n > 1:
            futures = self.client.map(_solve_cycle, [a[0] for a in args], *[[c] * n for c in common],
                                      [a[1] for a in args], pure=False)
            return self.client.gather(futures)
        iterator = args
        if self.progress:
            from tqdm.auto import tqdm

            iterator = tqdm(args, desc="uncertainty: meshing cycles", unit="cycle", leave=False)
        return [_solve_cycle(p, *common, r) for p, r in iterator]


def _client_of(client):
    """A dask client from a client or a cluster (``local_cluster``); None stays None."""
    if client is None or hasattr(client, "map"):
        return client, False
    from distributed import Client

    return Client(client), True


def _quantiles(values):
    values = np.asarray([v for v in values if v is not None and np.isfinite(v)], dtype=float)
    if values.size == 0:
        return None
    p05, p50, p95 = np.quantile(values, [0.05, 0.5, 0.95])
    return {"p05": float(p05), "p50": float(p50), "p95": float(p95), "median": float(p50)}


@cites("sobol_2001", "saltelli_2010", "herman_usher_2017")
def sobol_indices(names, outputs: Mapping[str, np.ndarray], base_samples: int, seed: int = 0,
                  confidence: float = 0.95, resamples: int = 200) -> dict:
    """Sobol' first-order and total indices with bootstrap intervals (SALib, Saltelli 2010 estimators).

    Parameters
    ----------
    names : list of str
        The factors, in the columns of the design of :func:`_saltelli_design`.
    outputs : Mapping[str, ndarray]
        Model output per name of output (``"margin"``, ``"cof"``), at the design's rows [any unit].
    base_samples : int
        N of the design [-].

    Returns
    -------
    dict
        ``{output: {factor: {"first", "first_ci", "total", "total_ci", "clipped"}}}`` [-]; an interval is
        [index - half-width, index + half-width] of the bootstrap at ``confidence``. Indices and interval ends are
        clipped to [0, 1] (``clipped``: whether any was outside; Saltelli's estimators leave [0, 1] at few base
        samples, and a share of variance cannot).
    """
    from SALib.analyze import sobol as sobol_analyze

    problem = {"num_vars": len(names), "names": list(names), "bounds": [[0.0, 1.0]] * len(names)}
    result = {}
    for output, y in outputs.items():
        y = np.asarray(y, dtype=float)
        if np.ptp(y) == 0.0:  # a constant output has no variance to share
            result[output] = {n: {"first": 0.0, "first_ci": [0.0, 0.0], "total": 0.0, "total_ci": [0.0, 0.0],
                                  "clipped": False} for n in names}
            continue
        # SALib seeds its bootstrap only for a truthy seed (seed 0 would draw new intervals each run): seed + 1
        si = sobol_analyze.analyze(problem, y, calc_second_order=False, num_resamples=resamples,
                                   conf_level=confidence, seed=int(seed) + 1)
        result[output] = {}
        for j, n in enumerate(names):
            raw = {"first": float(si["S1"][j]), "first_ci": [float(si["S1"][j] - si["S1_conf"][j]),
                                                             float(si["S1"][j] + si["S1_conf"][j])],
                   "total": float(si["ST"][j]), "total_ci": [float(si["ST"][j] - si["ST_conf"][j]),
                                                             float(si["ST"][j] + si["ST_conf"][j])]}
            # an index is a share of variance: the estimator's excursions outside [0, 1] are sampling error
            clipped = {key: clip_unit(value) for key, value in raw.items()}
            clipped["clipped"] = clipped != raw
            result[output][n] = clipped
    return result


def _saltelli_design(dimensions: int, base_samples: int, seed: int):
    """Saltelli's design of N (D + 2) rows in [0, 1]^D (SALib, first-order and total indices only)."""
    import warnings

    from SALib.sample import sobol as sobol_sample

    if base_samples < 2 or base_samples & (base_samples - 1):
        raise InputError(f"the Sobol' analysis needs a power of two of base samples (>= 2), got {base_samples}.")
    problem = {"num_vars": dimensions, "names": [f"x{j}" for j in range(dimensions)],
               "bounds": [[0.0, 1.0]] * dimensions}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return sobol_sample.sample(problem, base_samples, calc_second_order=False, scramble=True, seed=seed)


def designer_sentence(name, entry, prior, nominal) -> str:
    """One sentence: "stiction if vdw_bond_energy > 8.1e-21 J (nominal 5.43e-21 J); measure ..."."""
    from memstribo.parameters import SPECS

    unit = SPECS[name].unit if name in SPECS else ""
    unit = f" {unit}" if unit else ""
    measure = f"; measure {prior.measure}" if prior.measure else ""
    value = entry.get("critical_value")
    if value is None and entry.get("searched") is False:
        return (f"The margin hangs most on {name} (prior {prior.low:.3g}–{prior.high:.3g}{unit}, nominal "
                f"{nominal:.3g}{unit}); its critical value was not searched"
                + (f" ({entry['note']})" if entry.get("note") else "") + f"{measure}.")
    if value is None:
        return (f"The verdict does not flip within the prior of {name} ({prior.low:.3g}–{prior.high:.3g}{unit}), "
                f"its most influential constant{measure}.")
    sign = ">" if entry.get("stiction_above") else "<"
    return f"Stiction if {name} {sign} {value:.3g}{unit} (nominal {nominal:.3g}{unit}){measure}."


def _design(sampled, realisations, sets, solve_sets, rescalable, seed):
    """The points [(realisation, constants)] of ``realisations`` x ``sets`` samples.

    One low-discrepancy design of ``realisations * sets`` points over the priors; point
    ``i = j * realisations + r`` goes to realisation ``r`` (so a doubled ``sets`` extends the design).
    With ``solve_sets`` < ``sets``, the constants that need a new contact solve take only ``solve_sets``
    values per realisation (each group of ``sets / solve_sets`` points shares its first point's), while the
    rescaled bond energies keep all their values: fewer solves, each sample still drawn from the priors.
    ``solve_sets="pairs"``: groups of two (half the solves, at any ``sets``; a doubled ``sets`` keeps the pairs).
    """
    from memstribo.uncertainty.sampling import sample_constants

    design = sample_constants(sampled, realisations * sets, seed=seed)
    points = []
    group = _group_size(solve_sets, sets)
    for i, constants in enumerate(design):
        r, j = i % realisations, i // realisations
        if group > 1:
            first = design[(j - j % group) * realisations + r]
            constants = {k: (v if k in rescalable else first[k]) for k, v in constants.items()}
        points.append((r, constants))
    return points


def _group_size(solve_sets, sets) -> int:
    """Samples per realisation that share a contact solve under ``solve_sets`` (None, "pairs" or an int)."""
    if solve_sets == "pairs":
        return 2 if sets >= 2 else 1
    return 1 if not solve_sets or solve_sets >= sets else int(math.ceil(sets / int(solve_sets)))


def solved_sets(solve_sets, sets) -> int:
    """Distinct contact solves per realisation under ``solve_sets`` (None, "pairs" or an int) with ``sets`` constant
    sets per realisation [-]."""
    return int(math.ceil(sets / _group_size(solve_sets, sets)))


#: most base samples N of the Sobol' design (issue #41: 2^40 ended in a generic memory message after SALib
#: began to allocate): 2^14 = 16 384 gives N (D + 2) = 196 608 rows (cycles or rescalings) for D = 10 constants
MAX_SOBOL_SAMPLES = 2**14


def check_sobol_samples(sobol_samples, name: str = "sobol_samples") -> None:
    """Refuse a Sobol' base sample count that is not a power of two from 2 to :data:`MAX_SOBOL_SAMPLES`
    (before anything is allocated or run)."""
    if sobol_samples is None:
        return
    if isinstance(sobol_samples, bool) or not isinstance(sobol_samples, (int, np.integer)):
        raise InputError(f"{name} must be a whole number (a power of two), got {sobol_samples!r}.")
    n = int(sobol_samples)
    if n > MAX_SOBOL_SAMPLES:
        raise InputError(f"{name} = {n:,} base samples of the Sobol' design is above the limit of "
                         f"{MAX_SOBOL_SAMPLES:,} (2^14: N x (constants + 2) cycles or rescalings, about 200 000 at "
                         "10 constants); use fewer.")
    if n < 2 or n & (n - 1):
        raise InputError(f"{name} must be a power of two from 2 to {MAX_SOBOL_SAMPLES:,} (Saltelli's design), "
                         f"got {n:,}.")


def _check_samples(samples, realisations, steps_of_cycle, budget=DEFAULT_BUDGET, solve_sets=None):
    from memstribo.parameters.definitions import MEMORY_LIMIT_BYTES

    if samples != "auto":
        if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 1:
            raise InputError(f"samples must be a whole number >= 1 or 'auto', got {samples!r}.")
        from memstribo.uncertainty.sampling import MAX_SAMPLES

        if samples > MAX_SAMPLES:  # before the first cycle (the design's own check comes after the nominal ones)
            raise InputError(f"{samples} samples: at most {MAX_SAMPLES} (the design would not fit in memory).")
    if isinstance(realisations, bool) or not isinstance(realisations, (int, np.integer)) or realisations < 1:
        raise InputError(f"realisations must be a whole number >= 1, got {realisations!r}.")
    n = DEFAULT_BUDGET if samples == "auto" else int(samples)
    need = n * steps_of_cycle * BYTES_PER_CYCLE_STEP
    if need > MEMORY_LIMIT_BYTES / 2:
        raise InputError(f"{n} samples of {steps_of_cycle}-step cycles would keep about {need / 2**30:.1f} GiB of "
                         f"cycles in memory, more than the {MEMORY_LIMIT_BYTES / 2**31:.0f} GiB an uncertainty study "
                         "may use: use fewer samples or fewer steps.")
    if solve_sets is not None and solve_sets != "pairs" and (
            isinstance(solve_sets, bool) or not isinstance(solve_sets, (int, np.integer)) or solve_sets < 1):
        raise InputError(f"solve_sets must be a whole number >= 1 (distinct solves per realisation), 'pairs' or None "
                         f"(every set solved apart), got {solve_sets!r}.")
    if samples == "auto" and (isinstance(budget, bool) or int(budget) < realisations):
        raise InputError(f"budget ({budget}) must be at least the realisations ({realisations}).")


def _check_inputs(samples, realisations, n_steps, budget, solve_sets, confidence, threshold, decision,
                  sobol_samples=None, critical=True, sensitivity=True) -> dict:
    """Refuse bad inputs of :func:`uncertainty_study` before any cycle; returns the decision's options."""
    _check_samples(samples, realisations, n_steps, budget, solve_sets)
    check_sobol_samples(sobol_samples)
    if sensitivity not in (True, False, "regional"):
        raise InputError(f"sensitivity must be True, False or 'regional' (no Sobol' design), got {sensitivity!r}.")
    if critical not in (True, False, "rescaled"):
        raise InputError(f"critical must be True, False or 'rescaled' (the bond energies' only), got {critical!r}.")
    _check_levels(confidence, threshold)
    return decision_options(decision)


def _check_levels(confidence, threshold):
    def number(x):
        return not isinstance(x, bool) and isinstance(x, (int, float, np.integer, np.floating)) and math.isfinite(x)

    if not number(confidence) or not 0.0 < confidence < 1.0:
        raise InputError(f"confidence is a fraction strictly between 0 and 1, got {confidence!r}.")
    if not number(threshold) or not 0.0 <= threshold <= 1.0:
        raise InputError(f"threshold (the total Sobol' index above which a critical value is searched) is a fraction "
                         f"in [0, 1], got {threshold!r}.")


@cites("model", "wilson_1927", "sobol_2001", "saltelli_2010")
def uncertainty_study(params, roughness=None, *, samples="auto", realisations=None, steps=None, coating=None,
                      wear=1.0, client=None, progress=False, seed=0, fixed=(), sensitivity=True,
                      sobol_samples=None, sobol_steps=None, critical=True, budget=DEFAULT_BUDGET, confidence=0.95,
                      threshold=0.1, curve_points=9, priors=None, solve_sets=None, decision=None,
                      keep_samples=False, nominal_cycles=None) -> dict:
    """P(stiction) over roughness realisations x uncertain constants, what it hangs on, and where it flips.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Nominal parameters; constants set by the user are fixed (:func:`memstribo.uncertainty.priors.priors_for`).
    roughness, steps, wear
        As for :func:`memstribo.simulations.mesh.simulate_mesh` (steps [-], wear Omega [-]).
    samples : int or "auto"
        Realisations x constant sets [-]; ``"auto"`` doubles the constant sets (from 16 per realisation set) until
        the interval's half-width is below 0.05 or ``budget`` samples.
    realisations, coating
        Realisations per constant set [-] (default ``min(16, samples)``); the coating (its constants are sampled).
    client : distributed.Client or a dask cluster, optional
        Run the cycles on its workers (:func:`memstribo.simulations.study.local_cluster`).
    seed, fixed
        Seed of the designs (not of the roughness); constants kept at their nominal value (each with a prior).
    sensitivity : bool or "regional"
        Sobol' indices, critical values, the decision's sensitivity; ``"regional"``: no Sobol' design (:func:`_screen`).
    sobol_samples : int, optional
        Base samples N of Saltelli's design (a power of two; default 32): N (D + 3) rows for D constants.
    sobol_steps : int, optional
        Steps of the cycles of the Sobol' design (default ``steps``); a coarser cycle ranks the constants at lower
        cost (the probabilities and critical values keep ``steps``).
    critical : bool or "rescaled"
        Critical values of the constants whose total index of the margin exceeds ``threshold`` [-] or that flip
        (``"rescaled"``: the rescaled bond energies' only, no new cycle; the main job's, issue 40).
    nominal_cycles : Mapping[int, xarray.Dataset], optional
        Realisation -> its reduced cycle at the nominal constants, solved with these inputs (the run's ensemble).
    confidence, curve_points
        Level of the intervals, in (0, 1) [-]; values of the dominant constant for the curve P(stiction) against it.
    priors : Mapping[str, Prior], optional
        Priors to use instead of the parameter set's.
    solve_sets : int or "pairs", optional
        Distinct values per realisation of the constants that need a new contact solve (default: every set its own;
        ``"pairs"``: one per two sets, as the main job); the bond energies keep every set's value (:func:`_design`).
        The samples of a group share their contact solution: the interval is Wilson's at ``samples / design_effect``
        samples (:func:`_probability`); the result's ``solve_sets`` is the distinct solves per realisation.
    decision : Mapping, optional
        Options of :func:`memstribo.uncertainty.decision.decision_analysis` (:func:`.decision_options`).
    keep_samples : bool
        Also return ``sample_points`` and ``sample_summaries`` (for :mod:`memstribo.laboratory.posterior`).

    Returns
    -------
    dict
        ``stiction_probability`` [-], ``stiction_probability_ci`` ([low, high], [-]), ``stiction_count``,
        ``samples``, ``stiction_probability_text``, ``stiction_probability_nominal`` and ``_nominal_ci`` /
        ``_nominal_text`` (the realisations at nominal constants), ``margin_quantiles`` [N] (``p05``, ``p50``,
        ``p95``, ``median``) and ``margin_quantiles_nominal``, ``startup_margin_quantiles`` (where the cycle has it),
        ``cof_quantiles`` and ``cof_split_quantiles`` [-], ``sensitivity`` ({constant: {first, first_ci,
        total, total_ci, cof_first, cof_first_ci, cof_total, cof_total_ci, critical_value, note}}),
        ``dominant``, ``critical_curve``, ``designer_sentence``, ``priors``, ``sampled_constants``,
        ``fixed_constants``, ``unconverged_samples``, ``failed_samples``, ``solves``, ``rescalings``,
        ``design_effect`` and ``effective_samples`` [-] (samples that share a contact solve: :func:`_probability`),
        ``solve_seconds``, ``rescale_seconds``, ``elapsed`` [s], ``contact_rows_reused`` (:mod:`.solve_cache`),
        ``nominal_cycles_reused``, ``workers``, ``warnings``; with ``sensitivity``: ``sobol_design`` and
        :func:`memstribo.uncertainty.decision.decision_analysis`'s keys.

    Raises
    ------
    InputError
        Bad sample counts, fixed constants, priors, ``confidence``, ``threshold``, ``critical`` or ``decision``
        options; a sample count above the memory estimate.
    """
    start = time.perf_counter()
    coating_name, priors, fixed_names, sampled, realisations = _what_is_sampled(params, priors, coating, wear, fixed,
                                                                               realisations, samples)
    decision = _check_inputs(samples, realisations, int(params["mesh_steps"] if steps is None else steps), budget,
                             solve_sets, confidence, threshold, decision, sobol_samples, critical, sensitivity)
    client, own_client = _client_of(client)
    result = None
    try:
        runner = _Runner(params, roughness, steps, coating_name, wear, client, progress)
        R = int(realisations)
        reused = runner.adopt(nominal_cycles, R)  # solved already (the run's mesh ensemble)
        nominal = runner.summaries([(r, {}) for r in range(R)])
        sets_count, points, summaries = _sample(runner, sampled, R, samples, solve_sets, seed, confidence, budget)
        result = _verdict(summaries, nominal, R, sets_count, solve_sets, confidence, priors, sampled, fixed_names)
        result.update({"sample_points": points, "sample_summaries": summaries} if keep_samples else {})
        runners = [runner]
        if sensitivity and sampled:  # the margin's (Sobol'), then the decision's (MODEL 7h); or the regional only
            runners.append(_analyse(result, params, runner, sampled, nominal, points, summaries, R, seed, confidence,
                                    (roughness, steps, coating_name, wear, client, progress), sobol_samples or 32,
                                    sobol_steps, critical, threshold, curve_points, decision, sensitivity))
        result["warnings"] = _warnings(result)
        result["nominal_cycles_reused"] = reused
        _count(result, runners)
        result["elapsed"] = time.perf_counter() - start
        return result
    finally:
        _stop_keeping(result)
        if own_client:
            client.close()


def _analyse(result, params, runner, sampled, nominal, points, summaries, R, seed, confidence, cycle, sobol_samples,
             sobol_steps, critical, threshold, curve_points, decision, sensitivity=True):
    """Sobol' indices of the margin (:func:`_sensitivity`), then the sensitivity of the decision
    (:func:`memstribo.uncertainty.decision.decision_analysis`), into ``result``; returns the Sobol' rows' runner.
    ``cycle``: (roughness, steps, coating_name, wear, client, progress). ``sensitivity="regional"``: :func:`_screen`."""
    if sensitivity == "regional":  # the decision's on the samples only (the main job's)
        _screen(result, params, runner, sampled, nominal, points, summaries, R, seed, confidence, cycle[2], critical,
                threshold, curve_points, decision)
        return runner
    sobol_runner, rows = _sensitivity(result, params, runner, sampled, R, seed, confidence, *cycle, sobol_samples,
                                      sobol_steps, critical, threshold, curve_points)
    decision_analysis(result, params, runner, sampled, nominal, points, summaries, rows, R, seed, confidence,
                      threshold=threshold, critical=critical, **decision)
    return sobol_runner


def _what_is_sampled(params, priors, coating, wear, fixed, realisations, samples):
    """(coating name, priors, fixed names, sampled priors, realisations) of :func:`uncertainty_study`."""
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.sampling import _check_fixed

    coating_name = getattr(coating, "name", coating) if coating is not None else None
    if priors is None:  # a fully worn coating (wear 1) leaves bare blocks only: its constants do not act
        priors = priors_for(params, coating_name if float(wear) < 1.0 else None)
    fixed_names = _check_fixed(priors, fixed)
    sampled = {name: p for name, p in priors.items() if name not in fixed_names}
    if realisations is None:
        realisations = DEFAULT_REALISATIONS if samples == "auto" else max(1, min(DEFAULT_REALISATIONS, int(samples)))
    return coating_name, priors, fixed_names, sampled, realisations


def _stop_keeping(result) -> None:
    """Forget the kept contact solves of this process; ``result["contact_rows_reused"]``: how many were reused (Dask
    workers keep their own, dropped with their cluster)."""
    from memstribo.simulations.mesh.solve_cache import stop_keeping

    counts = stop_keeping()
    if result is not None:
        result["contact_rows_reused"] = counts["hits"]


def _count(result, runners):
    """Worker processes, solves, rescalings and their wall times [s] over the runners (the Sobol' rows' own where its steps differ)."""
    runners = list({id(r): r for r in runners}.values())
    client = runners[0].client
    result["workers"] = len(client.scheduler_info().get("workers", {})) or 1 if client is not None else 1
    for name in ("solves", "rescalings", "solve_seconds", "rescale_seconds"):
        result[name] = sum(getattr(r, name) for r in runners)


def _sample(runner, sampled, R, samples, solve_sets, seed, confidence, budget):
    """(constant sets per realisation, points, summaries) of the design; ``samples="auto"`` doubles the sets until the
    interval's half-width is below :data:`TARGET_HALF_WIDTH` or the budget is spent."""
    if samples != "auto":
        sets_count = max(1, int(samples) // R)
        points = _design(sampled, R, sets_count, solve_sets, runner.rescalable(), seed)
        return sets_count, points, runner.summaries(points)
    sets_count = 16
    while True:
        points = _design(sampled, R, sets_count, solve_sets, runner.rescalable(), seed)
        summaries = runner.summaries(points)
        p = _probability(summaries, confidence)
        if (0.5 * (p["ci"][1] - p["ci"][0]) < TARGET_HALF_WIDTH and not p["failed"]) \
                or 2 * R * sets_count > int(budget):
            return sets_count, points, summaries
        sets_count *= 2


def _warnings(result) -> list[str]:
    warnings = []
    if result["failed_samples"]:
        warnings.append(f"{result['failed_samples']} sampled point(s) failed (the model refused their inputs): "
                        "counted, and the interval of P(stiction) covers both outcomes of each")
    if result.get("solve_sets") and result.get("design_effect", 1.0) > 1.0:  # issue 40: say what sharing costs
        from memstribo.uncertainty.intervals import binomial_interval

        low, high = result["stiction_probability_ci"]
        plain = binomial_interval(result["stiction_count"], result["samples"], result["confidence"])
        if 0.5 * (high - low) > TARGET_HALF_WIDTH >= 0.5 * (plain[1] - plain[0]):
            warnings.append(f"the shared-solve design (solve_sets = {result['solve_sets']}) widens the interval of "
                            f"P(stiction) to +-{0.5 * (high - low):.3f} (design effect "
                            f"{result['design_effect']:.2f}), beyond the precision of +-{TARGET_HALF_WIDTH:g} that "
                            f"{result['samples']} independent samples would reach (+-{0.5 * (plain[1] - plain[0]):.3f})"
                            ": give more solve sets, or more samples")
    if result["unconverged_samples"]:
        warnings.append(f"{result['unconverged_samples']} sampled cycle(s) have unconverged contact steps: counted "
                        "as computed")
    return warnings


def _verdict(summaries, nominal, R, sets_count, solve_sets, confidence, priors, sampled, fixed_names) -> dict:
    """The probabilities with their intervals and the quantiles of margin and COF (keys of uncertainty_study)."""
    p_all = _probability(summaries, confidence)
    p_nom = _probability(nominal, confidence)
    ok = [s for s in summaries if not s.get("failed")]
    ok_nominal = [s for s in nominal if not s.get("failed")]
    result = {
        "stiction_probability": p_all["probability"],
        "stiction_probability_ci": p_all["ci"],
        "stiction_count": p_all["count"],
        "samples": p_all["samples"],
        "stiction_probability_text": p_all["text"],
        "design_effect": p_all["design_effect"],
        "effective_samples": p_all["effective_samples"],
        "stiction_probability_nominal": p_nom["probability"],
        "stiction_probability_nominal_ci": p_nom["ci"],
        "stiction_count_nominal": p_nom["count"],
        "stiction_probability_nominal_text": p_nom["text"],
        "realisations": R,
        "constant_sets": sets_count,
        "solve_sets": None if solve_sets is None else solved_sets(solve_sets, sets_count),
        "confidence": confidence,
        "margin_quantiles": _quantiles([s["stiction_margin"] for s in ok]),
        "margin_quantiles_nominal": _quantiles([s["stiction_margin"] for s in ok_nominal]),
        "cof_quantiles": _quantiles([s["cof_mean"] for s in ok]),
        "cof_split_quantiles": {k: _quantiles([s.get(k, 0.0) for s in ok])
                                for k in ("cof_chemical", "cof_vdw", "cof_elastic", "cof_capillary")},
        "priors": {name: p.to_dict() for name, p in priors.items()},
        "sampled_constants": list(sampled),
        "fixed_constants": sorted(fixed_names),
        "unconverged_samples": sum(1 for s in ok if s.get("unconverged_steps", 0) > 0),
        "failed_samples": p_all["failed"] + p_nom["failed"],
        "failures": sorted({s["error"] for s in summaries + nominal if s.get("failed")})[:10],
    }
    if ok and all(s.get("startup_margin") is not None for s in summaries + nominal if not s.get("failed")):
        # the start-up verdict over the priors, like the running one (MODEL 7f, issue #35)
        result["startup_margin_quantiles"] = _quantiles([s["startup_margin"] for s in ok])
        s_all = _probability(summaries, confidence, "startup_stiction")
        s_nom = _probability(nominal, confidence, "startup_stiction")
        result.update({
            "startup_stiction_probability": s_all["probability"], "startup_stiction_probability_ci": s_all["ci"],
            "startup_stiction_count": s_all["count"], "startup_stiction_probability_text": s_all["text"],
            "startup_stiction_probability_nominal": s_nom["probability"],
            "startup_stiction_probability_nominal_ci": s_nom["ci"],
            "startup_stiction_count_nominal": s_nom["count"],
            "startup_stiction_probability_nominal_text": s_nom["text"]})
    result.update(sensitivity={}, dominant=None, critical_curve=None, designer_sentence="")
    return result


def _startup_output(summaries, failed) -> dict:
    """``{"startup": the Sobol' rows' start-up margins [N]}`` where every row has one (a failed row filled with the
    median, as the running margin's), else {}."""
    if not all(f or s.get("startup_margin") is not None for s, f in zip(summaries, failed)):
        return {}
    startup = np.array([np.nan if f else s["startup_margin"] for s, f in zip(summaries, failed)])
    if np.isnan(startup).any():
        startup[np.isnan(startup)] = np.nanmedian(startup)
    return {"startup": startup}


def _sensitivity(result, params, runner, sampled, R, seed, confidence, roughness, steps, coating_name, wear, client,
                 progress, sobol_samples, sobol_steps, critical, threshold, curve_points):
    """Sobol' indices, critical values and the curve of the dominant constant into ``result``; returns the
    runner of the Sobol' rows (``runner`` itself unless ``sobol_steps`` differs), for its counts, and the rows
    (``{"points", "summaries", "blocks"}``, a block per base sample) where they ran at the study's steps, else None
    (they then judge the verdict at other steps and do not join the samples of the decision's sensitivity)."""
    names = list(sampled)
    factors = names + [REALISATION_FACTOR]
    design = _saltelli_design(len(factors), int(sobol_samples), seed)
    sobol_runner = runner if sobol_steps is None or sobol_steps == steps else \
        _Runner(params, roughness, sobol_steps, coating_name, wear, client, progress)
    points = []
    for row in design:
        constants = {name: sampled[name].ppf(row[j]) for j, name in enumerate(names)}
        points.append((min(int(row[-1] * R), R - 1), constants))
    summaries = sobol_runner.summaries(points)
    failed = [s.get("failed", False) for s in summaries]
    margin = np.array([np.nan if f else s["stiction_margin"] for s, f in zip(summaries, failed)])
    cof = np.array([np.nan if f else s["cof_mean"] for s, f in zip(summaries, failed)])
    if any(failed):  # counted, and filled with the median so that the estimators run (reported)
        margin[np.isnan(margin)] = np.nanmedian(margin)
        cof[np.isnan(cof)] = np.nanmedian(cof)
    outputs = {"margin": margin, "cof": cof, **_startup_output(summaries, failed)}
    indices = sobol_indices(factors, outputs, int(sobol_samples), seed, confidence)
    sensitivity = {}
    for name in factors:
        m, c = indices["margin"][name], indices["cof"][name]
        sensitivity[name] = {"first": m["first"], "first_ci": m["first_ci"], "total": m["total"],
                             "total_ci": m["total_ci"], "cof_first": c["first"], "cof_first_ci": c["first_ci"],
                             "cof_total": c["total"], "cof_total_ci": c["total_ci"],
                             "clipped": bool(m["clipped"] or c["clipped"]), "critical_value": None, "note": ""}
        if "startup" in indices:  # the start-up margin's indices (MODEL 7f, issue #35)
            u = indices["startup"][name]
            sensitivity[name].update(startup_first=u["first"], startup_first_ci=u["first_ci"],
                                     startup_total=u["total"], startup_total_ci=u["total_ci"])
    sensitivity[REALISATION_FACTOR]["note"] = "aleatory (part-to-part roughness): no critical value"
    ranked = sorted(factors, key=lambda n: -sensitivity[n]["total"])
    result["sensitivity"] = {name: sensitivity[name] for name in ranked}
    result["sobol_design"] = {"base_samples": int(sobol_samples), "rows": int(design.shape[0]),
                              "steps": sobol_steps or steps or int(params["mesh_steps"]),
                              "failed_rows": int(sum(failed))}
    rows = None
    if sobol_runner is runner:
        rows = {"points": points, "summaries": summaries,
                "blocks": [f"sobol {i // (len(factors) + 2)}" for i in range(len(points))]}
    constants_ranked = [n for n in ranked if n != REALISATION_FACTOR]
    if not constants_ranked:
        return sobol_runner, rows
    dominant = constants_ranked[0]
    result["dominant"] = dominant
    for name in constants_ranked:
        entry = sensitivity[name]
        entry["searched"] = False
        if not critical or entry["total"] <= threshold:
            entry["note"] = entry["note"] or (f"total index {entry['total']:.2g} <= {threshold:g}: not searched"
                                              if critical else "not searched")
            continue
        _search_critical(result, runner, sampled, name, entry, R, critical, f"total index {entry['total']:.2g}")
    _dominant_outputs(result, params, runner, sampled, dominant, sensitivity[dominant], R, coating_name,
                      curve_points)
    return sobol_runner, rows


def _search_critical(result, runner, sampled, name, entry, R, critical, why) -> None:
    """The critical value of ``name`` (and of its start-up margin) into ``entry``; with ``critical="rescaled"`` only
    where ``name`` is rescaled (no new cycle), else a note saying where it is searched."""
    if critical == "rescaled" and name not in runner.rescalable():
        entry["note"] = (f"{why}; not searched here (each value needs new contact solves: `memstribo mesh "
                         "--uncertainty 64 --sobol` searches it)")
        return
    entry["searched"] = True
    function, reals = _margin_function(runner, name, R)
    found = critical_value(function, sampled[name])
    entry["critical_value"] = found["critical_value"]
    entry["stiction_above"] = found["stiction_above"]
    entry["note"] = found["note"] + f" (median over {reals} realisations, others nominal)"
    if "startup_margin_quantiles" in result:  # where the median start-up margin crosses zero (MODEL 7f)
        function, _ = _margin_function(runner, name, R, "startup_margin")
        found = critical_value(function, sampled[name])
        entry["startup_critical_value"] = found["critical_value"]
        entry["startup_stiction_above"] = found["stiction_above"]
        entry["startup_note"] = found["note"]  # e.g. no crossing inside the prior


def _dominant_outputs(result, params, runner, sampled, dominant, entry, R, coating_name, curve_points) -> None:
    """The designer's sentence on the dominant constant and the curve P(stiction) against it (the others nominal,
    over the realisations; left out where it would need new solves and its critical value was not searched)."""
    nominal_value = float(params[dominant]) if dominant in params and params[dominant] is not None else \
        _coating_nominal(dominant, coating_name)
    result["designer_sentence"] = designer_sentence(dominant, entry, sampled[dominant], nominal_value)
    if not entry.get("searched") and dominant not in runner.rescalable():
        return  # critical False or "rescaled": its curve would need the new solves its critical value was spared
    prior = sampled[dominant]
    values = sorted(set([float(v) for v in prior.ppf(np.linspace(0.0, 1.0, max(2, int(curve_points))))]
                        + ([entry["critical_value"]] if entry.get("critical_value") else [])))
    reals = R if dominant in runner.rescalable() else min(R, SOLVED_REALISATIONS)
    curve = {"name": dominant, "values": values, "probability": [], "ci_low": [], "ci_high": [], "realisations": reals,
             "critical_value": entry.get("critical_value"), "nominal": nominal_value}
    for x in values:
        p = _probability(runner.summaries([(r, {dominant: x}) for r in range(reals)]), result["confidence"])
        curve["probability"].append(p["probability"])
        curve["ci_low"].append(p["ci"][0])
        curve["ci_high"].append(p["ci"][1])
    result["critical_curve"] = curve


def _margin_correlation(sampled, points, summaries) -> dict:
    """Spearman's rank correlation of the stiction margin with each factor over the study's samples, with its p-value
    ({factor: {"rho", "p_value"}}, [-]; a factor that does not vary: rho 0, p 1)."""
    from scipy.stats import spearmanr

    keep = [i for i, s in enumerate(summaries) if not s.get("failed") and s.get("stiction_margin") is not None]
    margin = np.array([summaries[i]["stiction_margin"] for i in keep], dtype=float)
    columns = {name: np.array([points[i][1][name] for i in keep], dtype=float) for name in sampled}
    columns[REALISATION_FACTOR] = np.array([points[i][0] for i in keep], dtype=float)
    out = {}
    for name, x in columns.items():
        if len(keep) < 3 or np.ptp(x) == 0 or np.ptp(margin) == 0:
            out[name] = {"rho": 0.0, "p_value": 1.0}
            continue
        rho, p_value = spearmanr(x, margin)
        out[name] = {"rho": float(rho), "p_value": float(p_value)}
    return out


def _screen(result, params, runner, sampled, nominal, points, summaries, R, seed, confidence, coating_name, critical,
            threshold, curve_points, decision) -> None:
    """``sensitivity="regional"`` (the main job's, issue 40): no Sobol' design; the regional index of the verdict on
    the study's own samples ranks the constants (:func:`memstribo.uncertainty.decision.decision_analysis` at depth
    "regional"), the first above its noise level is the dominant one, with its critical value where ``critical``
    allows it."""
    decision_analysis(result, params, runner, sampled, nominal, points, summaries, None, R, seed, confidence,
                      threshold=threshold, critical=critical, **{**decision, "depth": "regional"})
    regional = result["decision_sensitivity"]
    ranked = [n for n, e in regional.items() if n != REALISATION_FACTOR and e["index"] is not None
              and e.get("noise_level") is not None and e["index"] > e["noise_level"]]
    result["sensitivity_method"] = "regional"
    result["margin_correlation"] = correlation = _margin_correlation(sampled, points, summaries)
    why = "regional index {:.2g}"
    if not ranked:  # a unanimous verdict: no factor separates stuck from free; the margin's rank correlation ranks
        ranked = [n for n in sorted(correlation, key=lambda n: -abs(correlation[n]["rho"]))
                  if n != REALISATION_FACTOR and correlation[n]["p_value"] < 0.05]
        why = "rank correlation with the margin {:+.2g}"
    if not ranked:
        return
    dominant = ranked[0]
    result["dominant"] = dominant
    score = regional[dominant]["index"] if why.startswith("regional") else correlation[dominant]["rho"]
    entry = {"searched": False, "critical_value": None, "note": "", "ranked_by": why.format(score)}
    if critical:
        _search_critical(result, runner, sampled, dominant, entry, R, critical, why.format(score))
    result["dominant_entry"] = entry
    _dominant_outputs(result, params, runner, sampled, dominant, entry, R, coating_name, curve_points)


def _coating_nominal(name, coating_name):
    from memstribo.physics.coating import get_coating

    return float(getattr(get_coating(coating_name), name[len("coating_"):]))
