"""Confidence intervals of a stiction probability estimated from a finite number of samples (MODEL 7d).

"0 of 16 realisations stick" is compatible with a true probability up to about 19 % (Wilson score
interval at 95 %): no probability without its interval, in text, JSON, report and maps.
"""

from __future__ import annotations


from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["binomial_interval", "clustered_interval", "wilson_interval", "format_probability", "ensemble_interval",
           "half_width", "sample_probability", "METHODS"]

#: interval methods: memstribo's name -> scipy.stats.BinomTestResult.proportion_ci's
METHODS = {"wilson": "wilson", "clopper-pearson": "exact", "exact": "exact", "wilsoncc": "wilsoncc"}


def _check(k, n, confidence):
    for name, value in (("k", k), ("n", n)):
        if isinstance(value, bool) or not float(value).is_integer():
            raise InputError(f"binomial interval: {name} must be a whole number, got {value!r}.")
    k, n = int(k), int(n)
    if n < 1:
        raise InputError(f"binomial interval: n (the number of samples) must be at least 1, got {n}.")
    if not 0 <= k <= n:
        raise InputError(f"binomial interval: k = {k} must lie between 0 and n = {n}.")
    if not 0.0 < float(confidence) < 1.0:
        raise InputError(f"binomial interval: confidence must lie strictly between 0 and 1, got {confidence!r}.")
    return k, n


@cites("wilson_1927", "clopper_pearson_1934")
def binomial_interval(k, n, confidence=0.95, method="wilson") -> tuple[float, float]:
    """Confidence interval of a probability from ``k`` events in ``n`` independent samples [-].

    Parameters
    ----------
    k : int
        Samples that stick [-].
    n : int
        Samples [-], >= 1.
    confidence : float
        Confidence level in (0, 1) [-] (default 0.95).
    method : {"wilson", "clopper-pearson", "wilsoncc"}
        Wilson score interval (Wilson 1927; default: 0 of 16 gives 0-0.194), the exact
        Clopper-Pearson interval (1934; 0 of 16 gives 0-0.206), or Wilson with continuity correction.
        Computed by :meth:`scipy.stats.binomtest(k, n).proportion_ci`.

    Returns
    -------
    (float, float)
        Lower and upper bound of the probability [-].
    """
    from scipy.stats import binomtest

    k, n = _check(k, n, confidence)
    if method not in METHODS:
        raise InputError(f"binomial interval: unknown method {method!r}; allowed: {', '.join(METHODS)}.")
    ci = binomtest(k, n).proportion_ci(confidence_level=float(confidence), method=METHODS[method])
    low, high = float(ci.low), float(ci.high)
    return (0.0 if k == 0 else low), (1.0 if k == n else high)


@cites("wilson_1927")
def wilson_interval(p, n, confidence=0.95) -> tuple[float, float]:
    """Wilson score interval of a proportion ``p`` [-] from ``n`` samples [-], ``n`` not necessarily whole.

    ``(p + z^2/2n -+ z sqrt(p (1 - p)/n + z^2/4n^2)) / (1 + z^2/n)`` with ``z`` the normal quantile of
    ``(1 + confidence)/2`` (Wilson 1927); for a whole ``n`` it is :func:`binomial_interval`'s (to round-off).
    An effective sample count (:func:`clustered_interval`) is not whole. Returns (low, high) [-].
    """
    from scipy.stats import norm

    p, n = float(p), float(n)
    if not n > 0.0:
        raise InputError(f"Wilson interval: n must be positive, got {n!r}.")
    if not 0.0 <= p <= 1.0:
        raise InputError(f"Wilson interval: p must lie in [0, 1], got {p!r}.")
    if not 0.0 < float(confidence) < 1.0:
        raise InputError(f"Wilson interval: confidence must lie strictly between 0 and 1, got {confidence!r}.")
    z = float(norm.ppf(0.5 + 0.5 * float(confidence)))
    scale = 1.0 + z * z / n
    centre = (p + z * z / (2.0 * n)) / scale
    half = z / scale * (p * (1.0 - p) / n + z * z / (4.0 * n * n)) ** 0.5
    return (0.0 if p == 0.0 else max(0.0, centre - half)), (1.0 if p == 1.0 else min(1.0, centre + half))


@cites("wilson_1927", "kish_1965")
def clustered_interval(flags, clusters, confidence=0.95) -> dict:
    """Interval of a probability from samples of which some share a cluster (a contact solution), honestly widened.

    Samples that share a cluster (in the uncertainty study: a roughness realisation and the constants of one
    contact solve, with their own bond energies) are correlated, and ``n`` of them carry less information
    than ``n`` independent ones. The design effect (Kish 1965) is the ratio of the variance of the estimate
    over clusters, ``n_c/(n_c - 1) sum_i (y_i - p m_i)^2 / n^2`` (``y_i`` events among the ``m_i`` samples of
    cluster ``i``; the cluster-robust variance of a ratio estimate) to the binomial ``p (1 - p) / n``, never
    below 1; where every sample agrees (``p`` = 0 or 1) it is the worst case ``n / n_c`` (every cluster one
    sample's worth). The interval is then Wilson's (:func:`wilson_interval`) with ``n / deff`` samples.

    Parameters
    ----------
    flags : sequence of bool or 0/1
        The event (stiction) per sample [-].
    clusters : sequence of hashable
        The cluster of each sample (the same value: the same contact solution).
    confidence : float
        Level [-].

    Returns
    -------
    dict
        ``ci`` ([low, high], [-]), ``design_effect`` [-], ``effective_samples`` [-], ``clusters`` [-].
        Where no cluster holds two samples: :func:`binomial_interval`, design effect 1.
    """
    import numpy as np

    y = np.asarray([1.0 if f else 0.0 for f in flags])
    n = y.size
    if n < 1 or len(clusters) != n:
        raise InputError(f"clustered interval: {n} samples and {len(clusters)} cluster labels (need >= 1, equal).")
    labels: dict = {}
    index = np.array([labels.setdefault(c, len(labels)) for c in clusters])
    n_c = len(labels)
    if n_c == n:
        k = int(y.sum())
        return {"ci": list(binomial_interval(k, n, confidence)), "design_effect": 1.0, "effective_samples": float(n),
                "clusters": n_c}
    p = float(y.mean())
    if n_c == 1:
        deff = float(n)
    elif 0.0 < p < 1.0:
        events = np.bincount(index, weights=y, minlength=n_c)
        sizes = np.bincount(index, minlength=n_c)
        variance = n_c / (n_c - 1.0) * float(((events - p * sizes) ** 2).sum()) / n ** 2
        deff = max(1.0, variance / (p * (1.0 - p) / n))
    else:
        deff = n / n_c
    deff = min(deff, float(n))
    return {"ci": list(wilson_interval(p, n / deff, confidence)), "design_effect": deff,
            "effective_samples": n / deff, "clusters": n_c}


def half_width(k, n, confidence=0.95, method="wilson") -> float:
    """Half the width of :func:`binomial_interval` [-] (the adaptive study stops below 0.05)."""
    low, high = binomial_interval(k, n, confidence, method)
    return 0.5 * (high - low)


def _percent(x: float) -> str:
    p = 100.0 * x
    if p == 0.0 or p == 100.0:
        return f"{p:.0f}"
    if p < 1.0 or p > 99.0:
        return f"{p:.1g}" if p < 1.0 else f"{p:.3g}"
    return f"{p:.0f}"


def format_probability(k, n, confidence=0.95, method="wilson", interval=None) -> str:
    """``"0 of 16 (95 % CI 0–19 %)"``: the count and its confidence interval in percent.

    ``interval``: a (low, high) computed elsewhere (the study's, widened by failed samples);
    default :func:`binomial_interval`.
    """
    k, n = _check(k, n, confidence)
    low, high = interval if interval is not None else binomial_interval(k, n, confidence, method)
    level = 100.0 * float(confidence)
    level_text = f"{level:.0f}" if float(level).is_integer() else f"{level:g}"
    return f"{k} of {n} ({level_text} % CI {_percent(low)}–{_percent(high)} %)"


def ensemble_interval(summary, confidence=0.95, method="wilson") -> dict:
    """The ensemble verdict (:func:`memstribo.simulations.mesh.ensemble_summary`) with its interval.

    Parameters
    ----------
    summary : dict
        With ``per_realisation`` (each with ``stiction``) or ``realisations`` and
        ``stiction_probability``.

    Returns
    -------
    dict
        A copy of ``summary`` with ``stiction_count`` [-], ``stiction_probability_ci`` ([low, high],
        [-]) and ``stiction_probability_text`` (``"0 of 16 (95 % CI 0–19 %)"``).
    """
    out = dict(summary)
    if summary.get("per_realisation"):
        flags = [bool(r["stiction"]) for r in summary["per_realisation"]]
        n, k = len(flags), sum(flags)
    else:
        n = int(summary["realisations"])
        k = int(round(float(summary["stiction_probability"]) * n))
    if n < 1:
        raise InputError("ensemble_interval: the ensemble has no realisation.")
    low, high = binomial_interval(k, n, confidence, method)
    out["stiction_count"] = k
    out["stiction_probability_ci"] = [low, high]
    out["stiction_probability_text"] = format_probability(k, n, confidence, method)
    return out


def sample_probability(summaries, confidence=0.95, key="stiction") -> dict:
    """Count, estimate and interval of P(stiction) over the uncertainty study's sample summaries.

    ``key``: ``stiction``, the running verdict, or ``startup_stiction``. Samples that share a cycle (``cycle_id``: a
    grouped design, fixed solve constants) widen it by their design effect (:func:`clustered_interval`); a failed
    sample (``failed``) may stick or not, and the interval covers both. Returns ``count``, ``samples``, ``failed``,
    ``probability``, ``ci`` ([low, high]), ``design_effect``, ``effective_samples`` [-] and ``text``.
    """

    n = len(summaries)
    failed = sum(1 for s in summaries if s.get("failed"))
    k = sum(1 for s in summaries if not s.get("failed") and s[key])
    clusters = [s.get("cycle_id") for s in summaries]
    deff = 1.0
    if None in clusters or len(set(clusters)) == n:
        low = binomial_interval(k, n, confidence)[0]
        high = binomial_interval(k + failed, n, confidence)[1]  # a failed point may stick or not: both covered
    else:
        low_flags = [bool(not s.get("failed") and s[key]) for s in summaries]
        high_flags = [bool(s.get("failed") or s[key]) for s in summaries]
        below, above = clustered_interval(low_flags, clusters, confidence), \
            clustered_interval(high_flags, clusters, confidence)
        low, high = below["ci"][0], above["ci"][1]
        deff = max(below["design_effect"], above["design_effect"])
    estimate = k / (n - failed) if n > failed else float("nan")
    shared = f", design effect {deff:.3g} (samples share contact solves)" if deff > 1.0 else ""
    return {"count": k, "samples": n, "failed": failed, "probability": estimate, "ci": [low, high],
            "design_effect": deff, "effective_samples": n / deff,
            "text": format_probability(k, n, confidence, interval=(low, high))
            + (f", {failed} failed" if failed else "") + shared}
