"""What the verdict hangs on (MODEL 7d, 7f): the start-up verdict, the local limits and what they do to the margins.

**Start-up (MODEL 7f, issue #35).** The running verdict compares the kinetic friction (energy per sliding distance)
with F_t. A gear at rest must start. At each rest position c the teeth have dwelt, and the share of their bonds that
has formed follows the logarithmic ageing of silica nanocontacts
(:func:`memstribo.physics.static_friction.logarithmic_ageing_share`; every bond where ``startup_dwell`` is unset).
Each bond, sheared sideways at its normal gap, resists with its lateral law, which peaks at 1.27 U / D
(:func:`~memstribo.physics.static_friction.lennard_jones_lateral_peak`); the bonds of one nanoblock row share the
registry of the row's crystals (MODEL 7d) and so a phase of their renewal period, and the rows are out of phase
(``lattice_registry = random``) or in phase (``shared``). The static force of a pair is the largest, over the sliding
offset, of the rows' summed bond forces at their phases
(:func:`~memstribo.physics.static_friction.population_static_force`), plus its elastic and capillary friction as in
sliding. It is not floored at the kinetic force: a pair can start and then stall, which the running verdict says.

Starting is a torque balance (:func:`~memstribo.physics.static_friction.startup_drive_torque`): the drive torque T
against the load torque T_L on the gear (``load_torque``) and each pair's friction with its moment arm, the flank's
radius of curvature. As a force at the pinion's pitch radius, like the running verdict's, the start-up resisting
force is R_s(c) = [T_L r_b1 / r_b2 + r_b1 sum_k F_s,k |rho1_k / r_b1 - rho2_k / r_b2|] / r_w1 over the pairs k in
mesh, and the start-up margin is F_t - max_c R_s(c). Friction at the pitch point costs no torque (no sliding there).

**Local limits.** A chemical bond population transmits the shear stress U_chem / D_chem^3 over its overlap
(N = A / D_chem^2 bonds of force U_chem / D_chem, 3-10 and 3-1): 41.8 GPa for silicon, 53 GPa at its lateral peak,
far above the ideal shear strength of silicon (6.8 GPa, Roundy and Cohen 2001), where the crystal shears before the
bonds break. The cycle reports the share of its friction from such over-strength bond populations and from the
chemical bonds of atomic blocks past the threshold strain of the bilinear law, and both margins with every bond
population's shear stress capped at the ideal shear strength (one warning per cycle, saying whether the verdict
changes).
"""

from __future__ import annotations


import numpy as np

from memstribo.simulations.mesh.verdict import resisting_force, sliding_average


def formed_share(params) -> float:
    """Share of the bonds formed at rest [-]: the logarithmic ageing law after ``startup_dwell``
    (:func:`memstribo.physics.static_friction.logarithmic_ageing_share`); 1 where the dwell is unset."""
    from memstribo.physics.static_friction import logarithmic_ageing_share

    dwell = params["startup_dwell"]
    if dwell is None:
        return 1.0
    return float(logarithmic_ageing_share(float(dwell), float(params["ageing_onset_time"]),
                                          float(params["ageing_full_time"])))


def row_bond_forces(row_bonds, bond_energies, bond_length) -> np.ndarray:
    """Each row's kinetic bond force N U / D per step [N], (steps, rows), from its bond counts ``row_bonds`` (3, steps,
    rows: chemical, vdW over bare gear blocks, vdW over coated ones) and the three bonds' energies [J] (3-1, 3-10,
    3-12)."""
    energies = np.asarray(bond_energies, dtype=float)
    return np.einsum("k,ksr->sr", energies, np.asarray(row_bonds, dtype=float)) / float(bond_length)


def static_friction_force(row_forces, bond_phases, share, rest) -> np.ndarray:
    """The start-up friction force of the pair at each rest position [N]: the formed share of the rows' bond
    populations at their phases, their largest sum over the sliding offset
    (:func:`memstribo.physics.static_friction.population_static_force`), plus ``rest`` (elastic and capillary
    friction) [N]."""
    from memstribo.physics.static_friction import population_static_force

    return share * np.asarray(population_static_force(row_forces, bond_phases)) + rest


def startup_resisting_force(params, pair, positions, static) -> np.ndarray:
    """R_s(c): the start-up torque balance of every pair in mesh as a force at the pinion's pitch radius [N] (module
    docstring; :func:`memstribo.physics.static_friction.startup_drive_torque`)."""
    from memstribo.physics.static_friction import friction_lever

    rb1, rb2 = (float(r) for r in pair.base_radii)

    def lever(c):  # each pair's moment arm over the pinion's base radius, at its own contact
        return np.asarray(friction_lever(*pair.radii_of_curvature(c), rb1, rb2))

    friction = resisting_force(positions, static, pair.first_contact, pair.last_contact, pair.base_pitch, lever)
    return (float(params["load_torque"]) / rb2 + friction) * rb1 / float(pair.pitch_radii[0])


def _capped_energies(params, energies, bond) -> list[float]:
    """The bond energies with each population's shear stress at its lateral peak, 1.27 U / D^3, capped at the ideal
    shear strength (a uniform factor per bond kind: one bond per D^2)."""
    from memstribo.physics.static_friction import LATERAL_PEAK_FORCE

    strength = float(params["ideal_shear_strength"])
    return [min(u, strength * bond ** 3 / LATERAL_PEAK_FORCE) for u in energies]


def bond_energies(params, coating=None) -> list[float]:
    """The energies [J] of the three bond kinds of :func:`row_bond_forces`: U_chem, U_vdW (bare) and the coating's."""
    from memstribo.physics.vdw_energy import vdw_bond_energy_of

    coated = float(coating.vdw_bond_energy) if coating is not None else 0.0
    return [float(params["bond_energy"]), vdw_bond_energy_of(params), coated]


def startup_and_limits(params, setup, cycle, verdict, coating=None) -> dict:
    """Start-up forces and the margins with the bond stress capped, per step (forces [N]) and as shares [-].

    Returns a dict: ``static`` (start-up friction force of the pair at each rest position), ``startup_resisting``
    (R_s(c)), ``resisting_capped`` and ``startup_resisting_capped`` (the same with every bond population's shear
    stress capped at ``ideal_shear_strength``), ``share_rigid`` and ``share_overstrength`` (shares of the cycle's
    friction energy), ``peak_ratio`` (a bond's lateral peak over its kinetic force, 1.2687), ``bond_stress`` (the
    shear stress of a chemical bond population, U_chem / D_chem^3 [Pa]), ``formed_share`` and ``bond_phases``.
    """
    from memstribo.physics.static_friction import LATERAL_PEAK_FORCE

    pair = setup.pair
    out, f_el, sliding = cycle["out"], cycle["f_el"], cycle["kin"]["sliding"]
    bond = float(params["bond_length"])
    share = formed_share(params)
    rest = f_el + out["f_cap"]  # elastic and capillary friction: as in sliding
    rows = out["row_bonds"].shape[-1]
    registry = setup.registry
    phases = registry.bond_phase if registry is not None and registry.bond_phase is not None else np.zeros(rows)
    energies = bond_energies(params, coating)
    static = static_friction_force(row_bond_forces(out["row_bonds"], energies, bond), phases, share, rest)
    static_capped = static_friction_force(row_bond_forces(out["row_bonds"], _capped_energies(params, energies, bond),
                                                          bond), phases, share, rest)
    # local limits: a chemical bond population's shear stress, U / D^3, against the ideal shear strength
    strength = float(params["ideal_shear_strength"])
    bond_stress = float(params["bond_energy"]) / bond**3
    cap_running = min(1.0, strength / bond_stress)
    capped_inst = out["f_chem"] * cap_running + out["f_vdw_capped"] + rest
    capped_avg = sliding_average(capped_inst, sliding, verdict["averaging"])
    energy = float(verdict["energy"].sum())
    over = (out["f_chem"] * (bond_stress > strength) + out["f_vdw_over"]) * sliding
    return dict(static=static, startup_resisting=startup_resisting_force(params, pair, setup.positions, static),
                resisting_capped=resisting_force(setup.positions, capped_avg, pair.first_contact, pair.last_contact,
                                                 pair.base_pitch),
                startup_resisting_capped=startup_resisting_force(params, pair, setup.positions, static_capped),
                peak_ratio=LATERAL_PEAK_FORCE, bond_stress=bond_stress,
                share_rigid=float((out["f_chem_rigid"] * sliding).sum() / energy) if energy > 0 else 0.0,
                share_overstrength=float(over.sum() / energy) if energy > 0 else 0.0, formed_share=share,
                bond_phases=np.asarray(phases, dtype=float))


def stiction_mode(running_margin: float, startup_margin: float) -> str:
    """Which verdict fails: ``running`` (the kinetic friction exceeds F_t), ``start-up`` (only the start from rest
    fails) or ``none``."""
    if running_margin < 0:
        return "running"
    return "start-up" if startup_margin < 0 else "none"


def local_limits_warning(params, out, limits, margins) -> str | None:
    """One sentence for the cycle: the friction share past the local limits and what capping it does to the verdict.

    ``margins``: the running and start-up margins without and with the cap [N] (``running``, ``startup``,
    ``running_capped``, ``startup_capped``). None when no friction comes from past the limits.
    """
    rigid_steps = int((out["rigid_atomic_blocks"] > 0).sum())
    if limits["share_rigid"] <= 0 and limits["share_overstrength"] <= 0 and not rigid_steps:
        return None
    strength = float(params["ideal_shear_strength"])
    mode = stiction_mode(margins["running"], margins["startup"])
    capped = stiction_mode(margins["running_capped"], margins["startup_capped"])
    change = (f"the verdict does not change ({mode})" if mode == capped
              else f"the verdict changes from '{mode}' to '{capped}' stiction".replace("'none' stiction", "none"))
    return (f"local limits: {100 * limits['share_rigid']:.3g} % of the friction comes from the chemical bonds of "
            f"atomic blocks past the threshold strain of the bilinear law ({params['threshold_strain']:g}; rigid "
            f"blocks in {rigid_steps} of {out['rigid_atomic_blocks'].size} steps) and "
            f"{100 * limits['share_overstrength']:.3g} % from bond populations that transmit more than the ideal "
            f"shear strength of silicon ({strength / 1e9:.3g} GPa, Roundy and Cohen 2001; a chemical bond population "
            f"transmits U_chem / D_chem^3 = {limits['bond_stress'] / 1e9:.3g} GPa, "
            f"{limits['peak_ratio'] * limits['bond_stress'] / 1e9:.3g} GPa at its lateral peak); with every bond "
            f"population's shear stress capped at that strength the stiction margin is "
            f"{margins['running_capped'] * 1e6:.4g} µN (uncapped {margins['running'] * 1e6:.4g} µN) and the start-up "
            f"margin {margins['startup_capped'] * 1e6:.4g} µN (uncapped {margins['startup'] * 1e6:.4g} µN): {change}")


def apply_limits(params, setup, cycle, verdict, coating=None) -> None:
    """Add the start-up forces and the local limits to a cycle's verdict (``verdict["limits"]``), and their one
    warning to ``verdict["warnings"]``."""
    limits = verdict["limits"] = startup_and_limits(params, setup, cycle, verdict, coating)
    f_t = verdict["f_t"]
    margins = dict(running=f_t - float(verdict["resisting"].max()),
                   startup=f_t - float(limits["startup_resisting"].max()),
                   running_capped=f_t - float(limits["resisting_capped"].max()),
                   startup_capped=f_t - float(limits["startup_resisting_capped"].max()))
    sentence = local_limits_warning(params, cycle["out"], limits, margins)
    if sentence:
        verdict["warnings"].append(sentence)


def startup_from_dataset(dataset, params, energies) -> dict | None:
    """The start-up verdict of a solved cycle with other bond energies, without a new solve (the uncertainty
    study's rescaling, issue #35 item 5): ``startup_margin``, ``startup_stiction``, ``static_cof_max``,
    ``startup_margin_capped`` [N or -]. ``energies``: U_chem, U_vdW (bare) and the coating's [J]
    (:func:`bond_energies`). None for a dataset without the rows' bond counts (written before version 4)."""
    from memstribo.physics.gear import GearPair

    names = ("bonds_chemical_row", "bonds_vdw_bare_row", "bonds_vdw_coated_row")
    if not all(name in dataset for name in names) or "bond_phase" not in dataset:
        return None
    counts = np.stack([np.asarray(dataset[name], dtype=float) for name in names])
    phases = np.asarray(dataset["bond_phase"], dtype=float)
    share = float(dataset.attrs.get("startup_formed_share", 1.0))
    rest = np.asarray(dataset["friction_force_elastic"], dtype=float)
    if "friction_force_capillary" in dataset:
        rest = rest + np.asarray(dataset["friction_force_capillary"], dtype=float)
    bond = float(params["bond_length"])
    params = params.updated({"load_torque": float(dataset.attrs.get("load_torque", params["load_torque"]))})
    pair = GearPair.from_parameters(params)
    c = np.asarray(dataset["c"], dtype=float)
    f_t = float(dataset.attrs["tangential_force_total"])
    static = static_friction_force(row_bond_forces(counts, energies, bond), phases, share, rest)
    capped = static_friction_force(row_bond_forces(counts, _capped_energies(params, energies, bond), bond), phases,
                                   share, rest)
    margin = f_t - float(startup_resisting_force(params, pair, c, static).max())
    denominator = np.asarray(dataset["normal_force"] + dataset["adhesion_force"], dtype=float)
    return {"startup_margin": margin, "startup_stiction": bool(margin < 0),
            "static_cof_max": float(np.max(static / denominator)),
            "startup_margin_capped": f_t - float(startup_resisting_force(params, pair, c, capped).max())}
