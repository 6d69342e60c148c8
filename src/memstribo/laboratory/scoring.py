"""Honest scoring of the laboratory rows: which rows count, leave-one-source-out coverage, a model discrepancy (MODEL 7e).

- One measurement published twice is one row: a row with ``same_as`` is left out of every count and fit.
- A row that any fit used (``fitted_by``: a parameter set's own calibration, or the laboratory calibration) or that
  the model was designed to reproduce (``design_target``) is never held out (:attr:`Measurement.held_out`).
- Coverage of the 90 % bands is measured by leave-one-source-out cross-validation over every row with a value
  and a scatter: for each research group (``source_group``), the constants are importance-weighted on the
  rows of the other groups (the laboratory calibration redone on that training fold) and the group's rows are
  predicted with that posterior. Rows fixed by a parameter set's own fit and design targets are only trained on,
  never scored (that fit is not redone per fold). The count of rows inside their band is reported with its
  Wilson interval (:func:`memstribo.uncertainty.intervals.binomial_interval`).
- The model discrepancy (Kennedy and O'Hagan 2001) is multiplicative and log-normal per quantity,
  y = m(theta) exp(delta_q) e, delta_q ~ N(0, sigma_q^2): sigma_q is fitted on each training fold by maximum
  likelihood (scipy's bounded scalar minimiser) of the log residuals ln(y_i / median_i) with the model's
  log-spread over samples x realisations and the measurement's scatter in quadrature,

      -ln L(sigma) = sum_i [ d_i^2 / (v_i + sigma^2) + ln(v_i + sigma^2) ] / 2,

  then the constants are re-weighted with sigma_q added to each training row's log-sd (a two-step, modular fit:
  the discrepancy does not feed back into its own sigma), and the band is the weighted predictive values times exp(sigma_q z) over a
  fixed grid of normal quantiles z. A quantity with fewer than :data:`MIN_ROWS` training rows takes the
  pooled sigma of all quantities. The discrepancy says by how much the model is known to miss; it is a
  weakness to shrink by physics, never a tuning knob.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["SCORED_QUANTITIES", "MIN_ROWS", "DISCREPANCY_GRID", "independent_rows", "scoreable",
           "fit_discrepancy", "discrepancy_sigmas", "discrepancy_band", "loso_coverage", "coverage_summary"]

#: quantities scored against a band (a trend or a lifetime is judged otherwise)
SCORED_QUANTITIES = ("static_cof", "kinetic_cof", "adhesion_energy", "pull_off_force", "interfacial_shear_strength",
                     "crack_length")
#: fewest training rows of a quantity for its own discrepancy (else the pooled one)
MIN_ROWS = 2
#: normal quantiles over which the discrepancy spreads each predicted value
DISCREPANCY_GRID = 33
#: largest discrepancy sigma searched [ln units] (a factor e^6 = 400)
MAX_SIGMA = 6.0


def independent_rows(rows):
    """The rows that count: every row but the duplicates (``same_as``)."""
    return [r for r in rows if r.same_as is None]


def scoreable(row, values) -> bool:
    """Whether a row enters the cross-validation: not a duplicate, a scored quantity, predicted, a relative scatter."""
    return (row.same_as is None and row.quantity in SCORED_QUANTITIES and values is not None
            and np.size(values) > 0 and row.relative_sd() is not None)


def _log_moments(values, weights):
    """Weighted mean and variance of ln(values) over samples x realisations (each sample's realisations share its
    weight)."""
    v = np.log(np.maximum(np.asarray(values, dtype=float), 1e-300))
    if v.ndim == 1:
        v = v[:, None]
    w = np.repeat(np.asarray(weights, dtype=float) / v.shape[1], v.shape[1])
    w = w / w.sum()
    mean = float(np.sum(w * v.ravel()))
    return mean, float(np.sum(w * (v.ravel() - mean) ** 2))


def _residuals(rows, values, weights):
    """(d_i, v_i) of each row: log residual against the weighted median and log-variance (model + measurement)."""
    from memstribo.laboratory.predict import band

    out = []
    for row in rows:
        median = band(values[row.id], weights)[0]
        _, var = _log_moments(values[row.id], weights)
        r = row.relative_sd()
        out.append((math.log(row.value / median), var + math.log1p(r * r)))
    return out


@cites("kennedy_ohagan_2001")
def fit_discrepancy(residuals) -> float:
    """Maximum-likelihood sigma of a multiplicative log-normal discrepancy [-, ln units] (module docstring).

    Parameters
    ----------
    residuals : list of (float, float)
        Per row, the log residual d_i = ln(measured / predicted median) and its known log-variance v_i
        (the model's spread plus the measurement's scatter), both in ln units.

    Returns
    -------
    float
        sigma in [0, MAX_SIGMA]; 0 for no rows.
    """
    from scipy.optimize import minimize_scalar

    if not residuals:
        return 0.0
    d = np.array([x[0] for x in residuals], dtype=float)
    v = np.array([x[1] for x in residuals], dtype=float)
    if not (np.all(np.isfinite(d)) and np.all(np.isfinite(v)) and np.all(v >= 0)):
        raise InputError("discrepancy fit: residuals and variances must be finite, variances >= 0.")

    def negative_log_likelihood(sigma):
        total = v + sigma * sigma + 1e-12
        return float(0.5 * np.sum(d * d / total + np.log(total)))

    best = minimize_scalar(negative_log_likelihood, bounds=(0.0, MAX_SIGMA), method="bounded",
                           options={"xatol": 1e-4})
    sigma = float(best.x)
    # the bounded search does not test the end point 0 itself: no discrepancy where that is as likely
    return 0.0 if negative_log_likelihood(0.0) <= negative_log_likelihood(sigma) else sigma


def discrepancy_band(values, weights, sigma, level=0.90):
    """Median and central band of the predictive values times exp(sigma z), z over a fixed normal-quantile grid.

    Returns (median, low, high) in the values' unit; sigma = 0 gives :func:`memstribo.laboratory.predict.band`'s.
    """
    from scipy.stats import norm

    from memstribo.laboratory.predict import band

    v = np.asarray(values, dtype=float)
    if v.ndim == 1:
        v = v[:, None]
    w = np.ones(v.shape[0]) if weights is None else np.asarray(weights, dtype=float)
    if not sigma > 0:
        return band(v, w, level)
    z = norm.ppf((np.arange(DISCREPANCY_GRID) + 0.5) / DISCREPANCY_GRID)
    spread = v[:, :, None] * np.exp(sigma * z)[None, None, :]
    return band(spread.reshape(v.shape[0], -1), w, level)


def discrepancy_sigmas(train, values, weights):
    """sigma per quantity on the training rows (pooled where a quantity has fewer than MIN_ROWS)."""
    residuals = dict(zip((r.id for r in train), _residuals(train, values, weights)))
    pooled = fit_discrepancy(list(residuals.values()))
    out = {"pooled": pooled}
    for q in SCORED_QUANTITIES:
        mine = [residuals[r.id] for r in train if r.quantity == q]
        out[q] = fit_discrepancy(mine) if len(mine) >= MIN_ROWS else pooled
    return out


def _fold_weights(train, values, sigmas=None):
    from memstribo.laboratory.calibration import importance_weights, log_likelihood

    n = np.asarray(next(iter(values.values()))).shape[0]
    if not train:
        return np.full(n, 1.0 / n)
    extra = None if sigmas is None else [sigmas[r.quantity] for r in train]
    return importance_weights(log_likelihood(train, [values[r.id] for r in train], discrepancy=extra))


@cites("kennedy_ohagan_2001")
def loso_coverage(rows, values, level=0.90, confidence=0.95) -> dict:
    """Leave-one-source-out coverage of the ``level`` bands, without and with the model discrepancy.

    Parameters
    ----------
    rows : list of Measurement
    values : dict
        Row id -> predicted values over the prior samples, shape (n_samples, n_realisations) (None: not predicted).
    level, confidence : float
        The band's central probability and the coverage interval's level.

    Returns
    -------
    dict
        ``folds`` (per group: ``group``, ``train`` (count), ``ess``, ``sigma`` {quantity: sigma}), ``rows`` (per
        scored row: ``id``, ``group``, ``quantity``, ``measured``, ``band`` (median, low, high), ``inside``,
        ``band_discrepancy``, ``inside_discrepancy``), ``without`` and ``with`` (:func:`coverage_summary`),
        ``sigma_all`` (the discrepancy fitted on every row), ``trained_only`` (ids only trained on, with the fit).
    """
    from memstribo.laboratory.calibration import effective_sample_size

    usable = [r for r in rows if scoreable(r, values.get(r.id))]
    scored = [r for r in usable if not r.design_target and not (r.fitted_by and not r.calibration)]
    if not usable:
        raise InputError("no row can be cross-validated: none is predicted with a value and a scatter.")
    folds, results = [], []
    for group in sorted({r.source_group for r in scored}):
        train = [r for r in usable if r.source_group != group]
        w0 = _fold_weights(train, values)
        sigmas = discrepancy_sigmas(train, values, w0) if train else {q: 0.0 for q in SCORED_QUANTITIES}
        w1 = _fold_weights(train, values, sigmas)
        folds.append({"group": group, "train": len(train), "ess": effective_sample_size(w0),
                      "ess_discrepancy": effective_sample_size(w1), "sigma": sigmas})
        for r in (r for r in scored if r.source_group == group):
            plain = discrepancy_band(values[r.id], w0, 0.0, level)
            wide = discrepancy_band(values[r.id], w1, sigmas[r.quantity], level)
            results.append({"id": r.id, "group": group, "quantity": r.quantity, "measured": r.value,
                            "band": plain, "inside": bool(plain[1] <= r.value <= plain[2]),
                            "band_discrepancy": wide, "inside_discrepancy": bool(wide[1] <= r.value <= wide[2])})
    w_all = _fold_weights(usable, values)
    return {"folds": folds, "rows": results, "level": level,
            "without": coverage_summary([x["inside"] for x in results], level, confidence),
            "with": coverage_summary([x["inside_discrepancy"] for x in results], level, confidence),
            "sigma_all": discrepancy_sigmas(usable, values, w_all),
            "trained_only": [(r.id, r.fitted_by if r.fitted_by and not r.calibration else "design target")
                             for r in usable if r not in scored]}


def coverage_summary(flags, level=0.90, confidence=0.95) -> dict:
    """``inside``, ``rows``, ``coverage`` and its Wilson ``interval`` (at ``confidence``) against the nominal ``level``."""
    from memstribo.uncertainty.intervals import binomial_interval

    k, n = int(sum(bool(f) for f in flags)), len(flags)
    interval = tuple(binomial_interval(k, n, confidence)) if n else (math.nan, math.nan)
    return {"inside": k, "rows": n, "coverage": k / n if n else math.nan, "interval": interval,
            "nominal": level, "confidence": confidence}
