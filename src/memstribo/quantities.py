"""The one vocabulary of results: every output quantity named once, with its unit and meaning.

Every command's JSON, every NetCDF variable's ``units`` and ``long_name`` attributes, the CSV
headers, the report's tables and docs/quantities.md take a quantity's name, unit and long name from
:data:`QUANTITIES` (or, for an input, from the parameter's spec in :mod:`memstribo.parameters`).
The same quantity has the same name everywhere: a time series ``X`` over the steps of a cycle or a
slide, its statistics over the cycle ``X_mean``, ``X_max``, ``X_min``, its spread over roughness
realisations ``X_median``, ``X_p05``, ``X_p95`` (:data:`STATISTICS`). A scalar of the same name as
a time series (``stiction_margin``, ``mesh_efficiency``, ``tangential_force``) is the cycle's value
of that quantity, as its description says.

Units are UDUNITS strings (CF conventions): ``'1'`` for a dimensionless number, ``''`` for text,
flags and labels. ``python -m memstribo.quantities`` prints docs/quantities.md.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Quantity", "QUANTITIES", "STATISTICS", "quantity", "unit", "attrs", "attrs_or", "known", "markdown_table"]


@dataclass(frozen=True)
class Quantity:
    """One output quantity: ``name``, ``unit`` (UDUNITS; '1' dimensionless, '' text), ``long_name`` (short,
    for axes and attributes) and ``description`` (what it is, equation or section)."""

    name: str
    unit: str
    long_name: str
    description: str = ""


#: prefix -> whose value it is (``bare_stiction_margin``: the stiction margin of the bare teeth)
QUALIFIERS = {"bare": "bare teeth", "coated": "coated teeth"}

#: suffix -> (how it reads in a long name, what it is)
STATISTICS = {
    "mean": ("mean", "mean over the steps of the cycle or slide"),
    "max": ("maximum", "largest value over the steps"),
    "min": ("minimum", "smallest value over the steps"),
    "median": ("median", "median over the roughness realisations"),
    "p05": ("5 % quantile", "5 % quantile over the roughness realisations"),
    "p95": ("95 % quantile", "95 % quantile over the roughness realisations"),
}

_TEXT = ""

_ENTRIES = [
    # --- friction, the meshing cycle and flat sliding (thesis 3.3, 4.6-4.9, MODEL 7b) ---------------------
    ("cof", "1", "coefficient of friction", "apparent COF F_f / (F_N + F_adh) of the step (3-7)"),
    ("cof_chemical", "1", "COF from chemical bonds", "chemical part of the COF (3-8, 3-9)"),
    ("cof_vdw", "1", "COF from vdW bonds", "van der Waals part of the COF (3-8, 3-9)"),
    ("cof_elastic", "1", "COF from elastic interlocking", "elastic-interlocking part of the COF (3-9, 3-25)"),
    ("cof_capillary", "1", "COF from capillary menisci", "part of the COF from breaking capillary menisci (humid air)"),
    ("fraction_chemical", "1", "chemical share of friction", "share of the dissipated energy from chemical bonds"),
    ("fraction_vdw", "1", "vdW share of friction", "share of the dissipated energy from vdW bonds"),
    ("fraction_elastic", "1", "elastic share of friction", "share of the dissipated energy from elastic interlocking"),
    ("friction_force", "N", "friction force", "friction force F_f: dissipated energy per sliding distance, averaged over "
     "friction_averaging_distance in the meshing cycle (3-1, MODEL 7b)"),
    ("friction_force_chemical", "N", "friction force of chemical bonds", "friction force of breaking chemical bonds"),
    ("friction_force_vdw", "N", "friction force of vdW bonds", "friction force of breaking vdW bonds"),
    ("friction_force_elastic", "N", "friction force of elastic interlocking", "friction force of elastic interlocking (3-25)"),
    ("friction_force_capillary", "N", "friction force of capillary menisci", "friction force of breaking menisci"),
    ("friction_force_instantaneous", "N", "instantaneous friction force",
     "friction force of the step's bond population, interlocking and menisci, before averaging (3-1)"),
    ("friction_shear_stress", "Pa", "friction shear stress", "friction force over the real contact area"),
    ("resisting_force", "N", "resisting force R(c)", "friction of every pair in mesh at position c (MODEL 7b)"),
    ("tangential_force", "N", "tangential force F_t", "available tangential force T / r1 of the drive torque (4-27)"),
    ("stiction_margin", "N", "stiction margin", "F_t - R(c); as a scalar the cycle's smallest, F_t - max R "
     "(negative: stiction; MODEL 7b)"),
    ("stiction", _TEXT, "stiction", "true (1) where max R(c) > F_t: the teeth stick"),
    ("stiction_probability", "1", "stiction probability", "fraction of roughness realisations that stick"),
    ("mesh_efficiency", "1", "mesh efficiency", "1 - friction power / input power T omega1; as a scalar the cycle's "
     "mean (MODEL 7b)"),
    ("adhesion_force", "N", "adhesion force F_adh", "adhesion force (3-31, 3-32, or the cohesive zone of the contact "
     "solve; in humid air plus the water bridges' part, capillary_adhesion_force)"),
    ("capillary_force", "N", "capillary force", "line load of the capillary menisci's traction inside the contact "
     "solve (it loads the contact; not part of F_adh since issue #28)"),
    ("wetted_area", "m^2", "wetted area", "area under capillary menisci"),
    ("capillary_pull_off", "N", "capillary pull-off force", "force to pull the flanks apart against the water "
     "bridges of the rough rows: every gap below h_c plus the liquid-like adsorbed films (the termination's "
     "isotherm less its bound layers), each pinion block's "
     "pull-off the smaller of (3-32) with the bridges' work and the meniscus bound (gamma / r_K) A + gamma L of its "
     "bridged area and contact lines, summed (3-31); none below a molecular Kelvin radius (adsorbed film); "
     "issues #28, #36, docs/humidity.md"),
    ("capillary_adhesion_force", "N", "capillary part of F_adh", "the water bridges' part of the adhesion force "
     "F_adh in humid air: each pinion block's pull-off, bounded as capillary_pull_off's, over the elements where the "
     "bridge's work of separation exceeds the vdW work w12 (one work per element, the larger of the two), summed "
     "(3-31); issues #28, #36, docs/humidity.md"),
    ("bridged_area", "m^2", "bridged area", "area of the rough rows where the gap is below h_c plus the liquid-like "
     "adsorbed films (water or vapour bridges, issues #28, #36)"),
    ("bridged_perimeter", "m", "bridged perimeter", "length of the water bridges' contact lines on the rough rows: "
     "two lines across the block width per wetted run (issue #36); the meniscus bound is (gamma / r_K) "
     "bridged_area + gamma bridged_perimeter"),
    ("adsorbed_water_thickness", "m", "adsorbed water film thickness", "thickness t(RH) of the water film on "
     "hydrophilic silicon oxide from the published isotherm (Asay and Kim 2005; Verdaguer et al. 2007)"),
    ("normal_force", "N", "normal force", "normal force on the tooth pair (mesh) or on the structure (slide)"),
    ("normal_force_total", "N", "total normal force", "normal force F_t / cos(alpha) of the load case, shared by the "
     "pairs in mesh"),
    ("load_share", "1", "load share", "load share of the pair (load_sharing, thesis Figure 4-11)"),
    ("energy_dissipated", "J", "energy dissipated", "energy dissipated in the step (as a scalar: over the cycle)"),
    ("energy_chemical", "J", "energy of chemical bonds", "energy dissipated by breaking chemical bonds"),
    ("energy_vdw", "J", "energy of vdW bonds", "energy dissipated by breaking vdW bonds"),
    ("energy_elastic", "J", "energy of elastic interlocking", "energy dissipated by elastic interlocking (3-25)"),
    ("energy_capillary", "J", "energy of capillary menisci", "energy dissipated by breaking capillary menisci"),
    ("bonds_chemical", "1", "chemical bonds", "chemical bonds between touching atomic blocks N_chem (3-10)"),
    ("bonds_vdw", "1", "vdW bonds", "van der Waals bonds N_vdW, weighted by the interface model (3-12)"),
    ("bonds_vdw_bare", "1", "vdW bonds over bare gear blocks", "the part of bonds_vdw over gear blocks whose coating "
     "is worn (coated cycles; U_vdW of silicon acts on them)"),
    ("bonds_vdw_coated", "1", "vdW bonds over coated gear blocks", "the part of bonds_vdw over gear blocks still "
     "coated (coated cycles; the coating's U_vdW acts on them)"),
    ("sliding_distance", "m", "sliding distance", "sliding distance |u1 - u2| dt of the step (as a scalar: in all)"),
    ("sliding_velocity", "m/s", "sliding velocity", "sliding velocity u1 - u2 (4-12)"),
    ("time", "s", "time", "time since the first point of contact (4-18)"),
    ("c", "m", "position on the line of action", "position of the contact point on the line of action (0: pitch point)"),
    ("position", "m", "position along the line of action",
     "position of the contact point along the line of action, the same as c (0: pitch point): the x-axis of the "
     "cycle's plots, with step kept as the index"),
    ("step", "1", "step", "index of the step"),
    ("steps", "1", "steps", "number of steps of the cycle or slide"),
    ("effective_radius", "m", "radius of relative curvature", "R_ef of the teeth at the contact point (4-11)"),
    ("block_load", "N", "nanoblock load", "normal load of each nanoblock (pinion and gear flanks, rows)"),
    ("block_flank", _TEXT, "flank of the nanoblock", "pinion or gear"),
    ("block_row", "1", "row of the nanoblock", "row of nanoblocks across the face width"),
    ("block_index", "1", "index of the nanoblock", "index of the nanoblock along its flank"),
    ("rigid_atomic_blocks", "1", "rigid atomic blocks", "atomic blocks past the threshold strain (rigid branch of the "
     "bilinear law)"),
    ("unconverged_steps", "1", "unconverged steps", "steps whose contact solve did not converge"),
    ("window_exceeded", _TEXT, "window exceeded", "true where the contact reached the ends of the contact window"),
    ("window_exceeded_steps", "1", "steps past the window", "steps whose contact reached the window's ends"),
    ("steps_above_elastic_limit", "1", "steps above the elastic limit", "steps whose peak pressure exceeds "
     "elastic_limit_pressure"),
    ("max_shear_stress", "Pa", "largest friction shear stress", "largest friction stress on the real contact area, "
     "against the ideal shear strength of silicon (MODEL 7c)"),
    ("max_contact_pressure", "Pa", "largest contact pressure", "largest element pressure of the rough contact"),
    # --- what the verdict hangs on (MODEL 7d, issue #26) --------------------------------------------------------
    ("static_friction_force", "N", "start-up friction force", "the force that starts a pair at rest (MODEL 7f): the "
     "largest, over the sliding offset, of its rows' bond forces at their registries (each bond's lateral law, peak "
     "1.27 U / D), times the share formed after the dwell, plus its elastic and capillary friction"),
    ("startup_resisting_force", "N", "start-up resisting force", "R_s(c): the start-up torque balance as a force at the "
     "pinion's pitch radius, the load torque and every pair in mesh with its friction's moment arm (the flanks' radii "
     "of curvature; MODEL 7f)"),
    ("bonds_chemical_row", "1", "chemical bonds per row", "chemical bonds of each nanoblock row (3-10)"),
    ("bonds_vdw_bare_row", "1", "vdW bonds over bare gear blocks per row", "vdW bonds of each row over bare gear blocks "
     "(3-12)"),
    ("bonds_vdw_coated_row", "1", "vdW bonds over coated gear blocks per row", "vdW bonds of each row over coated gear "
     "blocks (3-12)"),
    ("row", "1", "nanoblock row", "index of the nanoblock row across the face width"),
    ("bond_phase", "1", "bond phase of the row", "each row's phase in its bonds' renewal period at rest (the lattice "
     "registry, MODEL 7d, 7f)"),
    ("load_torque", "N m", "load torque on the gear at start-up", "load torque of the start-up torque balance (MODEL 7f)"),
    ("startup_load_torque_limit", "N m", "largest load torque that still starts", "the load torque on the gear at "
     "which the start-up margin reaches zero, the friction as computed (MODEL 7f); the frictionless pair delivers "
     "T r_b2 / r_b1"),
    ("startup_torque_arm", "m", "start-up torque arm", "r_w1 r_b2 / r_b1: a start-up margin at the pinion's pitch "
     "radius as a load torque on the gear"),
    ("startup_formed_share", "1", "share of bonds formed at rest", "the logarithmic ageing law after startup_dwell "
     "(1: every bond; MODEL 7f)"),
    ("static_cof", "1", "start-up COF", "start-up friction force / (F_N + F_adh) of the pair"),
    ("startup_margin", "N", "start-up margin", "F_t - max R_s(c) (negative: the gear cannot start; "
     "MODEL 7f)"),
    ("startup_stiction_probability", "1", "start-up stiction probability", "fraction of roughness realisations "
     "whose gear cannot start from rest (MODEL 7d)"),
    ("startup_stiction", _TEXT, "start-up stiction", "true where the start-up resisting force exceeds F_t somewhere"),
    ("stiction_mode", _TEXT, "which verdict fails", "running (the kinetic friction exceeds F_t), start-up (only the "
     "start from rest fails) or none"),
    ("resisting_force_capped", "N", "resisting force, bond stress capped", "R(c) with each bond population's shear "
     "stress capped at the ideal shear strength of silicon (local limits, MODEL 7d)"),
    ("startup_resisting_force_capped", "N", "start-up resisting force, bond stress capped", "start-up R(c) with the "
     "bonds' shear stress capped at the ideal shear strength"),
    ("stiction_margin_capped", "N", "stiction margin, bond stress capped", "F_t - max R(c) with the bonds' shear stress "
     "capped at the ideal shear strength of silicon"),
    ("startup_margin_capped", "N", "start-up margin, bond stress capped", "start-up margin with the bonds' shear stress "
     "capped at the ideal shear strength of silicon"),
    ("stiction_mode_capped", _TEXT, "which verdict fails, capped", "stiction_mode with the bonds' shear stress capped "
     "at the ideal shear strength"),
    ("friction_share_rigid", "1", "friction share of rigid blocks", "share of the cycle's friction energy from the "
     "chemical bonds of atomic blocks past the threshold strain of the bilinear law"),
    ("friction_share_overstrength", "1", "friction share beyond the ideal strength", "share of the cycle's friction "
     "energy from bond populations whose shear stress exceeds the ideal shear strength of silicon"),
    ("friction_force_chemical_rigid", "N", "chemical friction of rigid blocks", "chemical friction force from pairs of "
     "atomic blocks of which one is past the threshold strain"),
    ("plastic_fraction", "1", "plastically loaded fraction", "share of the contact elements at the hardness (pressure "
     "capped, elastic-perfectly-plastic; MODEL 7d); as a scalar over the cycle's contact elements"),
    ("plastic_steps", "1", "steps with plastic flow", "steps where some contact element reached the hardness"),
    ("stiction_margin_uncapped", "N", "stiction margin without the pressure cap", "the stiction margin of the same "
     "cycle solved purely elastically (no hardness cap)"),
    ("startup_margin_uncapped", "N", "start-up margin without the pressure cap", "the start-up margin of the same "
     "cycle solved purely elastically"),
    ("cof_mean_uncapped", "1", "mean COF without the pressure cap", "cof_mean of the same cycle solved purely "
     "elastically"),
    ("window", "m", "contact window", "length of the contact window solved at each step (sized to hold the contact "
     "and the vdW range unless mesh_window is set)"),
    ("step_converged", _TEXT, "converged in the steps", "true when doubling the steps changes the margin and the mean "
     "COF by less than 2 %"),
    ("step_change_margin", "1", "change of the margin with the steps", "change of the stiction margin when the steps "
     "are doubled, relative to |margin| (MODEL 7d)"),
    ("step_change_margin_ft", "1", "change of the margin with the steps, of F_t", "the same change of the stiction "
     "margin relative to F_t (the figure before issue #25)"),
    ("grid_converged", _TEXT, "converged in the grid", "true when doubling the grid's resolution changes the margin "
     "(of |margin|) and the mean COF by less than 2 %"),
    ("grid_change_margin", "1", "change of the margin with the grid", "change of the stiction margin when the grid's "
     "resolution is doubled, relative to |margin|"),
    ("grid_change_cof", "1", "change of the COF with the grid", "relative change of the mean COF when the grid's "
     "resolution is doubled"),
    ("grid_change_adhesion", "1", "change of the adhesion force with the grid", "relative change of the mean "
     "adhesion force when the grid's resolution is doubled"),
    ("adhesion_force_resolved", _TEXT, "adhesion force resolved", "true when the mean adhesion force changes by less "
     "than 5 % on the last grid halving (MODEL 7d)"),
    ("elements_checked", "1", "elements across 2a of the check", "mesh_elements_across_contact of the finer cycle of "
     "the grid-convergence check"),
    ("elements_across_contact", "1", "elements across 2a", "mesh_elements_across_contact of the cycle reported"),
    ("grid_spacing", "m", "grid spacing", "element width of the contact solves of the cycle reported"),
    ("refinement", _TEXT, "refinement", "the comparisons of the self-refining cycle, one sentence each"),
    ("verdict", _TEXT, "verdict", "running stiction, start-up stiction, no stiction, or undetermined (an unsettled "
     "fixed point: no COF or stiction flag is a result)"),
    ("undetermined_reason", _TEXT, "why undetermined", "why the cycle gives no verdict (empty when it gives one)"),
    ("step_change_cof", "1", "change of the COF with the steps", "relative change of the mean COF when the steps are "
     "doubled"),
    ("step_change_startup", "1", "change of the start-up margin with the steps", "relative change of the start-up "
     "margin when the steps are doubled (of |margin|; MODEL 7h)"),
    ("grid_change_startup", "1", "change of the start-up margin with the grid", "relative change of the start-up "
     "margin when the grid's resolution is doubled (of |margin|; MODEL 7h)"),
    ("step_margin_bound", _TEXT, "bound of the step check", "which bound decided the margin's step check: 'margin' "
     "(2 % of |margin|) or 'resisting force' (0.5 % of it; MODEL 7h)"),
    ("grid_margin_bound", _TEXT, "bound of the grid check", "which bound decided the margin's grid check (MODEL 7h)"),
    ("step_startup_bound", _TEXT, "bound of the start-up step check", "which bound decided the start-up margin's step "
     "check (MODEL 7h)"),
    ("grid_startup_bound", _TEXT, "bound of the start-up grid check", "which bound decided the start-up margin's grid "
     "check (MODEL 7h)"),
    ("margin_bound", _TEXT, "bound of the margin check", "which bound decided the margin's check (MODEL 7h)"),
    ("startup_bound", _TEXT, "bound of the start-up check", "which bound decided the start-up margin's check"),
    ("steps_checked", "1", "steps of the check", "steps of the finer cycle of the step-convergence check"),
    ("realisations", "1", "roughness realisations", "independent roughness realisations of the ensemble"),
    ("area_multiple", "1", "multiple of the nominal contact area", "apparent contact area over the default "
     "(thesis 4.9.4)"),
    ("realisation", "1", "roughness realisation", "index of the roughness realisation"),
    ("realisation_stiction_margin", "N", "stiction margin of each realisation", "F_t - max R of each roughness "
     "realisation's cycle"),
    ("realisation_cof_mean", "1", "mean COF of each realisation", "mean COF of each roughness realisation's cycle"),
    ("realisation_mesh_efficiency", "1", "mesh efficiency of each realisation", "mesh efficiency of each roughness "
     "realisation's cycle"),
    ("per_realisation", _TEXT, "per realisation", "the summary of each realisation"),
    ("roughness_rows", _TEXT, "rows of the roughness", "how the rows of nanoblocks got their roughness lines"),
    # --- the contact solves ------------------------------------------------------------------------------------
    ("contact_width", "m", "contact width", "measure of the contact set of the rough contact, where the gap is "
     "closed (row mean; with the Maugis-Dugdale zone it includes the contact's tensile edges, not the open zone)"),
    ("contact_approach", "m", "contact approach", "rigid approach of the rough contact solve (row mean)"),
    ("contact_converged", _TEXT, "contact converged", "true where the contact solve converged in every row"),
    ("contact_residual", "1", "contact residual", "largest complementarity residual over the rows"),
    ("contact_iterations", "1", "contact iterations", "mean conjugate-gradient iterations over the rows"),
    ("hertz_half_width", "m", "Hertz half-width", "Hertz half-width a of smooth teeth (4-24)"),
    ("hertz_peak_pressure", "Pa", "Hertz peak pressure", "Hertz peak pressure p0 of smooth teeth (4-26)"),
    ("contact_length", "m", "contact length", "measure of the contact set of a line contact"),
    ("contact_fraction", "1", "contact fraction", "fraction of the surface in contact"),
    ("contact_radius", "m", "contact radius", "radius of an axisymmetric contact"),
    ("contact", _TEXT, "in contact", "true where the element is in contact"),
    ("max_pressure", "Pa", "largest pressure", "largest contact pressure of the solve"),
    ("min_pressure", "Pa", "smallest pressure", "smallest (most tensile) contact pressure of the solve"),
    ("max_pressure_radius", "m", "radius of the largest pressure", "radius at which the pressure is largest"),
    ("mean_pressure", "Pa", "mean pressure", "load over the nominal area"),
    ("pressure", "Pa", "contact pressure", "contact pressure"),
    ("gap", "m", "gap", "deformed gap between the surfaces"),
    ("mean_gap", "m", "mean gap", "mean deformed gap"),
    ("approach", "m", "approach", "rigid-body approach of the bodies (slide: of the structure's backing)"),
    ("load", "N/m", "line load", "load per unit face width of a line contact"),
    ("iterations", "1", "iterations", "conjugate-gradient iterations of the solve"),
    ("residual", "1", "residual", "relative complementarity residual of the solve"),
    ("converged", _TEXT, "converged", "true when the solve met its tolerance; of a meshing cycle, sweep or map point: "
     "when its step and grid checks passed (MODEL 7d)"),
    ("solve_seconds", "s", "solve time", "wall time of the solve"),
    ("adhesive_load", "N/m", "adhesive line load", "tensile line load of the cohesive zone"),
    ("cohesive_length", "m", "cohesive length", "measure of the cohesive zone"),
    ("cohesive_stress", "Pa", "cohesive stress", "Maugis-Dugdale stress sigma0 (MODEL 7c)"),
    ("cohesive_range", "m", "cohesive range", "Maugis-Dugdale range h0 = w / sigma0 (MODEL 7c)"),
    ("maugis_parameter", "1", "Maugis parameter", "lambda of the line contact (Johnson & Greenwood 2008)"),
    ("pull_off_line_load", "N/m", "pull-off line load", "tensile line load at separation (positive)"),
    ("pull_off_half_width", "m", "half-width at pull-off", "contact half-width at pull-off"),
    ("maugis_dugdale_pull_off_line_load", "N/m", "Maugis-Dugdale pull-off line load", "closed form of the "
     "Maugis-Dugdale line contact at the same lambda"),
    ("maugis_dugdale_pull_off_half_width", "m", "Maugis-Dugdale half-width at pull-off", "closed form at the same "
     "lambda"),
    ("jkr_pull_off_line_load", "N/m", "JKR pull-off line load", "(3/4)(4 pi E* w^2 R)^(1/3) of the JKR line contact"),
    ("unloading_steps", "1", "unloading steps", "load steps of the unloading branch"),
    # --- nanoscale constants, nanoblocks and sliding ---------------------------------------------------------
    ("epsilon", "J", "Lennard-Jones epsilon", "well depth of the 12-6 potential (3.3.3)"),
    ("sigma", "m", "Lennard-Jones sigma", "zero-crossing distance of the 12-6 potential (3.3.3)"),
    ("bond_energy_chemical", "J", "chemical bond energy", "energy of one chemical bond (3.3.4)"),
    ("bond_energy_vdw", "J", "vdW bond energy", "energy of one van der Waals bond (3.3.5)"),
    ("contact_modulus", "Pa", "contact modulus E*", "1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2"),
    ("no_slip_coefficient", "1", "no-slip coefficient C_NS", "(3-33)"),
    ("maugis_stress", "Pa", "Maugis stress sigma0", "16 w / (9 sqrt(3) z0) (MODEL 2)"),
    ("maugis_range", "m", "Maugis range h0", "w / sigma0 (MODEL 2)"),
    ("half_width", "m", "half-width of an adhesive block", "half-width a of the block's pull-off contact (3-32)"),
    ("pull_off_force_block", "N", "pull-off force of a block", "sqrt(8 pi w E* C_NS a^3) (3-32)"),
    ("blocks", "1", "nanoblocks", "nanoblocks in contact in the estimate of thesis 3.5"),
    ("bonds_chemical_per_block", "1", "chemical bonds per block", "chemical bonds of one fully overlapped atomic "
     "block (thesis 3.5 estimate)"),
    ("bonds_vdw_per_block", "1", "vdW bonds per block", "vdW bonds of one adhesive block (thesis 3.5 estimate)"),
    ("energy_chemical_per_block", "J", "chemical bond energy per block", "N_chem U_chem of one block (3.5)"),
    ("energy_vdw_per_block", "J", "vdW bond energy per block", "N_vdW U_vdW of one block (3.5)"),
    ("thesis_inputs_cof", "1", "COF from the thesis's printed inputs", "the 3.5 estimate with the values printed "
     "in thesis 3.5"),
    ("thesis_inputs_friction_force", "N", "friction force from the thesis's printed inputs", "the 3.5 estimate "
     "with the values printed in thesis 3.5"),
    ("thesis_counts_cof", "1", "COF from the thesis's bond counts", "the 3.5 estimate with the bond counts printed "
     "in thesis 3.5"),
    ("atomic_in_contact", "1", "atomic blocks in contact", "atomic blocks touching the counter surface"),
    ("atomic_compression", "m", "atomic compression", "compression of each atomic block"),
    ("atomic_stress", "Pa", "atomic stress", "normal stress on each atomic block"),
    ("atomic_rigid", _TEXT, "rigid atomic block", "true for an atomic block on the rigid branch of the bilinear law"),
    ("max_atomic_stress", "Pa", "largest atomic stress", "largest normal stress on an atomic block"),
    ("structure_height", "m", "structure height", "height of the undeformed atomic tips above the counter mean line"),
    ("load_residual", "1", "load residual", "relative force-balance error |F_N - load| / load"),
    ("block_force", "N", "adhesive block force", "normal force through each adhesive block"),
    ("block_adhesion_force", "N", "adhesive block pull-off force", "pull-off force (3-32) of each adhesive block"),
    ("adhesive_compression", "m", "adhesive compression", "compression of each adhesive block"),
    ("bulk_compression", "m", "bulk compression", "compression of the bulk segment under each nanoblock"),
    ("shrink", "m", "nanoblock shrink", "total shrink of each nanoblock (bulk + adhesive + most compressed atomic block)"),
    ("rules", _TEXT, "rules", "which rule produced each nanoblock size"),
    ("parameters", _TEXT, "parameters", "every model parameter (memstribo parameters --json): value [SI], unit, kind, "
     "bounds, choices, allowed values, why, source"),
    # --- gear ---------------------------------------------------------------------------------------------------
    ("pitch_radii", "m", "pitch radii", "pitch radii of pinion and gear (4-1)"),
    ("base_radii", "m", "base radii", "base radii of pinion and gear (4-2)"),
    ("tip_radii", "m", "tip radii", "tip radii of pinion and gear"),
    ("tip_thickness", "m", "tip thickness", "tooth thickness at the tip circle, pinion and gear (ISO 21771)"),
    ("centre_distance", "m", "centre distance", "centre distance of the pair"),
    ("base_pitch", "m", "base pitch", "base pitch pi m cos(alpha)"),
    ("path_of_contact", "m", "path of contact", "length of the path of contact (4-5)"),
    ("contact_ratio", "1", "contact ratio", "path of contact over base pitch (4-6)"),
    ("first_contact", "m", "first point of contact", "position of the first point of contact on the line of action"),
    ("last_contact", "m", "last point of contact", "position of the last point of contact on the line of action"),
    ("single_tooth_zone", "m", "single-tooth zone", "ends of the single-tooth zone on the line of action"),
    ("effective_radius_pitch", "m", "radius of relative curvature at the pitch point", "R_ef at the pitch point (4-11)"),
    # --- roughness (ISO 4287, ISO 25178) ---------------------------------------------------------------------
    ("Ra", "m", "Ra", "arithmetic mean deviation of the profile (ISO 4287)"),
    ("Rq", "m", "Rq", "root-mean-square deviation of the profile (ISO 4287)"),
    ("Rq_std", "m", "spread of Rq", "standard deviation of Rq over the scan lines of a map"),
    ("Rp", "m", "Rp", "largest peak height (ISO 4287)"),
    ("Rv", "m", "Rv", "largest valley depth (ISO 4287)"),
    ("Rz", "m", "Rz", "largest height of the profile Rp + Rv (ISO 4287)"),
    ("Rsk", "1", "Rsk", "skewness (ISO 4287)"),
    ("Rku", "1", "Rku", "kurtosis (ISO 4287)"),
    ("Sa", "m", "Sa", "arithmetic mean height of the surface (ISO 25178)"),
    ("Sq", "m", "Sq", "root-mean-square height of the surface (ISO 25178)"),
    ("Sp", "m", "Sp", "largest peak height of the surface (ISO 25178)"),
    ("Sv", "m", "Sv", "largest valley depth of the surface (ISO 25178)"),
    ("Sz", "m", "Sz", "largest height of the surface (ISO 25178)"),
    ("Ssk", "1", "Ssk", "skewness of the surface (ISO 25178)"),
    ("Sku", "1", "Sku", "kurtosis of the surface (ISO 25178)"),
    ("rms_slope", "1", "rms slope", "root-mean-square slope of the profile"),
    ("lambda_q", "m", "lambda_q", "root-mean-square wavelength 2 pi Rq / rms slope"),
    ("length", "m", "length", "length of the profile"),
    ("sample_spacing", "m", "sample spacing", "distance between the samples of the profile"),
    ("dy", "m", "row spacing", "distance between the scan lines of a map"),
    ("n_points", "1", "points", "samples of the profile or scan line"),
    ("n_rows", "1", "rows", "scan lines of a map"),
    ("n_line_scans", "1", "line scans", "scan lines analysed"),
    ("uniform", _TEXT, "uniform sampling", "true when the samples are evenly spaced"),
    ("profile", _TEXT, "profile", "name of the roughness profile"),
    ("x", "m", "position", "position along the sliding direction"),
    ("y", "m", "position across", "position across the sliding direction"),
    ("z", "m", "height", "height of the surface"),
    # --- coatings and damage (thesis 5.4, 5.5) ----------------------------------------------------------------
    ("wear", "1", "worn fraction Omega", "worn fraction of the gear's coating (the pinion's is worn; 5.5.3)"),
    ("critical_wear", "1", "critical worn fraction", "Omega at which stiction returns; NaN: never, bare or unknown"),
    ("cycles_to_failure", "1", "cycles to coating failure", "meshing cycles until the coating first fails "
     "(omega = 1); NaN: unknown or bare"),
    ("cycles_to_stiction", "1", "cycles to stiction", "meshing cycles until the worn fraction brings stiction back; "
     "NaN: unknown, bare or never"),
    ("target_cof", "1", "target COF", "the mean COF a calibration aims at"),
    ("cof_before", "1", "COF before calibration", "mean COF of the meshing cycle with the coating's own U_vdW"),
    ("cof_after", "1", "COF after calibration", "mean COF of the meshing cycle with the calibrated U_vdW"),
    ("vdw_bond_energy_before", "J", "U_vdW before calibration", "the coating's vdW bond energy before"),
    ("vdw_bond_energy_after", "J", "U_vdW after calibration", "the calibrated vdW bond energy"),
    ("factor", "1", "calibration factor", "calibrated over original value"),
    ("runs", "1", "runs", "meshing cycles the calibration ran"),
    ("config_file", _TEXT, "config file", "the TOML written for --config"),
    ("worn_fraction", "1", "worn fraction", "worn fraction Omega of the coating after N cycles"),
    ("cycles", "1", "meshing cycles", "meshing cycles N"),
    ("life_ratio_corner_to_central", "1", "life ratio corner / central", "coating life at a corner asperity over "
     "that at a central one"),
    ("omega_over_c1_max", _TEXT, "largest damage rate omega / c1", "largest damage rate per cycle over the damage "
     "coefficient (unit: Pa to the damage exponent)"),
    ("omega_over_c1_central", _TEXT, "damage rate omega / c1, central asperity", "damage per meshing cycle over "
     "c1 along the sliding line through a central asperity (unit: Pa to the damage exponent)"),
    ("omega_over_c1_corner", _TEXT, "damage rate omega / c1, corner asperity", "the same at a corner asperity"),
    ("omega_over_c1_side", _TEXT, "damage rate omega / c1, side asperity", "the same at a side asperity"),
    ("location", "m", "location", "position of the most damaged point"),
    ("central", _TEXT, "central asperity", "the result at a central asperity"),
    ("corner", _TEXT, "corner asperity", "the result at a corner asperity"),
    ("side", _TEXT, "side asperity", "the result at a side asperity"),
    # --- labels of a run, a sweep, a map ------------------------------------------------------------------------
    ("name", _TEXT, "name", "name of the surface or study"),
    ("source", _TEXT, "source", "where the data came from (file and channel, or synthetic and seed)"),
    ("channel", _TEXT, "channel", "channel of the instrument file"),
    ("kind", _TEXT, "kind", "profile or map"),
    ("synthetic", _TEXT, "synthetic", "true for a synthetic surface"),
    ("coating", _TEXT, "coating", "the teeth's coating"),
    ("parameter", _TEXT, "swept parameter", "name of the swept parameter"),
    ("points", _TEXT, "points", "the results of each point"),
    ("warnings", _TEXT, "warnings", "physical limits passed and numerical trouble, as sentences (MODEL 7c)"),
    ("note", _TEXT, "note", "what could not be computed at the point"),
    ("error", _TEXT, "error", "error message of a failed point (empty: ok)"),
    ("point_id", _TEXT, "point id", "id of the point's file in points/"),
    ("elapsed", "s", "elapsed time", "wall time of the command"),
    ("folder", _TEXT, "results folder", "the folder a run wrote"),
    ("report", _TEXT, "report", "path of report.html"),
    ("complete", _TEXT, "complete", "true when every requested stage finished"),
    ("stages", _TEXT, "stages", "status of each stage of the run"),
    ("failed_stages", _TEXT, "failed stages", "the stages that did not finish, with the reason"),
    ("kept_stages", _TEXT, "kept stages", "stages kept from the earlier run (--resume)"),
    ("asperity_loads", "N", "asperity loads", "load of each asperity class of a nanoblock (5.5.2)"),
    ("shares", "1", "load shares", "share of the block load of each asperity class (5.5.2)"),
    ("load_case", _TEXT, "load case", "torque or thesis (MODEL 7b)"),
    ("interface_model", _TEXT, "interface model", "gap or thesis (MODEL 7c)"),
    ("contact_adhesion", _TEXT, "contact adhesion", "none or maugis (MODEL 7c)"),
    ("mesh_contact", _TEXT, "mesh contact", "line or surface"),
    ("environment", _TEXT, "environment", "vacuum or air"),
    # --- tooth strength and temperature (MODEL §10, issue #30; docs/strength.md, docs/thermal.md) ---------
    ("root_stress", "Pa", "tooth root stress", "tensile stress in the loaded root fillet: ISO 6336-3 method B "
     "(30 deg tangent section, Y_S) with the moment and the direct stress of the normal and the friction force; "
     "as root_stress_max of a cycle [pinion, gear]"),
    ("root_stress_pinion", "Pa", "tooth root stress (pinion)", "tensile root stress of the pinion tooth in mesh at "
     "the step (ISO 6336-3 method B, the pair's normal and friction force)"),
    ("root_stress_gear", "Pa", "tooth root stress (gear)", "tensile root stress of the gear tooth in mesh at the step "
     "(ISO 6336-3 method B, the pair's normal and friction force)"),
    ("root_stress_compressive_min", "Pa", "most compressive root stress",
     "most compressive stress in the unloaded root fillet over the cycle, [pinion, gear]"),
    ("root_effective_area", "m^2", "effective stressed area of the root",
     "Weibull effective area b integral (sigma/sigma_max)^m ds of the loaded root and flank, [pinion, gear]"),
    ("fracture_probability", "1", "fracture probability on the first load",
     "probability that any tooth of the pair breaks on the first load (Weibull, size effect by area)"),
    ("fracture_probability_pinion_tooth", "1", "fracture probability of a pinion tooth",
     "probability that one pinion tooth breaks on the first load"),
    ("fracture_probability_gear_tooth", "1", "fracture probability of a gear tooth",
     "probability that one gear tooth breaks on the first load"),
    ("cycles_to_fracture_p01", "1", "cycles to 1 % fracture probability",
     "pinion revolutions until a tooth of the pair has broken with probability 1 % (delayed failure of "
     "polysilicon in air, strength falling as N^(-1/n)); null without tensile stress"),
    ("flash_temperature", "K", "flash temperature rise", "mean contact temperature rise over the band at the step "
     "(Jaeger's moving band source, Blok's partition)"),
    ("bulk_temperature_rise", "K", "bulk temperature rise", "rise of the hotter gear's flank away from the flash: its "
     "disc's rise (mean friction power over the hub's conductance, radiation and, in air, the air gap) plus the "
     "conduction along the tooth from its root"),
    ("disc_temperature_rise", "K", "disc temperature rise", "mean friction power into each gear over the conductance "
     "of its hub, its radiation and, in air, the air gap, [pinion, gear]"),
    ("tooth_temperature_rise", "K", "tooth temperature rise", "rise along each gear's tooth from its root to the "
     "dissipation-weighted contact point (a fin of the pitch thickness), [pinion, gear]"),
    ("flash_diffusion_length_max", "m", "flash diffusion length", "largest depth a / min(L, sqrt L) that the flash's "
     "heat reaches over the heated steps; the half-space holds while it is below the tooth's thickness"),
    ("contact_temperature_max", "K", "largest contact temperature",
     "ambient temperature + bulk temperature rise + largest flash temperature rise"),
    ("laboratory_rows", _TEXT, "laboratory rows", "per published measurement: id, quantity, measured value, predicted "
     "median and 90 % band (SI, the row's unit), inside or outside, or why not predicted (issue 28)"),
    ("held_out_inside_before", "1", "held-out hits before calibration", "held-out measurements inside the 90 % band over "
     "roughness x prior samples (issue 28)"),
    ("held_out_inside_after", "1", "held-out hits after calibration", "held-out measurements inside the 90 % band over "
     "roughness x posterior (issue 28)"),
    ("held_out_predicted", "1", "held-out rows predicted", "held-out measurements the model could predict (issue 28)"),
    ("effective_sample_size", "1", "effective sample size", "(sum w)^2 / sum w^2 of the calibration's importance weights"),
    ("calibration_rows", _TEXT, "calibration rows", "ids of the measurements a 'memstribo calibrate' fit used "
     "(never held out; issue 37)"),
    ("calibrated_constants", _TEXT, "calibrated constants", "per calibrated constant: name, prior and posterior median "
     "and 5-95 % interval (SI, the parameter's unit; issue 37)"),
    ("calibrated_set_file", _TEXT, "calibrated parameter set", "the parameter set file written by 'memstribo calibrate', "
     "for --parameter-set FILE (issue 37)"),
    ("fitted_constants", _TEXT, "fitted constants", "fitted or calibrated constants the run uses, with their value, "
     "unit and fit conditions (issue 28)"),
    # --- what the verdict hangs on (MODEL 7d, issue 27; memstribo.uncertainty) -----------------------------
    ("stiction_count", "1", "stiction count", "samples (realisations, or realisations x constant sets) that stick"),
    ("stiction_probability_ci", "1", "stiction probability interval",
     "95 % confidence interval [low, high] of the stiction probability from the number of samples (Wilson)"),
    ("solve_sets", "1", "solve sets", "distinct values per realisation of the constants that need a contact solve "
     "(null: every constant set its own); the bond energies keep every set's"),
    ("solve_seconds", "s", "contact solve time", "wall time the uncertainty study spent solving meshing cycles"),
    ("workers", "1", "worker processes", "processes the uncertainty study's meshing cycles ran on (1: this process; "
     "more: a Dask cluster, the run's by default one per core, issue 40)"),
    ("contact_rows_reused", "1", "contact solves reused",
     "rows' contact solves (a row over the whole cycle) the uncertainty study took from an earlier solve with the "
     "same inputs instead of solving them again (issue 40; in this process, not counting Dask workers')"),
    ("nominal_cycles_reused", "1", "nominal cycles reused",
     "realisations at the nominal constants the uncertainty study took from the run's mesh ensemble instead of "
     "solving them again (the same function of the same inputs; issue 40)"),
    ("rescale_seconds", "s", "rescaling time", "wall time the uncertainty study spent rescaling solved cycles to "
     "other bond energies"),
    ("design_effect", "1", "design effect of shared contact solves",
     "variance of P(stiction) over the samples that share a contact solve (a realisation and the solve's constants), "
     "over the binomial variance of independent samples, at least 1 (Kish 1965); the interval uses "
     "effective_samples = samples / design_effect"),
    ("effective_samples", "1", "effective samples", "samples / design_effect: the independent samples worth as much "
     "as the study's correlated ones (its interval of P(stiction) is Wilson's at this count)"),
    ("stiction_probability_text", _TEXT, "stiction probability with interval",
     "the count and its interval, e.g. '0 of 16 (95 % CI 0-19 %)'"),
    ("startup_stiction_count", "1", "start-up stiction count", "roughness realisations whose start-up margin is "
     "negative (the gear cannot start from rest)"),
    ("startup_stiction_probability_ci", "1", "start-up stiction probability interval",
     "95 % confidence interval [low, high] of the start-up stiction probability from the number of realisations "
     "(Wilson)"),
    ("startup_stiction_probability_text", _TEXT, "start-up stiction probability with interval",
     "the count and its interval, e.g. '16 of 16 (95 % CI 81-100 %)'"),
    # the verdict under the laboratory's posterior (memstribo mesh --uncertainty N --calibration FILE, issue 37)
    ("posterior_stiction_probability", "1", "stiction probability under the posterior",
     "share of the study's samples that stick, importance-weighted by the --calibration file's likelihood (or its "
     "calibrated posterior over the prior)"),
    ("posterior_stiction_probability_ci", "1", "stiction probability interval under the posterior",
     "95 % Wilson interval [low, high] at the weights' Kish effective sample size"),
    ("posterior_startup_stiction_probability", "1", "start-up stiction probability under the posterior",
     "share of the study's samples whose start-up margin is negative, importance-weighted as above"),
    ("posterior_startup_stiction_probability_ci", "1", "start-up stiction probability interval under the posterior",
     "95 % Wilson interval [low, high] at the weights' Kish effective sample size"),
    ("posterior_effective_samples", "1", "effective samples of the posterior",
     "Kish's (sum w)^2 / sum w^2 of the importance weights: the equally weighted samples the posterior is worth"),
    ("posterior_calibration", _TEXT, "calibration file", "the --calibration file the posterior comes from"),
    ("posterior_moved_by", _TEXT, "measurements that moved the verdict",
     "per row of the --calibration file: its id, P(stiction) under that row alone and its shift from the prior, "
     "its effective samples; largest shift first"),
    ("stiction_probability_nominal", "1", "stiction probability at nominal constants",
     "fraction of roughness realisations that stick with every constant at its nominal value"),
    ("stiction_probability_nominal_ci", "1", "stiction probability interval at nominal constants",
     "95 % confidence interval [low, high] of stiction_probability_nominal (Wilson)"),
    ("stiction_probability_nominal_text", _TEXT, "stiction probability at nominal constants, with interval",
     "the count over the realisations at nominal constants and its interval"),
    ("startup_stiction_probability_nominal", "1", "start-up stiction probability at nominal constants",
     "fraction of roughness realisations that cannot start with every constant at its nominal value"),
    ("startup_stiction_probability_nominal_ci", "1", "start-up stiction probability interval at nominal constants",
     "95 % confidence interval [low, high] of startup_stiction_probability_nominal (Wilson)"),
    ("startup_stiction_probability_nominal_text", _TEXT, "start-up stiction probability at nominal constants, with "
     "interval", "the count over the realisations at nominal constants and its interval"),
    ("startup_stiction_probability_low", "1", "start-up stiction probability, lower bound", "lower bound of the 95 % "
     "interval of the start-up stiction probability"),
    ("startup_stiction_probability_high", "1", "start-up stiction probability, upper bound", "upper bound of the 95 % "
     "interval of the start-up stiction probability"),
    ("stiction_probability_low", "1", "stiction probability, lower bound", "lower bound of the 95 % interval"),
    ("stiction_probability_high", "1", "stiction probability, upper bound", "upper bound of the 95 % interval"),
    ("uncertainty_samples", "1", "uncertainty samples", "realisations x constant sets of the uncertainty study"),
    ("constant_sets", "1", "constant sets", "sets of the uncertain constants drawn from their priors (Sobol' design)"),
    ("margin_quantiles", "N", "stiction margin quantiles",
     "5/50/95 % quantiles of the stiction margin over realisations x constant sets (p05, p50, p95, median)"),
    ("margin_quantiles_nominal", "N", "stiction margin quantiles at nominal constants",
     "5/50/95 % quantiles of the stiction margin over the realisations at nominal constants"),
    ("startup_margin_quantiles", "N", "start-up margin quantiles",
     "5/50/95 % quantiles of the start-up margin over realisations x constant sets"),
    ("cof_quantiles", "1", "mean COF quantiles", "5/50/95 % quantiles of the cycle's mean COF over the samples"),
    ("cof_split_quantiles", "1", "COF split quantiles",
     "5/50/95 % quantiles of the chemical, vdW, elastic and capillary parts of the mean COF"),
    ("sensitivity", _TEXT, "sensitivity",
     "per constant: Sobol' first-order and total indices of the margin (first, total) and of the mean COF "
     "(cof_first, cof_total) with their bootstrap intervals, clipped to [0, 1] (clipped: whether an estimate or an "
     "interval end was outside), and the critical value [unit of the constant] where the median margin crosses "
     "zero, or null with a note"),
    ("sobol_design", _TEXT, "Sobol' design",
     "the design of the Sobol' indices: base_samples N, rows N (D + 2), steps of its cycles, failed_rows"),
    ("decision_sensitivity", _TEXT, "sensitivity of the decision",
     "per factor: the Kolmogorov-Smirnov distance between its values in the samples that stick and in those that "
     "do not (index, in [0, 1]; regional sensitivity, Spear and Hornberger 1980) with its bootstrap interval "
     "(index_ci) and the distance noise reaches (noise_level), and the same for the start-up verdict; per constant "
     "also the median margin [N] and the stuck count with the constant alone at each end of its prior, the others "
     "nominal (margin_at_low, margin_at_high, stiction_at_low, stiction_at_high), and can_flip (MODEL 7h)"),
    ("decision_design", _TEXT, "samples of the decision's sensitivity",
     "the samples the regional index uses (the study's and the Sobol' rows at the same steps): samples, stuck, free, "
     "failed, blocks, sources, resamples, confidence"),
    ("flipping_constants", _TEXT, "constants that flip the verdict",
     "the constants that alone flip the running verdict inside their prior: the sign of the median margin at an end "
     "of the prior, the others nominal, differs from the nominal constants' (MODEL 7h)"),
    ("flipping_constants_startup", _TEXT, "constants that flip the start-up verdict",
     "as flipping_constants, for the start-up margin"),
    ("robust_bayes", _TEXT, "robust-Bayes band",
     "per decisive constant: P(stiction) with its interval under the prior and under the prior with each bound "
     "moved by a factor (2) either way (priors), the band [smallest, largest], band_ci, span, prior_dominated, the "
     "critical value and critical_measurable (in the units of the measurement that decides it: shear strength in "
     "MPa, adhesion hysteresis or work of adhesion in mJ/m^2, widths in nm)"),
    ("prior_dominated", _TEXT, "prior-dominated",
     "true where a robust-Bayes band of P(stiction) spans more than 0.3: the probability is mostly the prior"),
    ("prior_dominated_constants", _TEXT, "prior-dominating constants", "the constants whose band spans more than 0.3"),
    ("sensitivity_method", _TEXT, "what ranks the constants",
     "'regional': the regional index of the verdict on the study's own samples (no Sobol' design; the main job's "
     "since issue 40); absent: Sobol' indices of the margin (sensitivity)"),
    ("dominant_entry", _TEXT, "the dominant constant's critical value",
     "with sensitivity_method 'regional': what ranked the dominant constant first (ranked_by), its critical_value, "
     "stiction_above, searched (False: not searched, the note says where it is) and note"),
    ("margin_correlation", _TEXT, "rank correlation with the margin",
     "with sensitivity_method 'regional': Spearman's rank correlation rho of the stiction margin with each factor "
     "over the study's samples and its p_value [-]; it ranks the constants where every sample gives the same verdict"),
    ("decision_depth", _TEXT, "depth of the decision's sensitivity",
     "'full': regional index, each constant at the ends of its prior, critical values, robust-Bayes bands; "
     "'regional': the regional index on the study's samples only (no further cycle; the main job's default), "
     "the flips and bands then None: not checked"),
    ("decision_sentence", _TEXT, "what the verdict hangs on",
     "the constants that alone flip the verdict, with their critical values in measurable units, and whether "
     "P(stiction) is prior-dominated"),
    ("dominant_constant", _TEXT, "dominant constant", "the constant with the largest total Sobol' index of the margin"),
    ("designer_sentence", _TEXT, "what to do", "where the verdict flips and what to measure"),
    ("sampled_constants", _TEXT, "sampled constants", "the constants sampled from their priors"),
    ("fixed_constants", _TEXT, "fixed constants", "constants with a prior held at their value (--fix, --set)"),
    ("unconverged_samples", "1", "unconverged samples", "sampled cycles with unconverged contact steps (kept)"),
    ("failed_samples", "1", "failed samples", "sampled points the model refused (counted in the interval)"),
    ("priors", _TEXT, "priors", "the prior of each uncertain constant: distribution, bounds [SI], source, reason"),
    # --- the design search (memstribo design, issue #39) -------------------------------------------------------
    ("torque_window", "N*m", "safe drive-torque window", "fracture edge (capped at the range's top) minus stiction "
     "edge, 0 where they cross: the design's safe window (docs/design.md)"),
    ("torque_window_high", "N*m", "safe drive-torque window, optimistic end", "the window with its stiction edge at "
     "the torque below it on the search's torque grid (the edge lies between the two)"),
    ("stiction_torque", "N*m", "stiction edge", "lowest torque of the search's grid whose running and start-up "
     "P(stiction) are below p_s by the upper end of their 95 % interval (NaN: none)"),
    ("stiction_torque_bracket", "N*m", "stiction edge, torque below", "the grid torque below the stiction edge"),
    ("fracture_torque", "N*m", "fracture edge", "drive torque at which the probability that a tooth breaks within "
     "the required cycles reaches p_f (tooth_life, fracture_probability_within)"),
    ("footprint", "m2", "footprint", "area of the pair's bounding rectangle (r_a1 + a + r_a2) x 2 max(r_a1, r_a2)"),
    ("cycles_spent", "1", "meshing cycles spent", "meshing cycles of a design's verdicts (realisations x verdicts; "
     "convergence spot checks not counted)"),
    ("verdicts", "1", "ensemble verdicts", "ensemble verdicts (map points) a design's evaluation ran"),
    ("feasible", "1", "feasible", "1 where the design meets every geometric constraint, else 0 (no cycle ran)"),
    ("generation", "1", "generation", "the search generation that first proposed the design (0: the default design)"),
    ("design_id", _TEXT, "design id", "hash of the design's values: its file in OUT/evaluations/"),
]

QUANTITIES: dict[str, Quantity] = {name: Quantity(name, unit, long, text) for name, unit, long, text in _ENTRIES}


def _parameter(name: str) -> Quantity | None:
    from memstribo.parameters.definitions import SPECS

    spec = SPECS.get(name)
    if spec is None:
        return None
    unit_ = spec.unit if spec.unit else ("1" if spec.kind in ("float", "int") else _TEXT)
    return Quantity(name, unit_, name.replace("_", " "), f"input parameter: {spec.description}")


def quantity(name: str) -> Quantity:
    """The :class:`Quantity` of an output name: a registered quantity, a statistic of one (``cof_mean``,
    ``stiction_margin_p05``), or an input parameter (its unit and description from the parameter's spec).

    Raises
    ------
    KeyError
        When the name is none of these: register it in :data:`QUANTITIES`.
    """
    if name in QUANTITIES:
        return QUANTITIES[name]
    base, _, suffix = name.rpartition("_")
    if suffix in STATISTICS and base:
        try:
            q = quantity(base)  # a statistic of a quantity, or of a statistic (cof_mean_p05)
        except KeyError:
            q = None
        if q is not None and not q.description.startswith("input parameter"):
            reads, what = STATISTICS[suffix]
            return Quantity(name, q.unit, f"{q.long_name}, {reads}", f"{what} of: {q.description}")
    qualifier, _, rest = name.partition("_")
    if qualifier in QUALIFIERS and rest:
        try:
            q = quantity(rest)
        except KeyError:
            q = None
        if q is not None:
            return Quantity(name, q.unit, f"{q.long_name} ({QUALIFIERS[qualifier]})",
                            f"of the {QUALIFIERS[qualifier]}: {q.description}")
    parameter = _parameter(name)
    if parameter is not None:
        return parameter
    raise KeyError(f"{name!r} is not in memstribo's vocabulary of results (memstribo.quantities.QUANTITIES)")


def known(name: str) -> bool:
    """Whether ``name`` is a registered quantity, a statistic of one, or an input parameter."""
    try:
        quantity(name)
    except KeyError:
        return False
    return True


def unit(name: str) -> str:
    """UDUNITS unit of an output name ('1' dimensionless, '' text)."""
    return quantity(name).unit


def attrs(name: str, long_name: str | None = None) -> dict[str, str]:
    """CF attributes ``units`` and ``long_name`` of an output variable (``long_name`` overrides the registry's)."""
    q = quantity(name)
    return {"units": q.unit, "long_name": long_name or q.long_name}


def attrs_or(name: str, unit: str = "") -> dict[str, str]:
    """CF attributes of an output name: the vocabulary's where it knows the name, else ``unit`` and the name in
    words (the results of a user's own study function, which the vocabulary cannot know)."""
    if known(name):
        return attrs(name)
    return {"units": unit, "long_name": name.replace("_", " ")}


def markdown_table() -> str:
    """docs/quantities.md: every registered quantity with its unit, long name and description."""
    lines = ["# Output quantities", "",
             "Every name that memstribo writes (JSON of every command, NetCDF variables and attributes, CSV headers, "
             "the report) comes from this table (`memstribo.quantities.QUANTITIES`), or is an input parameter "
             "(`memstribo parameters`). Statistics add a suffix to the name: "
             + ", ".join(f"`_{s}` ({reads})" for s, (reads, _) in STATISTICS.items())
             + ". Units are UDUNITS strings: `1` is dimensionless, an empty unit is text or a flag.", "",
             "Generated by `python -m memstribo.quantities > docs/quantities.md` (a test keeps it current).", "",
             "| name | unit | long name | description |", "|---|---|---|---|"]
    for q in QUANTITIES.values():
        cells = [f"`{q.name}`", q.unit or "(text)", q.long_name, q.description]
        lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(markdown_table(), end="")
