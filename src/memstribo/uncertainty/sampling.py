"""Low-discrepancy designs over the priors (MODEL 7d): scrambled, seeded Sobol' or Latin-hypercube points."""

from __future__ import annotations

from collections.abc import Mapping

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["sample_constants", "unit_design", "MAX_SAMPLES"]

#: most constant sets one design may hold (each a cycle or a rescaling; far beyond any study's budget)
MAX_SAMPLES = 1 << 20


def _check_fixed(priors: Mapping, fixed) -> set:
    names = list(fixed.keys() if isinstance(fixed, Mapping) else fixed)
    seen = set()
    for name in names:
        if name in seen:
            raise InputError(f"the constant '{name}' is named twice among the fixed constants.")
        seen.add(name)
        if name not in priors:
            raise InputError(f"'{name}' is fixed but has no prior: only constants with a prior are sampled "
                             f"({', '.join(priors) or 'none here'}); a measured input is never sampled, and "
                             "--set NAME=VALUE fixes a constant at a value.")
    return seen


@cites("owen_1998")
def unit_design(dimensions: int, n: int, seed: int = 0):
    """``n`` points in the unit cube ``[0, 1)^dimensions`` [-], shape (n, dimensions).

    A scrambled Sobol' sequence (:class:`scipy.stats.qmc.Sobol`, Owen scrambling) when ``n`` is a
    power of two, whose first ``n/2`` points are the design of ``n/2`` (a doubled design extends
    the smaller one); a scrambled Latin hypercube (:class:`scipy.stats.qmc.LatinHypercube`)
    otherwise. Seeded: the same ``seed`` gives the same points.
    """
    import numpy as np
    from scipy.stats import qmc

    if isinstance(n, bool) or int(n) != n or n < 1:
        raise InputError(f"the number of samples must be a whole number >= 1, got {n!r}.")
    n = int(n)
    if n > MAX_SAMPLES:
        raise InputError(f"{n} samples: at most {MAX_SAMPLES} (the design would not fit in memory).")
    if dimensions == 0:
        return np.zeros((n, 0))
    if n & (n - 1) == 0:
        return qmc.Sobol(dimensions, scramble=True, seed=seed).random_base2(n.bit_length() - 1)
    return qmc.LatinHypercube(dimensions, scramble=True, seed=seed).random(n)


def sample_constants(priors: Mapping, n: int, seed: int = 0, fixed=()) -> list[dict[str, float]]:
    """``n`` sets of the uncertain constants, a low-discrepancy design over their priors.

    Parameters
    ----------
    priors : Mapping[str, Prior]
        From :func:`memstribo.uncertainty.priors.priors_for`.
    n : int
        Number of constant sets [-] (a power of two gives a Sobol' design, see :func:`unit_design`).
    seed : int
        Seed of the scrambling.
    fixed : iterable of str, or Mapping
        Constants not to sample (names, or a name -> value mapping whose names count); each must
        have a prior.

    Returns
    -------
    list of dict
        ``[{name: value [SI]}]`` for the sampled constants, in the order of ``priors``.

    Raises
    ------
    InputError
        ``n`` below 1 or above :data:`MAX_SAMPLES`, a fixed constant without a prior or named twice.
    """
    fixed_names = _check_fixed(priors, fixed)
    names = [name for name in priors if name not in fixed_names]
    u = unit_design(len(names), n, seed)
    columns = {name: priors[name].ppf(u[:, j]) for j, name in enumerate(names)}
    return [{name: float(columns[name][i]) for name in names} for i in range(u.shape[0])]
