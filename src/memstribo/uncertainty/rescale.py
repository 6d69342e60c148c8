"""A new bond energy without a new contact solve (issue 27 item 6).

Given the contact solution of a cycle, the bond counts of every step do not depend on the bond
energies: ``N_chem`` counts overlaps of touching atomic blocks (3-10) and ``N_vdW`` the footprint
inside the adhesive layer or at the local gap (3-12, MODEL 7c). The friction of the bonds is then
linear in the energies (3.5, 3-1)::

    F_chem = N_chem U_chem / D_chem,     F_vdW = N_vdW U_vdW / D_chem        (bare flanks)

and everything after it is linear or a maximum: the sliding average over
``friction_averaging_distance`` (MODEL 7b), the resisting force R(c) of all pairs in mesh, the
margin ``F_t - max R``, the cycle's COF ``sum E / integral (F_N + F_adh) ds`` (the adhesion force
does not involve the bond energies). :func:`rescale_cycle` recomputes these from one solved cycle's
dataset; it agrees with a full rerun to round-off (tests/test_uncertainty.py).

A coated cycle (worn blocks, ``wear`` < 1) writes its vdW bond count over bare and over coated gear
blocks apart (:data:`SPLIT_VARIABLES`): U_vdW of silicon acts on the first, the coating's on the second,
and both rescale. Not rescaled: anything that changes the contact solve or the block mechanics
(moduli, Hamaker constant, D0, block geometry, threshold strain, the coating's work of adhesion), and a
coated cycle's vdW energies when its dataset predates the split (then U_chem only).
"""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError
from memstribo.physics.vdw_energy import vdw_bond_energy_of
from memstribo.references import cites

__all__ = ["RESCALED", "CYCLE_VARIABLES", "SPLIT_VARIABLES", "reduce_cycle", "rescalable", "rescale_cycle",
           "rescale_cycles"]

#: the constants that enter the cycle only through the bond energies (linear), per kind of cycle
#: U_vdW = phi w12 / n_site is linear in phi (MODEL 7h), so the dissipated fraction rescales exactly as U_vdW does
RESCALED = ("bond_energy", "vdw_bond_energy", "vdw_dissipated_fraction")

#: per-step variables of the cycle's dataset that the rescaling reads
CYCLE_VARIABLES = ("time", "sliding_distance", "normal_force", "adhesion_force", "bonds_chemical", "bonds_vdw",
                   "friction_force_chemical", "friction_force_vdw", "friction_force_elastic",
                   "friction_force_capillary", "contact_converged")

#: per-step variables of a coated cycle that let its vdW energies be rescaled: the vdW bond count over the bare
#: and over the coated gear blocks (written by the meshing cycle when it has a coating)
SPLIT_VARIABLES = ("bonds_vdw_bare", "bonds_vdw_coated")


def reduce_cycle(dataset):
    """The cycle's dataset without the per-block tables: the variables :func:`rescale_cycle` and
    :func:`memstribo.simulations.mesh.summarize` need, small enough to send between Dask workers."""
    drop = [name for name in dataset.variables if "block" in dataset[name].dims]
    return dataset.drop_vars(drop)


def _coated(dataset) -> bool:
    return not str(dataset.attrs.get("coating", "none")).startswith("none") and float(dataset.attrs.get("wear", 1.0)) < 1.0


def rescalable(dataset) -> tuple[str, ...]:
    """The constants :func:`rescale_cycle` can change on this cycle: both bond energies for bare
    flanks; on a coated cycle also ``coating_vdw_bond_energy`` (its dataset has :data:`SPLIT_VARIABLES`),
    or ``bond_energy`` only where the dataset lacks them (written before the split)."""
    if not _coated(dataset):
        return RESCALED
    if all(name in dataset for name in SPLIT_VARIABLES):
        return RESCALED + ("coating_vdw_bond_energy",)
    return ("bond_energy",)


@cites("thesis", "model")
def rescale_cycle(dataset, params_nominal, overrides) -> dict:
    """The summary of a solved cycle with other bond energies, without solving the contacts again.

    Parameters
    ----------
    dataset : xarray.Dataset
        A cycle of :func:`memstribo.simulations.mesh.simulate_mesh` (or its :func:`reduce_cycle`),
        solved with ``params_nominal``.
    params_nominal : memstribo.parameters.Parameters
        The parameters of that cycle (gear geometry for R(c), the bond length D_chem [m] and the
        bond energies it was solved with [J]).
    overrides : Mapping[str, float]
        New values [J] of constants of :func:`rescalable` (``bond_energy``, ``vdw_bond_energy``).

    Returns
    -------
    dict
        The keys of :func:`memstribo.simulations.mesh.summarize` that the bond energies change
        (``stiction_margin`` [N], ``stiction``, ``resisting_force_max`` [N], ``cof_mean`` and its split
        [-], ``friction_force_mean``/``_max`` [N], energies [J], ``mesh_efficiency`` [-]) and the others
        of the cycle unchanged, with ``rescaled`` = True.

    Raises
    ------
    InputError
        A constant that this cycle cannot rescale (it changes the contact solve or the block
        mechanics, or the cycle is coated), or a variable the dataset lacks.
    """
    return rescale_cycles(dataset, params_nominal, [overrides])[0]


@cites("thesis", "model")
def rescale_cycles(dataset, params_nominal, overrides_list, base=None) -> list[dict]:
    """:func:`rescale_cycle` of one solved cycle for many sets of bond energies (issue 27 item 6).

    The parts that do not depend on the bond energies (the summary of the cycle, the gear pair, the
    sliding averages of the elastic and capillary friction, the COF's denominator) are computed once;
    each set then costs its two bond friction forces, their sliding averages and R(c). Each set's
    arithmetic is :func:`rescale_cycle`'s, in the same order: the same numbers to the last bit.

    Parameters
    ----------
    dataset, params_nominal
        As for :func:`rescale_cycle`.
    overrides_list : sequence of Mapping[str, float]
        One mapping of new bond energies [J] per set.
    base : dict, optional
        ``summarize(dataset)`` when the caller has it already [SI].

    Returns
    -------
    list of dict
        One summary per set, as :func:`rescale_cycle` returns.
    """
    from memstribo.physics.gear import GearPair
    from memstribo.simulations.mesh import resisting_force, sliding_average, summarize

    allowed = rescalable(dataset)
    if (params_nominal.get("vdw_energy_rule") or "thesis") == "hysteresis" and any(
            "vdw_bond_energy" in o for o in overrides_list):  # the solve would not use it (MODEL 7h)
        raise InputError("rescale_cycle: under vdw_energy_rule 'hysteresis' U_vdW is phi w12 / n_site, not "
                         "vdw_bond_energy: rescale vdw_dissipated_fraction instead.")
    overrides_list = [_as_bond_energies(params_nominal, o) if "vdw_dissipated_fraction" in o else o
                      for o in overrides_list]
    for overrides in overrides_list:
        for name in overrides:
            if name not in allowed:
                raise InputError(f"rescale_cycle: '{name}' cannot be changed without a new cycle (allowed here: "
                                 f"{', '.join(allowed)}); run simulate_mesh with it.")
    missing = [name for name in CYCLE_VARIABLES if name not in dataset and name != "friction_force_capillary"]
    if missing:
        raise InputError(f"rescale_cycle: the dataset lacks {', '.join(missing)}.")
    f_el = np.asarray(dataset["friction_force_elastic"], dtype=float)
    f_cap = (np.asarray(dataset["friction_force_capillary"], dtype=float) if "friction_force_capillary" in dataset
             else np.zeros_like(f_el))
    sliding = np.asarray(dataset["sliding_distance"], dtype=float)
    averaging = float(dataset.attrs["friction_averaging_distance"])
    avg_el, avg_cap = (sliding_average(f, sliding, averaging) for f in (f_el, f_cap))
    pair = GearPair.from_parameters(params_nominal)
    c = np.asarray(dataset["c"], dtype=float)
    f_t = float(dataset.attrs["tangential_force_total"])
    e_el, e_cap = f_el * sliding, f_cap * sliding
    denominator = np.asarray(dataset["normal_force"] + dataset["adhesion_force"], dtype=float)
    work = float((denominator * sliding).sum())
    time = np.asarray(dataset["time"], dtype=float)
    weights = np.gradient(time) if time.size > 1 else np.ones(1)
    weights = weights / weights.sum()
    input_power = float(dataset.attrs["input_power"])
    period = pair.base_pitch / pair.contact_point_speed
    base = summarize(dataset) if base is None else base  # the keys the bond energies do not change
    # the start-up verdict (peak instantaneous force at rest, MODEL 7d) is not rescaled yet: its keys would be the
    # nominal energies' (stale), so they are blanked; its per-mechanism peak forces would make it rescalable
    # the tooth's strength and temperature follow the nominal friction force too: blanked likewise
    startup_known, stale = _stale_keys(dataset, params_nominal, base)
    out = []
    for overrides in overrides_list:
        f_chem, f_vdw = _bond_friction(dataset, params_nominal, overrides)
        friction_avg = (sliding_average(f_chem, sliding, averaging) + sliding_average(f_vdw, sliding, averaging)
                        + avg_el + avg_cap)  # the cycle's order of summation
        resisting = resisting_force(c, friction_avg, pair.first_contact, pair.last_contact, pair.base_pitch)
        margin = f_t - float(resisting.max())
        energy = {"energy_chemical": f_chem * sliding, "energy_vdw": f_vdw * sliding, "energy_elastic": e_el,
                  "energy_capillary": e_cap}
        split = {f"cof_{k.split('_')[1]}": (float(v.sum()) / work if work > 0 else 0.0) for k, v in energy.items()}
        total_energy = sum(float(v.sum()) for v in energy.values())
        summary = dict(base)
        summary.update({
            "cof_mean": split["cof_chemical"] + split["cof_vdw"] + split["cof_elastic"] + split["cof_capillary"],
            **split,
            "cof_max": float(np.max(friction_avg / denominator)),
            "friction_force_mean": float((friction_avg * weights).sum()),
            "friction_force_max": float(friction_avg.max()),
            "resisting_force_max": float(resisting.max()),
            "stiction": bool(margin < 0),
            "stiction_margin": margin,
            "mesh_efficiency": 1.0 - total_energy / (input_power * period),
            "energy_dissipated": total_energy,
            **{k: float(v.sum()) for k, v in energy.items()},
            "rescaled": True,
        })
        _rescaled_startup(summary, dataset, params_nominal, overrides, margin, startup_known)
        for key in stale:
            summary[key] = None
        summary["not_rescaled"] = list(stale)
        out.append(summary)
    return out


#: The start-up keys of a summary that :func:`_rescaled_startup` recomputes for a set of bond energies.
_RESCALED_STARTUP = ("startup_margin", "startup_stiction", "static_cof_max", "startup_margin_capped", "stiction_mode",
                     "stiction_mode_capped")


def _stale_keys(dataset, params_nominal, base) -> tuple[bool, list[str]]:
    """(whether the start-up verdict rescales, the summary keys a rescaled set blanks). The start-up verdict rescales
    from the rows' bond counts (MODEL 7f; :func:`memstribo.simulations.mesh.limits.startup_from_dataset`) where the
    dataset has them; its ensemble keys and the tooth's strength and temperature (which follow the nominal friction
    force) are blanked."""
    from memstribo.simulations.mesh.limits import startup_from_dataset
    from memstribo.simulations.tooth_life import TOOTH_LIFE_KEYS

    known = startup_from_dataset(dataset, params_nominal, _energies(dataset, params_nominal, {})) is not None
    stale = [key for key in base if (key.startswith("startup") and not (known and key in _RESCALED_STARTUP))
             or key in TOOTH_LIFE_KEYS]
    return known, stale


def _rescaled_startup(summary, dataset, params_nominal, overrides, margin, known) -> None:
    """Put a set's start-up verdict, its stiction modes and its verdict word into ``summary`` (``margin``: the set's
    running margin [N])."""
    from memstribo.simulations.mesh.limits import startup_from_dataset

    if known:
        startup = startup_from_dataset(dataset, params_nominal, _energies(dataset, params_nominal, overrides))
        capped_margin = summary.get("stiction_margin_capped")
        summary.update(startup)
        summary["stiction_mode"] = "running" if margin < 0 else ("start-up" if startup["startup_margin"] < 0
                                                                  else "none")
        if capped_margin is not None:  # the running capped margin is the nominal's (not rescaled): kept as it was
            summary["stiction_mode_capped"] = ("running" if capped_margin < 0 else
                                               "start-up" if startup["startup_margin_capped"] < 0 else "none")
    if summary.get("verdict") not in (None, "undetermined"):  # the rescaled set's own verdict word
        mode = summary.get("stiction_mode")
        summary["verdict"] = ("running stiction" if margin < 0 else "start-up stiction" if mode == "start-up"
                              else "no stiction")


def _as_bond_energies(params_nominal, overrides) -> dict:
    """``overrides`` with the dissipated fraction phi as the U_vdW it gives [J]: U_vdW = phi w12 / n_site is linear in
    phi (:func:`memstribo.physics.vdw_energy.hysteresis_site_energy`), so phi scales the nominal U_vdW; under the
    thesis rule phi does not act (U_vdW as given)."""
    out = dict(overrides)
    phi = float(out.pop("vdw_dissipated_fraction"))
    if "vdw_bond_energy" not in out and (params_nominal.get("vdw_energy_rule") or "thesis") == "hysteresis":
        out["vdw_bond_energy"] = vdw_bond_energy_of(params_nominal) * phi / float(params_nominal["vdw_dissipated_fraction"])
    return out


def _energies(dataset, params_nominal, overrides) -> list[float]:
    """U_chem, U_vdW (bare) and the coating's U_vdW [J] of a set (:func:`memstribo.simulations.mesh.limits.bond_energies`
    order), the nominal where a set does not override them."""
    u_chem = float(overrides.get("bond_energy", params_nominal["bond_energy"]))
    u_vdw = float(overrides.get("vdw_bond_energy", vdw_bond_energy_of(params_nominal)))
    u_coat = 0.0
    if _coated(dataset):
        from memstribo.physics.coating import get_coating

        u_coat = float(overrides.get("coating_vdw_bond_energy", params_nominal["coating_vdw_bond_energy"]
                                     or get_coating(dataset.attrs["coating"]).vdw_bond_energy))
    return [u_chem, u_vdw, u_coat]


def _bond_friction(dataset, params_nominal, overrides):
    """(chemical, vdW) friction force per step [N] with the overridden bond energies: F = N U / D_chem (3-10, 3.5)."""
    bond = float(params_nominal["bond_length"])
    f_chem = np.asarray(dataset["friction_force_chemical"], dtype=float)
    f_vdw = np.asarray(dataset["friction_force_vdw"], dtype=float)
    if "bond_energy" in overrides:  # (3-10), (3.5): F = N U / D_chem
        f_chem = np.asarray(dataset["bonds_chemical"], dtype=float) * float(overrides["bond_energy"]) / bond
    if "vdw_bond_energy" in overrides or "coating_vdw_bond_energy" in overrides:
        if _coated(dataset):
            from memstribo.physics.coating import get_coating

            u_bare = overrides.get("vdw_bond_energy", vdw_bond_energy_of(params_nominal))
            u_coat = overrides.get("coating_vdw_bond_energy", params_nominal["coating_vdw_bond_energy"]
                                   or get_coating(dataset.attrs["coating"]).vdw_bond_energy)
            f_vdw = (np.asarray(dataset["bonds_vdw_bare"]) * float(u_bare)
                     + np.asarray(dataset["bonds_vdw_coated"]) * float(u_coat)) / bond
        else:
            f_vdw = np.asarray(dataset["bonds_vdw"], dtype=float) * float(overrides["vdw_bond_energy"]) / bond
    return f_chem, f_vdw
