"""The verdict of a meshing cycle: friction averaged over sliding, R(c) of all pairs in mesh, the stiction margin,
the mesh efficiency, the warnings, and the summary (the keys of ``memstribo mesh --json``)."""

from __future__ import annotations

import math

import numpy as np

from memstribo.materials.pair import dundurs_beta
from memstribo.physics.gear import tangential_force
from memstribo.quantities import unit as quantity_unit


def cycle_verdict(params, setup, cycle) -> dict:
    """The verdict of a cycle's steps: friction averaged over the sliding distance and split by mechanism,
    energies, R(c) of all pairs in mesh, the stiction margin F_t - R(c), the mesh efficiency, the friction
    shear stress and the warnings (MODEL 7b; thesis 4-27). Forces [N], energies [J], stresses [Pa]."""
    pair = setup.pair
    out, kin, f_el = cycle["out"], cycle["kin"], cycle["f_el"]
    sliding = kin["sliding"]
    f_t = float(tangential_force(params["drive_torque"], pair.pitch_radii[0]))
    v = dict(f_t=f_t, denominator=setup.load + out["f_adh"])
    v["e_chem"], v["e_vdw"] = out["f_chem"] * sliding, out["f_vdw"] * sliding
    v["e_el"] = f_el * sliding
    v["e_cap"] = out["f_cap"] * sliding
    energy = v["energy"] = v["e_chem"] + v["e_vdw"] + v["e_el"] + v["e_cap"]
    averaging = v["averaging"] = params["friction_averaging_distance"] or params["atomic_pitch"]
    # every part averaged alike (the average is linear), so the parts add up to the friction force
    v["f_chem_avg"], v["f_vdw_avg"], v["f_el_avg"], v["f_cap_avg"] = (sliding_average(f, sliding, averaging) for f in (
        out["f_chem"], out["f_vdw"], f_el, out["f_cap"]))
    friction_avg = v["friction_avg"] = v["f_chem_avg"] + v["f_vdw_avg"] + v["f_el_avg"] + v["f_cap_avg"]
    v["resisting"] = resisting_force(setup.positions, friction_avg, pair.first_contact, pair.last_contact,
                                     pair.base_pitch)
    v["margin"] = f_t - v["resisting"]
    # mesh efficiency: friction power of all pairs in mesh over the input power T omega1 (MODEL 7b)
    power_pair = np.divide(energy, setup.step_time, out=np.zeros_like(energy), where=setup.step_time > 0)
    power_loss = resisting_force(setup.positions, power_pair, pair.first_contact, pair.last_contact, pair.base_pitch)
    input_power = v["input_power"] = float(params["drive_torque"]) * float(pair.pinion_speed)
    v["efficiency"] = 1.0 - power_loss / input_power
    period = pair.base_pitch / pair.contact_point_speed
    v["efficiency_mean"] = 1.0 - float(energy.sum()) / (input_power * period)
    # mean friction stress over the real contact area, against the ideal shear strength
    contact_area = out["contact_width"] * setup.effective_face_width
    v["shear_stress"] = np.divide(friction_avg, contact_area, out=np.zeros_like(friction_avg), where=contact_area > 0)
    beta = dundurs_beta(params["youngs_modulus"], params["poisson_ratio"], params["counter_youngs_modulus"],
                        params["counter_poisson_ratio"])
    v["undetermined"] = _undetermined(params, cycle, beta)
    v["warnings"] = _warnings(params, out, setup, v["shear_stress"], v["efficiency"], v["undetermined"])
    return v


def _undetermined(params, cycle, beta) -> str:
    """Why the cycle gives no verdict (an unsettled friction fixed point of dissimilar teeth), or "" (issue #25)."""
    if cycle["converged"]:
        return ""
    changes = cycle.get("changes")
    by = (f": between the last two passes the margin changes by {changes[0] * 100:.2g} % of itself and the mean COF by "
          f"{changes[1] * 100:.2g} %" if changes else "")
    return (f"the F_t/F_f fixed point of dissimilar materials (Dundurs beta {beta:.3g}) did not settle within "
            f"mesh_friction_passes = {int(params['mesh_friction_passes'])} passes{by} (goal < 0.1 %): the verdict is "
            "undetermined, no COF or stiction flag is a result; raise mesh_friction_passes")


#: The keys of the summary (``memstribo mesh --json``) and of the ensemble verdict, with their units from the
#: vocabulary (:mod:`memstribo.quantities`).
SUMMARY_KEYS = ("cof_mean", "cof_max", "cof_chemical", "cof_vdw", "cof_elastic", "friction_force_mean",
                "friction_force_max", "adhesion_force_mean", "normal_force_max", "tangential_force", "stiction",
                "stiction_margin", "steps", "sliding_distance", "energy_dissipated", "energy_chemical",
                "energy_vdw", "energy_elastic", "unconverged_steps", "window_exceeded_steps",
                "max_contact_pressure", "steps_above_elastic_limit", "resisting_force_max", "normal_force_total",
                "mesh_efficiency", "mesh_efficiency_min", "max_shear_stress", "load_case", "interface_model",
                "contact_adhesion", "mesh_contact", "environment", "relative_humidity", "cof_capillary",
                "capillary_pull_off_mean", "capillary_adhesion_force_mean",
                "energy_capillary", "roughness_rows", "warnings", "step_converged", "step_change_margin",
                "step_change_cof", "steps_checked", "realisations", "stiction_probability", "stiction_count",
                "stiction_probability_ci", "stiction_probability_text",
                "stiction_margin_median", "stiction_margin_p05", "stiction_margin_p95", "cof_mean_median",
                "cof_mean_p05", "cof_mean_p95", "mesh_efficiency_median", "mesh_efficiency_p05",
                "mesh_efficiency_p95", "per_realisation", "startup_margin", "startup_stiction", "static_cof_max",
                "stiction_mode", "stiction_margin_capped", "startup_margin_capped", "stiction_mode_capped",
                "friction_share_rigid", "friction_share_overstrength", "plastic_fraction", "plastic_fraction_max",
                "plastic_steps", "stiction_margin_uncapped", "startup_margin_uncapped", "cof_mean_uncapped",
                "hardness", "window", "lattice_registry", "startup_stiction_probability", "startup_stiction_count",
                "startup_stiction_probability_ci", "startup_stiction_probability_text", "startup_margin_median",
                "startup_margin_p05", "startup_margin_p95", "startup_load_torque_limit")


SUMMARY_UNITS = {key: quantity_unit(key) for key in SUMMARY_KEYS}


#: Below this relative humidity the Kelvin radius of water at 25 degC is below one molecular diameter (0.311 nm,
#: :func:`memstribo.physics.capillary.molecular_kelvin_radius`): an adsorbed film, not a meniscus (RH 0.185;
#: MODEL 7g, docs/humidity.md).
_LOWEST_MENISCUS_HUMIDITY = 0.185


def sliding_average(values, sliding, distance):
    """Energy-per-distance average of a force over a window of sliding distance (MODEL 7b).

    Step ``i`` slides ``sliding[i]`` and dissipates ``values[i] * sliding[i]`` uniformly over it;
    the result at step ``i`` is the energy dissipated within ``distance / 2`` of sliding on either
    side of the step's midpoint, divided by the sliding distance that window covers (shorter at
    the ends of the path). Steps that do not slide (the pitch point) get the average of their
    neighbourhood. This makes the friction force a property of a physical sliding distance,
    not of the step size.

    Parameters
    ----------
    values : array_like
        Force at each step [N] (e.g. the friction force of the bond population).
    sliding : array_like
        Sliding distance of each step [m], >= 0.
    distance : float
        Averaging distance [m], > 0.

    Returns
    -------
    ndarray
        Averaged force [N].
    """
    values = np.asarray(values, dtype=float)
    sliding = np.asarray(sliding, dtype=float)
    edges = np.concatenate([[0.0], np.cumsum(sliding)])
    energy = np.concatenate([[0.0], np.cumsum(values * sliding)])
    centre = 0.5 * (edges[:-1] + edges[1:])
    lo = np.clip(centre - 0.5 * distance, edges[0], edges[-1])
    hi = np.clip(centre + 0.5 * distance, edges[0], edges[-1])
    covered = hi - lo
    # cumulative energy is piecewise linear in the cumulative sliding distance
    e_hi = np.interp(hi, edges, energy)
    e_lo = np.interp(lo, edges, energy)
    return np.divide(e_hi - e_lo, covered, out=values.copy(), where=covered > 0)


def resisting_force(positions, friction_force, first_contact, last_contact, base_pitch, weight=None):
    """R(c): the friction forces of every tooth pair in mesh when one pair is at c [N] (MODEL 7b).

    The other pairs sit whole base pitches away on the path of contact, at ``c + k p_b`` for
    every integer k with ``c_f <= c + k p_b <= c_l``; each resists the drive with its friction
    force at its own position (taken from the same cycle, interpolated in c). ``weight``: a function
    of the pairs' positions [m] that scales each pair's force (the start-up torque balance's moment
    arm, :func:`memstribo.simulations.mesh.limits.startup_resisting_force`); None: 1.
    """
    c = np.asarray(positions, dtype=float)
    total = np.zeros_like(c)
    k_max = int(math.ceil((last_contact - first_contact) / base_pitch)) + 1
    for k in range(-k_max, k_max + 1):
        other = c + k * base_pitch
        on_path = (other >= first_contact - 1e-15) & (other <= last_contact + 1e-15)
        force = np.interp(other, c, friction_force)
        if weight is not None:
            force = force * weight(np.clip(other, first_contact, last_contact))
        total += np.where(on_path, force, 0.0)
    return total


def _window_advice(params) -> str:
    """What to do about a window too short: a set ``mesh_window`` stays as set, a sized one grew until memory."""
    if params["mesh_window"] is not None:
        return "mesh_window is set; unset it and the window sizes itself"
    return "the window grew as far as the memory bound allows (use a coarser mesh_grid_spacing)"


def _warnings(params, out, setup, shear_stress, efficiency, undetermined="") -> list[str]:
    """Physical limits and numerical trouble of a cycle, as sentences (MODEL 7c)."""
    warnings = []
    if setup.hertz_width_ratio > 0.2:
        warnings.append(f"the Hertz half-width reaches {setup.hertz_width_ratio:.2g} of the radius of relative "
                        "curvature: the half-space contact model (a << R) is stretched")
    unconverged = int((out["unconverged"] > 0).sum())
    if unconverged:
        warnings.append(f"the contact solve did not converge in {unconverged} step(s) (flagged in contact_converged)")
    exceeded = int((out["window_exceeded"] > 0).sum())
    if exceeded:
        warnings.append(f"the contact reached the ends of the {setup.grid.size * setup.grid_spacing * 1e6:.3g} µm window "
                        f"in {exceeded} step(s): {_window_advice(params)}")
    if params["interface_model"] == "gap" and (out["vdw_edge"] > 0).any():
        warnings.append(f"the gap at the window's ends is below vdw_cutoff in {int((out['vdw_edge'] > 0).sum())} "
                        f"step(s): vdW beyond the window is missed; {_window_advice(params)}")
    above = int((out["max_pressure"] > params["elastic_limit_pressure"]).sum())
    if above and not out["plastic_elements"].any():  # with plastic flow: the hardness cap's sentence (limits)
        warnings.append(f"the rough contact's peak pressure exceeds the elastic limit of silicon "
                        f"({params['elastic_limit_pressure'] / 1e9:.3g} GPa) in {above} step(s)")
    # atomic blocks past the threshold strain: one sentence for the cycle with what they do to the verdict
    # (memstribo.simulations.mesh.limits.local_limits_warning, MODEL 7d)
    peak_shear = float(np.max(shear_stress)) if shear_stress.size else 0.0
    if peak_shear > params["ideal_shear_strength"]:
        warnings.append(f"the friction stress over the real contact reaches {peak_shear / 1e9:.3g} GPa, above the ideal "
                        f"shear strength of silicon ({params['ideal_shear_strength'] / 1e9:.3g} GPa): the teeth "
                        "would shear and wear rather than slide")
    if undetermined:
        warnings.append(undetermined)
    if (efficiency <= 0).any():
        warnings.append(f"the instantaneous mesh efficiency is zero or below in {int((efficiency <= 0).sum())} "
                        "step(s): friction takes more power than the drive supplies there")
    if params["environment"] == "air":
        from memstribo.physics.capillary import molecular_kelvin_radius
        from memstribo.physics.vapours import vapour_state

        state = vapour_state(params)
        if state["ratio"] > 0.0 and state["kelvin"] == 0.0:
            warnings.append(f"{state['vapour']} at p/p_sat {state['ratio']:g} (relative humidity for water): the Kelvin "
                            f"radius ({state['kelvin_raw'] * 1e9:.2g} nm) is below one molecular diameter "
                            f"({molecular_kelvin_radius(state['molar_volume']) * 1e9:.3g} nm), a molecular size: the "
                            "condensate is an adsorbed film, not a meniscus, and no meniscus force or rupture is "
                            "counted (MODEL 7g, docs/humidity.md)")
    return warnings


def summarize(dataset) -> dict:
    """The summary of a meshing cycle: the keys of ``memstribo mesh --json`` (SI).

    One COF per meaning: ``cof_mean`` is the cycle's dissipated energy over
    ``integral (F_N + F_adh) ds`` (3-7 over the cycle), and its split by mechanism
    (``cof_chemical``, ``cof_vdw``, ``cof_elastic``) is the same ratio per mechanism, so the
    parts add up to ``cof_mean`` exactly. The stiction verdict: ``resisting_force_max`` is the
    largest R(c), ``stiction_margin`` = ``tangential_force`` - ``resisting_force_max`` (MODEL 7b). ``verdict`` is
    "running stiction", "start-up stiction", "no stiction" or "undetermined" (an unsettled fixed point of dissimilar teeth: ``stiction`` is then
    None and ``undetermined_reason`` says why; the numbers are the last pass's, not a result).
    """
    import json

    time = np.asarray(dataset["time"])
    weights = np.gradient(time) if time.size > 1 else np.ones(1)
    weights = weights / weights.sum()
    sliding = np.asarray(dataset["sliding_distance"])
    denominator = np.asarray(dataset["normal_force"] + dataset["adhesion_force"])
    work = float((denominator * sliding).sum())
    energy = {k: float(dataset[k].sum()) for k in ("energy_chemical", "energy_vdw", "energy_elastic",
                                                   "energy_capillary") if k in dataset}
    split = {f"cof_{k.split('_')[1]}": (v / work if work > 0 else 0.0) for k, v in energy.items()}
    friction = np.asarray(dataset["friction_force"])
    resisting = np.asarray(dataset["resisting_force"])
    f_t = float(dataset.attrs["tangential_force_total"])
    margin = f_t - float(resisting.max())
    efficiency = np.asarray(dataset["mesh_efficiency"])
    undetermined = str(dataset.attrs.get("undetermined_reason", ""))
    return {
        "verdict": _verdict_word(dataset, f_t, margin, undetermined),
        "undetermined_reason": undetermined,
        "cof_mean": split["cof_chemical"] + split["cof_vdw"] + split["cof_elastic"] + split.get("cof_capillary", 0.0),
        "cof_max": float(dataset["cof"].max()),
        **split,
        "friction_force_mean": float((friction * weights).sum()),
        "friction_force_max": float(friction.max()),
        "resisting_force_max": float(resisting.max()),
        "adhesion_force_mean": float((np.asarray(dataset["adhesion_force"]) * weights).sum()),
        "normal_force_max": float(dataset["normal_force"].max()),
        "normal_force_total": float(dataset.attrs["normal_force_total"]),
        "tangential_force": f_t,
        "stiction": None if undetermined else bool(margin < 0),
        "stiction_margin": margin,
        "mesh_efficiency": float(dataset.attrs["mesh_efficiency_mean"]),
        "mesh_efficiency_min": float(efficiency.min()),
        "max_shear_stress": float(dataset["friction_shear_stress"].max()),
        "steps": int(time.size),
        "sliding_distance": float(sliding.sum()),
        "energy_dissipated": float(sum(energy.values())),
        **energy,
        "unconverged_steps": int((~np.asarray(dataset["contact_converged"], dtype=bool)).sum()),
        "window_exceeded_steps": int(np.asarray(dataset["window_exceeded"], dtype=bool).sum()),
        "max_contact_pressure": float(dataset["max_contact_pressure"].max()),
        "steps_above_elastic_limit": int((np.asarray(dataset["max_contact_pressure"])
                                          > dataset.attrs.get("elastic_limit_pressure", np.inf)).sum()),
        "load_case": str(dataset.attrs["load_case"]),
        "environment": str(dataset.attrs.get("environment", "vacuum")),
        "relative_humidity": float(dataset.attrs.get("relative_humidity", 0.0)),
        "interface_model": str(dataset.attrs["interface_model"]),
        "contact_adhesion": str(dataset.attrs["contact_adhesion"]),
        "mesh_contact": str(dataset.attrs.get("mesh_contact", "line")),
        "roughness_rows": str(dataset.attrs["roughness_rows"]),
        **_limit_summary(dataset, f_t, margin),
        # in air: the force to pull the flanks apart against the rough rows' water bridges (issue #28)
        **({"capillary_pull_off_mean": float((np.asarray(dataset["capillary_pull_off"]) * weights).sum()),
            "capillary_adhesion_force_mean": float((np.asarray(dataset["capillary_adhesion_force"]) * weights).sum())}
           if "capillary_pull_off" in dataset else {}),
        **json.loads(dataset.attrs.get("tooth_life", "{}")),  # root stress, fracture, temperature (MODEL §10)
        "fitted_constants": json.loads(dataset.attrs.get("fitted_constants", "[]")),  # with their fit conditions
        "warnings": json.loads(dataset.attrs.get("warnings", "[]")),
    }


def _verdict_word(dataset, f_t, margin, undetermined) -> str:
    """"undetermined" (an unsettled fixed point, issue #25), "running stiction", "start-up stiction" (MODEL 7d, where
    the dataset has the start-up verdict) or "no stiction"."""
    if undetermined:
        return "undetermined"
    if margin < 0:
        return "running stiction"
    if "startup_resisting_force" in dataset and f_t - float(dataset["startup_resisting_force"].max()) < 0:
        return "start-up stiction"
    return "no stiction"


def _limit_summary(dataset, f_t, margin) -> dict:
    """The start-up verdict, the margins with the bond stress capped, the plastic fraction (MODEL 7d); empty for a
    dataset written before them."""
    if "startup_resisting_force" not in dataset:
        return {}
    startup = f_t - float(dataset["startup_resisting_force"].max())
    running_capped = f_t - float(dataset["resisting_force_capped"].max())
    startup_capped = f_t - float(dataset["startup_resisting_force_capped"].max())
    plastic = np.asarray(dataset["plastic_fraction"])
    contact = float(dataset.attrs.get("contact_elements", 0.0))

    def mode(running, start):
        return "running" if running < 0 else ("start-up" if start < 0 else "none")

    summary = {
        "startup_margin": startup, "startup_stiction": bool(startup < 0),
        "static_cof_max": float(dataset["static_cof"].max()), "stiction_mode": mode(margin, startup),
        "stiction_margin_capped": running_capped, "startup_margin_capped": startup_capped,
        "stiction_mode_capped": mode(running_capped, startup_capped),
        "friction_share_rigid": float(dataset.attrs["friction_share_rigid"]),
        "friction_share_overstrength": float(dataset.attrs["friction_share_overstrength"]),
        "plastic_fraction": float(dataset.attrs["plastic_elements"]) / contact if contact > 0 else 0.0,
        "plastic_fraction_max": float(plastic.max()), "plastic_steps": int((plastic > 0).sum()),
        "hardness": None if math.isnan(float(dataset.attrs["hardness"])) else float(dataset.attrs["hardness"]),
        "window": float(dataset.attrs["window"]),
        "lattice_registry": str(dataset.attrs["lattice_registry"]),
    }
    if "startup_torque_arm" in dataset.attrs:  # the largest load torque on the gear that still starts (MODEL 7f)
        summary["startup_load_torque_limit"] = max(0.0, float(dataset.attrs["load_torque"])
                                                   + startup * float(dataset.attrs["startup_torque_arm"]))
    for key in ("stiction_margin_uncapped", "startup_margin_uncapped", "cof_mean_uncapped"):
        if key in dataset.attrs:
            summary[key] = float(dataset.attrs[key])
    return summary


# --- convergence on what is decided (MODEL 7d, 7h; issues #25, #35, #38) ----------------------------------------
#: Largest relative change of the margin (of |margin|) and of the mean COF (of itself) that counts as converged.
TOLERANCE = 0.02

#: A margin near zero passes where its change stays below this share of the resisting force it is the difference of
#: (MODEL 7h: 2 % of itself or 0.5 % of the resisting force, whichever is larger), with its sign kept.
RESISTING_TOLERANCE = 0.005


def relative_change(new: float, old: float) -> float:
    """|new - old| / |old| [-]; infinite where old is 0 and new is not (nothing to be relative to)."""
    change = abs(float(new) - float(old))
    scale = abs(float(old))
    if scale > 0.0:
        return change / scale
    return 0.0 if change == 0.0 else float("inf")


def margin_check(fine: float, coarse: float, resisting: float) -> dict:
    """Whether a margin has converged on the decision (MODEL 7h): its sign kept and its change below 2 % of |margin|
    or 0.5 % of the resisting force (``resisting`` [N], the coarse cycle's), whichever is larger.

    Returns ``change`` (of |coarse| [-]), ``change_of_resisting`` [-], ``bound`` (``"margin"`` or ``"resisting force"``:
    which bound applied), ``sign_kept`` and ``passed``."""
    change = abs(float(fine) - float(coarse))
    by_margin, by_resisting = TOLERANCE * abs(float(coarse)), RESISTING_TOLERANCE * abs(float(resisting))
    sign_kept = (fine < 0) == (coarse < 0)
    return {"change": relative_change(fine, coarse),
            "change_of_resisting": change / abs(float(resisting)) if resisting else float("inf"),
            "bound": "margin" if by_margin >= by_resisting else "resisting force", "sign_kept": bool(sign_kept),
            "passed": bool(sign_kept and change < max(by_margin, by_resisting))}


def compare_cycles(fine: dict, coarse: dict) -> dict:
    """The changes between two cycles' summaries (:func:`memstribo.simulations.mesh.summarize`).

    Returns
    -------
    dict
        ``margin`` (of |margin| of ``coarse``), ``margin_ft`` (of F_t), ``cof`` (of the coarse mean COF),
        ``adhesion`` (of the coarse mean adhesion force), all [-]; ``margin_bound`` (which bound of
        :func:`margin_check` applied); where both have the start-up verdict, ``startup`` (its margin's change, of
        |margin|) and ``startup_bound``; ``passed``: each margin by :func:`margin_check` and the COF below
        :data:`TOLERANCE`.
    """
    running = margin_check(fine["stiction_margin"], coarse["stiction_margin"],
                           coarse["tangential_force"] - coarse["stiction_margin"])  # R = F_t - margin
    margin_ft = abs(fine["stiction_margin"] - coarse["stiction_margin"]) / max(abs(coarse["tangential_force"]), 1e-300)
    cof = relative_change(fine["cof_mean"], coarse["cof_mean"])
    adhesion = relative_change(fine["adhesion_force_mean"], coarse["adhesion_force_mean"])
    out = {"margin": running["change"], "margin_ft": margin_ft, "cof": cof, "adhesion": adhesion,
           "margin_bound": running["bound"]}
    passed = running["passed"] and cof < TOLERANCE
    if fine.get("startup_margin") is not None and coarse.get("startup_margin") is not None:
        startup = margin_check(fine["startup_margin"], coarse["startup_margin"],
                               coarse["tangential_force"] - coarse["startup_margin"])
        out.update(startup=startup["change"], startup_bound=startup["bound"])
        passed = passed and startup["passed"]
    out["passed"] = bool(passed)
    return out
