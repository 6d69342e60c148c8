"""Roughness of measured and synthetic surfaces (thesis 3.4.1, 4.2; MODEL §1).

A :class:`Profile` is one line scan ``z(x)`` in metres. This module levels profiles and
maps (least-squares line or plane), resamples them with shape-preserving PCHIP (MATLAB's
``pchip``), computes the ISO 4287 profile parameters and the ISO 25178 areal ones, the
Abbott-Firestone curve and the mean width of the asperities cut at a level (3-26), and
makes seeded synthetic Gaussian profiles with an exact Rq and rms slope.

Conventions
-----------
- Heights are taken about the mean line (the mean of the heights given); the functions
  that compute one parameter do not level: :func:`level_profile` first, or call
  :func:`profile_statistics`, which levels.
- The local slope is the first difference ``S_i = (z[i+1] - z[i]) / (x[i+1] - x[i])``, so
  that a profile of n points has n - 1 slopes and Eq. (4-6) in [1] reads
  ``rms_slope = sqrt(sum(S_i**2) / (n - 1))``.
- Rz is the maximum height Rp + Rv of the whole profile (ISO 4287 would average it over
  sampling lengths; the thesis uses none).

References
----------
.. [1] N. S. T. Almuramady, PhD thesis (see :data:`memstribo.references.REFERENCES`).
.. [2] ISO 4287:1997; ISO 25178-2:2012.
.. [3] F. N. Fritsch, R. E. Carlson, SIAM J. Numer. Anal. 17 (1980) 238-246.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "Profile",
    "ProfileStatistics",
    "ArealStatistics",
    "LineScanStatistics",
    "level_profile",
    "level_plane",
    "resample_pchip",
    "arithmetic_mean_height",
    "rms_height",
    "skewness",
    "kurtosis",
    "max_peak_height",
    "max_valley_depth",
    "max_height",
    "rms_slope",
    "rms_wavelength",
    "bearing_area_curve",
    "asperity_widths",
    "mean_asperity_width",
    "profile_statistics",
    "areal_statistics",
    "line_scan_statistics",
    "synthetic_profile",
    "power_spectrum_1d",
    "synthesize_like",
    "RowRoughness",
    "row_roughness",
    "default_profile",
    "Ra",
    "Rq",
    "Rsk",
    "Rku",
    "Rp",
    "Rv",
    "Rz",
]

#: relative tolerance on the steps of x below which a profile counts as uniformly sampled
UNIFORM_RTOL = 1e-3


# --------------------------------------------------------------------------------------------
# the profile
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Profile:
    """One line scan z(x).

    Attributes
    ----------
    x : numpy.ndarray
        Positions along the scan [m], 1-D, strictly increasing; uniform unless
        :attr:`is_uniform` says otherwise.
    z : numpy.ndarray
        Heights [m], same shape as ``x``.
    name : str
        Short name (file name, member, channel or "synthetic ...").
    source : str
        Provenance: file, channel, or "synthetic: ...".
    synthetic : bool
        True when the profile was generated, not measured.
    """

    x: np.ndarray
    z: np.ndarray
    name: str = "profile"
    source: str = ""
    synthetic: bool = False

    def __post_init__(self):
        x = np.array(self.x, dtype=float)
        z = np.array(self.z, dtype=float)
        if x.ndim != 1 or z.shape != x.shape:
            raise InputError(f"profile '{self.name}': x and z must be 1-D arrays of the same length "
                             f"(got shapes {x.shape} and {z.shape}).")
        if x.size < 2:
            raise InputError(f"profile '{self.name}' has {x.size} point(s); at least 2 are needed.")
        bad = int(np.count_nonzero(~np.isfinite(z)))
        if bad or not np.all(np.isfinite(x)):
            raise InputError(f"profile '{self.name}' has {bad} NaN or infinite height(s) (or non-finite x); "
                             "all heights must be finite: remove or fill them before use.")
        if np.any(np.diff(x) <= 0):
            raise InputError(f"profile '{self.name}': x must be strictly increasing.")
        x.setflags(write=False)
        z.setflags(write=False)
        object.__setattr__(self, "x", x)
        object.__setattr__(self, "z", z)

    @property
    def n_points(self) -> int:
        """Number of points."""
        return int(self.x.size)

    @property
    def is_uniform(self) -> bool:
        """Whether the steps of x are equal (to :data:`UNIFORM_RTOL`)."""
        steps = np.diff(self.x)
        return bool(np.ptp(steps) <= UNIFORM_RTOL * steps.mean())

    @property
    def sample_spacing(self) -> float:
        """Sampling step [m]; the mean step for a non-uniform profile."""
        return float((self.x[-1] - self.x[0]) / (self.x.size - 1))

    @property
    def length(self) -> float:
        """Scan length [m]: n_points x sample_spacing for a uniform profile (the instrument's scan
        size, as SurfaceTopography reports it), x[-1] - x[0] for a non-uniform one."""
        if self.is_uniform:
            return self.n_points * self.sample_spacing
        return float(self.x[-1] - self.x[0])

    def replace(self, **changes) -> "Profile":
        """A copy with some fields changed."""
        fields = dict(x=self.x, z=self.z, name=self.name, source=self.source, synthetic=self.synthetic)
        fields.update(changes)
        return Profile(**fields)


def _as_xz(profile_or_z, x=None, sample_spacing=None):
    """(x, z, profile or None) from a Profile or from arrays."""
    if isinstance(profile_or_z, Profile):
        return profile_or_z.x, profile_or_z.z, profile_or_z
    z = np.asarray(profile_or_z, dtype=float)
    if z.ndim != 1:
        raise InputError(f"heights must be a 1-D array (got shape {z.shape}).")
    if sample_spacing is not None and not (np.isfinite(sample_spacing) and sample_spacing > 0):
        raise InputError(f"sample_spacing must be a positive length in m (got {sample_spacing!r}).")
    if x is None:
        x = np.arange(z.size) * (1.0 if sample_spacing is None else float(sample_spacing))
    x = np.asarray(x, dtype=float)
    if x.shape != z.shape:
        raise InputError(f"x and z must have the same shape (got {x.shape} and {z.shape}).")
    if not np.all(np.isfinite(x)) or np.any(np.diff(x) <= 0):
        raise InputError("x must be finite and strictly increasing.")
    return x, z, None


def _heights(z, minimum=1, what="this statistic"):
    z = np.asarray(z.z if isinstance(z, Profile) else z, dtype=float)
    if z.size < minimum:
        raise InputError(f"{what} needs at least {minimum} heights (got {z.size}).")
    bad = int(np.count_nonzero(~np.isfinite(z)))
    if bad:
        raise InputError(f"{bad} of {z.size} heights are NaN or infinite; all heights must be finite.")
    return z


# --------------------------------------------------------------------------------------------
# levelling and resampling
# --------------------------------------------------------------------------------------------


@cites("thesis", "iso_4287")
def level_profile(profile, x=None):
    """Subtract the least-squares straight line ("removing the overall profile slope", 4.2.1 in [1]).

    Parameters
    ----------
    profile : Profile or array_like
        The profile, or its heights z [m] (then ``x`` [m], default: the point index).
    x : array_like, optional
        Positions [m] when ``profile`` is an array.

    Returns
    -------
    Profile or numpy.ndarray
        The levelled profile (same type as the input): zero mean and zero least-squares slope.
    """
    xs, z, prof = _as_xz(profile, x)
    _heights(z, 2, "levelling a profile")
    t = xs - xs.mean()
    zc = z - z.mean()
    residual = zc - t * (np.dot(t, zc) / np.dot(t, t))
    return prof.replace(z=residual) if prof is not None else residual


@cites("iso_25178")
def level_plane(heights, dx=1.0, dy=1.0):
    """Subtract the least-squares plane from a map.

    Parameters
    ----------
    heights : array_like
        Heights [m], shape (ny, nx), rows along x.
    dx, dy : float
        Pixel sizes [m] (they do not change the residual of a uniform grid).

    Returns
    -------
    numpy.ndarray
        Residual heights [m], shape (ny, nx).
    """
    h = np.asarray(heights, dtype=float)
    if h.ndim != 2 or min(h.shape) < 2:
        raise InputError(f"a map needs shape (ny, nx) with ny, nx >= 2 (got {h.shape}).")
    _heights(h.ravel(), 3, "levelling a map")
    ny, nx = h.shape
    xs = (np.arange(nx) - (nx - 1) / 2) * dx
    ys = (np.arange(ny) - (ny - 1) / 2) * dy
    hc = h - h.mean()
    # xs and ys are centred and the grid is a product: the normal equations decouple
    slope_x = np.dot(hc.sum(axis=0), xs) / (ny * np.dot(xs, xs))
    slope_y = np.dot(hc.sum(axis=1), ys) / (nx * np.dot(ys, ys))
    return hc - slope_x * xs[np.newaxis, :] - slope_y * ys[:, np.newaxis]


@cites("thesis", "fritsch_carlson_1980")
def resample_pchip(profile, spacing, x=None):
    """Resample a profile to a uniform step with shape-preserving PCHIP (MATLAB ``pchip``).

    The thesis halves its AFM step from 78 nm to 39 nm this way (4.2.1 in [1]). PCHIP
    (Fritsch-Carlson [3]) is monotone between the data points: it neither overshoots nor
    creates new extrema, and it reproduces linear data exactly.

    Parameters
    ----------
    profile : Profile or array_like
        The profile, or its heights z [m] (then ``x`` [m] is required).
    spacing : float
        New step [m], > 0.
    x : array_like, optional
        Positions [m] when ``profile`` is an array.

    Returns
    -------
    Profile or tuple of numpy.ndarray
        The resampled profile from x[0] on, floor((x[-1] - x[0]) / spacing) + 1 points;
        for array input the tuple (x_new, z_new).
    """
    from scipy.interpolate import PchipInterpolator

    if isinstance(profile, Profile):
        xs, z, prof = profile.x, profile.z, profile
    else:
        if x is None:
            raise InputError("resample_pchip needs x [m] when given an array of heights.")
        xs, z, prof = _as_xz(profile, x)
    if not (np.isfinite(spacing) and spacing > 0):
        raise InputError(f"resampling step must be a positive length in m (got {spacing!r}).")
    span = xs[-1] - xs[0]
    n = int(math.floor(span / spacing * (1 + 1e-12))) + 1
    if n < 2:
        raise InputError(f"resampling step {spacing:.4g} m is longer than the profile ({span:.4g} m).")
    x_new = xs[0] + np.arange(n) * spacing
    z_new = PchipInterpolator(xs, z, extrapolate=False)(np.minimum(x_new, xs[-1]))
    if prof is None:
        return x_new, z_new
    return prof.replace(x=x_new, z=z_new,
                        source=f"{prof.source}; PCHIP-resampled to {spacing:.6g} m")


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


# --------------------------------------------------------------------------------------------
# synthetic profiles
# --------------------------------------------------------------------------------------------


def _levelled_stats(z, dx):
    t = np.arange(z.size) - (z.size - 1) / 2
    zc = z - z.mean()
    r = zc - t * (np.dot(t, zc) / np.dot(t, t))
    return r, np.sqrt(np.mean(r ** 2)), np.sqrt(np.sum(np.diff(r) ** 2) / (z.size - 1)) / dx


@cites("jacobs_2017")
def synthetic_profile(length, sample_spacing, rq, rms_slope_value, rng=None, name="synthetic profile"):
    """A seeded Gaussian random profile with exactly the given Rq and rms slope.

    White Gaussian noise from ``rng`` is filtered by a Gaussian low-pass filter
    ``exp(-(k l)^2 / 4)`` (a Gaussian autocorrelation of length l); l is found by root
    finding so that the levelled profile's ratio Delta_q / Rq equals the one asked, then
    the profile is scaled to Rq. The profile is levelled (zero mean, zero least-squares
    slope) and its Rq (4-2) and rms slope (4-6, first differences) match to ~1e-10.

    Parameters
    ----------
    length : float
        Scan length [m]; the profile has round(length / sample_spacing) points (>= 16).
    sample_spacing : float
        Step [m].
    rq : float
        Rq [m], > 0.
    rms_slope_value : float
        Delta_q [-], > 0. With white noise as the roughest case, Delta_q / Rq must be below
        about sqrt(2) / sample_spacing; and lambda_q = 2 pi Rq / Delta_q must fit in the length.
    rng : numpy.random.Generator or int or None
        Random generator or seed (no global state is used).
    name : str
        Name of the profile.

    Returns
    -------
    Profile
        Labelled ``synthetic=True``, with the recipe in ``source``.
    """
    from scipy.optimize import brentq

    for label, value in (("length", length), ("sample_spacing", sample_spacing), ("rq", rq),
                         ("rms_slope", rms_slope_value)):
        if not (isinstance(value, (int, float, np.floating, np.integer)) and np.isfinite(value) and value > 0):
            raise InputError(f"synthetic profile: {label} must be a positive number (got {value!r}).")
    n = int(round(length / sample_spacing))
    if n < 16:
        raise InputError(f"synthetic profile: length / sample_spacing = {length / sample_spacing:.3g}; "
                         "at least 16 points are needed.")
    if not (rng is None or isinstance(rng, np.random.Generator)
            or (isinstance(rng, (int, np.integer)) and not isinstance(rng, bool) and rng >= 0)):
        raise InputError(f"synthetic profile: rng must be a numpy Generator, a non-negative integer seed or None "
                         f"(got {rng!r}).")
    generator = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
    dx = float(sample_spacing)
    noise_spectrum = np.fft.rfft(generator.standard_normal(n))
    k = 2 * np.pi * np.fft.rfftfreq(n, d=dx)

    def shaped(correlation_length):
        return np.fft.irfft(noise_spectrum * np.exp(-(k * correlation_length) ** 2 / 4), n)

    target = rms_slope_value / rq

    def mismatch(log_l):
        _, q, s = _levelled_stats(shaped(math.exp(log_l)), dx)
        return math.log(s / q) - math.log(target)

    lo, hi = math.log(1e-3 * dx), math.log(0.25 * n * dx)
    f_lo, f_hi = mismatch(lo), mismatch(hi)
    if f_lo < 0:
        limit = target * math.exp(f_lo)
        raise InputError(f"synthetic profile: rms slope {rms_slope_value:.4g} is too steep for Rq {rq:.4g} m at a "
                         f"step of {dx:.4g} m (this noise allows rms_slope / Rq up to about {limit:.4g} 1/m): "
                         "use a finer sample_spacing or a smaller rms slope.")
    if f_hi > 0:
        raise InputError(f"synthetic profile: lambda_q = 2 pi Rq / rms_slope = {2 * math.pi / target:.4g} m does not "
                         f"fit in a length of {n * dx:.4g} m: use a longer profile or a larger rms slope.")
    log_l = brentq(mismatch, lo, hi, xtol=1e-14, rtol=8.9e-16, maxiter=200)
    z, q, _ = _levelled_stats(shaped(math.exp(log_l)), dx)
    z = z * (rq / q)
    x = np.arange(n) * dx
    source = (f"synthetic: Gaussian random profile, Gaussian autocorrelation length {math.exp(log_l):.4g} m, "
              f"Rq {rq:.6g} m, rms slope {rms_slope_value:.6g}, step {dx:.6g} m, {n} points, "
              f"rng {'seed ' + str(rng) if isinstance(rng, (int, np.integer)) else 'given'}")
    return Profile(x=x, z=z, name=name, source=source, synthetic=True)


@cites("thesis", "model")
def default_profile(params, length=None, spacing=None) -> Profile:
    """The default roughness of the thesis case: a seeded synthetic profile (MODEL §1.3).

    The thesis's silicon AFM scan is not published. This profile has the chapter-4
    statistics (``roughness_rq``, ``roughness_rms_slope``, exact at the measured step
    ``roughness_sample_spacing`` = 78 nm), seeded by ``roughness_seed``, and is then
    resampled with PCHIP to ``roughness_resample_spacing`` (39 nm, as in 4.2.1 of [1]), or
    to ``spacing`` when given (a finer step for the contact solver). After resampling Rq
    and Delta_q change slightly (PCHIP smooths between the points).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set.
    length : float, optional
        Profile length [m]; default ``roughness_length``.
    spacing : float, optional
        Step [m] of the returned profile; default ``roughness_resample_spacing`` (unset: no
        resampling).

    Returns
    -------
    Profile
        ``synthetic=True``; ``source`` says that it is synthetic and why.
    """
    length = params["roughness_length"] if length is None else length
    profile = synthetic_profile(length, params["roughness_sample_spacing"], params["roughness_rq"],
                                params["roughness_rms_slope"], rng=int(params["roughness_seed"]),
                                name="thesis default roughness (synthetic)")
    profile = profile.replace(source="the thesis's scan is not published; " + profile.source)
    step = params["roughness_resample_spacing"] if spacing is None else spacing
    if step is not None and step != params["roughness_sample_spacing"]:
        profile = resample_pchip(profile, step)
    return profile


# --------------------------------------------------------------------------------------------
# independent lines with measured statistics (rows across the face width, ensembles; MODEL 7b)
# --------------------------------------------------------------------------------------------
def power_spectrum_1d(profile: Profile, bins_per_decade: int = 12):
    """Smoothed one-sided power spectral density of a levelled profile.

    The periodogram ``C(q) = dx / n |Z(q)|^2`` of the levelled heights (Hann window, power
    restored) averaged in logarithmic wavenumber bins, so that one scan gives a smooth
    spectrum to synthesise from (Jacobs, Junge and Pastewka 2017, Surf. Topogr. 5 013001).

    Parameters
    ----------
    profile : Profile
        Line scan on a uniform grid [m].
    bins_per_decade : int
        Logarithmic bins per decade of wavenumber.

    Returns
    -------
    (ndarray, ndarray)
        Wavenumbers q [rad/m] (bin centres) and the PSD C(q) [m^3].
    """
    levelled = level_profile(profile)
    z = np.asarray(levelled.z, dtype=float)
    n = z.size
    if n < 16:
        raise InputError(f"profile '{profile.name}' has {n} points; synthesising lines like it needs at least 16.")
    dx = float(levelled.x[1] - levelled.x[0])
    window = np.hanning(n)
    window /= math.sqrt(np.mean(window**2))
    spectrum = np.abs(np.fft.rfft(z * window)) ** 2 * dx / n
    q = 2 * np.pi * np.fft.rfftfreq(n, dx)
    q, spectrum = q[1:], spectrum[1:]
    edges = np.logspace(math.log10(q[0]) - 1e-9, math.log10(q[-1]) + 1e-9,
                        max(2, int(math.ceil(bins_per_decade * math.log10(q[-1] / q[0])))) + 1)
    index = np.digitize(q, edges) - 1
    keep = np.bincount(index, minlength=edges.size - 1) > 0
    q_mean = np.bincount(index, weights=np.log(q), minlength=edges.size - 1)[keep]
    c_mean = np.bincount(index, weights=spectrum, minlength=edges.size - 1)[keep]
    counts = np.bincount(index, minlength=edges.size - 1)[keep]
    return np.exp(q_mean / counts), c_mean / counts


def synthesize_like(profile: Profile, length: float, rng=None, spacing: float | None = None,
                    name: str | None = None) -> Profile:
    """An independent line with the power spectrum and Rq of a measured profile.

    Fourier synthesis with random phases (Jacobs et al. 2017; the method of
    SurfaceTopography's ``fourier_synthesis``, with the measured spectrum instead of a
    power law): the smoothed PSD of ``profile`` (:func:`power_spectrum_1d`) is interpolated
    log-log onto the wavenumbers of the new length, held at its long-wavelength value below
    the scan's lowest wavenumber (a roll-off) and cut above its Nyquist wavenumber; amplitudes
    get Rayleigh scatter and uniform random phases; the levelled result is scaled to the
    measured Rq. The heights are Gaussian whatever the measured distribution (say so where it
    matters).

    Parameters
    ----------
    profile : Profile
        Measured line scan (the statistics to copy).
    length : float
        Length of the new line [m] (may exceed the scan: that is the point).
    rng : numpy.random.Generator or int or None
        Random generator or seed.
    spacing : float, optional
        Step of the new line [m]; default the profile's.
    name : str, optional

    Returns
    -------
    Profile
        ``synthetic=True``, with the recipe in ``source``.
    """
    if not (np.isfinite(length) and length > 0):
        raise InputError(f"synthesize_like: length must be a positive number of metres, got {length!r}.")
    generator = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
    q_measured, c_measured = power_spectrum_1d(profile)
    dx = float(profile.x[1] - profile.x[0]) if spacing is None else float(spacing)
    n = int(math.ceil(length / dx)) + 1
    if n > 50_000_000:
        raise InputError(f"synthesize_like: {n} points ({length:.3g} m at {dx:.3g} m) is too many.")
    q = 2 * np.pi * np.fft.rfftfreq(n, dx)
    log_c = np.interp(np.log(np.maximum(q, q_measured[0])), np.log(q_measured), np.log(np.maximum(c_measured, 1e-300)))
    amplitude = np.sqrt(np.exp(log_c)) * (q <= q_measured[-1] * (1 + 1e-9))
    amplitude[0] = 0.0
    amplitude = amplitude * generator.rayleigh(1.0, q.size)
    phases = np.exp(2j * np.pi * generator.random(q.size))
    z = np.fft.irfft(amplitude * phases, n)
    z, rq_new, _ = _levelled_stats(z, dx)
    rq_target = rms_height(level_profile(profile).z)
    z = z * (rq_target / rq_new) if rq_new > 0 else z
    x = np.arange(n) * dx
    source = (f"synthetic: Fourier synthesis (random phases) from the power spectrum of '{profile.name}', "
              f"scaled to its Rq {rq_target:.4g} m; {n} points at {dx:.4g} m")
    return Profile(x=x, z=z, name=name or f"synthesised like {profile.name}", source=source, synthetic=True)


@dataclass(frozen=True)
class RowRoughness:
    """Roughness lines of the nanoblock rows of both flanks across the face width (MODEL 7b).

    Attributes
    ----------
    pinion, gear : list of Profile
        One line per row of nanoblocks, each at least the length asked.
    lattice_offsets : ndarray
        Offset across the face width of the gear's atomic-block lattice relative to the
        pinion's, per row [m] (uniform in [0, atomic pitch)): the lattices are not aligned.
    measured_lines, synthesised_lines : int
        How many of the 2 x rows lines are measured and how many synthesised.
    method : str
        How the lines were made (one sentence).
    name, source : str
        The roughness the statistics come from, and its provenance.
    synthetic : bool
        Whether the statistics themselves are synthetic (the thesis default).
    """

    pinion: list
    gear: list
    lattice_offsets: np.ndarray
    measured_lines: int
    synthesised_lines: int
    method: str
    name: str
    source: str
    synthetic: bool


def _realisation_rng(seed: int, realisation: int) -> np.random.Generator:
    return np.random.default_rng(np.random.SeedSequence([int(seed), int(realisation)]))


def row_roughness(roughness, params, rows: int, length: float, realisation: int = 0) -> RowRoughness:
    """Independent roughness lines for ``rows`` nanoblock rows on each flank (MODEL 7b).

    Never one line copied to every row (that adds the rows' friction spikes in phase):

    - ``None`` / ``"thesis"``: the synthetic default recipe (:func:`default_profile`) with
      independent seeds; realisation 0's first pinion line is exactly the default profile;
    - a :class:`Profile` (a measured line scan): it is the first pinion line of realisation 0
      when it is long enough; every other line is synthesised like it (:func:`synthesize_like`);
    - a map (``line_scans()``, pixel size ``dy``): scan lines one nanoblock width apart are
      the pinion's rows, the next ones the gear's; a map with too few lines, or lines shorter
      than ``length``, is completed by lines synthesised from its mean spectrum, and the
      realisations > 0 take other lines of the map where there are enough, else synthesise.

    Parameters
    ----------
    roughness : None, "thesis", Profile or SurfaceMap-like
    params : Parameters
    rows : int
        Rows of nanoblocks across the face width.
    length : float
        Length every line must have [m] (the flank travel plus the contact window).
    realisation : int
        Index of the roughness realisation (0, 1, ...); seeds derive from ``roughness_seed``.

    Returns
    -------
    RowRoughness
    """
    seed = int(params["roughness_seed"])
    rng = _realisation_rng(seed, realisation)
    offsets = rng.random(rows) * float(params["atomic_pitch"])
    n_lines = 2 * rows
    if roughness is None or (isinstance(roughness, str) and roughness == "thesis"):
        base_length = max(float(params["roughness_length"]), 1.05 * length + 4 * params["roughness_sample_spacing"])
        lines = []
        for k in range(n_lines):
            if realisation == 0 and k == 0:
                lines.append(default_profile(params, length=base_length))
                continue
            line = synthetic_profile(base_length, params["roughness_sample_spacing"], params["roughness_rq"],
                                     params["roughness_rms_slope"], rng=rng,
                                     name="thesis default roughness (synthetic)")
            step = params["roughness_resample_spacing"]
            if step is not None and step != params["roughness_sample_spacing"]:
                line = resample_pchip(line, step)
            lines.append(line)
        first = lines[0]
        return RowRoughness(lines[:rows], lines[rows:], offsets, 0, n_lines,
                            f"{n_lines} independent seeded synthetic lines with the thesis's statistics "
                            f"(seed {seed}, realisation {realisation})", first.name, first.source, True)
    if isinstance(roughness, Profile):
        usable = float(roughness.x[-1] - roughness.x[0]) >= length
        lines, measured = [], 0
        for k in range(n_lines):
            if realisation == 0 and k == 0 and usable:
                lines.append(roughness)
                measured = 1
            else:
                lines.append(synthesize_like(roughness, 1.02 * length, rng, name=f"{roughness.name}, line {k}"))
        return RowRoughness(lines[:rows], lines[rows:], offsets, measured, n_lines - measured,
                            ("the measured profile for the first pinion row, " if measured else "")
                            + f"{n_lines - measured} lines synthesised from its power spectrum (random phases, "
                            f"realisation {realisation})"
                            + ("" if usable else f"; the scan ({(roughness.x[-1] - roughness.x[0]) * 1e6:.3g} um) "
                               f"is shorter than the {length * 1e6:.3g} um of flank travel"),
                            roughness.name, roughness.source, bool(roughness.synthetic))
    if hasattr(roughness, "line_scans"):
        scans = list(roughness.line_scans())
        name = getattr(roughness, "name", "surface map")
        source = getattr(roughness, "source", "")
        dy = float(getattr(roughness, "dy", 0.0) or 0.0)
        stride = max(1, int(round(float(params["adhesive_width"]) / dy))) if dy > 0 else 1
        long_enough = [s for s in scans if float(s.x[-1] - s.x[0]) >= length]
        picked = []
        start = realisation * n_lines * stride
        for k in range(n_lines):
            index = start + k * stride
            if index < len(scans) and float(scans[index].x[-1] - scans[index].x[0]) >= length:
                picked.append(scans[index])
            else:
                picked.append(None)
        measured = sum(p is not None for p in picked)
        reference = max(scans, key=lambda s: s.x.size)
        lines = [p if p is not None else synthesize_like(reference, 1.02 * length, rng, name=f"{name}, line {k}")
                 for k, p in enumerate(picked)]
        note = (f"{measured} measured scan lines ({stride} map rows apart, one nanoblock width) and "
                f"{n_lines - measured} lines synthesised from the map's power spectrum (realisation {realisation})")
        if not long_enough:
            note += f"; the map's lines are shorter than the {length * 1e6:.3g} um of flank travel"
        return RowRoughness(lines[:rows], lines[rows:], offsets, measured, n_lines - measured, note, name, source,
                            False)
    raise InputError(f"roughness must be None, 'thesis', a file path, a Profile or a SurfaceMap; got "
                     f"{type(roughness).__name__}.")
