"""The meshing cycle as an xarray Dataset: variables with units and long names, block loads, attributes."""

from __future__ import annotations

import numpy as np

from memstribo.materials.pair import contact_modulus_of
from memstribo.physics.gear import hertz_line_contact
from memstribo.quantities import attrs as quantity_attrs
from memstribo.simulations.mesh.setup import normal_force_of_load_case


def cycle_dataset(params, setup, cycle, verdict, modulus, beta, coating, wear, realisation, sliding_axis):
    """The cycle as an xarray Dataset over ``step`` (coordinates ``c`` and ``position`` [m]) and ``block``, each
    variable with the units and long name of :mod:`memstribo.quantities`."""
    import xarray as xr

    step = np.arange(setup.positions.size)

    def var(name, values, dims=("step",)):
        return xr.Variable(dims, np.asarray(values), attrs=quantity_attrs(name))

    block_load, block_coords = _block_table(cycle["block_loads"], step)
    data = {name: var(name, values) for name, values in _variables(params, setup, cycle, verdict, step).items()}
    data["load_share"].attrs["long_name"] = f"load share of the pair ({params['load_sharing']}, Figure 4-11)"
    if coating is not None:  # vdW bonds over bare and over coated gear blocks: U_vdW of each rescales (issue 27)
        data["bonds_vdw_bare"] = var("bonds_vdw_bare", cycle["out"]["vdw_bonds_bare"])
        data["bonds_vdw_coated"] = var("bonds_vdw_coated", cycle["out"]["vdw_bonds_coated"])
    data["block_load"] = var("block_load", block_load, dims=("step", "block"))
    # each row's bond counts: the start-up force from the rows' registries, and its rescaling by bond energy (MODEL 7f)
    for name, counts in zip(("bonds_chemical_row", "bonds_vdw_bare_row", "bonds_vdw_coated_row"),
                            cycle["out"]["row_bonds"]):
        data[name] = var(name, counts, dims=("step", "row"))
    data["bond_phase"] = var("bond_phase", verdict["limits"]["bond_phases"], dims=("row",))
    coords = {
        "step": ("step", step, quantity_attrs("step")),
        "row": ("row", np.arange(cycle["out"]["row_bonds"].shape[-1]), quantity_attrs("row")),
        "c": ("step", setup.positions, quantity_attrs("c")),
        # the position along the line of action, for plots over the path of contact (step stays the index)
        "position": ("step", setup.positions, quantity_attrs("position")),
        **{name: ("block", values, quantity_attrs(name)) for name, values in block_coords.items()},
    }
    attrs = _attributes(params, setup, cycle, verdict, modulus, beta, coating, wear, realisation, sliding_axis)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _block_table(block_loads, step):
    """Per-block loads [N] (``step``, ``block``): pinion then gear material blocks, rows; and the block coordinates."""
    k_lists = [np.concatenate([bl[0].ravel() for bl in block_loads]), np.concatenate([bl[2].ravel() for bl in
                                                                                    block_loads])]
    k_min = [int(k.min()) for k in k_lists]
    k_max = [int(k.max()) for k in k_lists]
    widths = [k_max[i] - k_min[i] + 1 for i in range(2)]
    n_rows_solved = len(block_loads)
    table = np.zeros((step.size, 2, n_rows_solved, max(widths)))
    steps_idx = np.repeat(step, block_loads[0][0].shape[1])
    for r, (k1, l1, k2, l2) in enumerate(block_loads):
        table[steps_idx, 0, r, (k1 - k_min[0]).ravel()] = l1.ravel()
        table[steps_idx, 1, r, (k2 - k_min[1]).ravel()] = l2.ravel()
    block_load = table.reshape(step.size, -1)
    coords = {
        "block_flank": np.repeat(np.array(["pinion", "gear"]), n_rows_solved * max(widths)),
        "block_row": np.tile(np.repeat(np.arange(n_rows_solved), max(widths)), 2),
        "block_index": np.concatenate([np.tile(np.arange(max(widths)) + k_min[0], n_rows_solved),
                                       np.tile(np.arange(max(widths)) + k_min[1], n_rows_solved)]),
    }
    return block_load, coords


def _variables(params, setup, cycle, verdict, step) -> dict:
    """The per-step variables of the dataset, by their names in :mod:`memstribo.quantities`."""
    pair = setup.pair
    out, kin, v = cycle["out"], cycle["kin"], verdict
    modulus = contact_modulus_of(params)
    # smooth-teeth Hertz contact under the line load actually solved (load / L_eff), Eqs. (4-22)-(4-26)
    hertz = hertz_line_contact(setup.load, setup.effective_face_width, pair.effective_radius(setup.positions),
                               modulus)
    denominator = v["denominator"]
    return {
        "time": pair.time(setup.positions),
        "load_share": pair.load_share(setup.positions, params["load_sharing"]),
        "normal_force": setup.load,
        "effective_radius": kin["r_ef"],
        "hertz_half_width": hertz.half_width,
        "hertz_peak_pressure": hertz.peak_pressure,
        "sliding_velocity": kin["slip"],
        "sliding_distance": kin["sliding"],
        "contact_width": out["contact_width"],
        "max_contact_pressure": out["max_pressure"],
        "contact_approach": out["approach"],
        "contact_converged": out["unconverged"] == 0,
        "contact_residual": out["residual"],
        "contact_iterations": out["iterations"],
        "window_exceeded": out["window_exceeded"] > 0,
        "bonds_chemical": out["chem_bonds"],
        "bonds_vdw": out["vdw_bonds"],
        "friction_force_chemical": out["f_chem"],
        "friction_force_vdw": out["f_vdw"],
        "friction_force_elastic": cycle["f_el"],
        "friction_force_instantaneous": cycle["friction"],
        "friction_force": v["friction_avg"],
        "resisting_force": v["resisting"],
        "adhesion_force": out["f_adh"],
        "cof": v["friction_avg"] / denominator,
        "cof_chemical": v["f_chem_avg"] / denominator,
        "cof_vdw": v["f_vdw_avg"] / denominator,
        "cof_elastic": v["f_el_avg"] / denominator,
        "cof_capillary": v["f_cap_avg"] / denominator,
        "friction_force_capillary": out["f_cap"],
        "capillary_force": out["f_cap_adh"],
        "wetted_area": out["wetted"],
        "energy_capillary": v["e_cap"],
        "energy_chemical": v["e_chem"],
        "energy_vdw": v["e_vdw"],
        "energy_elastic": v["e_el"],
        "energy_dissipated": v["energy"],
        "tangential_force": np.full(step.size, v["f_t"]),
        "stiction_margin": v["margin"],
        "mesh_efficiency": v["efficiency"],
        "friction_shear_stress": v["shear_stress"],
        "rigid_atomic_blocks": out["rigid_atomic_blocks"],
        **_limit_variables(cycle, verdict, denominator),
        # in air only (a vacuum dataset stays as it was): the water bridges of the rough rows (issue #28)
        **({"capillary_pull_off": out["f_cap_pull"], "bridged_area": out["bridged"],
            "bridged_perimeter": out["bridged_perimeter"],
            "capillary_adhesion_force": out["f_cap_bridge"]}
           if params["environment"] == "air" else {}),
    }


def _limit_variables(cycle, verdict, denominator) -> dict:
    """The start-up verdict, the local limits and the plastic fraction per step (MODEL 7d)."""
    out, limits = cycle["out"], verdict["limits"]
    return {
        "static_friction_force": limits["static"],
        "static_cof": limits["static"] / denominator,
        "startup_resisting_force": limits["startup_resisting"],
        "resisting_force_capped": limits["resisting_capped"],
        "startup_resisting_force_capped": limits["startup_resisting_capped"],
        "friction_force_chemical_rigid": out["f_chem_rigid"],
        "plastic_fraction": np.divide(out["plastic_elements"], out["contact_elements"],
                                      out=np.zeros_like(out["plastic_elements"]), where=out["contact_elements"] > 0),
    }


def _attributes(params, setup, cycle, verdict, modulus, beta, coating, wear, realisation, sliding_axis) -> dict:
    """The dataset's attributes: the case, the roughness rows, the F_t/F_f iteration and the warnings (JSON)."""
    import json

    rows_info = setup.row_roughness
    return {
        "title": "memstribo meshing-cycle simulation (thesis 4.6, 4.9)",
        "load_case": params["load_case"],
        "interface_model": params["interface_model"],
        "environment": params["environment"],
        "relative_humidity": float(params["relative_humidity"]) if params["environment"] == "air" else 0.0,
        "contact_adhesion": params["contact_adhesion"],
        "mesh_contact": params["mesh_contact"],
        "vdw_cutoff": float(params["vdw_cutoff"]),
        "friction_averaging_distance": float(verdict["averaging"]),
        "realisation": int(realisation),
        "sliding_axis": sliding_axis,
        "roughness": setup.roughness_name,
        "roughness_synthetic": int(setup.roughness_synthetic),
        "roughness_source": setup.roughness_source,
        "roughness_rows": rows_info.method,
        "roughness_lines_measured": int(rows_info.measured_lines),
        "roughness_lines_synthesised": int(rows_info.synthesised_lines),
        "roughness_lines_completed": int(getattr(rows_info, "completed_lines", 0)),
        "roughness_measured_share": float(getattr(rows_info, "measured_share", 0.0)),
        "block_load_variant": BLOCK_LOAD_VARIANT,
        "rows": setup.rows,
        "rows_solved": len(cycle["block_loads"]),
        "effective_face_width": setup.effective_face_width,
        "dundurs_beta": beta,
        "friction_passes": cycle["passes"],
        "friction_fixed_point_converged": int(cycle["converged"]),
        "undetermined_reason": verdict["undetermined"],
        "contact_modulus": modulus,
        "coating": "none (bare silicon)" if coating is None else coating.name,
        "wear": float(wear) if coating is not None else 1.0,
        "grid_spacing": setup.grid_spacing,
        "window": setup.grid.size * setup.grid_spacing,
        "tangential_force_total": verdict["f_t"],
        "normal_force_total": float(normal_force_of_load_case(params, setup.pair)),
        "input_power": verdict["input_power"],
        "mesh_efficiency_mean": verdict["efficiency_mean"],
        "elastic_limit_pressure": params["elastic_limit_pressure"],
        "ideal_shear_strength": params["ideal_shear_strength"],
        "hardness": float(params["hardness"]) if params["hardness"] is not None else float("nan"),
        "lattice_registry": params["lattice_registry"],
        "load_torque": float(params["load_torque"]),
        # a start-up margin [N] at the pinion's pitch radius as a load torque on the gear [N m]: r_w1 r_b2 / r_b1
        "startup_torque_arm": float(setup.pair.pitch_radii[0] * setup.pair.base_radii[1] / setup.pair.base_radii[0]),
        "startup_formed_share": float(verdict["limits"]["formed_share"]),
        "friction_share_rigid": verdict["limits"]["share_rigid"],
        "friction_share_overstrength": verdict["limits"]["share_overstrength"],
        "plastic_elements": float(cycle["out"]["plastic_elements"].sum()),
        "contact_elements": float(cycle["out"]["contact_elements"].sum()),
        "warnings": json.dumps(verdict["warnings"]),
    }


BLOCK_LOAD_VARIANT = ("decoupled: rough contact solved without the block springs, block loads = pressure over "
                      "each nanoblock's footprint, shared among its atomic blocks by the fixed-load model (3.4.2)")
