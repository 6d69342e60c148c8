"""The widths of the asperities cut by a level (thesis 3-26): the one roughness statistic of the thesis that
SurfaceTopography does not compute."""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites
from memstribo.surfaces.profile import _as_xz, _heights


@cites("thesis")
def asperity_widths(profile, level, x=None):
    """Widths [m] of the asperities cut at ``level``: the connected runs where z > level (3-26 in [1]).

    Each width runs from the up-crossing to the down-crossing of the level, both found by
    linear interpolation between the neighbouring points. Runs that touch either end of the
    profile are cut off by the scan and are left out.

    Parameters
    ----------
    profile : Profile or array_like
        Profile, or heights z [m] (then ``x`` [m]).
    level : float
        Cut level [m], in the same frame as z (about the mean line for a levelled profile).
    x : array_like, optional
        Positions [m].

    Returns
    -------
    numpy.ndarray
        The widths [m] of the complete runs (possibly empty).
    """
    xs, z, _ = _as_xz(profile, x)
    _heights(z, 2, "asperity widths")
    above = z > level
    change = np.diff(above.astype(np.int8))
    ups = np.flatnonzero(change == 1)      # z[i] <= level < z[i+1]
    downs = np.flatnonzero(change == -1)   # z[i] > level >= z[i+1]
    if above[0]:
        downs = downs[1:]                  # the first run started before the scan
    n_runs = min(ups.size, downs.size)     # a run still open at the end has no down-crossing
    ups, downs = ups[:n_runs], downs[:n_runs]

    def crossing(i):
        return xs[i] + (level - z[i]) / (z[i + 1] - z[i]) * (xs[i + 1] - xs[i])

    return crossing(downs) - crossing(ups)


@cites("thesis")
def mean_asperity_width(profile, level, x=None):
    r"""Mean width of the asperities cut at ``level``, Eq. (3-26)/(4-3) in [1]: d = (1/n) sum d_i.

    Parameters
    ----------
    profile : Profile or array_like
        Profile, or heights z [m] (then ``x`` [m]).
    level : float
        Cut level [m].
    x : array_like, optional
        Positions [m].

    Returns
    -------
    float
        Mean width [m] of the complete runs where z > level (see :func:`asperity_widths`).

    Raises
    ------
    InputError
        If no complete asperity crosses the level (profile too short or level too high/low).
    """
    widths = asperity_widths(profile, level, x)
    if widths.size == 0:
        raise InputError(f"no complete asperity above the level {level:.4g} m: the profile is too short "
                         "for this statistic or the level is above the highest peak / below the deepest valley.")
    return float(widths.mean())
