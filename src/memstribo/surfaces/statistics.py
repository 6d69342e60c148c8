"""The ISO 4287 profile and ISO 25178 areal roughness parameters (Ra, Rq, Rsk, Rku, Rp, Rv, Rz, rms slope and
wavelength, the Abbott-Firestone curve) and the statistics records of a profile, a map and its line scans."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites
from memstribo.surfaces.profile import Profile, _as_xz, _heights, level_plane, level_profile


# --------------------------------------------------------------------------------------------
# height parameters (about the mean line)
# --------------------------------------------------------------------------------------------


@cites("thesis", "iso_4287")
def arithmetic_mean_height(z):
    r"""Ra, the arithmetic mean deviation from the mean line, Eq. (4-1) in [1].

    .. math:: R_a = \frac{1}{n}\sum_i |z_i - \bar z|

    Parameters
    ----------
    z : array_like or Profile
        Heights [m].

    Returns
    -------
    float
        Ra [m].
    """
    z = _heights(z, 1, "Ra")
    return float(np.mean(np.abs(z - z.mean())))


@cites("thesis", "iso_4287")
def rms_height(z):
    r"""Rq, the root mean square deviation from the mean line, Eq. (4-2) in [1].

    .. math:: R_q = \sqrt{\frac{1}{n}\sum_i (z_i - \bar z)^2}

    Parameters
    ----------
    z : array_like or Profile
        Heights [m], as in :func:`arithmetic_mean_height`.

    Returns
    -------
    float
        Rq [m].
    """
    z = _heights(z, 1, "Rq")
    return float(np.sqrt(np.mean((z - z.mean()) ** 2)))


@cites("iso_4287")
def skewness(z):
    """Rsk = mean((z - mean)^3) / Rq^3 [-] of heights z [m]; InputError for a flat profile."""
    z = _heights(z, 2, "Rsk")
    zc = z - z.mean()
    rq = np.sqrt(np.mean(zc ** 2))
    if rq == 0:
        raise InputError("skewness of a flat profile (Rq = 0) is undefined.")
    return float(np.mean(zc ** 3) / rq ** 3)


@cites("iso_4287")
def kurtosis(z):
    """Rku = mean((z - mean)^4) / Rq^4 [-] (3 for Gaussian heights); InputError for a flat profile."""
    z = _heights(z, 2, "Rku")
    zc = z - z.mean()
    rq2 = np.mean(zc ** 2)
    if rq2 == 0:
        raise InputError("kurtosis of a flat profile (Rq = 0) is undefined.")
    return float(np.mean(zc ** 4) / rq2 ** 2)


@cites("iso_4287")
def max_peak_height(z):
    """Rp, the highest peak above the mean line [m], of heights z [m]."""
    z = _heights(z, 1, "Rp")
    return float(z.max() - z.mean())


@cites("iso_4287")
def max_valley_depth(z):
    """Rv, the depth of the deepest valley below the mean line [m] (a positive number)."""
    z = _heights(z, 1, "Rv")
    return float(z.mean() - z.min())


@cites("iso_4287")
def max_height(z):
    """Rz = Rp + Rv [m] over the whole profile (no sampling lengths; ISO's Rt)."""
    z = _heights(z, 1, "Rz")
    return float(z.max() - z.min())


@cites("thesis", "iso_4287")
def rms_slope(profile, x=None, sample_spacing=None):
    r"""Rms slope Delta_q, Eq. (4-6) and (3-27) in [1].

    .. math:: \Delta_q = \sqrt{\frac{1}{n-1}\sum_{i=1}^{n-1} S_i^2}, \qquad
              S_i = \frac{z_{i+1} - z_i}{x_{i+1} - x_i}

    Parameters
    ----------
    profile : Profile or array_like
        Profile, or heights z [m] (then ``x`` [m] or ``sample_spacing`` [m]).
    x : array_like, optional
        Positions [m].
    sample_spacing : float, optional
        Uniform step [m] when neither a Profile nor ``x`` is given.

    Returns
    -------
    float
        Delta_q [-].
    """
    if not isinstance(profile, Profile) and x is None and sample_spacing is None:
        raise InputError("rms_slope needs x [m] or sample_spacing [m] with an array of heights.")
    xs, z, _ = _as_xz(profile, x, sample_spacing)
    _heights(z, 2, "the rms slope")
    slopes = np.diff(z) / np.diff(xs)
    return float(np.sqrt(np.sum(slopes ** 2) / (z.size - 1)))


@cites("thesis")
def rms_wavelength(rq, rms_slope_value):
    r"""Rms wavelength (mean spacing of asperities) lambda_q = 2 pi Rq / Delta_q, Eq. (4-5) in [1].

    Note: the thesis's printed lambda_q (58.4 nm, 64.35 nm) does not follow from its printed
    Rq and Delta_q (which give about 420 nm); memstribo keeps the formula (MODEL §1.3).

    Parameters
    ----------
    rq : float
        Rq [m].
    rms_slope_value : float
        Delta_q [-], > 0.

    Returns
    -------
    float
        lambda_q [m].
    """
    if not rms_slope_value > 0:
        raise InputError(f"lambda_q needs a positive rms slope (got {rms_slope_value!r}): the profile is flat.")
    return float(2.0 * math.pi * rq / rms_slope_value)


@cites("thesis", "iso_4287")
def bearing_area_curve(z, levels=None):
    """Abbott-Firestone (bearing area, material ratio) curve (Figure 3-18 in [1]).

    Parameters
    ----------
    z : array_like or Profile
        Heights [m] (about the mean line if you want levels relative to it).
    levels : array_like, optional
        Heights [m] at which to evaluate; default: every height, from the highest down.

    Returns
    -------
    material_ratio : numpy.ndarray
        Fraction [-] of the points at or above each level (0..1).
    levels : numpy.ndarray
        The levels [m].
    """
    z = _heights(z, 1, "the Abbott-Firestone curve")
    ordered = np.sort(z)
    if levels is None:
        levels = ordered[::-1]
        ratio = np.arange(1, z.size + 1) / z.size
        return ratio, levels
    levels = np.asarray(levels, dtype=float)
    ratio = (z.size - np.searchsorted(ordered, levels, side="left")) / z.size
    return ratio, levels


Ra = arithmetic_mean_height
Rq = rms_height
Rsk = skewness
Rku = kurtosis
Rp = max_peak_height
Rv = max_valley_depth
Rz = max_height


# --------------------------------------------------------------------------------------------
# statistics of a profile and of a map
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ProfileStatistics:
    """Roughness parameters of one levelled profile (ISO 4287; thesis 4.2.3).

    Attributes
    ----------
    Ra, Rq : float
        Arithmetic and root mean square deviation [m], (4-1), (4-2).
    Rsk, Rku : float
        Skewness and kurtosis [-].
    Rp, Rv, Rz : float
        Highest peak, deepest valley (positive) and their sum [m].
    rms_slope : float
        Delta_q [-], (4-6).
    lambda_q : float
        2 pi Rq / Delta_q [m], (4-5).
    n_points : int
        Number of points.
    sample_spacing : float
        Step [m] (mean step if not uniform).
    length : float
        Scan length [m] (see :attr:`Profile.length`).
    uniform : bool
        Whether the profile is uniformly sampled.
    """

    Ra: float
    Rq: float
    Rsk: float
    Rku: float
    Rp: float
    Rv: float
    Rz: float
    rms_slope: float
    lambda_q: float
    n_points: int
    sample_spacing: float
    length: float
    uniform: bool = True

    def to_dict(self) -> dict:
        """The fields as a dict (SI values)."""
        return dict(self.__dict__)


@cites("thesis", "iso_4287")
def profile_statistics(profile: Profile, level: bool = True) -> ProfileStatistics:
    """Roughness parameters of a profile after subtracting its least-squares line.

    Parameters
    ----------
    profile : Profile
        The profile (at least 3 points).
    level : bool
        Subtract the least-squares line first (default; the thesis's "after removing the
        overall profile slope").

    Returns
    -------
    ProfileStatistics
    """
    if not isinstance(profile, Profile):
        raise InputError("profile_statistics needs a Profile.")
    if profile.n_points < 3:
        raise InputError(f"profile '{profile.name}' has {profile.n_points} points; roughness statistics "
                         "after levelling need at least 3.")
    p = level_profile(profile) if level else profile
    z = p.z
    rq = rms_height(z)
    if rq == 0:
        raise InputError(f"profile '{profile.name}' is flat after levelling (Rq = 0): no roughness to describe.")
    slope = rms_slope(p)
    return ProfileStatistics(
        Ra=arithmetic_mean_height(z), Rq=rq, Rsk=skewness(z), Rku=kurtosis(z), Rp=max_peak_height(z),
        Rv=max_valley_depth(z), Rz=max_height(z), rms_slope=slope, lambda_q=rms_wavelength(rq, slope),
        n_points=p.n_points, sample_spacing=p.sample_spacing, length=p.length, uniform=p.is_uniform)


@dataclass(frozen=True)
class ArealStatistics:
    """Areal parameters of a plane-levelled map (ISO 25178-2).

    Attributes
    ----------
    Sa, Sq : float
        Arithmetic and root mean square height [m].
    Ssk, Sku : float
        Skewness and kurtosis [-].
    Sp, Sv, Sz : float
        Highest peak, deepest valley (positive) and their sum [m].
    """

    Sa: float
    Sq: float
    Ssk: float
    Sku: float
    Sp: float
    Sv: float
    Sz: float

    def to_dict(self) -> dict:
        return dict(self.__dict__)


@cites("iso_25178")
def areal_statistics(heights, dx=1.0, dy=1.0) -> ArealStatistics:
    """Sa, Sq, Ssk, Sku, Sp, Sv, Sz of a map after subtracting its least-squares plane.

    Parameters
    ----------
    heights : array_like
        Heights [m], shape (ny, nx).
    dx, dy : float
        Pixel sizes [m].

    Returns
    -------
    ArealStatistics
    """
    h = level_plane(heights, dx, dy).ravel()
    if rms_height(h) == 0:
        raise InputError("the map is flat after levelling (Sq = 0): no roughness to describe.")
    return ArealStatistics(Sa=arithmetic_mean_height(h), Sq=rms_height(h), Ssk=skewness(h), Sku=kurtosis(h),
                           Sp=max_peak_height(h), Sv=max_valley_depth(h), Sz=max_height(h))


@dataclass(frozen=True)
class LineScanStatistics(ProfileStatistics):
    """Profile parameters of the rows of a map, each row levelled on its own, then aggregated.

    Aggregation: Rq and rms_slope are pooled (root of the mean of the squares over the
    rows, i.e. the rms over all levelled points and all slopes), lambda_q = 2 pi Rq /
    rms_slope of the pooled values; Ra, Rsk, Rku, Rp, Rv, Rz are means over the rows
    (ISO 4287 averages Rp, Rv, Rz over sampling lengths in the same way). ``n_points``,
    ``sample_spacing``, ``length`` describe one row.

    Attributes
    ----------
    n_line_scans : int
        Number of rows.
    Rq_std : float
        Standard deviation [m] of the per-row Rq.
    """

    n_line_scans: int = 0
    Rq_std: float = 0.0


@cites("thesis", "iso_4287")
def line_scan_statistics(heights, dx) -> LineScanStatistics:
    """Profile parameters of every row of a map (rows along x), each levelled by its own line.

    Parameters
    ----------
    heights : array_like
        Heights [m], shape (ny, nx), rows = scan lines along x.
    dx : float
        Pixel size along x [m].

    Returns
    -------
    LineScanStatistics
    """
    h = np.asarray(heights, dtype=float)
    if h.ndim != 2 or h.shape[1] < 3:
        raise InputError(f"line-scan statistics need a map of shape (ny, nx) with nx >= 3 (got {h.shape}).")
    _heights(h.ravel(), 3, "line-scan statistics")
    ny, nx = h.shape
    t = np.arange(nx) - (nx - 1) / 2
    hc = h - h.mean(axis=1, keepdims=True)
    r = hc - np.outer(hc @ t / np.dot(t, t), t)         # each row minus its own least-squares line
    rq_rows = np.sqrt(np.mean(r ** 2, axis=1))
    if np.any(rq_rows == 0):
        raise InputError(f"{int(np.count_nonzero(rq_rows == 0))} scan line(s) are flat after levelling; "
                         "their skewness and kurtosis are undefined.")
    slopes = np.diff(r, axis=1) / dx
    rq = float(np.sqrt(np.mean(rq_rows ** 2)))
    slope = float(np.sqrt(np.sum(slopes ** 2) / (ny * (nx - 1))))
    return LineScanStatistics(
        Ra=float(np.mean(np.abs(r))), Rq=rq,
        Rsk=float(np.mean(np.mean(r ** 3, axis=1) / rq_rows ** 3)),
        Rku=float(np.mean(np.mean(r ** 4, axis=1) / rq_rows ** 4)),
        Rp=float(np.mean(r.max(axis=1))), Rv=float(np.mean(-r.min(axis=1))),
        Rz=float(np.mean(r.max(axis=1) - r.min(axis=1))), rms_slope=slope,
        lambda_q=rms_wavelength(rq, slope), n_points=nx, sample_spacing=float(dx), length=nx * float(dx),
        uniform=True, n_line_scans=ny, Rq_std=float(np.std(rq_rows)))
