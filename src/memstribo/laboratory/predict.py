"""Each measurement's case built with the paper's conditions, predicted with its uncertainty (MODEL 7e).

The test structures (flat pads, sidewalls, spheres, cantilever arrays, pull-off, nanocontacts) are the
cases of :mod:`memstribo.laboratory.cases` (the rough contact solve, the bonds, the bounded menisci), dispatched by
the row's geometry; a microbeam row is adhered to its substrate here (the work of separation of the rough gap map
under the library's Lennard-Jones surface law and menisci, :mod:`memstribo.physics.rough_capillary`). The
roughness is synthesised from the paper's Rq and correlation length (or a stated assumption) with one seed per
realisation. Each prediction is the median and the 90 % band (5th to 95th percentile) over roughness realisations
x constant samples; a row whose case the model cannot build is returned as "not predicted" with the reason.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from memstribo.errors import InputError
from memstribo.laboratory.cases._roughness import SIDEWALL_ROUGHNESS, stated_roughness as _roughness  # noqa: F401
from memstribo.references import cites

__all__ = ["Prediction", "predict_row", "predict_all", "band", "row_values", "static_cof", "FRICTION"]

FRICTION = ("static_cof", "kinetic_cof")
#: side [m] and points per side of a microbeam's synthetic gap map (a 5.12 um square, 10 nm spacing)
BEAM_MAP_SIZE = 5.12e-6
BEAM_MAP_POINTS = 512
#: chemical bond energy of a coated surface [J]: no chemical bonds (thesis 5.4), the spec's floor 1e-21 J
COATED_BOND_ENERGY = 1e-21


@dataclass
class Prediction:
    """The prediction of one measurement row.

    Attributes
    ----------
    id, quantity : str
    measured : float
        The row's value (SI).
    status : str
        "predicted" or "not predicted".
    reason : str
        Why not predicted, or notes on how the case was built.
    values : ndarray
        One predicted value per (constant sample, realisation), shape (n_samples, n_realisations).
    median, low, high : float
        Median and 90 % band (5th, 95th percentile) of ``values`` [unit of the row] (NaN if not predicted).
    inside : bool or None
        Whether the measurement lies inside the band (None if not predicted).
    case : str
        The case in words (model, load, roughness, parameter set).
    """

    id: str
    quantity: str
    measured: float
    status: str
    reason: str = ""
    values: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    median: float = math.nan
    low: float = math.nan
    high: float = math.nan
    inside: bool | None = None
    case: str = ""

    @property
    def ratio(self) -> float:
        """Measured / predicted median (NaN if not predicted)."""
        return self.measured / self.median if self.status == "predicted" and self.median else math.nan


def band(values, weights=None, level=0.90):
    """Median and central band of ``values`` (optionally weighted per constant sample).

    Parameters
    ----------
    values : array_like, shape (n_samples, n_realisations)
        Predicted values.
    weights : array_like, shape (n_samples,), optional
        Importance weights of the constant samples (each sample's realisations share its weight).
    level : float
        Central probability of the band (0.90: 5th to 95th percentile).

    Returns
    -------
    tuple of float
        (median, low, high).
    """
    v = np.asarray(values, dtype=float)
    if v.ndim == 1:
        v = v[:, None]
    w = np.ones(v.shape[0]) if weights is None else np.asarray(weights, dtype=float)
    if w.shape != (v.shape[0],) or np.any(w < 0) or not w.sum() > 0:
        raise InputError("weights must be one non-negative number per constant sample, not all zero.")
    flat = v.ravel()
    wf = np.repeat(w / v.shape[1], v.shape[1])
    order = np.argsort(flat)
    cdf = np.cumsum(wf[order]) / wf.sum()
    tail = (1.0 - level) / 2.0

    def quantile(q):
        return float(np.interp(q, cdf - 0.5 * wf[order] / wf.sum(), flat[order]))

    return quantile(0.5), quantile(tail), quantile(1.0 - tail)


def _not_predicted(row, reason):
    return Prediction(id=row.id, quantity=row.quantity, measured=row.value, status="not predicted", reason=reason)


def _base_parameters(row, sample, calibration_coating, base=None):
    from memstribo.parameters import get_parameter_values
    from memstribo.parameters.definitions import SPECS

    name = base.name if base is not None else "silicon_oxide_air" if row.environment == "air" else "silicon_thesis"
    params = base if base is not None else get_parameter_values(name)
    overrides = {}
    for key, value in sample.items():
        if key.startswith("coating_") and row.coating != calibration_coating:
            continue  # the sampled coating constants stand for the calibration coating only
        if key not in SPECS:
            raise InputError(f"constant sample names {key!r}, which is not a parameter; see 'memstribo parameters'.")
        overrides[key] = value
    rh = row.number("relative_humidity")
    if row.environment == "air" and rh is not None:
        overrides["relative_humidity"] = rh
    return params.updated(overrides, origin="laboratory case") if overrides else params, name


def _coated(params, coating_name):
    from memstribo.physics.coating import get_coating

    coating = get_coating(coating_name, params)
    # the coating's own (calibrated) U_vdW as given: the thesis's rule, not the bare flanks' hysteresis (MODEL 7h)
    return params.updated({"bond_energy": COATED_BOND_ENERGY, "vdw_energy_rule": "thesis",
                           "vdw_bond_energy": coating.vdw_bond_energy,
                           "hamaker_constant": coating.hamaker_constant, "cutoff_distance": coating.cutoff_distance,
                           "work_of_adhesion": coating.work_of_adhesion},
                          origin=f"coating {coating.name}: no chemical bonds (thesis 5.4), its vdW constants")


def _profile(rq, correlation_length, length, seed, spacing=None):
    from memstribo.surfaces.roughness import synthetic_profile

    spacing = spacing or min(correlation_length / 8.0, 5e-9)
    # Gaussian autocorrelation exp(-x^2 / l^2): rms slope sqrt(2) Rq / l
    return synthetic_profile(length, spacing, rq, math.sqrt(2.0) * rq / correlation_length, rng=seed)


@cites("thesis", "model", "van_spengen_2010")
def _flat_capillary_pressure(row, params, rq, corr, seed):
    """The menisci's attraction per apparent area of a flat or sidewall contact in air [Pa] (issue #36, MODEL 7g).

    :func:`memstribo.physics.rough_capillary.meniscus_adhesion_pressure` on the gap map of the two rough surfaces
    held rigidly on their highest summit (the microbeam's map, :func:`_beam_gap`), at the row's RH (p / p_sat of the
    parameter set's vapour) and bridging height ``h_c`` plus the liquid-like films; a coated row takes its coating's
    water contact angle on both surfaces (OTS, 112 deg: no meniscus); 0 in vacuum or dry gas."""
    rh = row.number("relative_humidity")
    if row.environment != "air" or not rh:
        return 0.0
    from memstribo.physics import capillary, rough_capillary, vapours

    state = vapours.vapour_state(params.updated({"relative_humidity": rh, "vapour_pressure_ratio": None}))
    theta = state["contact_angle"]
    if row.coating:  # both surfaces coated (a SAM on the released structure): the coating's water angle
        from memstribo.physics.coating import get_coating

        theta = math.radians(float(getattr(get_coating(row.coating, params), "water_contact_angle_deg", math.nan)))
        if not math.isfinite(theta):
            return 0.0
    film = vapours.liquid_film_thickness(state["vapour"], state["termination"], rh) if theta < 0.5 * math.pi else 0.0
    height = capillary.bridging_height(state["kelvin"], film, film, theta)
    return rough_capillary.meniscus_adhesion_pressure(_beam_gap(rq, corr, seed), BEAM_MAP_SIZE / BEAM_MAP_POINTS,
                                                      state["kelvin"], height, state["surface_tension"])


@cites("model")
def static_cof(dataset, params) -> float:
    """Static COF of a sliding structure [-]: the start-up force at each rest position of a slide over F_N + F_adh,
    averaged over the rest positions (MODEL 7f: the same static force as the gear's start-up).

    The structure's nanoblocks are one crystal registry (a grain is larger than the 2-block structure): its bonds'
    forces N U / D add their lateral peaks in phase
    (:func:`memstribo.simulations.mesh.limits.static_friction_force`, the formed share of the ageing law after
    ``startup_dwell``), plus the elastic interlocking friction as in sliding.
    """
    from memstribo.simulations.mesh.limits import formed_share, static_friction_force

    bonds = (np.asarray(dataset["friction_force_chemical"], dtype=float)
             + np.asarray(dataset["friction_force_vdw"], dtype=float))
    static = static_friction_force(bonds[:, None], np.zeros(1), formed_share(params),
                                   np.asarray(dataset["friction_force_elastic"], dtype=float))
    pressing = np.asarray(dataset["normal_force"], dtype=float) + np.asarray(dataset["adhesion_force"], dtype=float)
    ratio = np.divide(static, pressing, out=np.zeros_like(static), where=pressing > 0)
    return float(ratio.mean())


@cites("delrio_2007", "deboer_2007")
def beam_work_of_separation(gap, params, relative_humidity):
    """Adhesion energy of a rigid rough interface [J/m^2]: the asperity-level microbeam model (issue #36, MODEL 7g).

    :func:`memstribo.physics.rough_capillary.rough_adhesion_energy` on the gap field ``gap``: per element the larger
    of the van der Waals energy ``A / (12 pi (g + D0)^2)`` and the water bridge's work ``(gamma / r_K) (h -
    max(g, t))`` where the gap is below the bridging height h (the liquid-like adsorbed films t of the oxide), none
    below a molecular Kelvin radius; Gamma is their mean. A touching interface holds ``w = A / (12 pi D0^2)`` dry and
    ``max(w, 2 gamma cos theta)`` wet.

    Parameters
    ----------
    gap : array_like
        Gaps of the interface at rest [m], >= 0 (a line or a map).
    params : memstribo.parameters.Parameters
        Uses ``hamaker_constant``, ``cutoff_distance``, ``work_of_adhesion`` (set: the Hamaker constant that gives
        it, ``12 pi D0^2 w``), ``vapour`` and ``surface_termination`` (the liquid, its contact angle and its
        liquid-like film, :mod:`memstribo.physics.vapours`; water on the oxide: ``water_contact_angle``),
        ``ambient_temperature``.
    relative_humidity : float
        RH (p / p_sat of the vapour) [-] in [0, 1); 0: no menisci.

    Returns
    -------
    tuple of float
        (Gamma, the van der Waals energy's mean, the bridges' work's mean) [J/m^2]; Gamma is not their sum (one work
        per element, the larger).
    """
    from memstribo.physics import rough_capillary, vapours

    g = np.asarray(gap, dtype=float)
    z0 = params["cutoff_distance"]
    hamaker = 12 * math.pi * z0**2 * params["work_of_adhesion"] if params["work_of_adhesion"] else \
        params["hamaker_constant"]
    vapour, termination = params["vapour"], params["surface_termination"]
    theta = vapours.vapour_contact_angle(vapour, termination, params["water_contact_angle"])
    temperature = params["ambient_temperature"]
    liquid = dict(films=2 * vapours.liquid_film_thickness(vapour, termination, relative_humidity) if theta < 0.5 *
                  math.pi else 0.0, temperature=temperature,
                  surface_tension=vapours.vapour_surface_tension(vapour, temperature),
                  molar_volume=vapours.vapour_properties(vapour)["molar_volume"])
    total = rough_capillary.rough_adhesion_energy(g, relative_humidity, hamaker, z0, theta, **liquid)
    vdw = float(np.mean(rough_capillary.vdw_adhesion_energy(g, hamaker, z0)))
    cap = float(np.mean(rough_capillary.capillary_adhesion_energy(g, relative_humidity, theta, **liquid)))
    return total, vdw, cap


def _surface_map(rq, corr, seed, size=None, points=None):
    """A Gaussian-correlated random height map (autocorrelation ``Rq^2 exp(-r^2 / l^2)``) [m], ``points`` square
    over ``size`` (default :data:`BEAM_MAP_POINTS` over :data:`BEAM_MAP_SIZE`): white noise filtered by the square
    root of its spectrum ``exp(-k^2 l^2 / 4)`` (FFT)."""
    size, points = size or BEAM_MAP_SIZE, points or BEAM_MAP_POINTS
    rng = np.random.default_rng(seed)
    k = 2.0 * math.pi * np.fft.fftfreq(points, size / points)
    spectrum = np.exp(-(k[:, None] ** 2 + k[None, :] ** 2) * corr**2 / 4.0)
    z = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal((points, points))) * np.sqrt(spectrum)))
    return z * (rq / z.std())


def _beam_gap(rq, corr, seed):
    # two independent rough surfaces (beam underside, substrate) as maps: the rigid beam rests on the highest summit
    # of their sum (a line would wet a whole cylinder-like band around its one contact and lose the plateau)
    from memstribo.physics.rough_capillary import rigid_interface_gaps

    return rigid_interface_gaps(_surface_map(rq, corr, seed), _surface_map(rq, corr, seed + 10_000))


def _beam_values(row, samples, realisations, calibration_coating, seed, base=None):
    rough = _roughness(row)
    if rough is None:
        return None, "no roughness stated or assumed for the microbeam"
    rq, corr, note = rough
    gaps = [_beam_gap(rq, corr, seed + k) for k in range(realisations)]
    values = np.zeros((len(samples), realisations))
    for i, sample in enumerate(samples):
        params, set_name = _base_parameters(row, sample, calibration_coating, base)
        if row.coating:
            params = _coated(params, row.coating)
        for k in range(realisations):
            if row.quantity == "adhesion_energy":
                values[i, k] = beam_work_of_separation(gaps[k], params, row.number("relative_humidity"))[0]
            else:  # trend: ratio of the work of separation at the high and the low RH of the row
                low, high = row.condition("relative_humidity_range")
                values[i, k] = (beam_work_of_separation(gaps[k], params, high)[0]
                                / beam_work_of_separation(gaps[k], params, low)[0])
    what = ("work of separation" if row.quantity == "adhesion_energy"
            else "ratio of the work of separation at RH {1:g} and {0:g}".format(*row.condition("relative_humidity_range")))
    case = (f"rigid microbeam on its substrate, {what} of the rough gap map (two surfaces Rq {rq * 1e9:.3g} nm each, "
            f"correlation length {corr * 1e9:.3g} nm, {note}): per element the larger of the van der Waals energy and the "
            f"water bridge's work (rough_capillary, DelRio et al. 2007), {set_name}")
    return values, case


def row_values(row, constant_samples=None, realisations=8, calibration_coating="OTS", seed=20260528, base=None):
    """The predicted values of one row over constant samples x roughness realisations.

    ``base``: the parameter set (with the user's ``--set`` values) every row starts from; default the lab's rule
    (silicon_oxide_air in air, silicon_thesis otherwise). The test structures of
    :mod:`memstribo.laboratory.cases` are dispatched by the row's geometry.

    Returns
    -------
    tuple
        (values of shape (n_samples, realisations), case text), or (None, reason) when the model cannot
        build the case.
    """
    samples = [{}] if constant_samples is None else list(constant_samples)
    if not samples:
        raise InputError("constant_samples must hold at least one dict (use [{}] for the nominal constants).")
    if realisations < 1:
        raise InputError(f"realisations must be at least 1, got {realisations}.")
    geometry = row.condition("geometry")
    from memstribo.physics.coating import available_coatings

    shipped = {c.upper() for c in available_coatings()}
    if row.coating and row.coating.upper() not in shipped:
        return None, f"coating {row.coating} is not among memstribo's coatings ({', '.join(sorted(shipped))})"
    if row.quantity in ("cycles_to_failure", "cycles_without_failure"):
        return None, ("memstribo's damage law (thesis 5.5) is the wear of a SAM coating on gear teeth; the start-stop life "
                      "of a bare polysilicon micromotor (hub wear and sticking) has no damage law in the model")
    from memstribo.laboratory.cases import case_values

    found = case_values(row, samples, realisations, base, calibration_coating, seed)
    if found is not NotImplemented:
        return found
    if row.quantity in FRICTION:  # flat and sidewall rows are cases (memstribo.laboratory.cases): the rest is not
        return None, (f"geometry {geometry}: the rotating rotor-on-hub contact is not a case memstribo builds "
                      "(it has flat contacts and involute gear teeth)")
    if row.quantity in ("adhesion_energy", "adhesion_trend_with_rh"):
        if geometry != "microbeam":
            return None, f"geometry {geometry}: adhesion is predicted for microbeams only"
        return _beam_values(row, samples, realisations, calibration_coating, seed, base)
    return None, f"no case for the quantity {row.quantity}"


def judge(row, values, weights=None, case=""):
    """A :class:`Prediction` from the values of a row (band, inside/outside)."""
    median, low, high = band(values, weights)
    if row.quantity == "adhesion_trend_with_rh":
        inside = bool((median > 1.0) == (row.value > 0))
    else:
        inside = bool(low <= row.value <= high)
    return Prediction(id=row.id, quantity=row.quantity, measured=row.value, status="predicted", values=values,
                      median=median, low=low, high=high, inside=inside, case=case)


def predict_row(row, constant_samples=None, realisations=8, weights=None, calibration_coating="OTS",
                seed=20260528, base=None) -> Prediction:
    """Predict one measurement at its conditions: median and 90 % band over realisations x constant samples.

    Parameters
    ----------
    row : memstribo.laboratory.data.Measurement
    constant_samples : list of dict, optional
        Parameter overrides, one dict per sample of the uncertain constants (default ``[{}]``: the nominal
        constants of the parameter set); ``coating_*`` keys apply to rows coated with ``calibration_coating``.
    realisations : int
        Roughness realisations per constant sample (seeds ``seed + k``).
    weights : array_like, optional
        Importance weights of the samples (a posterior); default equal.
    calibration_coating : str
        The coating the ``coating_*`` samples stand for.
    seed : int

    Returns
    -------
    Prediction
        "not predicted" with the reason where the model cannot build the case (never dropped).
    """
    values, case = row_values(row, constant_samples, realisations, calibration_coating, seed, base)
    if values is None:
        return _not_predicted(row, case)
    return judge(row, values, weights, case)


def predict_all(rows, constant_samples=None, realisations=8, weights=None, calibration_coating="OTS", base=None):
    """:func:`predict_row` for every row, in order (``base``: the parameter set every row starts from)."""
    return [predict_row(r, constant_samples, realisations, weights, calibration_coating, base=base) for r in rows]
