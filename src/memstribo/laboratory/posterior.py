"""The gear's verdict under the posterior of the laboratory (issue 37 item 6, MODEL 7e).

``memstribo mesh --uncertainty N --calibration FILE`` samples the uncertain constants from their priors
(:func:`memstribo.uncertainty.study.uncertainty_study`) and re-weights the same samples by what the laboratory
says about them (importance sampling: no new cycle is solved):

- a measurements TOML (``[[measurement]]`` rows): each point's constants predict every row that the model can
  predict (one roughness realisation per point, :func:`memstribo.laboratory.predict.row_values`), and the weight
  is the row likelihood of :func:`memstribo.laboratory.calibration.log_likelihood`;
- a calibrated parameter set (``[posterior.NAME]`` tables with ``median``, ``p05``, ``p95``, as written by
  ``python -m memstribo.laboratory``): the weight is the density ratio of that posterior (log-normal through the
  median and the 90 % range) to the prior of the study, constant by constant.

The posterior P(stiction) is the weighted share of sticking samples; its interval is Wilson's at the Kish
effective sample size (sum w)^2 / sum w^2 (Kish 1965) of the weights, so that a posterior resting on few samples
says so. Where the rows are measurements, each row's own weights say which measurements moved the verdict.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["calibration_kind", "row_weights", "posterior_set_weights", "weighted_probability", "gear_posterior",
           "posterior_notes"]

#: the normal quantile of the 95th percentile (a 90 % central range is +-1.645 sd)
Z95 = 1.6448536269514722


def calibration_kind(path) -> tuple[str, dict]:
    """("measurements", document) or ("posterior set", document) of a --calibration file; InputError otherwise."""
    file = Path(path)
    if not file.is_file():
        raise InputError(f"--calibration {path}: no such file (a measurements TOML or a calibrated parameter set).")
    try:
        data = tomllib.loads(file.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise InputError(f"--calibration {path}: not valid TOML ({error}).") from None
    if data.get("measurement"):
        return "measurements", data
    if data.get("posterior"):
        return "posterior set", data
    raise InputError(f"--calibration {path}: holds neither [[measurement]] rows nor [posterior.NAME] tables (a "
                     "calibrated parameter set written by 'python -m memstribo.laboratory').")


def _constants(points):
    from memstribo.parameters.definitions import SPECS

    return [{k: v for k, v in constants.items() if k in SPECS} for _, constants in points]


@cites("kish_1965")
def row_weights(rows, points, calibration_coating="OTS", seed=20260528, discrepancy=True) -> dict:
    """Per usable row, the log-likelihood of each study point's constants; rows the model cannot predict are listed.

    With ``discrepancy`` the likelihood carries the model discrepancy of :mod:`memstribo.laboratory.scoring`
    (a log-normal sigma per quantity, fitted by maximum likelihood on these rows over the prior samples): a model
    known to miss by a factor does not let one row's tight scatter pick a single sample.

    Returns
    -------
    dict
        ``loglik`` {row id: ndarray (n_points,)}, ``used`` (row ids), ``skipped`` [(id, reason)], ``sigma``
        {quantity: discrepancy sigma} (empty without ``discrepancy``).
    """
    from memstribo.laboratory.calibration import log_likelihood
    from memstribo.laboratory.predict import row_values
    from memstribo.laboratory.scoring import SCORED_QUANTITIES, discrepancy_sigmas

    samples = _constants(points)
    loglik, skipped = {}, []
    for row in rows:
        if row.same_as is not None:
            skipped.append((row.id, f"the same measurement as {row.same_as}"))
            continue
        if row.quantity not in SCORED_QUANTITIES or row.relative_sd() is None:
            skipped.append((row.id, "no value with a scatter to weigh the constants with"))
            continue
        values, case = row_values(row, samples, 1, calibration_coating, seed)
        if values is None:
            skipped.append((row.id, case))
            continue
        loglik[row.id] = values
    used = [r for r in rows if r.id in loglik]
    sigma = discrepancy_sigmas(used, loglik, np.ones(len(samples))) if discrepancy and used else {}
    for row in used:
        loglik[row.id] = log_likelihood([row], [loglik[row.id]], discrepancy=[sigma.get(row.quantity, 0.0)])
    return {"loglik": loglik, "used": [r.id for r in used], "skipped": skipped, "sigma": sigma}


def _prior_log_density(prior, x):
    """ln of the prior density at x (central difference of its CDF in ln x)."""
    h = 1e-4
    p = (prior.cdf(x * math.exp(h)) - prior.cdf(x * math.exp(-h))) / (2.0 * h * x)
    return math.log(p) if p > 0 else -math.inf


def posterior_set_weights(document, points, priors) -> tuple[np.ndarray, list]:
    """Weights of the study points under a calibrated set's ``[posterior.NAME]`` (log-normal through its median and
    90 % range) over the study's priors. Returns (weights, names used); constants the study does not sample are
    listed as not used."""
    from memstribo.laboratory.calibration import importance_weights

    log_w = np.zeros(len(points))
    used = []
    for name, table in document["posterior"].items():
        if name not in priors:
            continue
        try:
            median, p05, p95 = (float(table[k]) for k in ("median", "p05", "p95"))
        except (KeyError, TypeError, ValueError):
            raise InputError(f"[posterior.{name}] needs median, p05 and p95 (numbers).") from None
        if not (0 < p05 <= median <= p95):
            raise InputError(f"[posterior.{name}]: need 0 < p05 <= median <= p95, got {p05}, {median}, {p95}.")
        s = max(math.log(p95 / p05) / (2.0 * Z95), 1e-6)
        for j, (_, constants) in enumerate(points):
            x = float(constants[name])
            log_w[j] += -0.5 * (math.log(x / median) / s) ** 2 - math.log(s * x) - _prior_log_density(priors[name], x)
        used.append(name)
    if not used:
        raise InputError("the calibrated set's [posterior.NAME] constants are none of the study's sampled constants "
                         f"({', '.join(priors)}): the posterior cannot move the verdict.")
    finite = np.where(np.isfinite(log_w), log_w, -np.inf)
    if not np.isfinite(finite).any():
        raise InputError("no study sample lies where the calibrated posterior has weight.")
    return importance_weights(np.where(np.isfinite(finite), finite, finite[np.isfinite(finite)].min() - 1e3)), used


@cites("wilson_1927", "kish_1965")
def weighted_probability(flags, weights, confidence=0.95) -> dict:
    """Weighted share of ``flags`` with Wilson's interval at the Kish effective sample size.

    Returns ``probability``, ``ci`` [low, high], ``effective_samples`` and ``text``.
    """
    from memstribo.laboratory.calibration import effective_sample_size
    from memstribo.uncertainty.intervals import wilson_interval

    f = np.asarray(flags, dtype=float)
    w = np.asarray(weights, dtype=float)
    if f.shape != w.shape or not f.size:
        raise InputError("weighted_probability needs one weight per flag (at least one).")
    p = float(np.sum(w * f) / np.sum(w))
    p = 0.0 if p < 1e-12 else 1.0 if p > 1.0 - 1e-12 else p  # round-off of the weighted sum
    ess = effective_sample_size(w)
    low, high = wilson_interval(min(max(p, 0.0), 1.0), ess, confidence)
    text = f"{100 * p:.0f} % ({100 * confidence:.0f} % CI {100 * low:.0f}–{100 * high:.0f} %, effective samples {ess:.1f})"
    return {"probability": p, "ci": [low, high], "effective_samples": ess, "text": text}


def _flags(summaries, key):
    """Per sample: stuck (1), free (0), or None where the sample failed or the cycle lacks the verdict."""
    return [None if s.get("failed") or key not in s else bool(s[key]) for s in summaries]


def _probabilities(summaries, weights, confidence):
    out = {}
    for key, name in (("stiction", "stiction"), ("startup_stiction", "startup_stiction")):
        flags = _flags(summaries, key)
        keep = [i for i, f in enumerate(flags) if f is not None]
        if not keep:
            continue
        out[name] = weighted_probability([flags[i] for i in keep], np.asarray(weights)[keep], confidence)
    return out


def gear_posterior(path, points, summaries, priors, coating="OTS", confidence=0.95) -> dict:
    """P(stiction) and P(start-up stiction) of the study's samples under the prior and under the posterior of FILE.

    Parameters
    ----------
    path : str or Path
        A measurements TOML or a calibrated parameter set.
    points : list of (int, dict)
        The study's (realisation, constants) points.
    summaries : list of dict
        The cycle summary of each point (``stiction``, ``startup_stiction``, ``failed``).
    priors : Mapping[str, Prior]
        The study's priors (for a calibrated set's density ratio).
    coating : str
        The coating the ``coating_*`` constants stand for.

    Returns
    -------
    dict
        ``calibration`` (file and kind), ``prior`` and ``posterior`` ({stiction, startup_stiction}: each
        :func:`weighted_probability`), ``posterior_effective_samples``, ``rows_used``, ``rows_skipped``, and for a
        measurements file ``moved_by`` (per row: id, P(stiction) under that row alone, its shift from the prior,
        effective samples), largest shift first.
    """
    from memstribo.laboratory.calibration import effective_sample_size, importance_weights

    if len(points) != len(summaries) or not points:
        raise InputError("gear_posterior needs one summary per study point (at least one).")
    kind, document = calibration_kind(path)
    n = len(points)
    prior = _probabilities(summaries, np.full(n, 1.0 / n), confidence)
    out = {"calibration": {"file": str(path), "kind": kind}, "prior": prior, "rows_used": [], "rows_skipped": [],
           "moved_by": []}
    if kind == "posterior set":
        weights, used = posterior_set_weights(document, points, priors)
        out["rows_used"] = [f"[posterior.{name}]" for name in used]
    else:
        from memstribo.laboratory.data import load_measurements

        rows = load_measurements(path)
        found = row_weights(rows, points, coating)
        out["rows_skipped"] = found["skipped"]
        if not found["used"]:
            raise InputError(f"--calibration {path}: the model predicts none of its rows ("
                             + "; ".join(f"{i}: {why}" for i, why in found["skipped"]) + ").")
        out["rows_used"] = found["used"]
        out["discrepancy"] = {q: found["sigma"][q] for q in {r.quantity for r in rows if r.id in found["used"]}}
        weights = importance_weights(sum(found["loglik"].values()))
        base = prior.get("stiction", {}).get("probability")
        for row_id, ll in found["loglik"].items():
            alone = _probabilities(summaries, importance_weights(ll), confidence).get("stiction")
            if alone is None or base is None:
                continue
            out["moved_by"].append({"id": row_id, "stiction_probability": alone["probability"],
                                    "shift": alone["probability"] - base,
                                    "effective_samples": alone["effective_samples"]})
        out["moved_by"].sort(key=lambda x: -abs(x["shift"]))
    out["posterior"] = _probabilities(summaries, weights, confidence)
    out["posterior_effective_samples"] = effective_sample_size(weights)
    return out


def posterior_notes(post) -> list[str]:
    """The readable lines: prior and posterior side by side, the effective sample size, what moved it."""
    lines = [f"  under the laboratory's posterior ({post['calibration']['kind']} {post['calibration']['file']}; "
             f"importance weights, effective samples {post['posterior_effective_samples']:.1f} of the study's):"]
    for key, label in (("stiction", "P(stiction)"), ("startup_stiction", "P(start-up stiction)")):
        if key in post["prior"] and key in post["posterior"]:
            lines.append(f"    {label:<22} prior {post['prior'][key]['text']}  |  posterior {post['posterior'][key]['text']}")
    if post.get("discrepancy"):
        lines.append("    likelihood with the model discrepancy (log-normal sigma per quantity, fitted on the rows): "
                     + ", ".join(f"{q} {v:.2f}" for q, v in sorted(post["discrepancy"].items())))
    if post["moved_by"]:
        lines.append("    moved by (P(stiction) under each row alone, shift from the prior): "
                     + "; ".join(f"{m['id']} {100 * m['stiction_probability']:.0f} % ({100 * m['shift']:+.0f})"
                                 for m in post["moved_by"][:6]))
    if post["rows_skipped"]:
        lines.append(f"    {len(post['rows_skipped'])} row(s) not used: "
                     + "; ".join(f"{i} ({why[:80]})" for i, why in post["rows_skipped"][:4]))
    if post["posterior_effective_samples"] < 5:
        lines.append("    the posterior rests on fewer than 5 effective samples: its interval is wide; add samples "
                     "(--uncertainty N) before reading it")
    return lines
