"""The stiction verdict over independent roughness realisations: stiction probability and quantiles."""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError
from memstribo.simulations.mesh.cycle import simulate_mesh
from memstribo.simulations.mesh.verdict import summarize


#: Keys of one realisation in ``per_realisation`` of an ensemble.
REALISATION_KEYS = ("seed", "realisation", "stiction_margin", "cof_mean", "stiction", "mesh_efficiency")


def _ensemble_point(params, roughness, steps, coating, wear, realisation):
    summary = summarize(simulate_mesh(params, roughness, steps=steps, coating=coating, wear=wear,
                                      realisation=realisation))
    summary["realisation"] = realisation
    summary["seed"] = [int(params["roughness_seed"]), int(realisation)]
    return summary


def simulate_ensemble(params, roughness=None, *, realisations=None, steps=None, coating=None, wear=1.0,
                      client=None, progress=False):
    """The stiction verdict over independent roughness realisations (MODEL 7b).

    Each realisation is a meshing cycle (:func:`simulate_mesh`) with its own roughness lines
    (seeds ``(roughness_seed, realisation)``; the measured lines, where there are any, in
    realisation 0). With a ``dask.distributed`` ``client`` the realisations run as independent
    tasks on its workers; the result does not depend on how they were scheduled.

    Parameters
    ----------
    params, roughness, steps, coating, wear
        As for :func:`simulate_mesh`.
    realisations : int, optional
        Number of realisations (default the parameter ``realisations``).
    client : distributed.Client, optional
    progress : bool

    Returns
    -------
    dict
        ``realisations``, ``stiction_probability`` (fraction that sticks), ``stiction_margin_median``,
        ``_p05``, ``_p95`` [N], ``cof_mean_median``, ``_p05``, ``_p95``, ``mesh_efficiency_median``,
        ``per_realisation`` (list of dicts with the keys of :data:`REALISATION_KEYS`), and
        ``summaries`` (the full summary of every realisation, in order).
    """
    n = int(params["realisations"] if realisations is None else realisations)
    if n < 1:
        raise InputError(f"realisations must be at least 1, got {n}.")
    if client is not None:
        futures = client.map(_ensemble_point, [params] * n, [roughness] * n, [steps] * n, [coating] * n,
                             [wear] * n, list(range(n)), pure=False)
        summaries = client.gather(futures)
    else:
        iterator = range(n)
        if progress:
            from tqdm.auto import tqdm

            iterator = tqdm(iterator, desc="roughness realisations", unit="cycle")
        summaries = [_ensemble_point(params, roughness, steps, coating, wear, k) for k in iterator]
    return ensemble_summary(summaries)


def ensemble_summary(summaries) -> dict:
    """Stiction probability with its 95 % confidence interval and 5/50/95 % quantiles over realisation summaries.

    MODEL 7b and 7d: ``stiction_count`` of ``realisations`` stick; ``stiction_probability_ci`` is the Wilson
    interval of that fraction and ``stiction_probability_text`` says it in words ("0 of 16 (95 % CI 0–19 %)").
    """
    margins = np.array([s["stiction_margin"] for s in summaries])
    cofs = np.array([s["cof_mean"] for s in summaries])
    efficiency = np.array([s["mesh_efficiency"] for s in summaries])
    out = {"realisations": len(summaries),
           "stiction_probability": float(np.mean(margins < 0))}
    for name, values in (("stiction_margin", margins), ("cof_mean", cofs), ("mesh_efficiency", efficiency)):
        out[f"{name}_median"] = float(np.median(values))
        out[f"{name}_p05"] = float(np.quantile(values, 0.05))
        out[f"{name}_p95"] = float(np.quantile(values, 0.95))
    if all("startup_margin" in s for s in summaries):  # the start-up verdict (MODEL 7d)
        startup = np.array([s["startup_margin"] for s in summaries])
        out["startup_stiction_probability"] = float(np.mean(startup < 0))
        from memstribo.uncertainty.intervals import binomial_interval, format_probability

        count = int((startup < 0).sum())  # no probability without its interval (MODEL 7d)
        out["startup_stiction_count"] = count
        out["startup_stiction_probability_ci"] = list(binomial_interval(count, startup.size))
        out["startup_stiction_probability_text"] = format_probability(count, startup.size)
        out["startup_margin_median"] = float(np.median(startup))
        out["startup_margin_p05"] = float(np.quantile(startup, 0.05))
        out["startup_margin_p95"] = float(np.quantile(startup, 0.95))
    out["per_realisation"] = [{key: s[key] for key in REALISATION_KEYS} for s in summaries]
    out["summaries"] = list(summaries)
    from memstribo.uncertainty.intervals import ensemble_interval

    return ensemble_interval(out)  # no probability without its interval (MODEL 7d): count, 95 % CI, text
