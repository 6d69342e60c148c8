"""Synthetic roughness: seeded Gaussian profiles with an exact Rq and rms slope, the default profile of a parameter
set, and independent lines with a measured profile's spectrum for the rows across a face width (MODEL 7b)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites
from memstribo.surfaces.profile import Profile, level_profile, resample_pchip
from memstribo.surfaces.statistics import rms_height


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


def _amplitudes(spectrum, n: int, dx: float) -> np.ndarray:
    """sqrt(C(q)) [m^1.5] on the wavenumbers of an n-point real FFT at step dx [m] of a smoothed PSD
    ``spectrum`` = (q [rad/m], C [m^3]) (:func:`power_spectrum_1d`): interpolated log-log, held at its
    long-wavelength value below the scan's lowest wavenumber, cut above its Nyquist wavenumber, 0 at q = 0."""
    q_measured, c_measured = spectrum
    q = 2 * np.pi * np.fft.rfftfreq(n, dx)
    log_c = np.interp(np.log(np.maximum(q, q_measured[0])), np.log(q_measured), np.log(np.maximum(c_measured, 1e-300)))
    amplitude = np.sqrt(np.exp(log_c)) * (q <= q_measured[-1] * (1 + 1e-9))
    amplitude[0] = 0.0
    return amplitude


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
    spectrum = power_spectrum_1d(profile)
    dx = float(profile.x[1] - profile.x[0]) if spacing is None else float(spacing)
    n = int(math.ceil(length / dx)) + 1
    if n > 50_000_000:
        raise InputError(f"synthesize_like: {n} points ({length:.3g} m at {dx:.3g} m) is too many.")
    amplitude = _amplitudes(spectrum, n, dx)
    q = 2 * np.pi * np.fft.rfftfreq(n, dx)
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


#: Measured points next to each end of a measured line on which its synthesised continuation is conditioned.
_CONDITIONING_POINTS = 256
#: Variance of the white noise assumed on the measured heights in that conditioning, relative to Rq^2 [-].
_NOISE = 1e-4


@cites("jacobs_2017", "journel_huijbregts_1978")
def complete_line(measured: Profile, length: float, spectrum_of: Profile, rng=None, name: str | None = None) -> Profile:
    """A measured line shorter than ``length``, completed on both sides from a power spectrum; the measured heights
    are kept as they are.

    The levelled measured line sits in the middle of the new line (same step); the rest is a line synthesised from
    the spectrum of ``spectrum_of`` (:func:`synthesize_like`, twice as long, so that its periodicity does not tie
    the two ends together) conditioned on the measured heights next to each end (the last
    :data:`_CONDITIONING_POINTS` on each side) by simple kriging with the covariance of that spectrum: conditional
    simulation (Journel and Huijbregts 1978, ch. V), z = s + k^T K^-1 (z_measured - s) outside the measured part,
    where s is the unconditional line, K the covariance between the measured points used and k that between them
    and each point outside. The continuation meets the measured line without a step and has the spectrum's
    statistics away from it (a Gaussian process, whatever the measured height distribution).

    Parameters
    ----------
    measured : Profile
        The measured line (uniform step, at least 16 points).
    length : float
        Length of the completed line [m]; a line at least this long is returned as it is.
    spectrum_of : Profile
        The line whose spectrum and Rq the continuation has (e.g. the measured line itself, or a map's longest
        line).
    rng : numpy.random.Generator or int or None
    name : str, optional

    Returns
    -------
    Profile
        ``synthetic=False`` (its middle is measured); ``source`` says which part is measured.
    """
    import scipy.linalg

    span = float(measured.x[-1] - measured.x[0])
    if span >= length:
        return measured
    levelled = level_profile(measured)
    m = levelled.z.size
    if m < 16:
        raise InputError(f"line '{measured.name}' has {m} points; completing it needs at least 16.")
    dx = span / (m - 1)
    n = int(math.ceil(length / dx)) + 1
    generator = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
    unconditional = synthesize_like(spectrum_of, 2.0 * length, generator, spacing=dx)
    big = unconditional.z.size
    s = unconditional.z[:n] - unconditional.z[:n].mean()
    # the covariance of the synthesis: the inverse transform of C(q) on its grid, scaled to its Rq
    covariance = np.fft.irfft(_amplitudes(power_spectrum_1d(spectrum_of), big, dx) ** 2, big)
    rq = rms_height(level_profile(spectrum_of).z)
    covariance *= rq**2 / covariance[0] if covariance[0] > 0 else 0.0
    start = (n - m) // 2
    k = min(m, _CONDITIONING_POINTS)
    used = np.unique(np.concatenate([np.arange(k), np.arange(m - k, m)]))  # measured points used
    where = start + used
    outside = np.concatenate([np.arange(start), np.arange(start + m, n)])
    matrix = covariance[np.abs(where[:, None] - where[None, :])]
    # white noise on the measured heights, of 1 % of Rq (an instrument's noise floor), or the measured line's
    # short-wavelength power that the smoothed, band-limited spectrum leaves out (its step variance above the
    # model's 2 (C(0) - C(dx))) where that is more: the spectrum's covariance is smooth, and kriging on it without
    # noise extrapolates the measured line's curvature (a measured edge at 151 nm continued at 245 nm on di-3.di)
    excess = 0.5 * max(float(np.var(np.diff(levelled.z))) - 2.0 * float(covariance[0] - covariance[1]), 0.0)
    matrix[np.diag_indices_from(matrix)] += max(excess, _NOISE * float(covariance[0]))
    try:
        weights = scipy.linalg.cho_solve(scipy.linalg.cho_factor(matrix), levelled.z[used] - s[where])
    except np.linalg.LinAlgError:  # a spectrum with (numerically) no power at some wavelengths
        weights = np.linalg.lstsq(matrix, levelled.z[used] - s[where], rcond=None)[0]
    z = s.copy()
    z[outside] += covariance[np.abs(outside[:, None] - where[None, :])] @ weights
    z[start:start + m] = levelled.z
    source = (f"measured: '{measured.name}' ({span * 1e6:.4g} µm, points {start} to {start + m - 1} of {n}); "
              f"completed to {(n - 1) * dx * 1e6:.4g} µm by a continuation synthesised from the power spectrum of "
              f"'{spectrum_of.name}' and conditioned on the measured heights (kriging); {measured.source}")
    return Profile(x=np.arange(n) * dx, z=z, name=name or f"{measured.name}, completed", source=source,
                   synthetic=bool(measured.synthetic))


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
        How many of the 2 x rows lines are measured (wholly or in part) and how many synthesised whole.
    method : str
        How the lines were made (one sentence).
    name, source : str
        The roughness the statistics come from, and its provenance.
    synthetic : bool
        Whether the statistics themselves are synthetic (the thesis default).
    completed_lines : int
        How many of the measured lines are shorter than the travel and were completed from the spectrum
        (:func:`complete_line`).
    measured_share : float
        Share of the lines' total length that is measured [-].
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
    completed_lines: int = 0
    measured_share: float = 0.0


def _span(line: Profile) -> float:
    return float(line.x[-1] - line.x[0])


def _realisation_rng(seed: int, realisation: int) -> np.random.Generator:
    return np.random.default_rng(np.random.SeedSequence([int(seed), int(realisation)]))


def row_roughness(roughness, params, rows: int, length: float, realisation: int = 0) -> RowRoughness:
    """Independent roughness lines for ``rows`` nanoblock rows on each flank (MODEL 7b).

    Never one line copied to every row (that adds the rows' friction spikes in phase):

    - ``None`` / ``"thesis"``: the synthetic default recipe (:func:`default_profile`) with
      independent seeds; realisation 0's first pinion line is exactly the default profile;
    - a :class:`Profile` (a measured line scan): it is the first pinion line of realisation 0
      (completed from its spectrum where it is shorter than ``length``, :func:`complete_line`);
      every other line is synthesised like it (:func:`synthesize_like`);
    - a map (``line_scans()``, pixel size ``dy``): scan lines one nanoblock width apart are
      the pinion's rows, the next ones the gear's; lines shorter than ``length`` are used where
      they reach and completed from their own spectrum beyond (:func:`complete_line`); a map
      with too few lines is completed by lines synthesised whole from the spectrum of its longest
      line, and the realisations > 0 take other lines of the map where there are enough, else
      synthesise.

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
        return _profile_rows(roughness, rows, length, realisation, rng, offsets)
    if hasattr(roughness, "line_scans"):
        return _map_rows(roughness, params, rows, length, realisation, rng, offsets)
    raise InputError(f"roughness must be None, 'thesis', a file path, a Profile or a SurfaceMap; got "
                     f"{type(roughness).__name__}.")


def _profile_rows(roughness, rows, length, realisation, rng, offsets) -> RowRoughness:
    """:func:`row_roughness` of a measured profile (its first pinion line; every other line synthesised like it)."""
    n_lines = 2 * rows
    span = float(roughness.x[-1] - roughness.x[0])
    usable = span >= length
    lines, measured = [], 0
    for k in range(n_lines):
        if realisation == 0 and k == 0:
            lines.append(roughness if usable else complete_line(roughness, 1.02 * length, roughness, rng,
                                                               name=f"{roughness.name}, line {k}"))
            measured = 1
        else:
            lines.append(synthesize_like(roughness, 1.02 * length, rng, name=f"{roughness.name}, line {k}"))
    share = min(span, _span(lines[0])) / sum(_span(line) for line in lines) if measured else 0.0
    return RowRoughness(lines[:rows], lines[rows:], offsets, measured, n_lines - measured,
                        ("the measured profile for the first pinion row, " if measured else "")
                        + f"{n_lines - measured} lines synthesised from its power spectrum (random phases, "
                        f"realisation {realisation})"
                        + ("" if usable or not measured else
                           f"; the scan ({span * 1e6:.3g} µm) is shorter than the {length * 1e6:.3g} µm of flank "
                           f"travel: the first pinion line is measured over {span * 1e6:.3g} µm in its middle "
                           f"and completed to {_span(lines[0]) * 1e6:.3g} µm by a continuation synthesised from "
                           "its spectrum and conditioned on the measured heights"),
                        roughness.name, roughness.source, bool(roughness.synthetic),
                        0 if usable or not measured else 1, share)


def _map_rows(roughness, params, rows, length, realisation, rng, offsets) -> RowRoughness:
    """:func:`row_roughness` of a map: its scan lines one nanoblock width apart, completed where they are short."""
    n_lines = 2 * rows
    scans = list(roughness.line_scans())
    name = getattr(roughness, "name", "surface map")
    source = getattr(roughness, "source", "")
    dy = float(getattr(roughness, "dy", 0.0) or 0.0)
    stride = max(1, int(round(float(params["adhesive_width"]) / dy))) if dy > 0 else 1
    long_enough = [s for s in scans if float(s.x[-1] - s.x[0]) >= length]
    start = realisation * n_lines * stride
    reference = max(scans, key=lambda s: s.x.size)
    lines, measured, completed, measured_length = [], 0, 0, 0.0
    for k in range(n_lines):  # in this order: the random draws of the completions and syntheses
        index = start + k * stride
        if index >= len(scans):
            lines.append(synthesize_like(reference, 1.02 * length, rng, name=f"{name}, line {k}"))
            continue
        scan = scans[index]
        span = float(scan.x[-1] - scan.x[0])
        measured += 1
        measured_length += span
        if span >= length:
            lines.append(scan)
        else:  # measured where it reaches, completed from the map's spectrum beyond (issue #41)
            completed += 1
            lines.append(complete_line(scan, 1.02 * length, scan, rng, name=f"{name}, line {k}"))
    share = measured_length / sum(_span(line) for line in lines)
    note = (f"{measured} measured scan lines ({stride} map rows apart, one nanoblock width) and "
            f"{n_lines - measured} lines synthesised from the map's power spectrum (realisation {realisation})")
    if not long_enough:
        note += f"; the map's lines are shorter than the {length * 1e6:.3g} µm of flank travel"
        if completed:
            spans = sorted({round(float(s.x[-1] - s.x[0]) * 1e6, 3) for s in scans})
            note += (f": each measured line is used over its {spans[0]:.4g} µm in the middle of its flank's travel "
                     f"and completed to {1.02 * length * 1e6:.3g} µm by continuations synthesised from each line's "
                     f"own power spectrum and conditioned on the measured heights ({100 * share:.3g} % of the lines' "
                     "length measured)")
    return RowRoughness(lines[:rows], lines[rows:], offsets, measured, n_lines - measured, note, name, source,
                        False, completed, share)
