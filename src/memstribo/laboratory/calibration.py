"""Calibration of the uncertain constants on the declared rows: importance sampling of prior samples (MODEL 7e).

Prior samples of the constants (from :mod:`memstribo.uncertainty` when the package has it, else the
fallback prior declared in ``measurements.toml``) are weighted by the likelihood of the calibration rows:
log-normal on the ratio measured / predicted median, with the measurement's relative scatter and the
spread over roughness realisations added in quadrature,

    ln L_j = sum_i [ -1/2 (ln(y_i / m_ij) / s_ij)^2 - ln s_ij ],  s_ij^2 = ln(1 + r_i^2) + var_k ln v_ijk,

where y_i is row i's value, r_i its relative sd, m_ij the median over realisations k of sample j. The
posterior is the prior samples with weights w_j proportional to L_j; its effective size is
(sum w)^2 / sum w^2 (Kish 1965). Held-out rows are predicted with equal weights (prior) and with w (posterior).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["prior_samples", "log_likelihood", "importance_weights", "effective_sample_size", "weighted_quantile",
           "hit_rate", "CalibrationResult", "calibrate", "calibrated_set_toml"]


def prior_samples(params, settings, n, seed=0, coating=None):
    """Samples of the calibration constants: ``(list of dict, description)``.

    Uses :func:`memstribo.uncertainty.sampling.sample_constants` on
    :func:`memstribo.uncertainty.priors.priors_for` when that package is present (only the constants named in
    ``settings['constants']`` are kept); otherwise the fallback prior of ``settings['fallback_prior']``:
    log-uniform between the two factors times the nominal value (``coating_*`` names: the coating's value).
    """
    names = list(settings.get("constants", []))
    try:
        from memstribo.uncertainty.priors import priors_for
        from memstribo.uncertainty.sampling import sample_constants
    except ImportError:
        priors_for = None
    if priors_for is not None:
        priors = {k: v for k, v in priors_for(params, coating=coating).items() if k in names}
        if priors:
            return sample_constants(priors, n, seed=seed), "memstribo.uncertainty priors (MODEL 7d)"
    fallback = settings.get("fallback_prior", {})
    rng = np.random.default_rng(seed)
    columns = {}
    for name in names:
        if name not in fallback:
            raise InputError(f"calibration constant {name!r} has no prior: memstribo.uncertainty is not available and "
                             "measurements.toml gives no fallback_prior for it.")
        low, high = fallback[name]
        nominal = getattr(coating, name.removeprefix("coating_")) if name.startswith("coating_") else params[name]
        columns[name] = nominal * np.exp(rng.uniform(math.log(low), math.log(high), n))
    samples = [{k: float(v[j]) for k, v in columns.items()} for j in range(n)]
    text = ("fallback prior of measurements.toml (memstribo.uncertainty not present): log-uniform, "
            + ", ".join(f"{k} x[{v[0]:g}, {v[1]:g}] of nominal" for k, v in fallback.items() if k in names))
    return samples, text


def _log_sd(row, values, discrepancy=0.0):
    r = row.relative_sd()
    if r is None:
        raise InputError(f"row {row.id}: no relative scatter for the likelihood; give scatter sd, range or "
                         "relative_sd_assumed.")
    logs = np.log(np.maximum(values, 1e-300))
    model = logs.std(axis=1) if values.shape[1] > 1 else np.zeros(values.shape[0])
    return np.sqrt(math.log1p(r * r) + model**2 + discrepancy**2), np.median(values, axis=1)


def log_likelihood(rows, values, discrepancy=None) -> np.ndarray:
    """ln L of each constant sample (see the module docstring).

    Parameters
    ----------
    rows : list of Measurement
        The calibration rows.
    values : list of ndarray
        Per row, the predicted values of shape (n_samples, n_realisations), all > 0.
    discrepancy : list of float, optional
        Per row, the sigma of a multiplicative log-normal model discrepancy [ln units]
        (:mod:`memstribo.laboratory.scoring`), added to s_ij in quadrature; default none.

    Returns
    -------
    ndarray of shape (n_samples,)
    """
    if len(rows) != len(values) or not rows:
        raise InputError("log_likelihood needs one array of predicted values per calibration row (at least one).")
    if discrepancy is not None and len(discrepancy) != len(rows):
        raise InputError("log_likelihood: one discrepancy sigma per row, or none.")
    total = np.zeros(np.asarray(values[0]).shape[0])
    for i, (row, v) in enumerate(zip(rows, values)):
        v = np.asarray(v, dtype=float)
        s, median = _log_sd(row, v, 0.0 if discrepancy is None else float(discrepancy[i]))
        total += -0.5 * (np.log(row.value / median) / s) ** 2 - np.log(s)
    return total


def importance_weights(log_l) -> np.ndarray:
    """Normalised weights exp(ln L - max ln L) / sum."""
    ll = np.asarray(log_l, dtype=float)
    if not np.all(np.isfinite(ll)):
        raise InputError("log-likelihood holds NaN or infinite values.")
    w = np.exp(ll - ll.max())
    return w / w.sum()


@cites("kish_1965")
def effective_sample_size(weights) -> float:
    """(sum w)^2 / sum w^2 (Kish 1965): how many equally weighted samples the weighted ones are worth."""
    w = np.asarray(weights, dtype=float)
    return float(w.sum() ** 2 / (w**2).sum())


def weighted_quantile(values, weights, q) -> float:
    """Quantile ``q`` in [0, 1] of ``values`` with ``weights`` (midpoint interpolation of the weighted CDF)."""
    v, w = np.asarray(values, dtype=float), np.asarray(weights, dtype=float)
    order = np.argsort(v)
    cdf = (np.cumsum(w[order]) - 0.5 * w[order]) / w.sum()
    return float(np.interp(q, cdf, v[order]))


def hit_rate(predictions) -> dict:
    """Hits among predicted rows: ``{"inside", "predicted", "rate", "interval"}`` (interval: 95 %, None if unavailable)."""
    judged = [p for p in predictions if p.status == "predicted"]
    k, n = sum(bool(p.inside) for p in judged), len(judged)
    interval = None
    try:
        from memstribo.uncertainty.intervals import binomial_interval
    except ImportError:
        binomial_interval = None
    if binomial_interval is not None and n:
        interval = tuple(binomial_interval(k, n, confidence=0.95))
    return {"inside": k, "predicted": n, "rate": k / n if n else math.nan, "interval": interval}


@dataclass
class CalibrationResult:
    """What :func:`calibrate` found.

    Attributes
    ----------
    samples : list of dict
        Prior samples of the constants.
    prior : str
        Where the prior came from.
    weights : ndarray
        Posterior importance weights (sum 1).
    ess : float
        Effective sample size of the weights.
    constants : list of dict
        Per constant: ``name``, prior ``median``/``p05``/``p95`` and posterior ``post_median``/``post_p05``/``post_p95``.
    prior_predictions, posterior_predictions : list of Prediction
        Every row predicted with the prior samples (equal weights) and with the posterior weights.
    held_out_before, held_out_after : dict
        :func:`hit_rate` of the held-out rows (no fit used them, not a design target, not a duplicate).
    """

    samples: list
    prior: str
    weights: np.ndarray
    ess: float
    constants: list = field(default_factory=list)
    prior_predictions: list = field(default_factory=list)
    posterior_predictions: list = field(default_factory=list)
    held_out_before: dict = field(default_factory=dict)
    held_out_after: dict = field(default_factory=dict)


def calibrate(rows, samples, prior_text="given samples", realisations=3, calibration_coating="OTS") -> CalibrationResult:
    """Importance-sample ``samples`` on the rows declared ``calibration = true``; predict every row before and after.

    Parameters
    ----------
    rows : list of Measurement
    samples : list of dict
        Prior samples of the constants (parameter overrides).
    prior_text : str
        Where the samples came from (reported).
    realisations : int
        Roughness realisations per sample.
    calibration_coating : str
        The coating that ``coating_*`` sample keys stand for.

    Returns
    -------
    CalibrationResult
    """
    from memstribo.laboratory.predict import judge, row_values, _not_predicted

    if not samples:
        raise InputError("calibrate needs at least one prior sample.")
    computed = {}
    for row in rows:
        computed[row.id] = row_values(row, samples, realisations, calibration_coating)
    cal = [r for r in rows if r.calibration and computed[r.id][0] is not None]
    if not cal:
        raise InputError("no calibration row can be predicted: nothing to calibrate on.")
    weights = importance_weights(log_likelihood(cal, [computed[r.id][0] for r in cal]))
    prior_pred, post_pred = [], []
    for row in rows:
        values, case = computed[row.id]
        if values is None:
            prior_pred.append(_not_predicted(row, case))
            post_pred.append(_not_predicted(row, case))
        else:
            prior_pred.append(judge(row, values, None, case))
            post_pred.append(judge(row, values, weights, case))
    constants = []
    for name in samples[0]:
        column = np.array([s[name] for s in samples])
        flat = np.ones(len(samples))
        constants.append({"name": name,
                          "median": weighted_quantile(column, flat, 0.5), "p05": weighted_quantile(column, flat, 0.05),
                          "p95": weighted_quantile(column, flat, 0.95),
                          "post_median": weighted_quantile(column, weights, 0.5),
                          "post_p05": weighted_quantile(column, weights, 0.05),
                          "post_p95": weighted_quantile(column, weights, 0.95)})
    held = {r.id for r in rows if r.held_out}  # never a row any fit used, a design target or a duplicate
    return CalibrationResult(samples=list(samples), prior=prior_text, weights=weights,
                             ess=effective_sample_size(weights), constants=constants,
                             prior_predictions=prior_pred, posterior_predictions=post_pred,
                             held_out_before=hit_rate([p for p in prior_pred if p.id in held]),
                             held_out_after=hit_rate([p for p in post_pred if p.id in held]))


def calibrated_set_toml(result: CalibrationResult, base="silicon_oxide_air", command="python -m memstribo.laboratory"):
    """The ``calibrated`` parameter set: posterior medians as values, the posterior as its prior ([posterior.NAME])."""
    lines = ["# Generated by '" + command + "' (issue 28): do not edit by hand.",
             "# The posterior medians of the laboratory calibration (docs/experiments.md); every other value is the",
             f"# base set's. [posterior.NAME] tables carry the posterior (weighted quantiles) as this set's prior.",
             "", "[meta]", 'name = "calibrated"', f'base = "{base}"',
             'description = "silicon_oxide_air with the constants calibrated on the declared laboratory rows"', ""]
    units = {"bond_energy": "J", "vdw_bond_energy": "J", "coating_vdw_bond_energy": "J"}
    for c in result.constants:
        note = " (the OTS coating's U_vdW: use this set with --coating OTS only)" if c["name"].startswith("coating_") else ""
        lines += [f"[parameters.{c['name']}]", f"value = {c['post_median']:.4e}", f'unit = "{units.get(c["name"], "")}"',
                  f'source = "posterior median of the laboratory calibration (importance sampling, {result.prior.split(":")[0]}, '
                  f'effective sample size {result.ess:.1f}){note}; docs/experiments.md"', ""]
    for c in result.constants:
        lines += [f"[posterior.{c['name']}]", 'distribution = "importance-weighted prior samples (quantiles)"',
                  f"median = {c['post_median']:.4e}", f"p05 = {c['post_p05']:.4e}", f"p95 = {c['post_p95']:.4e}",
                  f"prior_median = {c['median']:.4e}", ""]
    return "\n".join(lines)
