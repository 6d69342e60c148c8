"""Sensitivity of the decision, not only of the margin, and priors that admit what they are (MODEL 7h, issue 38).

Sobol' indices rank the constants by the variance of the margin they explain. A constant with a small share of
that variance can still flip the verdict (a threshold effect at the edge of its prior: the nanoblock width), and a
probability of stiction computed over a prior is partly the prior. This module holds the pieces the uncertainty
study (:func:`memstribo.uncertainty.study.uncertainty_study`) assembles:

- :func:`regional_sensitivity`: a distribution-based index of the stiction verdict for every factor, the
  Kolmogorov-Smirnov distance between the factor's values in the samples that stick and in those that do not
  (regional sensitivity analysis, Spear and Hornberger 1980; Pianosi et al. 2016), with a bootstrap interval and
  the distance that noise alone reaches (a permutation test). 1: the factor alone sorts stuck from free; near 0:
  the verdict does not depend on it.
- :func:`moved_priors` and :func:`robust_bayes_band`: P(stiction) under a class of priors, the constant's prior with
  each bound moved by a factor of 2 either way (robust Bayesian analysis, Berger 1994). Where the band spans more
  than :data:`PRIOR_DOMINATED_SPAN`, the probability is "prior-dominated": it says more about the prior than about
  the gear, and the measurement of that constant decides.
- :func:`measurable`: a critical value in units one can measure (a bond energy as the interfacial shear strength
  U / D_chem^3 and the adhesion hysteresis U / D_chem^2 it implies, a Hamaker constant as a work of adhesion).
- :func:`clip_unit`: Sobol' estimates and their bootstrap intervals kept inside [0, 1], where the indices live.
- :func:`critical_value`: where the median margin crosses zero with one constant moved, the others nominal;
  :func:`decision_analysis`: all of this on an uncertainty study's samples.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["critical_value", "ks_distance", "regional_sensitivity", "moved_priors", "robust_bayes_band", "measurable",
           "clip_unit", "decision_analysis", "decision_options", "decision_sentence", "PRIOR_DOMINATED_SPAN",
           "BAND_FACTOR", "REALISATION_FACTOR", "SOLVED_REALISATIONS", "DEPTHS"]

#: a robust-Bayes band of P(stiction) wider than this makes the verdict "prior-dominated" (MODEL 7h) [-]
PRIOR_DOMINATED_SPAN = 0.3
#: the factor by which each bound of a decisive prior is moved, either way (MODEL 7h) [-]
BAND_FACTOR = 2.0
#: name of the roughness realisation as a factor of the sensitivity analysis (aleatory, not a constant)
REALISATION_FACTOR = "roughness_realisation"

#: how far :func:`decision_analysis` goes: "full" (steps 1 to 3) or "regional" (step 1 only: no cycle beyond the
#: study's own; the main job's default since issue 40, the end points and bands cost hundreds of cycles)
DEPTHS = ("full", "regional")

#: realisations of the median margin of a constant that needs a new contact solve per value (critical values and
#: the end-point test of the decision); a rescaled bond energy uses every realisation
SOLVED_REALISATIONS = 8


def clip_unit(value):
    """``value`` (a number or a [low, high] pair) clipped to [0, 1]; None and NaN stay as they are."""
    if value is None:
        return None
    if isinstance(value, (list, tuple, np.ndarray)):
        return [clip_unit(v) for v in value]
    value = float(value)
    return value if math.isnan(value) else min(1.0, max(0.0, value))


def ks_distance(first, second) -> float:
    """Two-sample Kolmogorov-Smirnov distance, the largest gap between the two empirical CDFs [-] (ties allowed).

    NaN where either sample is empty.
    """
    a = np.sort(np.asarray(first, dtype=float))
    b = np.sort(np.asarray(second, dtype=float))
    if a.size == 0 or b.size == 0:
        return float("nan")
    grid = np.concatenate([a, b])
    fa = np.searchsorted(a, grid, side="right") / a.size
    fb = np.searchsorted(b, grid, side="right") / b.size
    return float(np.max(np.abs(fa - fb)))


def _block_rows(blocks, n):
    """{block size: (blocks of that size, size) matrix of row indices}: the units the bootstrap and the permutations
    move (a block's rows share values: a Saltelli block's rows repeat its A row's columns)."""
    if blocks is None:
        return {1: np.arange(n).reshape(n, 1)}
    blocks = list(blocks)
    if len(blocks) != n:
        raise InputError(f"regional sensitivity: {n} samples and {len(blocks)} block labels.")
    rows: dict = {}
    for i, label in enumerate(blocks):
        rows.setdefault(label, []).append(i)
    by_size: dict = {}
    for members in rows.values():
        by_size.setdefault(len(members), []).append(members)
    return {size: np.asarray(members, dtype=int) for size, members in by_size.items()}


@cites("spear_hornberger_1980", "pianosi_2016")
def regional_sensitivity(values: Mapping[str, np.ndarray], outcome, *, blocks=None, confidence: float = 0.95,
                         resamples: int = 500, seed: int = 0) -> dict:
    """Regional sensitivity of a yes/no outcome (stiction) to each factor: the KS distance between its values in
    the samples with the outcome and in those without (Spear and Hornberger 1980, Monte Carlo filtering).

    Parameters
    ----------
    values : Mapping[str, ndarray]
        Per factor, its value in each sample [unit of the factor] (any monotone transform gives the same index).
    outcome : sequence of bool
        The outcome of each sample (True: stiction).
    blocks : sequence of hashable, optional
        A label per sample: samples of one block are resampled and permuted together (the rows of one base sample
        of a Saltelli design share their values). Default: every sample its own block.
    confidence : float
        Level of the bootstrap interval, in (0, 1) [-].
    resamples : int
        Bootstrap resamples and permutations [-], >= 10.
    seed : int
        Seed of the resampling.

    Returns
    -------
    dict
        ``{factor: {"index", "index_ci", "noise_level"}}`` [-], all in [0, 1]: ``index`` the KS distance,
        ``index_ci`` its percentile bootstrap interval (blocks resampled with replacement), ``noise_level`` the
        ``confidence`` quantile of the distance over permutations of the outcome among blocks of equal size (what
        a factor the outcome does not depend on reaches with these samples). Where every sample has the same
        outcome, the indices are None (nothing to split).

    Raises
    ------
    InputError
        ``confidence`` outside (0, 1), fewer than 10 resamples, lengths that differ.
    """
    if not 0.0 < float(confidence) < 1.0:
        raise InputError(f"regional sensitivity: confidence must lie strictly between 0 and 1, got {confidence!r}.")
    if isinstance(resamples, bool) or int(resamples) != resamples or resamples < 10:
        raise InputError(f"regional sensitivity: resamples must be a whole number >= 10, got {resamples!r}.")
    flags = np.asarray([bool(f) for f in outcome])
    n = flags.size
    columns = {name: np.asarray(v, dtype=float) for name, v in values.items()}
    for name, column in columns.items():
        if column.shape != (n,):
            raise InputError(f"regional sensitivity: factor '{name}' has {column.size} values for {n} outcomes.")
    if n == 0 or flags.all() or not flags.any():
        return {name: {"index": None, "index_ci": None, "noise_level": None} for name in columns}
    groups = _block_rows(blocks, n)
    rng = np.random.default_rng(seed)
    alpha = 1.0 - float(confidence)
    boot_rows, perm_flags = [], []
    for _ in range(int(resamples)):
        picked = [members[rng.integers(0, len(members), len(members))].ravel() for members in groups.values()]
        boot_rows.append(np.concatenate(picked))
        permuted = flags.copy()
        for members in groups.values():
            permuted[members.ravel()] = flags[members[rng.permutation(len(members))].ravel()]
        perm_flags.append(permuted)
    out = {}
    for name, x in columns.items():
        index = ks_distance(x[flags], x[~flags])
        boot = np.array([ks_distance(x[r][flags[r]], x[r][~flags[r]]) for r in boot_rows])
        boot = boot[np.isfinite(boot)]
        noise = np.array([ks_distance(x[p], x[~p]) for p in perm_flags])
        ci = ([float(np.quantile(boot, alpha / 2)), float(np.quantile(boot, 1 - alpha / 2))] if boot.size
              else [index, index])
        out[name] = {"index": clip_unit(index), "index_ci": clip_unit(ci),
                     "noise_level": clip_unit(float(np.quantile(noise, float(confidence))))}
    return out


def _physical(prior, low, high):
    """(low, high, clipped) inside the parameter's physical bounds (its spec), where it has one (an exclusive bound:
    a millionth of the range inside it); None where nothing of the range is left."""
    from memstribo.parameters import SPECS, _in_range

    spec = SPECS.get(prior.name)
    clipped = False
    if spec is not None and spec.kind == "float":
        if spec.minimum is not None and (low < spec.minimum or (spec.exclusive_minimum and low == spec.minimum)):
            low, clipped = float(spec.minimum), True
            if spec.exclusive_minimum:
                low += 1e-6 * (high - low)
        if spec.maximum is not None and (high > spec.maximum or (spec.exclusive_maximum and high == spec.maximum)):
            high, clipped = float(spec.maximum), True
            if spec.exclusive_maximum:
                high -= 1e-6 * (high - low)
        if not (low < high and _in_range(low, spec) and _in_range(high, spec)):
            return None
    return low, high, clipped


@cites("berger_1994", "model")
def moved_priors(prior, factor: float = BAND_FACTOR) -> list[dict]:
    """The priors of a constant with each bound moved by ``factor`` either way (the class of a robust-Bayes band).

    Reading of "a factor of 2 each way" (docs/uncertainty.md): a log-uniform prior [a, b] has each bound
    multiplied or divided by the factor, the four corners [a/2, b/2] (shifted down), [2a, 2b] (shifted up),
    [a/2, 2b] (widened) and [2a, b/2] (narrowed; left out where 2a >= b/2). A uniform or normal prior, read on a
    linear axis, has each bound's distance from the prior's centre (its mean for a normal prior) multiplied or
    divided by the factor: with centre c and half-widths h_l = c - a and h_h = b - c, the corners are
    [c - f h_l, c + h_h / f] (shifted down), [c - h_l / f, c + f h_h] (shifted up), [c - f h_l, c + f h_h]
    (widened) and [c - h_l / f, c + h_h / f] (narrowed); a normal prior keeps its mean and scales its sd by the
    geometric mean of the two
    bounds' factors. A moved bound is kept inside the parameter's physical bounds (``clipped``).

    For a verdict that is monotone in the constant (stiction above a critical value, or below), P(stiction) is
    monotone in each bound, so its extremes over the class {low in [a/f, a f], high in [b/f, b f]} lie at these
    corners.

    Parameters
    ----------
    prior : Prior
    factor : float
        > 1 [-].

    Returns
    -------
    list of dict
        ``{"label", "prior", "low_factor", "high_factor", "clipped"}`` per moved prior (``prior`` a
        :class:`~memstribo.uncertainty.priors.Prior` of the same distribution).

    Raises
    ------
    InputError
        ``factor`` not a finite number above 1.
    """
    from memstribo.uncertainty.priors import Prior

    if isinstance(factor, bool) or not isinstance(factor, (int, float)) or not math.isfinite(factor) or factor <= 1.0:
        raise InputError(f"the robust-Bayes band moves each prior bound by a factor above 1, got {factor!r}.")
    f = float(factor)
    corners = (("shifted down", 1 / f, 1 / f), ("shifted up", f, f), ("widened", 1 / f, f), ("narrowed", f, 1 / f))
    out = []
    for label, low_factor, high_factor in corners:
        if prior.distribution == "loguniform":
            low, high = prior.low * low_factor, prior.high * high_factor
        else:
            centre = prior.mean if prior.distribution == "normal" else 0.5 * (prior.low + prior.high)
            # a bound moved outward by f: its distance from the centre times f; inward: divided by f
            out_low, out_high = 1.0 / low_factor, high_factor  # > 1: outward
            low = centre - (centre - prior.low) * out_low
            high = centre + (prior.high - centre) * out_high
        kept = _physical(prior, low, high) if low < high else None
        if kept is None or not kept[0] < kept[1] or (prior.distribution == "loguniform" and kept[0] <= 0):
            continue
        low, high, clipped = kept
        extra = {}
        if prior.distribution == "normal":
            scale = math.sqrt((1.0 / low_factor) * high_factor)
            extra = {"mean": prior.mean, "sd": prior.sd * scale}
            if not low <= prior.mean <= high:
                continue
        out.append({"label": label, "prior": Prior(prior.name, prior.distribution, low, high, source=prior.source,
                                                   reason=f"{label}: each bound moved by a factor {f:g}",
                                                   measure=prior.measure, **extra),
                    "low_factor": low_factor, "high_factor": high_factor, "clipped": clipped})
    return out


@cites("berger_1994", "model")
def robust_bayes_band(probability_under: Callable, prior, factor: float = BAND_FACTOR,
                      span: float = PRIOR_DOMINATED_SPAN) -> dict:
    """P(stiction) under the constant's prior and under each of :func:`moved_priors`, and how far it moves.

    Parameters
    ----------
    probability_under : callable
        Prior -> dict with ``probability`` [-] and ``ci`` ([low, high], [-]) (and any other keys, kept): the
        stiction probability with the constant drawn from that prior.
    prior : Prior
        The constant's prior.
    factor : float
        Each bound moved by this factor either way (> 1) [-].
    span : float
        A band wider than this is "prior-dominated", in (0, 1] [-].

    Returns
    -------
    dict
        ``priors`` (``[{"label", "low", "high", "probability", "ci", ...}]``, the prior itself first),
        ``band`` ([smallest, largest] estimate, [-]), ``band_ci`` ([lowest lower bound, highest upper bound] of
        their intervals, [-]), ``span`` [-] and ``prior_dominated`` (span > ``span``).

    Raises
    ------
    InputError
        ``span`` outside (0, 1], ``factor`` not above 1.
    """
    if isinstance(span, bool) or not isinstance(span, (int, float)) or not 0.0 < float(span) <= 1.0:
        raise InputError(f"the span that makes a probability prior-dominated is a fraction in (0, 1], got {span!r}.")
    entries = [{"label": "prior", "prior": prior, "low_factor": 1.0, "high_factor": 1.0, "clipped": False}]
    entries += moved_priors(prior, factor)
    rows = []
    for entry in entries:
        result = dict(probability_under(entry["prior"]))
        rows.append({"label": entry["label"], "low": entry["prior"].low, "high": entry["prior"].high,
                     "clipped": entry["clipped"], **result})
    estimates = [r["probability"] for r in rows if r["probability"] is not None and np.isfinite(r["probability"])]
    if not estimates:
        return {"priors": rows, "band": None, "band_ci": None, "span": None, "prior_dominated": None}
    low, high = min(estimates), max(estimates)
    ci_low = min(r["ci"][0] for r in rows if r.get("ci"))
    ci_high = max(r["ci"][1] for r in rows if r.get("ci"))
    return {"priors": rows, "band": [low, high], "band_ci": [ci_low, ci_high], "span": high - low,
            "prior_dominated": bool(high - low > float(span))}


#: per constant: (measurable quantity, its unit, the factor from SI to that unit, what it is)
_MEASURABLE_UNITS = {
    "adhesive_width": ("nanoblock width", "nm", 1e9),
    "adhesive_height": ("adhesive block height", "nm", 1e9),
    "atomic_width": ("atomic block width", "nm", 1e9),
    "atomic_height": ("atomic block height", "nm", 1e9),
    "atomic_pitch": ("atomic block pitch", "nm", 1e9),
    "vdw_site_density": ("van der Waals site density", "sites/nm^2", 1e-18),
    "youngs_modulus": ("Young's modulus", "GPa", 1e-9),
}


@cites("thesis", "model")
def measurable(name: str, value: float, params) -> list[dict]:
    """A constant's value in the units of the measurement that would pin it down.

    - A bond energy U (``vdw_bond_energy``, ``bond_energy``, ``coating_vdw_bond_energy``): the interfacial shear
      strength its bonds give, tau = U / D_chem^3 (one bond per D_chem^2, each resisting with U / D_chem: 3-1,
      3-10, 3-12) [MPa], and the energy it dissipates per area and per bond renewal, U / D_chem^2, the adhesion
      hysteresis the model implies [mJ/m^2].
    - ``vdw_dissipated_fraction`` phi (MODEL 7h): the adhesion hysteresis phi w12 [mJ/m^2] and the vdW shear strength
      phi w12 / D_chem [MPa].
    - ``hamaker_constant`` and ``cutoff_distance``: the work of adhesion w12 = A / (12 pi D0^2) (3-34) with the
      other at its value in ``params`` [mJ/m^2].
    - block sizes [nm], Young's modulus [GPa]; other constants in their own unit.

    Returns
    -------
    list of dict
        ``{"quantity", "value", "unit", "text", "short"}`` (``short``: the quantity's name in a sentence); empty for a
        value of None.
    """
    if value is None:
        return []
    value = float(value)
    if name in ("vdw_bond_energy", "bond_energy", "coating_vdw_bond_energy"):
        d = float(params["bond_length"])
        kind = "chemical" if name == "bond_energy" else "van der Waals"
        tau, hysteresis = value / d ** 3, value / d ** 2
        return [{"quantity": f"interfacial shear strength of the {kind} bonds (U / D_chem^3)", "value": tau / 1e6,
                 "unit": "MPa", "text": f"{tau / 1e6:.3g} MPa", "short": "interfacial shear strength"},
                {"quantity": "adhesion hysteresis per bond renewal (U / D_chem^2)", "value": hysteresis * 1e3,
                 "unit": "mJ/m^2", "text": f"{hysteresis * 1e3:.3g} mJ/m^2", "short": "adhesion hysteresis"}]
    if name == "vdw_dissipated_fraction":  # MODEL 7h: the adhesion hysteresis phi w12 and tau = phi w12 / D_chem
        w = params.get("work_of_adhesion") or float(params["hamaker_constant"]) / (
            12.0 * math.pi * float(params["cutoff_distance"]) ** 2)
        hysteresis, tau = value * w, value * w / float(params["bond_length"])
        return [{"quantity": "adhesion hysteresis of the flanks (phi w12)", "value": hysteresis * 1e3,
                 "unit": "mJ/m^2", "text": f"{hysteresis * 1e3:.3g} mJ/m^2", "short": "adhesion hysteresis"},
                {"quantity": "interfacial shear strength of the van der Waals sites (phi w12 / D_chem)",
                 "value": tau / 1e6, "unit": "MPa", "text": f"{tau / 1e6:.3g} MPa", "short": "interfacial shear strength"}]
    if name in ("hamaker_constant", "cutoff_distance"):
        a = value if name == "hamaker_constant" else float(params["hamaker_constant"])
        d0 = value if name == "cutoff_distance" else float(params["cutoff_distance"])
        w = a / (12.0 * math.pi * d0 ** 2)
        return [{"quantity": "work of adhesion w12 = A / (12 pi D0^2)", "value": w * 1e3, "unit": "mJ/m^2",
                 "text": f"{w * 1e3:.3g} mJ/m^2", "short": "work of adhesion"}]
    if name in _MEASURABLE_UNITS:
        quantity, unit, scale = _MEASURABLE_UNITS[name]
        return [{"quantity": quantity, "value": value * scale, "unit": unit, "text": f"{value * scale:.4g} {unit}",
                 "short": quantity}]
    from memstribo.parameters import SPECS

    unit = SPECS[name].unit if name in SPECS else ""
    return [{"quantity": name.replace("_", " "), "value": value, "unit": unit,
             "text": f"{value:.4g} {unit}".rstrip(), "short": name.replace("_", " ")}]


# --- the study's part: the samples it has, the ends of each prior, the moved priors --------------------------------
@cites("model")
def critical_value(margin_of, prior, *, tolerance=1e-3) -> dict:
    """Where ``margin_of(value)`` (the median margin [N]) crosses zero within ``prior`` (Brent's method).

    Parameters
    ----------
    margin_of : callable
        value [unit of the constant] -> median margin [N].
    prior : Prior
        Searched between ``low`` and ``high`` (on a log scale for a log-uniform prior).
    tolerance : float
        Relative tolerance on the value (of the searched interval's width) [-].

    Returns
    -------
    dict
        ``critical_value`` [unit of the constant] or None, ``stiction_above`` (True: stiction
        for values above it), ``margin_at_low``, ``margin_at_high`` [N], ``note``.
    """
    from scipy.optimize import brentq

    forward = math.log if prior.log_scale else (lambda x: x)
    back = math.exp if prior.log_scale else (lambda t: t)
    t_lo, t_hi = forward(prior.low), forward(prior.high)
    m_lo, m_hi = float(margin_of(prior.low)), float(margin_of(prior.high))
    out = {"margin_at_low": m_lo, "margin_at_high": m_hi, "critical_value": None, "stiction_above": None}
    if not (np.isfinite(m_lo) and np.isfinite(m_hi)):
        out["note"] = "the margin could not be computed at an end of the prior"
        return out
    if (m_lo < 0) == (m_hi < 0):
        state = "stiction" if m_lo < 0 else "no stiction"
        out["note"] = (f"no crossing within the prior: the median margin is {m_lo:+.3g} N at {prior.low:.4g} and "
                       f"{m_hi:+.3g} N at {prior.high:.4g} ({state} over the whole range)")
        return out
    root = brentq(lambda t: float(margin_of(back(t))), t_lo, t_hi, xtol=tolerance * abs(t_hi - t_lo), maxiter=60)
    out["critical_value"] = float(back(root))
    out["stiction_above"] = bool(m_hi < 0)
    out["note"] = f"the median margin crosses zero at {back(root):.4g} (stiction {'above' if m_hi < 0 else 'below'})"
    return out


def _margin_function(runner, name, R, key="stiction_margin"):
    """(value -> median of ``key`` over the realisations with ``name`` at that value and the others nominal [N], the
    number of realisations): all ``R`` for a rescaled bond energy, :data:`SOLVED_REALISATIONS` otherwise."""
    cache = {}
    reals = R if name in runner.rescalable() else min(R, SOLVED_REALISATIONS)

    def median_margin(x):
        if x not in cache:
            out = runner.summaries([(r, {name: x}) for r in range(reals)])
            values = [s[key] for s in out if not s.get("failed") and s.get(key) is not None]
            cache[x] = float(np.median(values)) if values else float("nan")
        return cache[x]
    return median_margin, reals


def _median(summaries, key):
    values = [s[key] for s in summaries if not s.get("failed") and s.get(key) is not None]
    return float(np.median(values)) if values else None


def _has_startup(summaries) -> bool:
    ok = [s for s in summaries if not s.get("failed")]
    return bool(ok) and all(s.get("startup_stiction") is not None for s in ok)


def _end_points(runner, name, prior, nominal, R, confidence, startup) -> dict:
    """The verdict with ``name`` at each end of its prior and the others nominal (median margin over the
    realisations, :func:`_margin_function`'s count), against the nominal constants'."""
    from memstribo.uncertainty.intervals import sample_probability as _probability

    reals = R if name in runner.rescalable() else min(R, SOLVED_REALISATIONS)
    reference = nominal[:reals]
    entry = {"realisations": reals, "nominal_margin": _median(reference, "stiction_margin"),
             "low": prior.low, "high": prior.high}
    if startup:
        entry["nominal_startup_margin"] = _median(reference, "startup_margin")
    for label, value in (("low", prior.low), ("high", prior.high)):
        out = runner.summaries([(r, {name: value}) for r in range(reals)])
        p = _probability(out, confidence)
        entry[f"margin_at_{label}"] = _median(out, "stiction_margin")
        entry[f"stiction_at_{label}"] = p["text"]
        entry[f"stiction_probability_at_{label}"] = p["probability"]
        entry[f"stiction_probability_at_{label}_ci"] = p["ci"]
        if startup and _has_startup(out):
            entry[f"startup_margin_at_{label}"] = _median(out, "startup_margin")
            entry[f"startup_stiction_at_{label}"] = _probability(out, confidence, "startup_stiction")["text"]

    def flips(key):
        reference = entry.get(f"nominal_{key}")
        if reference is None:
            return False
        return any(entry.get(f"{key}_at_{end}") is not None and (entry[f"{key}_at_{end}"] < 0) != (reference < 0)
                   for end in ("low", "high"))
    entry["can_flip"] = flips("margin")
    if startup:
        entry["can_flip_startup"] = flips("startup_margin")
    return entry


def _probability_under(runner, name, prior, points, summaries, subset, confidence, startup):
    """Prior -> P(stiction) of the study's samples ``subset`` with ``name`` re-drawn from that prior at the same
    quantile (the same low-discrepancy design, mapped by the new prior's inverse CDF); the prior itself: the study's."""
    from memstribo.uncertainty.intervals import sample_probability as _probability

    def under(moved):
        if moved is prior:
            out = [summaries[i] for i in subset]
        else:
            out = runner.summaries([(points[i][0], {**points[i][1],
                                                    name: float(moved.ppf(prior.cdf(points[i][1][name])))})
                                    for i in subset])
        p = _probability(out, confidence)
        row = {"probability": p["probability"], "ci": p["ci"], "text": p["text"], "samples": p["samples"]}
        if startup and _has_startup(out):
            q = _probability(out, confidence, "startup_stiction")
            row.update(startup_probability=q["probability"], startup_ci=q["ci"], startup_text=q["text"])
        return row
    return under


def _unit(name) -> str:
    from memstribo.parameters import SPECS

    return f" {SPECS[name].unit}" if name in SPECS and SPECS[name].unit else ""


def _critical_text(name, entry, params) -> str:
    value = entry.get("critical_value")
    if value is None:
        return ""
    sign = ">" if entry.get("stiction_above") else "<"
    text = f"stiction if {name} {sign} {value:.3g}{_unit(name)}"
    for m in measurable(name, value, params):
        if m["unit"] != _unit(name).strip() or m["quantity"] != name.replace("_", " "):
            rises = not (name == "cutoff_distance")  # w12 falls as D0 grows
            text += f", {m['short']} {sign if rises else ('<' if sign == '>' else '>')} {m['text']}"
    return text


def decision_sentence(flipping, flipping_startup, sensitivity, bands, factor, params) -> str:
    """The verdict's dependence in words: every constant that alone flips it, and whether P(stiction) is
    prior-dominated (with the measurement that would decide it, in measurable units)."""
    parts = []
    if flipping:
        items = []
        for name in flipping:
            critical = _critical_text(name, sensitivity.get(name, {}), params)
            items.append(f"{name} ({critical})" if critical else name)
        parts.append("One constant moved alone to an end of its prior, the others nominal, flips the verdict: "
                     + "; ".join(items) + ".")
    else:
        parts.append("No constant moved alone to an end of its prior (the others nominal) flips the verdict.")
    if flipping_startup:
        parts.append("The start-up verdict flips with: " + ", ".join(flipping_startup) + ".")
    dominated = [name for name, band in bands.items() if band.get("prior_dominated")]
    for name in dominated:
        band = bands[name]
        rows = sorted((r for r in band["priors"] if r["probability"] is not None), key=lambda r: r["probability"])
        lowest, highest = rows[0], rows[-1]
        measure = band.get("measure") or "a measurement of it"
        critical = _critical_text(name, sensitivity.get(name, {}), params)
        parts.append(f"P(stiction) is prior-dominated by {name}: with its prior's bounds moved by a factor "
                     f"{factor:g} it ranges from {lowest['text']} ({lowest['label']}) to {highest['text']} "
                     f"({highest['label']}); what decides it: {measure}" + (f" ({critical})" if critical else "")
                     + ".")
    if bands and not dominated:
        widest = max(bands, key=lambda n: bands[n]["span"] if bands[n]["span"] is not None else -1)
        if bands[widest]["span"] is not None:
            parts.append(f"P(stiction) is not prior-dominated: with each decisive prior's bounds moved by a factor "
                         f"{factor:g} it moves by at most {bands[widest]['span']:.2f} ({widest}).")
    return " ".join(parts)


def decision_options(options=None) -> dict:
    """The options of :func:`decision_analysis` (``band_factor``, ``band_samples``, ``span``, ``depth``), checked, with
    defaults.

    Raises
    ------
    InputError
        An unknown option, ``band_factor`` not a number above 1, ``band_samples`` not a whole number >= 1, ``span``
        not a fraction in (0, 1], ``depth`` not one of :data:`DEPTHS`.
    """
    out = {"band_factor": BAND_FACTOR, "band_samples": 32, "span": PRIOR_DOMINATED_SPAN, "depth": "full"}
    options = dict(options or {})
    unknown = sorted(set(options) - set(out))
    if unknown:
        raise InputError(f"unknown option(s) of the decision's sensitivity: {', '.join(unknown)}; allowed: "
                         f"{', '.join(out)}.")
    out.update(options)

    def number(x):
        return not isinstance(x, bool) and isinstance(x, (int, float, np.integer, np.floating)) and math.isfinite(x)

    if not number(out["band_factor"]) or out["band_factor"] <= 1.0:
        raise InputError(f"band_factor (each prior bound moved by it either way) must be a number above 1, "
                         f"got {out['band_factor']!r}.")
    samples = out["band_samples"]
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 1:
        raise InputError(f"band_samples must be a whole number >= 1, got {samples!r}.")
    if out["depth"] not in DEPTHS:
        raise InputError(f"depth (how far the decision's sensitivity goes) must be one of {', '.join(DEPTHS)}, "
                         f"got {out['depth']!r}.")
    if not number(out["span"]) or not 0.0 < out["span"] <= 1.0:
        raise InputError(f"span (a band wider than it is prior-dominated) is a fraction in (0, 1], "
                         f"got {out['span']!r}.")
    return out


def _regional(result, names, points, summaries, rows, seed, confidence, resamples) -> dict:
    """Step 1 of :func:`decision_analysis`: the regional index of the running (and start-up) verdict per factor,
    into ``result["decision_design"]``; returns ``{factor: entry}``."""
    all_points, all_summaries = list(points), list(summaries)
    blocks = [f"sample {i}" for i in range(len(points))]
    sources = ["the study's samples"]
    if rows:
        all_points += rows["points"]
        all_summaries += rows["summaries"]
        blocks += rows["blocks"]
        sources.append("the Sobol' design's rows (one block per base sample)")
    keep = [i for i, s in enumerate(all_summaries) if not s.get("failed")]
    values = {name: np.array([all_points[i][1][name] for i in keep]) for name in names}
    values[REALISATION_FACTOR] = np.array([all_points[i][0] for i in keep], dtype=float)
    kept_blocks = [blocks[i] for i in keep]
    stuck = [bool(all_summaries[i]["stiction"]) for i in keep]
    running = regional_sensitivity(values, stuck, blocks=kept_blocks, confidence=confidence, resamples=resamples,
                                   seed=seed)
    starting = None
    if "startup_margin_quantiles" in result and _has_startup([all_summaries[i] for i in keep]):
        starting = regional_sensitivity(values, [bool(all_summaries[i]["startup_stiction"]) for i in keep],
                                        blocks=kept_blocks, confidence=confidence, resamples=resamples, seed=seed)
    decision = {}
    for name in [REALISATION_FACTOR] + list(names):
        entry = dict(running[name])
        if starting is not None:
            entry.update(startup_index=starting[name]["index"], startup_index_ci=starting[name]["index_ci"],
                         startup_noise_level=starting[name]["noise_level"])
        decision[name] = entry
    result["decision_design"] = {"samples": len(keep), "stuck": int(sum(stuck)), "free": len(keep) - int(sum(stuck)),
                                 "failed": len(all_summaries) - len(keep), "blocks": len(set(kept_blocks)),
                                 "sources": sources, "resamples": int(resamples), "confidence": float(confidence)}
    return decision


def _band(runner, name, prior, points, summaries, entry, sensitivity, result, confidence, band_factor, band_samples,
          span) -> dict:
    """Step 3 of :func:`decision_analysis`: the robust-Bayes band of one decisive constant."""
    subset = list(range(len(points) if name in runner.rescalable() else min(len(points), int(band_samples))))
    startup = "startup_margin_quantiles" in result and _has_startup(summaries)
    band = robust_bayes_band(_probability_under(runner, name, prior, points, summaries, subset, confidence, startup),
                             prior, band_factor, span)
    band.update(factor=float(band_factor), samples=len(subset), distribution=prior.distribution,
                measure=prior.measure, critical_value=sensitivity.get(name, {}).get("critical_value"),
                stiction_above=sensitivity.get(name, {}).get("stiction_above"),
                critical_measurable=entry.get("critical_measurable", []))
    startup_rows = [r["startup_probability"] for r in band["priors"] if r.get("startup_probability") is not None]
    if startup_rows:
        band["startup_band"] = [min(startup_rows), max(startup_rows)]
    return band


def _regional_words(decision, above) -> str:
    """What the regional index says, in words: the factors above their noise level, none, or a unanimous verdict."""
    if all(entry["index"] is None for entry in decision.values()):
        return "Every sample gives the same verdict, so no factor separates stuck from free (no regional index)"
    if not above:
        return "No factor separates the samples that stick from those that do not beyond noise (regional sensitivity)"
    return ("The samples that stick differ from those that do not most in " + ", ".join(above[:3])
            + " (regional sensitivity)")


def _regional_only(result, decision) -> dict:
    """:func:`decision_analysis` at ``depth="regional"``: the regional index of every factor, nothing else checked."""
    ranked = sorted(decision, key=lambda n: -(decision[n]["index"] if decision[n]["index"] is not None else -1))
    above = [n for n in ranked if decision[n]["index"] is not None and decision[n].get("noise_level") is not None
             and decision[n]["index"] > decision[n]["noise_level"]]
    result.update({
        "decision_sensitivity": {n: decision[n] for n in ranked},
        "flipping_constants": None, "flipping_constants_startup": None, "robust_bayes": None,
        "prior_dominated": None, "prior_dominated_constants": None,
        "decision_sentence": (_regional_words(decision, above)
                              + "; whether a constant alone flips the verdict at the end of its prior, and how much of "
                              "P(stiction) is the prior's (robust-Bayes band), is not checked here: `memstribo mesh "
                              "--uncertainty 64 --sobol` does (hundreds of cycles)."),
    })
    return result


@cites("model", "spear_hornberger_1980", "berger_1994")
def decision_analysis(result, params, runner, sampled, nominal, points, summaries, rows, R, seed, confidence, *,
                      threshold=0.1, band_factor=BAND_FACTOR, band_samples=32, span=PRIOR_DOMINATED_SPAN,
                      resamples=500, critical=True, depth="full") -> dict:
    """The sensitivity of the decision into ``result`` (MODEL 7h; called by the uncertainty study).

    1. Regional sensitivity of the verdict (:func:`regional_sensitivity`) on the samples the study has: its own
       (realisations x constant sets) and the rows of the Sobol' design where they ran at the study's steps (each
       base sample's D + 2 rows one block).
    2. For every sampled constant, the verdict at each end of its prior with the others nominal (the median margin
       over the realisations, as the critical values take it): ``can_flip`` where its sign differs from the nominal
       constants'. A constant that can flip and was not searched for its critical value (total index at or below
       ``threshold``) is searched now (unless ``critical`` is False).
    3. For every decisive constant (it can flip the verdict, or its total index exceeds ``threshold``), the
       robust-Bayes band (:func:`robust_bayes_band`, each bound moved by ``band_factor``; wider than ``span``:
       prior-dominated): the study's samples with that constant re-drawn under each moved prior at the same design
       quantile (a rescaled bond energy: every sample, by rescaling; a constant that needs a contact solve: the
       first ``band_samples``).

    ``depth="regional"`` stops after step 1 (no cycle beyond the study's): ``flipping_constants``,
    ``robust_bayes`` and ``prior_dominated`` are then None (not checked, which is not "none flips"), and the
    sentence says which command checks them.

    Returns ``result`` with ``decision_depth``, ``decision_sensitivity``, ``decision_design``, ``flipping_constants``,
    ``flipping_constants_startup``, ``robust_bayes``, ``prior_dominated``, ``prior_dominated_constants`` and
    ``decision_sentence``.
    """
    names = list(sampled)
    sensitivity = result.get("sensitivity") or {}
    startup = "startup_margin_quantiles" in result
    decision = _regional(result, names, points, summaries, rows, seed, confidence, resamples)
    result["decision_depth"] = depth
    if depth == "regional":
        return _regional_only(result, decision)
    for name in names:  # 2. each constant alone at the ends of its prior
        ends = _end_points(runner, name, sampled[name], nominal, R, confidence, startup)
        decision[name].update(ends)
        entry = sensitivity.get(name)
        if entry is None:
            continue
        if critical and ends["can_flip"] and entry.get("critical_value") is None \
                and "not searched" in (entry.get("note") or ""):
            function, reals = _margin_function(runner, name, R)
            found = critical_value(function, sampled[name])
            entry.update(critical_value=found["critical_value"], stiction_above=found["stiction_above"],
                         note=found["note"] + f" (median over {reals} realisations, others nominal; searched because "
                                              "the verdict flips inside the prior)")
        if critical and startup and ends.get("can_flip_startup") and entry.get("startup_critical_value") is None:
            function, _ = _margin_function(runner, name, R, "startup_margin")
            found = critical_value(function, sampled[name])
            entry.update(startup_critical_value=found["critical_value"],
                         startup_stiction_above=found["stiction_above"])
        if entry.get("critical_value") is not None:
            decision[name]["critical_measurable"] = measurable(name, entry["critical_value"], params)
    flipping = [n for n in names if decision[n]["can_flip"]]
    flipping_startup = [n for n in names if decision[n].get("can_flip_startup")]
    decisive = [n for n in names if decision[n]["can_flip"]  # 3. the robust-Bayes band of each decisive constant
                or (n in sensitivity and sensitivity[n]["total"] > threshold)]
    bands = {name: _band(runner, name, sampled[name], points, summaries, decision[name], sensitivity, result,
                         confidence, band_factor, band_samples, span) for name in decisive}
    ranked = sorted(decision, key=lambda n: -(decision[n]["index"] if decision[n]["index"] is not None else -1))
    dominated = [n for n in bands if bands[n]["prior_dominated"]]
    result.update({
        "decision_sensitivity": {n: decision[n] for n in ranked},
        "flipping_constants": flipping,
        "flipping_constants_startup": flipping_startup,
        "robust_bayes": bands,
        "prior_dominated": (bool(dominated) if bands else None),
        "prior_dominated_constants": dominated,
        "decision_sentence": decision_sentence(flipping, flipping_startup, sensitivity, bands, float(band_factor),
                                               params),
    })
    return result
