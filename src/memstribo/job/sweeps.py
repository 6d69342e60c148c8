"""The run's sweeps as tables: summaries over a swept value as a Dataset, its columns, and a caption's sentence on a
COF above 1 (used by :mod:`memstribo.job.chain`)."""

from __future__ import annotations

import numpy as np

__all__ = ["sweep_dataset", "columns", "cof_above_one"]


def sweep_dataset(dimension, values, unit, long_name, summaries):
    """Summaries (:func:`memstribo.simulations.mesh.summarize`) of a sweep as a Dataset over ``dimension``."""
    import xarray as xr

    from memstribo.quantities import attrs
    from memstribo.simulations.mesh import SUMMARY_KEYS
    data = {key: (dimension, np.array([float(s[key]) for s in summaries], dtype=float), attrs(key))
            for key in SUMMARY_KEYS
            if all(key in s and isinstance(s[key], (int, float, np.number)) for s in summaries)}
    return xr.Dataset(data, coords={dimension: (dimension, np.asarray(values, dtype=float),
                                                {"units": unit, "long_name": long_name})})


def cof_above_one(dataset, x, x_text) -> str:
    """A caption's sentence saying why a sweep's mean COF exceeds 1 (e.g. 2.41 at 25 µN), or ""."""
    if "cof_mean" not in dataset:
        return ""
    cof = np.asarray(dataset["cof_mean"].values, dtype=float)
    if not np.any(np.isfinite(cof)) or np.nanmax(cof) <= 1.0:
        return ""
    i = int(np.nanargmax(cof))
    parts = [(name, float(dataset[name].values[i])) for name in ("cof_chemical", "cof_vdw", "cof_elastic")
             if name in dataset]
    largest = max(parts, key=lambda p: p[1]) if parts else None
    share = (f"; {largest[0].replace('cof_', '').replace('vdw', 'van der Waals')} bonds give {largest[1]:.3g} of it"
             if largest else "")
    return (f" The mean COF reaches {cof[i]:.3g} at {x_text(float(dataset[x].values[i]))}{share}. A COF above 1 is "
            "no error: the apparent COF is the energy of the bonds broken per sliding distance divided by the load "
            "F_N + F_adh (Eq. 3-7), and the number of bonds (set by the contact area) falls more slowly than the load, "
            "so at light loads the ratio exceeds 1 (the thesis's COF also falls with load, 4.9.3).")


def columns(dataset) -> dict[str, list]:
    """Every numeric coordinate and variable of ``dataset`` as a list of floats (the run's JSON summary)."""
    return {name: [float(v) for v in dataset[name].values] for name in list(dataset.coords) + list(dataset.data_vars)
            if dataset[name].dtype.kind in "fiub"}
