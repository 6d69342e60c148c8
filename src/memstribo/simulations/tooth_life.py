"""Will the tooth break, and how hot does the contact run: the meshing cycle's strength and temperature (MODEL §10).

:func:`tooth_life` reads a meshing-cycle dataset (:func:`memstribo.simulations.mesh.simulate_mesh`:
``c``, ``normal_force``, ``friction_force``, ``friction_force_instantaneous``,
``hertz_half_width``, ``energy_dissipated``) and returns the root stresses of pinion and gear
(:mod:`memstribo.physics.tooth_stress`), the probability of fracture on the first load and the
cycles to a 1 % probability of fracture in fatigue (:mod:`memstribo.physics.strength`), the flash
temperature of the contact and the bulk temperature rise (:mod:`memstribo.physics.thermal`), and
warnings where the contact temperature passes the coating's degradation temperature.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError
from memstribo.physics import strength, thermal, tooth_stress
from memstribo.references import cites

__all__ = ["TOOTH_LIFE_KEYS", "tooth_life", "with_tooth_life", "fracture_probability_within", "root_effective_area", "synthetic_cycle"]

#: keys of :func:`tooth_life` that are numbers (the mesh summary / JSON names; registered in memstribo.quantities)
TOOTH_LIFE_KEYS = ("root_stress_max", "root_stress_compressive_min", "fracture_probability",
                   "fracture_probability_pinion_tooth", "fracture_probability_gear_tooth", "cycles_to_fracture_p01",
                   "root_effective_area", "flash_temperature_max", "bulk_temperature_rise", "disc_temperature_rise",
                   "tooth_temperature_rise", "flash_diffusion_length_max", "contact_temperature_max")


def root_effective_area(shape, radius, normal_force, friction_force, face_width, weibull_modulus, friction_sign):
    """Effective stressed area A_eff of the loaded root fillet and flank of one tooth [m^2] (Weibull 1951).

    The tensile stress along the loaded side's outline (root land, fillet, flank up to the contact)
    is the bending stress of the chord at each height, ``Y_S 6 M(y) / (b s(y)^2)`` with the moment of
    the contact force about the chord's centre and the stress correction factor of the critical
    section, capped at the critical section's stress (:func:`tooth_stress.root_stress`); the etched
    sidewall of face width b carries it: ``A_eff = b integral (sigma / sigma_max)^m ds``.
    """
    peak = tooth_stress.root_stress(shape, radius, normal_force, friction_force, face_width, friction_sign)
    sigma_max = float(peak["tensile"])
    if sigma_max <= 0:
        return 0.0
    outline = shape.outline(points_fillet=120, points_flank=120, points_tip=2, points_root=30)
    point, normal, tangent = tooth_stress.flank_load_point(shape, radius)
    force = -float(normal_force) * normal + float(friction_sign) * float(friction_force) * tangent
    below = outline[:, 1] < point[1]
    pts = outline[below]
    s = 2.0 * pts[:, 0]
    moment = point[0] * force[1] - (point[1] - pts[:, 1]) * force[0]
    sigma = float(peak["stress_correction"]) * 6.0 * np.abs(moment) / (face_width * s * s)
    sigma = np.minimum(sigma, sigma_max)
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
    return strength.effective_area(arc, sigma, face_width, weibull_modulus)


def _get(dataset, name, fallback=None):
    if name in dataset:
        return np.asarray(dataset[name], dtype=float)
    if fallback is not None and fallback in dataset:
        return np.asarray(dataset[fallback], dtype=float)
    raise InputError(f"the meshing-cycle dataset has no variable '{name}' (tooth_life needs the output of "
                     "memstribo.simulations.mesh.simulate_mesh).")


@cites("iso_6336_3", "weibull_1951", "muhlstein_2001", "jaeger_1942", "blok_1937", "incropera_2007")
def tooth_life(dataset, params, pair=None, coating=None) -> dict:
    """Root stress, fracture probability, fatigue life and contact temperature of a meshing cycle.

    Parameters
    ----------
    dataset : xarray.Dataset or mapping of arrays
        The meshing cycle (:func:`memstribo.simulations.mesh.simulate_mesh`): coordinate ``c`` [m],
        ``normal_force`` [N] and ``friction_force`` [N] of the pair at each step,
        ``friction_force_instantaneous`` [N] (optional; else ``friction_force``), ``hertz_half_width``
        [m] and ``energy_dissipated`` [J] per step.
    params : memstribo.parameters.Parameters
        Gear, strength (``strength_characteristic``, ``weibull_modulus``, ``strength_reference_area``,
        ``fatigue_exponent``, ``fatigue_humidity_sensitivity``), thermal (``thermal_conductivity``,
        ``thermal_diffusivity``, ``emissivity``, ``hub_thermal_conductance``, ``heat_transfer_coefficient`` (in
        air only), ``ambient_temperature``), tooth form
        (``dedendum_coefficient``, ``root_fillet_coefficient``) and environment parameters.
    pair : memstribo.physics.gear.GearPair, optional
        Default: from ``params``.
    coating : memstribo.physics.coating.Coating, optional
        Its ``degradation_temperature`` [K] is compared with the contact temperature (a warning past it).

    Returns
    -------
    dict
        ``root_stress_max`` [pinion, gear] largest tensile root stress over the cycle [Pa];
        ``root_stress_compressive_min`` [pinion, gear] most compressive root stress [Pa];
        ``root_effective_area`` [pinion, gear] [m^2]; ``fracture_probability`` that any tooth of the pair
        breaks on the first load [-] and per tooth (``fracture_probability_pinion_tooth``,
        ``..._gear_tooth``); ``cycles_to_fracture_p01`` pinion revolutions to a 1 % probability that a
        tooth of the pair has broken (fatigue; ``None`` without tensile stress) [-];
        ``flash_temperature_max`` largest flash temperature rise of the contact over the cycle [K];
        ``bulk_temperature_rise`` of the flank of the hotter of the two gears, away from the flash: its disc's rise
        (the mean friction power over the hub's conductance, radiation and, in air, the air gap) plus the rise
        along the tooth from its root (a fin) [K]; ``disc_temperature_rise`` and ``tooth_temperature_rise``
        [pinion, gear] those two parts [K]; ``flash_diffusion_length_max`` how far the flash's heat reaches into
        a tooth, to compare with its thickness (the half-space's range) [m]; ``contact_temperature_max`` =
        ambient + bulk + flash [K]; ``root_stress`` per step ``{"pinion": array, "gear": array}`` [Pa];
        ``flash_temperature`` per step [K]; ``fatigue`` (the constants of :func:`fracture_probability_within`);
        ``warnings`` (list of str).
    """
    from memstribo.physics.gear import GearPair

    pair = GearPair.from_parameters(params) if pair is None else pair
    c = np.asarray(dataset["c"], dtype=float)
    fn = _get(dataset, "normal_force")
    ff = _get(dataset, "friction_force")
    ff_inst = _get(dataset, "friction_force_instantaneous", "friction_force")
    half = _get(dataset, "hertz_half_width")
    energy = _get(dataset, "energy_dissipated")
    warnings = []

    strength_result = _root_strength(pair, c, fn, ff, params, warnings)
    s_max, s_min, a_eff, p_tooth = (strength_result[k] for k in ("s_max", "s_min", "a_eff", "p_tooth"))
    p_pair, n01, fatigue, stresses = (strength_result[k] for k in ("p_pair", "n01", "fatigue", "stresses"))
    flash, bulk, contact, heat_path = _contact_temperature(pair, c, ff_inst, half, energy, params, coating, warnings)
    return {
        "root_stress_max": [s_max["pinion"], s_max["gear"]],
        "root_stress_compressive_min": [s_min["pinion"], s_min["gear"]],
        "root_effective_area": [a_eff["pinion"], a_eff["gear"]],
        "fracture_probability": p_pair,
        "fracture_probability_pinion_tooth": p_tooth["pinion"],
        "fracture_probability_gear_tooth": p_tooth["gear"],
        "cycles_to_fracture_p01": n01,
        "flash_temperature_max": float(np.max(flash)),
        "bulk_temperature_rise": bulk,
        "disc_temperature_rise": heat_path["disc"],
        "tooth_temperature_rise": heat_path["tooth"],
        "flash_diffusion_length_max": heat_path["flash_reach"],
        "contact_temperature_max": contact,
        "root_stress": {"pinion": stresses["pinion"]["tensile"], "gear": stresses["gear"]["tensile"]},
        "flash_temperature": flash,
        "fatigue": fatigue,
        "warnings": warnings,
    }


def _root_strength(pair, c, fn, ff, params, warnings) -> dict:
    """Root stresses over the cycle, first-load fracture risk per tooth and the fatigue constants (tooth_life)."""
    b = float(params["face_width"])
    m_w = float(params["weibull_modulus"])
    sigma_theta = float(params["strength_characteristic"])
    area_0 = float(params["strength_reference_area"])
    n_f = float(params["fatigue_exponent"])
    k_rh = float(params["fatigue_humidity_sensitivity"])
    rh = float(params["relative_humidity"]) if params["environment"] == "air" else 0.0
    strength.check_weibull(sigma_theta, m_w, area_0)
    # --- root stress over the cycle ---------------------------------------------------------------
    stresses = tooth_stress.cycle_root_stress(pair, c, fn, np.maximum(ff, 0.0), params["dedendum_coefficient"],
                                              params["root_fillet_coefficient"], face_width=b)
    sign = np.where(c >= 0.0, 1.0, -1.0)
    risk, p_tooth, a_eff, s_max, s_min = {}, {}, {}, {}, {}
    for name in ("pinion", "gear"):
        st = stresses[name]
        i = int(np.argmax(st["tensile"]))
        s_max[name] = float(st["tensile"][i])
        s_min[name] = float(np.min(st["compressive"]))
        a_eff[name] = root_effective_area(st["shape"], st["radius"][i], fn[i], max(ff[i], 0.0), b, m_w, sign[i])
        risk[name] = a_eff[name] / area_0 * (s_max[name] / sigma_theta) ** m_w
        p_tooth[name] = float(-math.expm1(-risk[name]))
    z1, z2 = pair.teeth_pinion, pair.teeth_gear
    p_pair = float(-math.expm1(-(z1 * risk["pinion"] + z2 * risk["gear"])))
    fatigue = {"risk_pinion": z1 * risk["pinion"], "risk_gear": z2 * risk["gear"],
               "gear_cycles_per_revolution": z1 / z2,
               "weibull_modulus": m_w, "fatigue_exponent": n_f, "relative_humidity": rh, "humidity_sensitivity": k_rh}
    n01 = _cycles_to(0.01, fatigue)
    if p_pair >= 0.01:
        warnings.append(f"the probability that a tooth breaks on the first load is {p_pair:.3g} (largest root stress "
                        f"{max(s_max.values()) / 1e9:.3g} GPa against a characteristic strength of "
                        f"{sigma_theta / 1e9:.3g} GPa)")

    return {"s_max": s_max, "s_min": s_min, "a_eff": a_eff, "p_tooth": p_tooth, "p_pair": p_pair, "n01": n01,
            "fatigue": fatigue, "stresses": stresses}


def _contact_temperature(pair, c, ff_inst, half, energy, params, coating, warnings):
    """(flash temperature rise per step [K], bulk rise [K], largest contact temperature [K]) of the cycle."""
    b = float(params["face_width"])
    # --- contact temperature ------------------------------------------------------------------------
    u1, u2 = pair.surface_velocities(c)
    v_s = np.abs(np.asarray(u1) - np.asarray(u2))
    flux = np.divide(np.maximum(ff_inst, 0.0) * v_s, 2.0 * half * b, out=np.zeros_like(v_s), where=half > 0)
    blok = thermal.blok_flash_temperature(flux, half, u1, u2, params["thermal_conductivity"],
                                          params["thermal_diffusivity"])
    flash = blok["flash"]
    heat = {"heated": (half > 0) & (flux > 0), "peclet": (blok["peclet_1"], blok["peclet_2"]),
            "energy": (energy * blok["share_1"], energy * (1.0 - blok["share_1"]))}
    heat_path = _heat_path(pair, c, half, heat, params, warnings)
    bulk = float(max(heat_path["bulk"]))
    ambient = float(params["ambient_temperature"])
    contact = ambient + bulk + float(np.max(flash))
    if coating is not None:
        limit = getattr(coating, "degradation_temperature", math.nan)
        if not math.isfinite(limit):
            raise InputError(f"coating {coating.name} has no degradation temperature: every coating set needs one.")
        if contact > limit:
            warnings.append(f"the contact temperature reaches {contact:.4g} K (ambient {ambient:.4g} K + bulk "
                            f"{bulk:.3g} K + flash {float(np.max(flash)):.3g} K), above the degradation temperature "
                            f"of {coating.name} ({limit:.4g} K)")
    return flash, bulk, contact, heat_path


def _length(metres: float) -> str:
    return f"{metres * 1e3:.3g} mm" if metres >= 1e-3 else f"{metres * 1e6:.3g} µm"


def _disc_rise(power, g_hub, emissivity, ambient, radiating_area, h_gap, gap_area) -> float:
    """The disc's rise with the radiation coefficient at the disc's own temperature [K].

    ``thermal.disc_temperature_rise`` with Eq. 1.9's h_r(T_amb + dT, T_amb), so that the radiated heat is
    eps sigma (T^4 - T_amb^4) exactly; h_r grows with dT, so the rise with h_r at the ambient (4 eps sigma
    T^3) bounds it above and brackets the root.
    """
    from scipy.optimize import brentq

    h_0 = thermal.radiation_coefficient(emissivity, ambient)
    upper = thermal.disc_temperature_rise(power, g_hub, h_0, radiating_area, h_gap, gap_area)
    if upper <= 0.0:
        return 0.0

    def balance(rise):
        h_r = thermal.radiation_coefficient(emissivity, ambient + rise, ambient)
        return rise - thermal.disc_temperature_rise(power, g_hub, h_r, radiating_area, h_gap, gap_area)

    if balance(upper) <= 0.0:
        return float(upper)
    return float(brentq(balance, 0.0, upper, xtol=1e-12 * max(upper, 1e-300), rtol=1e-12))


def _heat_path(pair, c, half, heat, params, warnings) -> dict:
    """Where the friction heat goes (issue 38, MODEL 7h; docs/thermal.md, "Bulk temperature").

    The mean power P_i into gear i (its Blok share of the energy dissipated over a meshing period)
    flows from the flank along the tooth to its root (the tooth a straight rectangular fin of the pitch
    thickness s, the face width b and the length from the root circle to the dissipation-weighted
    contact radius, its sides losing heat by radiation and, in air, across the air gap: Incropera
    Eq. 3.70), and leaves the disc through the hub, by radiation from both faces and, in air only,
    across the air gap. Returns the disc and tooth rises [K] per gear, the bulk rise (disc + tooth)
    per gear, and the flash half-space's largest diffusion length [m].
    """
    b = float(params["face_width"])
    k = float(params["thermal_conductivity"])
    kappa = float(params["thermal_diffusivity"])
    ambient = float(params["ambient_temperature"])
    air = params["environment"] == "air"
    h_r = thermal.radiation_coefficient(params["emissivity"], ambient)
    h_gap = float(params["heat_transfer_coefficient"]) if air else 0.0
    g_hub = float(params["hub_thermal_conductance"])
    period = pair.base_pitch / pair.contact_point_speed
    m = pair.module
    s = math.pi * m / 2.0  # tooth thickness on the pitch circle (no profile shift)
    area, perimeter = s * b, 2.0 * (s + b)
    h_fin = h_r + h_gap * s / perimeter  # the gap under the tooth's lower face only
    root = pair.pitch_radii - float(params["dedendum_coefficient"]) * m
    rho = np.abs(np.asarray(pair.radii_of_curvature(c), dtype=float))
    radius = np.sqrt(rho ** 2 + pair.base_radii[:, None] ** 2)
    out = {"disc": [], "tooth": [], "bulk": [], "length": [], "fin_ml": []}
    for i in (0, 1):
        energy_i = np.asarray(heat["energy"][i], dtype=float)
        power = float(np.sum(energy_i)) / period
        weights = np.maximum(energy_i, 0.0)
        r_mean = float(np.sum(weights * radius[i]) / np.sum(weights)) if np.sum(weights) > 0 else float(pair.pitch_radii[i])
        length = max(r_mean - float(root[i]), 0.0)
        tip = float(pair.tip_radii[i])
        disc = _disc_rise(power, g_hub, params["emissivity"], ambient, 2.0 * math.pi * tip ** 2, h_gap,
                          math.pi * tip ** 2)
        flank = thermal.fin_tip_excess_heat_input(power, disc, h_fin, perimeter, k, area, length)
        out["disc"].append(float(disc))
        out["tooth"].append(float(flank - disc))
        out["bulk"].append(float(flank))
        out["length"].append(length)
        out["fin_ml"].append(thermal.fin_parameter(h_fin, perimeter, k, area) * length)
    # the tooth carries the heat quasi-steadily while its diffusion time is short against a mesh
    t_tooth = max(out["length"]) ** 2 / kappa
    if t_tooth > pair.mesh_duration:
        warnings.append(f"the tooth's diffusion time L^2/kappa = {t_tooth:.3g} s exceeds the mesh duration "
                        f"{pair.mesh_duration:.3g} s: the tooth does not reach its steady conduction while it meshes, "
                        f"and its temperature rise ({max(out['tooth']):.3g} K) is an upper bound")
    # the flash temperature's half-space holds while the heat stays inside the tooth (its thickness s)
    heated = np.asarray(heat["heated"], dtype=bool)
    reach = np.zeros(half.size)
    for peclet in heat["peclet"]:
        ell = thermal.half_space_diffusion_length(half, np.maximum(peclet, 1e-12))
        reach = np.maximum(reach, np.where(heated, ell, 0.0))
    out["flash_reach"] = float(np.max(reach)) if reach.size else 0.0
    outside = int(np.sum(reach > s))
    if outside:
        low = float(np.min(reach[reach > s]))
        warnings.append(f"the flash temperature's half-space is outside its Péclet range at {outside} of "
                        f"{int(np.sum(heated))} heated steps: the heat reaches {_length(low)} to "
                        f"{_length(out['flash_reach'])} into the tooth (a / min(L, sqrt L)), beyond its thickness "
                        f"{_length(s)}; there the tooth's conduction carries it (bulk_temperature_rise), and the flash "
                        f"rise, whose logarithm runs out to that length, is an upper bound")
    return out


def _risk(fatigue, cycles):
    """The pair's risk of rupture after N pinion revolutions: each tooth's first-load risk times N_eff^(m/n)."""
    shift = 10.0 ** (fatigue["humidity_sensitivity"] * (fatigue["relative_humidity"]
                                                       - strength.FATIGUE_REFERENCE_HUMIDITY))
    power = fatigue["weibull_modulus"] / fatigue["fatigue_exponent"]
    n = np.asarray(cycles, dtype=float)
    gear_cycles = n * fatigue["gear_cycles_per_revolution"]
    return (fatigue["risk_pinion"] * np.maximum(n * shift, 1.0) ** power
            + fatigue["risk_gear"] * np.maximum(gear_cycles * shift, 1.0) ** power)


def _cycles_to(probability, fatigue):
    """Pinion revolutions at which the pair's fracture probability reaches ``probability`` (None: never)."""
    target = -math.log1p(-probability)
    if fatigue["risk_pinion"] + fatigue["risk_gear"] <= 0:
        return None
    if float(_risk(fatigue, 1.0)) >= target:
        return 1.0
    log_hi = 1.0
    while float(_risk(fatigue, 10.0**log_hi)) < target:
        log_hi += 10.0
        if log_hi > 300:
            return None
    lo, hi = 0.0, log_hi  # bisection on log10 N: the risk rises monotonically with N
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if float(_risk(fatigue, 10.0**mid)) < target:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-13:
            break
    return 10.0 ** (0.5 * (lo + hi))


def fracture_probability_within(result, cycles):
    """Probability that a tooth of the pair has broken within ``cycles`` pinion revolutions [-].

    ``P(N) = 1 - exp(-sum_teeth R_tooth N_eff^(m/n))`` with each tooth's first-load risk of :func:`tooth_life`
    (``result["fatigue"]``), a gear tooth seeing z1/z2 load cycles per pinion revolution, and
    ``N_eff = N 10^(k_RH (RH - 0.4))`` (:mod:`memstribo.physics.strength`, Eq. (2)), at least 1 (the first
    load). For the damage and lifetime figure, beside the coating's Omega(N).

    Parameters
    ----------
    result : dict
        The return of :func:`tooth_life`.
    cycles : array_like
        Pinion revolutions N [-] (>= 0).
    """
    from memstribo.checks import as_array

    n = as_array(cycles, "cycles", "", nonnegative=True)
    out = -np.expm1(-_risk(result["fatigue"], n))
    return float(out) if np.ndim(out) == 0 else out


def synthetic_cycle(params, cof=0.3, steps=41):
    """A meshing-cycle dataset without the contact solve, for tests and quick torque sweeps (dict of arrays).

    The normal force of each pair is the torque's load case shared by the dry load-sharing function
    (MODEL 7b), the friction force ``cof`` times it, the contact half-width Hertz's and the energy
    dissipated per step the friction force times the sliding distance of the step.
    """
    from memstribo.materials.pair import contact_modulus_of
    from memstribo.physics.gear import GearPair, hertz_line_contact, tangential_force

    pair = GearPair.from_parameters(params)
    c = pair.positions(steps)
    f_n_total = float(tangential_force(params["drive_torque"], pair.pitch_radii[0])) / math.cos(pair.pressure_angle)
    fn = pair.load_share(c, "dry") * f_n_total
    hertz = hertz_line_contact(fn, params["face_width"], pair.effective_radius(c), contact_modulus_of(params))
    ff = cof * fn
    dt = np.gradient(pair.time(c))
    sliding = np.abs(pair.sliding_velocity(c)) * dt
    return {"c": c, "normal_force": fn, "friction_force": ff, "friction_force_instantaneous": ff,
            "hertz_half_width": np.asarray(hertz.half_width), "energy_dissipated": ff * sliding}


def with_tooth_life(dataset, params, coating=None):
    """The meshing-cycle dataset with its tooth strength and contact temperature (MODEL §10), in place.

    Adds the per-step variables ``root_stress_pinion``, ``root_stress_gear`` [Pa] and
    ``flash_temperature`` [K], the attribute ``tooth_life`` (JSON of the :data:`TOOTH_LIFE_KEYS`, read by
    :func:`memstribo.simulations.mesh.summarize`), and the warnings of :func:`tooth_life` to the
    dataset's ``warnings``. A tooth form that the root-stress method cannot draw (an InputError of
    :func:`tooth_life`) leaves the keys null and says why in a warning: the friction verdict does not
    depend on it.
    """
    import json

    import xarray as xr

    from memstribo.quantities import attrs as quantity_attrs

    warnings = json.loads(dataset.attrs.get("warnings", "[]"))
    try:
        result = tooth_life(dataset, params, coating=coating)
    except InputError as exc:
        dataset.attrs["tooth_life"] = json.dumps({key: None for key in TOOTH_LIFE_KEYS})
        dataset.attrs["warnings"] = json.dumps(warnings + [f"tooth strength and temperature not computed: {exc}"])
        return dataset
    for name, values in (("root_stress_pinion", result["root_stress"]["pinion"]),
                         ("root_stress_gear", result["root_stress"]["gear"]),
                         ("flash_temperature", result["flash_temperature"])):
        dataset[name] = xr.Variable(("step",), np.asarray(values, dtype=float), attrs=quantity_attrs(name))
    dataset.attrs["tooth_life"] = json.dumps({key: result[key] for key in TOOTH_LIFE_KEYS})
    dataset.attrs["warnings"] = json.dumps(warnings + list(result["warnings"]))
    return dataset
