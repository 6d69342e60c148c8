"""What the verdict hangs on (MODEL 7d): the start-up verdict, the local limits and what they do to the margins.

**Start-up.** The running verdict compares the kinetic friction (energy per sliding distance) with F_t. A gear
at rest must start: at each rest position c the teeth have dwelt with every bond formed (after a dwell t, the
share 1 - exp(-t / bond_formation_time); all of them when the dwell is unset or bonds form on contact), and the
drive must pull every bond past the peak of its bond law before sliding begins. The start-up force of a pair is
that peak lateral force of its chemical and vdW bonds
(:func:`memstribo.physics.friction.peak_bond_force`, 2.69 times the kinetic force of the same bonds), plus its
elastic and capillary friction, and never less than its kinetic friction force; R(c) at start-up sums it over
every pair in mesh as the running R(c) does. So the start-up margin is never above the running one.

**Local limits.** A chemical bond population transmits the shear stress U_chem / D_chem^3 over its overlap
(N = A / D_chem^2 bonds of force U_chem / D_chem, 3-10 and 3-1): 41.8 GPa for silicon, 112 GPa at start-up, far
above the ideal shear strength of silicon (6.8 GPa, Roundy and Cohen 2001), where the crystal shears before the
bonds break. The cycle reports the share of its friction from such over-strength bond populations and from the
chemical bonds of atomic blocks past the threshold strain of the bilinear law, and both margins with every bond
population's shear stress capped at the ideal shear strength (one warning per cycle, saying whether the verdict
changes).
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.simulations.mesh.verdict import resisting_force, sliding_average


def formed_share(params) -> float:
    """Share of the bonds formed at rest [-]: 1 - exp(-startup_dwell / bond_formation_time), 1 when either is unset
    or zero formation time (bonds form on contact, thesis 3.5)."""
    dwell, formation = params["startup_dwell"], float(params["bond_formation_time"])
    if dwell is None or formation <= 0.0:
        return 1.0
    return float(-math.expm1(-float(dwell) / formation))


def startup_and_limits(params, setup, cycle, verdict) -> dict:
    """Start-up forces and the margins with the bond stress capped, per step (forces [N]) and as shares [-].

    Returns a dict: ``static`` (start-up friction force of the pair at each rest position), ``startup_resisting``
    (R(c) at start-up), ``resisting_capped`` and ``startup_resisting_capped`` (the same with every bond population's
    shear stress capped at ``ideal_shear_strength``), ``share_rigid`` and ``share_overstrength`` (shares of the
    cycle's friction energy), ``peak_ratio`` (start-up over kinetic force of one bond) and ``bond_stress``
    (the shear stress of a chemical bond population, U_chem / D_chem^3 [Pa]).
    """
    from memstribo.physics import friction

    pair = setup.pair
    out, f_el, sliding = cycle["out"], cycle["f_el"], cycle["kin"]["sliding"]
    bond = float(params["bond_length"])
    ratio = float(friction.peak_bond_force(1.0, 1.0, bond)) * bond  # 2.69 for the LJ 12-6 law
    share = formed_share(params)
    rest = f_el + out["f_cap"]  # elastic and capillary friction: as in sliding

    def resisting(force):
        return resisting_force(setup.positions, force, pair.first_contact, pair.last_contact, pair.base_pitch)

    static = np.maximum(share * ratio * (out["f_chem"] + out["f_vdw"]) + rest, verdict["friction_avg"])
    # local limits: a chemical bond population's shear stress, U / D^3, against the ideal shear strength
    strength = float(params["ideal_shear_strength"])
    bond_stress = float(params["bond_energy"]) / bond**3
    cap_running, cap_start = min(1.0, strength / bond_stress), min(1.0, strength / (ratio * bond_stress))
    capped_inst = out["f_chem"] * cap_running + out["f_vdw_capped"] + rest
    capped_avg = sliding_average(capped_inst, sliding, verdict["averaging"])
    static_capped = np.maximum(share * (ratio * out["f_chem"] * cap_start + out["f_vdw_static_capped"]) + rest,
                               capped_avg)
    energy = float(verdict["energy"].sum())
    over = (out["f_chem"] * (bond_stress > strength) + out["f_vdw_over"]) * sliding
    return dict(static=static, startup_resisting=resisting(static), resisting_capped=resisting(capped_avg),
                startup_resisting_capped=resisting(static_capped), peak_ratio=ratio, bond_stress=bond_stress,
                share_rigid=float((out["f_chem_rigid"] * sliding).sum() / energy) if energy > 0 else 0.0,
                share_overstrength=float(over.sum() / energy) if energy > 0 else 0.0, formed_share=share)


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
            f"{limits['peak_ratio'] * limits['bond_stress'] / 1e9:.3g} GPa at start-up); with every bond "
            f"population's shear stress capped at that strength the stiction margin is "
            f"{margins['running_capped'] * 1e6:.4g} µN (uncapped {margins['running'] * 1e6:.4g} µN) and the start-up "
            f"margin {margins['startup_capped'] * 1e6:.4g} µN (uncapped {margins['startup'] * 1e6:.4g} µN): {change}")


def apply_limits(params, setup, cycle, verdict) -> None:
    """Add the start-up forces and the local limits to a cycle's verdict (``verdict["limits"]``), and their one
    warning to ``verdict["warnings"]``."""
    limits = verdict["limits"] = startup_and_limits(params, setup, cycle, verdict)
    f_t = verdict["f_t"]
    margins = dict(running=f_t - float(verdict["resisting"].max()),
                   startup=f_t - float(limits["startup_resisting"].max()),
                   running_capped=f_t - float(limits["resisting_capped"].max()),
                   startup_capped=f_t - float(limits["startup_resisting_capped"].max()))
    sentence = local_limits_warning(params, cycle["out"], limits, margins)
    if sentence:
        verdict["warnings"].append(sentence)
