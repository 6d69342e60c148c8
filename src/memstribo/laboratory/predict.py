"""Each measurement's case built with the paper's conditions, predicted with its uncertainty (MODEL 7e).

A case is a flat or sidewall contact sliding under the paper's contact pressure (the fixed-load
sliding structure of :mod:`memstribo.simulations.sliding` on a rough counter profile), or a microbeam
adhered to its substrate (the work of separation of the rough gap field under the library's
Lennard-Jones surface law and menisci). The roughness is synthesised from the paper's Rq and
correlation length (or a stated assumption) with one seed per realisation. Each prediction is the
median and the 90 % band (5th to 95th percentile) over roughness realisations x constant samples;
a row whose case the model cannot build is returned as "not predicted" with the reason.

Speed (what the generator uses): friction cases slide the 2-block structure over 1 um in steps of
the bond length on a 2.4 um synthetic profile (about 0.03 s each); microbeams average over a 20 um
line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["Prediction", "predict_row", "predict_all", "band", "row_values", "static_cof", "FRICTION",
           "SLIDE_DISTANCE"]

FRICTION = ("static_cof", "kinetic_cof")
#: sliding distance of a friction case [m] and the length of its synthetic profile [m]
SLIDE_DISTANCE = 1.0e-6
PROFILE_LENGTH = 2.4e-6
#: length of a microbeam's synthetic gap line [m]
BEAM_LENGTH = 20e-6
#: the sidewall roughness when the source gives none: AFM of a polysilicon MEMS sidewall (van Spengen 2010)
SIDEWALL_ROUGHNESS = {"rq": 10.3e-9, "correlation_length": 83e-9,
                      "reason": "not in the cited record; polysilicon sidewall AFM, Rq 10.3 nm, exponential "
                                "correlation length 83 nm (van Spengen et al. 2010, doi:10.3762/bjnano.1.20)"}
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


def _roughness(row):
    """(rq, correlation_length, note) of the row's surfaces, or None for the parameter set's default."""
    for key in ("roughness", "roughness_assumed"):
        value = row.condition(key)
        if isinstance(value, dict) and "rq" in value:
            note = "stated" if key == "roughness" else f"assumed: {value.get('reason', '')}"
            return float(value["rq"]), float(value["correlation_length"]), note
    if row.condition("geometry") == "sidewall":
        r = SIDEWALL_ROUGHNESS
        return r["rq"], r["correlation_length"], "assumed: " + r["reason"]
    return None


def _base_parameters(row, sample, calibration_coating):
    from memstribo.parameters import get_parameter_values
    from memstribo.parameters.definitions import SPECS

    name = "silicon_oxide_air" if row.environment == "air" else "silicon_thesis"
    params = get_parameter_values(name)
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
def _friction_values(row, samples, realisations, calibration_coating, seed):
    from memstribo.simulations import sliding

    pressure = row.number("contact_pressure")
    rough = _roughness(row)
    values = np.zeros((len(samples), realisations))
    profiles = {}
    case = ""
    for i, sample in enumerate(samples):
        params, set_name = _base_parameters(row, sample, calibration_coating)
        if row.coating:
            params = _coated(params, row.coating)
        area = int(params["slider_blocks"]) * params["adhesive_width"] ** 2
        load = pressure * area
        for k in range(realisations):
            if k not in profiles:
                if rough is None:
                    rq, corr = params["roughness_rq"], math.sqrt(2.0) * params["roughness_rq"] / params["roughness_rms_slope"]
                else:
                    rq, corr = rough[0], rough[1]
                profiles[k] = _profile(rq, corr, PROFILE_LENGTH, seed + k)
            slid = sliding.slide_fixed_load(params, profiles[k], load=load, distance=SLIDE_DISTANCE)
            values[i, k] = (static_cof(slid, params) if row.quantity == "static_cof"
                            else sliding.summarize(slid).cof_mean)
        if not case:
            note = "roughness: the parameter set's (the thesis's statistics; the source states none)" if rough is None \
                else f"roughness Rq {rough[0] * 1e9:.3g} nm, correlation length {rough[1] * 1e9:.3g} nm ({rough[2]})"
            case = (f"fixed-load sliding structure ({int(params['slider_blocks'])} nanoblocks) over a synthetic profile, "
                    f"{set_name}{' + ' + row.coating + ' (U_chem off)' if row.coating else ''}, nominal pressure "
                    f"{pressure:.3g} Pa -> load {load:.3g} N on the structure; {note}; "
                    + ("static COF: the start-up force of the structure's bonds at rest (one crystal registry: "
                       "their lateral peak, 1.27 U / D, MODEL 7f) plus its elastic friction, over F_N + F_adh, "
                       "averaged over the rest positions of the slide"
                       if row.quantity == "static_cof" else "kinetic COF = cof_mean"))
    return values, case


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


@cites("maugis_1992", "israelachvili_2011")
def beam_work_of_separation(gap, params, relative_humidity):
    """Work of separation of a rigid rough interface [J/m^2]: vdW surface law + menisci, averaged over the gap line.

    The two surfaces are pulled apart from the rough gap field ``gap`` (0 at the touching summit) to
    infinity; the work per apparent area is the integral over the extra separation s of the mean
    attraction: the Lennard-Jones (9-3) surface stress of :func:`memstribo.physics.adhesion.lennard_jones_surface_stress`
    at h = z0 + g + s (its integral from z0 is w, so a fully touching interface gives w), plus the
    meniscus pressure gamma / r_K wherever g + s <= h_c (:func:`memstribo.physics.capillary.capillary_pressure`,
    r_K from RH, h_c = r_K (cos theta1 + cos theta2)), which integrates to 2 gamma cos(theta) on a fully wetted
    interface.

    Parameters
    ----------
    gap : array_like
        Gaps of the interface at rest [m], >= 0.
    params : memstribo.parameters.Parameters
        Uses ``hamaker_constant``, ``cutoff_distance``, ``work_of_adhesion`` (unset: A / (12 pi D0^2), (3-34)),
        ``water_contact_angle``, ``temperature``.
    relative_humidity : float
        RH [-] in [0, 1); 0: no menisci.

    Returns
    -------
    tuple of float
        (total, vdW part, capillary part) [J/m^2].
    """
    from memstribo.physics import capillary
    from memstribo.physics.adhesion import lennard_jones_surface_stress

    g = np.asarray(gap, dtype=float)
    z0 = params["cutoff_distance"]
    w = params["work_of_adhesion"] or params["hamaker_constant"] / (12 * math.pi * z0**2)
    s = np.concatenate([[0.0], np.geomspace(1e-3 * z0, 2e-6, 600)])
    stress = np.array([np.mean(-lennard_jones_surface_stress(z0 + g + si, w, z0)) for si in s])
    vdw = float(np.trapezoid(stress, s))
    cap = 0.0
    if relative_humidity > 0:
        theta = params["water_contact_angle"]
        r_k = capillary.kelvin_radius(relative_humidity, params["ambient_temperature"])
        h_c = capillary.condensation_height(r_k, theta, theta)
        if h_c > 0:
            sc = np.linspace(0.0, h_c, 801)
            pressure = np.array([np.mean(capillary.capillary_pressure(g + si, r_k, theta, theta)) for si in sc])
            cap = float(np.trapezoid(pressure, sc))
    return vdw + cap, vdw, cap


def _beam_gap(rq, corr, seed):
    # two independent rough surfaces (beam underside, substrate); the rigid beam rests on the highest summit
    a = _profile(rq, corr, BEAM_LENGTH, seed).z
    b = _profile(rq, corr, BEAM_LENGTH, seed + 10_000).z
    s = a + b
    return s.max() - s


def _beam_values(row, samples, realisations, calibration_coating, seed):
    rough = _roughness(row)
    if rough is None:
        return None, "no roughness stated or assumed for the microbeam"
    rq, corr, note = rough
    gaps = [_beam_gap(rq, corr, seed + k) for k in range(realisations)]
    values = np.zeros((len(samples), realisations))
    for i, sample in enumerate(samples):
        params, set_name = _base_parameters(row, sample, calibration_coating)
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
    case = (f"rigid microbeam on its substrate, {what} of the rough gap line (two surfaces Rq {rq * 1e9:.3g} nm each, "
            f"correlation length {corr * 1e9:.3g} nm, {note}): Lennard-Jones surface law + menisci, {set_name}")
    return values, case


def row_values(row, constant_samples=None, realisations=8, calibration_coating="OTS", seed=20260528):
    """The predicted values of one row over constant samples x roughness realisations.

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
    surface = str(row.condition("surface")).lower()
    if "nitride" in surface:
        return None, "silicon nitride against polysilicon: memstribo has no silicon nitride pair (parameter sets are silicon and its oxide)"
    if row.coating and row.coating.upper() not in ("OTS", "FDTS"):
        return None, f"coating {row.coating} is not among memstribo's coatings (OTS, FDTS)"
    if row.quantity in ("cycles_to_failure", "cycles_without_failure"):
        return None, ("memstribo's damage law (thesis 5.5) is the wear of a SAM coating on gear teeth; the start-stop life "
                      "of a bare polysilicon micromotor (hub wear and sticking) has no damage law in the model")
    if row.quantity in FRICTION:
        if geometry not in ("flat", "sidewall"):
            return None, (f"geometry {geometry}: the rotating rotor-on-hub contact is not a case memstribo builds "
                          "(it has flat contacts and involute gear teeth)")
        if row.number("contact_pressure") is None:
            return None, ("the load is not stated in the cited record; the model's COF depends on the load "
                          "(adhesion-dominated, falling with load), so there is no prediction without it")
        if row.environment == "air" and row.number("relative_humidity") is None:
            return None, "the humidity is not stated and no assumption is declared"
        return _friction_values(row, samples, realisations, calibration_coating, seed)
    if row.quantity in ("adhesion_energy", "adhesion_trend_with_rh"):
        if geometry != "microbeam":
            return None, f"geometry {geometry}: adhesion is predicted for microbeams only"
        return _beam_values(row, samples, realisations, calibration_coating, seed)
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
                seed=20260528) -> Prediction:
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
    values, case = row_values(row, constant_samples, realisations, calibration_coating, seed)
    if values is None:
        return _not_predicted(row, case)
    return judge(row, values, weights, case)


def predict_all(rows, constant_samples=None, realisations=8, weights=None, calibration_coating="OTS"):
    """:func:`predict_row` for every row, in order."""
    return [predict_row(r, constant_samples, realisations, weights, calibration_coating) for r in rows]
