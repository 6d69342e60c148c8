"""The meshing-cycle simulation: rough teeth through the whole path of contact (thesis 4.6, 4.9).

memstribo's version of the thesis's "true gap" algorithm (Figure 4-18, MODEL.md §7), with a
real elastic contact solver in place of the thesis's unpublished one. For every position ``c``
of the contact point on the line of action (every time step) from the first to the last point
of contact:

1. **Roughness at the contact.** Each flank carries its own roughness profile attached to its
   involute roll coordinate ``s_i`` (the arc length from the base circle, ``s = R^2 / (2 r_b)``
   with the radius of curvature ``R`` of (4-20), (4-21)). In a frame moving with the contact
   point (x along the common tangent, 0 at the contact point), the material of flank ``i``
   passes at its own surface speed ``u_i`` (4-12): the pinion's point at roll coordinate
   ``sigma_1`` sits at ``x = s_1(c) - sigma_1``, the gear's at ``x = sigma_2 - s_2(c)``.
   The undeformed gap is ``h(x) = x^2 / (2 R_ef(c)) - z_1(s_1 - x) - z_2(s_2 + x)`` (4-8 to 4-11).
2. **Rough contact.** :func:`memstribo.physics.contact.solve_line_contact` (free-boundary half-plane
   BEM) under the load per unit width of the step, ``w = share(c) F_ext / L_eff`` with the
   dry or lubricated load-sharing function (4.3.1): the single-tooth zone carries the full
   load. The window (``mesh_window``) is checked at every step: the contact must not reach
   its ends. The Hertz contact is only ~90 nm wide (less than one nanoblock, 195.5 nm), so
   the grid is fine (``mesh_grid_spacing`` = 2 nm: ~40 elements across it).
3. **Nanoblocks.** Nanoblocks tile each flank on a square lattice of period ``w_adh`` along the
   flank and across the face width (``floor(L / w_adh)`` rows; the face width covered by whole
   rows, ``L_eff``, carries the load). Each nanoblock carries ``m x m`` atomic blocks at the pitch
   ``atomic_pitch``. A nanoblock's load is the contact pressure integrated over its footprint
   (``w_adh`` times the integral along x); the **fixed-load nanoblock model** (3.4.2,
   :func:`memstribo.physics.nanoblock.mechanics.structure_fixed_load`) then shares it among its atomic
   blocks, whose interference with the counter surface is minus the local deformed gap of the
   contact solution at their centres ("each block sits at the local height of its flank").
   This is the *decoupled* block-load variant (the contact solve does not see the block
   springs); the dataset says so in its ``block_load_variant`` attribute.
4. **Bonds and energies.** Chemical bonds form over the overlap, along x, of opposing atomic
   blocks that both touch (3-10): ``N_chem = m w_at L_chem / D_chem^2`` per overlapping pair
   (``m`` rows of atomic blocks across each nanoblock, aligned across the face width). As the
   two lattices slide past each other the overlaps, bond counts and block loads fluctuate (the
   peaks of Figure 5-18). Each pinion nanoblock holds van der Waals bonds over the length
   ``L_vdW`` of its footprint where the gap is inside the adhesive layer (thickness
   ``adhesive_layer_thickness``; unset: the adhesive-block height ``H_adh``, thesis 3.5, the
   same rule as the flat sliding models, :func:`memstribo.physics.nanoblock.geometry.adhesive_layer_thickness`;
   the Maugis range ``h0 = w / sigma0`` of MODEL §2 is an explicit alternative):
   ``N_vdW = w_adh L_vdW / D_chem^2`` (3-12), and adds its pull-off force
   ``sqrt(8 pi w12 E* C_NS a^3)``, ``a = L_vdW / 2`` (3-31, 3-32). All bonds break and re-form
   every bond length of sliding (3.5): the friction force of the bonds is
   ``(N_chem U_chem + N_vdW U_vdW) / D_chem``; the energy dissipated in a step is that force
   times the step's sliding distance ``|u1 - u2| dt``. Elastic interlocking (3-25):
   ``1/2 k de^2`` for the change of every atomic and adhesive block's compression between
   steps, times the sliding part of the relative motion ``|u1 - u2| / (u1 + u2)`` (pure rolling
   is reversible). Zero sliding at the pitch point gives zero dissipation in that step.
5. **Friction, adhesion, COF, stiction.** ``F_f`` (and its split), ``F_adh``, the apparent COF
   ``mu = F_f / (F_N + F_adh)`` (3-7) split into chemical, vdW and elastic parts (3-8, 3-9), and
   the stiction margin ``F_t - F_f`` with the pair's share of ``F_t = T / r_1`` (4-27). For
   dissimilar materials (Dundurs beta != 0) the friction traction ``mu p`` changes the normal
   gap by ``(2 beta / E*) mu sign(u1 - u2) int p dx``: the cycle is repeated with it until
   ``F_f`` changes by less than 1e-3 (thesis 4.6 step 7); for identical materials one pass
   is exact.

Coatings (thesis 5.5.3): the pinion's coating is fully worn; a fraction ``wear`` (Omega) of the
gear's nanoblocks is bare, chosen deterministically by a low-discrepancy sequence over the
block lattice. A coated gear block forms no chemical bonds; vdW bonds over it use the
coating's bond energy and work of adhesion, inside the same adhesive layer as a bare block
(the layer is a geometric band of the nanoblock model, not a property of the chemistry).
``wear=1`` is bare silicon.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from memstribo.errors import InputError
from memstribo.materials.pair import contact_modulus_of, dundurs_beta, no_slip_coefficient, work_of_adhesion
from memstribo.physics.gear import GearPair, hertz_line_contact, tangential_force
from memstribo.quantities import attrs as quantity_attrs
from memstribo.quantities import unit as quantity_unit
from memstribo.references import cites

__all__ = ["MeshSetup", "simulate_mesh", "summarize", "sweep", "critical_humidity", "SUMMARY_UNITS",
           "BLOCK_LOAD_VARIANT", "roll_coordinate", "normal_force_of_load_case", "vdw_gap_factor",
           "lattice_overlap_across", "sliding_average", "resisting_force", "step_convergence",
           "simulate_ensemble", "ensemble_summary"]

BLOCK_LOAD_VARIANT = ("decoupled: rough contact solved without the block springs, block loads = pressure over "
                      "each nanoblock's footprint, shared among its atomic blocks by the fixed-load model (3.4.2)")

#: The keys of the summary (``memstribo mesh --json``) and of the ensemble verdict, with their units from the
#: vocabulary (:mod:`memstribo.quantities`).
SUMMARY_KEYS = ("cof_mean", "cof_max", "cof_chemical", "cof_vdw", "cof_elastic", "friction_force_mean",
                "friction_force_max", "adhesion_force_mean", "normal_force_max", "tangential_force", "stiction",
                "stiction_margin", "steps", "sliding_distance", "energy_dissipated", "energy_chemical",
                "energy_vdw", "energy_elastic", "unconverged_steps", "window_exceeded_steps",
                "max_contact_pressure", "steps_above_elastic_limit", "resisting_force_max", "normal_force_total",
                "mesh_efficiency", "mesh_efficiency_min", "max_shear_stress", "load_case", "interface_model",
                "contact_adhesion", "mesh_contact", "environment", "relative_humidity", "cof_capillary",
                "energy_capillary", "roughness_rows", "warnings", "step_converged", "step_change_margin",
                "step_change_cof", "steps_checked", "realisations", "stiction_probability",
                "stiction_margin_median", "stiction_margin_p05", "stiction_margin_p95", "cof_mean_median",
                "cof_mean_p05", "cof_mean_p95", "mesh_efficiency_median", "mesh_efficiency_p05",
                "mesh_efficiency_p95", "per_realisation")
SUMMARY_UNITS = {key: quantity_unit(key) for key in SUMMARY_KEYS}

#: Largest Hertz half-width over radius of relative curvature a / R_ef that a meshing cycle accepts: beyond it the
#: contact is as wide as the teeth's curvature and the half-space model (a << R) says nothing (#15 item 4).
HERTZ_RATIO_LIMIT = 0.5

_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0
_SILVER = math.sqrt(2.0) - 1.0


# --------------------------------------------------------------------------------------------
# small published relations used here
# --------------------------------------------------------------------------------------------
def roll_coordinate(radius_of_curvature, base_radius):
    """Arc length of an involute from the base circle to the point of radius of curvature R.

    Parameters
    ----------
    radius_of_curvature : array_like
        R [m] (the distance to the base-circle tangency point, 4-20/4-21).
    base_radius : float
        r_b [m].

    Returns
    -------
    ndarray
        s = R^2 / (2 r_b) [m]; ds/dt = R omega is the surface speed u (4-12).
    """
    return np.asarray(radius_of_curvature, dtype=float) ** 2 / (2.0 * base_radius)


def _work_of_adhesion(params):
    """w12 of the parameter set, or A / (12 pi D0^2) (3-34) when unset [J/m^2]."""
    w = params["work_of_adhesion"]
    return float(work_of_adhesion(params["hamaker_constant"], params["cutoff_distance"]) if w is None else w)


# --------------------------------------------------------------------------------------------
# set-up: geometry, roughness on both flanks, lattices
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MeshSetup:
    """Everything a meshing simulation needs besides the physics constants.

    Attributes
    ----------
    pair : GearPair
    positions : ndarray
        c of each step [m] (includes the pitch point c = 0).
    step_time : ndarray
        Time weight of each step (trapezoidal) [s].
    load : ndarray
        Normal load on the pair at each step, share(c) F_ext [N].
    rows : int
        Nanoblock rows across the face width [-].
    effective_face_width : float
        rows * w_adh [m].
    grid : ndarray
        x of the contact elements relative to the contact point [m].
    pinion_profiles, gear_profiles : list of (x, z)
        Levelled roughness of each row of each flank, x = roll coordinate [m].
    roughness_name : str
    roughness_synthetic : bool
    roughness_source : str
    grid_spacing : float
        Element width of the contact solves [m].
    row_roughness : memstribo.surfaces.roughness.RowRoughness
        How the rows' lines were made (measured, synthesised), and the lattice offsets.
    realisation : int
        Index of the roughness realisation.
    hertz_width_ratio : float
        Largest Hertz half-width over the radius of relative curvature a / R_ef of the cycle [-]
        (the half-space model needs a << R; refused above :data:`HERTZ_RATIO_LIMIT`, warned above 0.2).
    """

    pair: GearPair
    positions: np.ndarray
    step_time: np.ndarray
    load: np.ndarray
    rows: int
    effective_face_width: float
    grid: np.ndarray
    pinion_profiles: list
    gear_profiles: list
    roughness_name: str
    roughness_synthetic: bool
    roughness_source: str
    grid_spacing: float
    row_roughness: object
    realisation: int
    hertz_width_ratio: float = 0.0


def _positions(pair: GearPair, steps: int) -> np.ndarray:
    """``steps`` positions from c_f to c_l, nearly uniform, with the pitch point c = 0 among them."""
    c_f, c_l = pair.first_contact, pair.last_contact
    n_before = int(round((steps - 1) * (-c_f) / (c_l - c_f)))
    n_before = min(max(n_before, 1), steps - 2)
    before = np.linspace(c_f, 0.0, n_before + 1)
    after = np.linspace(0.0, c_l, steps - n_before)
    return np.concatenate([before, after[1:]])


def _flank_ranges(pair, positions, window):
    r1, r2 = pair.radii_of_curvature(positions)
    s1 = roll_coordinate(r1, pair.base_radii[0])
    s2 = roll_coordinate(r2, pair.base_radii[1])
    half = 0.5 * window
    return s1, s2, (s1.min() - half, s1.max() + half), (s2.min() - half, s2.max() + half)


def orient_map(surface, sliding_axis: str = "x"):
    """A map turned so that its rows run along the sliding direction (the flank's roll coordinate).

    ``sliding_axis="x"``: the scan lines (rows along x) run along the flank, as scanned;
    ``"y"``: the map is transposed, its columns become the lines. Profiles pass unchanged.
    """
    if sliding_axis not in ("x", "y"):
        raise InputError(f"sliding axis must be 'x' or 'y', got {sliding_axis!r}.")
    if sliding_axis == "x" or not hasattr(surface, "line_scans"):
        return surface
    from dataclasses import replace

    return replace(surface, heights=np.ascontiguousarray(np.asarray(surface.heights).T), dx=surface.dy,
                   dy=surface.dx, source=f"{surface.source}; transposed: sliding along y")


def _read_roughness(roughness, sliding_axis="x"):
    """A Profile, a map (rows along the sliding direction), or None (the synthetic default)."""
    from memstribo.surfaces import roughness as rough

    if roughness is None or (isinstance(roughness, str) and roughness == "thesis"):
        return None
    if isinstance(roughness, (str, Path)):
        from memstribo.surfaces.readers import read_topography

        return orient_map(read_topography(roughness), sliding_axis)
    if isinstance(roughness, rough.Profile) or hasattr(roughness, "line_scans"):
        return orient_map(roughness, sliding_axis)
    raise InputError(f"roughness must be None, 'thesis', a file path, a Profile or a SurfaceMap; got "
                     f"{type(roughness).__name__}.")


def normal_force_of_load_case(params, pair: GearPair) -> float:
    """Total tooth normal force of the load case [N] (MODEL 7b).

    ``torque``: F_n = F_t / cos alpha_w with F_t = T / r_w1 (4-27), the force that the drive
    torque implies on the line of action; ``thesis``: ``normal_load`` as given (F_ext of 4.9).
    """
    if params["load_case"] == "thesis":
        return float(params["normal_load"])
    f_t = float(tangential_force(params["drive_torque"], pair.pitch_radii[0]))
    return f_t / math.cos(pair.pressure_angle)


def _prepare(params, roughness, steps, realisation=0, sliding_axis="x") -> MeshSetup:
    from memstribo.surfaces import roughness as rough

    pair = GearPair.from_parameters(params)
    steps = int(params["mesh_steps"] if steps is None else steps)
    if steps < 3:
        raise InputError(f"a meshing cycle needs at least 3 steps, got {steps}.")
    positions = _positions(pair, steps)
    t = pair.time(positions)
    step_time = np.concatenate([[0.5 * (t[1] - t[0])], 0.5 * (t[2:] - t[:-2]), [0.5 * (t[-1] - t[-2])]])
    share = pair.load_share(positions, params["load_sharing"])
    load = share * normal_force_of_load_case(params, pair)
    w_adh = params["adhesive_width"]
    rows = int(params["face_width"] // w_adh)
    if rows < 1:
        raise InputError(f"face_width ({params['face_width']:.4g} m) is narrower than one nanoblock "
                         f"(adhesive_width {w_adh:.4g} m).")
    # grid and window from the largest Hertz contact of the load case, unless given
    modulus = contact_modulus_of(params)
    hertz = hertz_line_contact(load, rows * w_adh, pair.effective_radius(positions), modulus)
    a_max = float(np.max(hertz.half_width))
    hertz_peak = hertz.peak_pressure
    if hertz_peak.max() > params["elastic_limit_pressure"]:
        i = int(np.argmax(hertz_peak))
        raise InputError(f"the tooth load ({load[i] * 1e6:.4g} uN, load case '{params['load_case']}') is beyond "
                         f"the elastic range: the Hertz peak pressure reaches {hertz_peak[i] / 1e9:.3g} GPa at c = "
                         f"{positions[i] * 1e6:.3g} um, above the elastic limit of silicon "
                         f"({params['elastic_limit_pressure'] / 1e9:.3g} GPa, elastic_limit_pressure); the elastic "
                         "model of the thesis no longer holds.")
    ratio = float(np.max(hertz.half_width / pair.effective_radius(positions)))
    if ratio > HERTZ_RATIO_LIMIT:  # a contact as wide as the teeth's curvature: no half-space, no Hertz, no answer
        raise InputError(
            f"the contact of the teeth would be {a_max * 1e6:.3g} um wide on each side, {ratio:.2g} times their radius "
            f"of relative curvature (E* = {modulus / 1e9:.3g} GPa under {float(np.max(load)) * 1e3:.3g} mN): the "
            f"elastic half-space contact model needs a half-width well below the radius (allowed: a/R_ef <= "
            f"{HERTZ_RATIO_LIMIT:g}). A counter body this soft, or this load, is outside the model; use a stiffer "
            "counter_youngs_modulus or a smaller load.")
    dx = params["mesh_grid_spacing"]
    if dx is None:
        dx = 2 * a_max / int(params["mesh_elements_across_contact"])
    window = params["mesh_window"]
    if window is None:
        window = 2.4 * a_max + 6 * w_adh
    if params["mesh_grid_spacing"] is None:
        dx = min(dx, window / 64)  # a sized grid always has the 64 elements the solver needs
    n = int(round(window / dx))
    if n < 64:
        raise InputError(f"mesh_window / mesh_grid_spacing = {n}: at least 64 contact elements are needed.")
    from memstribo.parameters import check_mesh_size

    check_mesh_size(steps, n * dx, dx, what="mesh_steps" if steps == params["mesh_steps"] else "steps")
    grid = (np.arange(n) - 0.5 * (n - 1)) * dx
    _, _, (lo1, hi1), (lo2, hi2) = _flank_ranges(pair, positions, n * dx + 2 * w_adh)
    needed = max(hi1 - lo1, hi2 - lo2)
    lines = rough.row_roughness(_read_roughness(roughness, sliding_axis), params, rows, needed, realisation)
    pinion, gear = [], []
    for scan_p, scan_g in zip(lines.pinion, lines.gear):
        for scan in (scan_p, scan_g):
            span = float(scan.x[-1] - scan.x[0])
            if span < needed:  # pragma: no cover - row_roughness synthesises long enough lines
                raise InputError(f"roughness line '{scan.name}' is {span * 1e6:.4g} um long, but the flank travel "
                                 f"needs {needed * 1e6:.4g} um.")
        # each line's middle sits at the middle of its flank's travel (independent of the window)
        zp = rough.level_profile(scan_p)
        pinion.append((zp.x - 0.5 * (zp.x[0] + zp.x[-1]) + 0.5 * (lo1 + hi1), zp.z))
        zg = rough.level_profile(scan_g)
        gear.append((zg.x - 0.5 * (zg.x[0] + zg.x[-1]) + 0.5 * (lo2 + hi2), zg.z))
    return MeshSetup(pair, positions, step_time, load, rows, rows * w_adh, grid, pinion, gear, lines.name,
                     lines.synthetic, lines.source, float(dx), lines, realisation, ratio)


def _heights(profile, coordinate):
    from scipy.interpolate import PchipInterpolator

    x, z = profile
    return PchipInterpolator(x, z, extrapolate=False)(coordinate)


# --------------------------------------------------------------------------------------------
# the cycle
# --------------------------------------------------------------------------------------------
def _cohesive_zone(params):
    """(sigma0 [Pa], h0 [m]) of the Maugis-Dugdale zone of the contact solve, or (None, None) without it."""
    if params["contact_adhesion"] != "maugis":
        return None, None
    from memstribo.physics.adhesion import nanoscale_constants

    constants = nanoscale_constants(params)
    return float(constants.maugis_stress), float(constants.maugis_range)


def _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, shear_term, pbar, capillary=None, warm_start=None):
    """Rough contact of every step of one row: pressure, deformed gap, solver info, cohesive line load.

    ``capillary``: (Laplace pressure [Pa], condensation height per step and element [m], shape
    (steps, n)) of the menisci in humid air, a second Dugdale-type traction inside the solve
    (:func:`memstribo.physics.contact.solve_line_contact`, docs/humidity.md); the sixth info column is
    then the menisci's line load [N/m]. ``warm_start``: a dict of each row's pressures (steps, n) of
    a previous cycle, the initial pressure of each step's solve where present (:func:`simulate_mesh`);
    this row's pressures are stored in it.
    """
    from memstribo.physics.contact import solve_line_contact

    grid = setup.grid
    dx = setup.grid_spacing
    z1 = _heights(setup.pinion_profiles[row], s1[:, None] - grid[None, :])
    z2 = _heights(setup.gear_profiles[row], s2[:, None] + grid[None, :])
    separation = grid[None, :] ** 2 / (2 * r_ef[:, None]) - z1 - z2
    if shear_term is not None:
        separation = separation + shear_term
    line_load = setup.load / setup.effective_face_width
    n_steps = separation.shape[0]
    pressure = np.zeros_like(separation)
    gap = np.zeros_like(separation)
    info = np.zeros((n_steps, 5 if capillary is None else 6))  # converged, residual, iterations, approach,
    sigma0, h0 = _cohesive_zone(params)                            # cohesive line load (, capillary line load)
    adhesive = {} if sigma0 is None else {"cohesive_stress": sigma0, "cohesive_range": h0}
    previous = None
    start = None
    stress = (sigma0 or 0.0) + (capillary[0] if capillary is not None else 0.0)  # the tensile traction's limit
    if warm_start is not None and row in warm_start:
        start, stress_before = warm_start[row]
        if start.shape != separation.shape:
            start = None
        else:  # tensile parts scaled to this traction (the Laplace pressure changes with humidity)
            start = np.where(start < 0.0, start * (stress / stress_before if stress_before > 0 else 0.0), start)
    for i in range(n_steps):
        if start is not None:
            previous = start[i]
        if capillary is not None:
            adhesive = {**adhesive, "capillary_stress": capillary[0], "capillary_range": capillary[1][i]}
        solution = solve_line_contact(separation[i], dx, modulus, load=line_load[i],
                                      tolerance=params["mesh_contact_tolerance"], initial_pressure=previous,
                                      **adhesive)
        pressure[i], gap[i] = solution.pressure, solution.gap
        info[i, :5] = (solution.converged, solution.residual, solution.iterations, solution.approach,
                       getattr(solution, "adhesive_load", 0.0))
        if capillary is not None:
            info[i, 5] = solution.capillary_load
        previous = solution.pressure
        if pbar is not None:
            pbar.update(1)
    if warm_start is not None:
        warm_start[row] = (pressure.copy(), stress)
    return pressure, gap, info


def _solve_contacts_surface(setup, params, modulus, r_ef, s1, s2, pbar):
    """The strip of the face width under the window as one surface (3D) contact per step (rows interact).

    Each nanoblock row is ``k = round(w_adh / dx)`` element rows wide across the face width and
    carries its own roughness line (the same line over its k element rows); the free-boundary
    half-space solve (:func:`memstribo.physics.surface_contact.solve_surface_contact`) carries the pair's
    whole load. Returns per-row pressure and gap (means over each row's element rows), shapes
    (rows, steps, n), and the solver info per step (converged, residual, iterations, approach).
    """
    from memstribo.physics.surface_contact import solve_surface_contact

    grid = setup.grid
    dx = setup.grid_spacing
    rows = len(setup.pinion_profiles)
    w_adh = setup.effective_face_width / setup.rows
    k = max(1, int(round(w_adh / dx)))
    dy = w_adh / k
    n_steps, n = s1.size, grid.size
    lines = np.empty((rows, n_steps, n))
    for row in range(rows):
        z1 = _heights(setup.pinion_profiles[row], s1[:, None] - grid[None, :])
        z2 = _heights(setup.gear_profiles[row], s2[:, None] + grid[None, :])
        lines[row] = grid[None, :] ** 2 / (2 * r_ef[:, None]) - z1 - z2
    pressure = np.zeros((rows, n_steps, n))
    gap = np.zeros((rows, n_steps, n))
    info = np.zeros((n_steps, 5))
    previous = None
    for i in range(n_steps):
        separation = np.repeat(lines[:, i, :], k, axis=0)  # (rows * k, n)
        solution = solve_surface_contact(separation, dx, dy, modulus, load=float(setup.load[i]), periodic=False,
                                         tolerance=params["mesh_contact_tolerance"], initial_pressure=previous)
        field_p = solution.pressure.reshape(rows, k, n)
        field_g = solution.gap.reshape(rows, k, n)
        pressure[:, i, :] = field_p.mean(axis=1)
        gap[:, i, :] = field_g.mean(axis=1)
        info[i] = (solution.converged, solution.residual, solution.iterations, solution.approach, 0.0)
        previous = solution.pressure if solution.converged and np.any(solution.pressure > 0) else None
        if pbar is not None:
            pbar.update(rows)
    return pressure, gap, info


def vdw_gap_factor(gap, cutoff_distance, vdw_cutoff):
    """Share of a block's contact vdW energy at local gap D: (D0 / max(D, D0))^2, 0 beyond the cut-off.

    The flat-flat Hamaker law: the interaction energy per area at separation D is
    A / (12 pi D^2) (Israelachvili 2011, Table 13.1), which at contact (D <= D0) is the work of
    adhesion w12 = A / (12 pi D0^2) (3-34); the ratio is the factor (MODEL 7c).

    Parameters
    ----------
    gap : array_like
        Local gap D between the surfaces [m] (0 in contact).
    cutoff_distance : float
        D0 [m].
    vdw_cutoff : float
        Gap beyond which vdW is neglected (a numerical cut-off) [m].

    Returns
    -------
    ndarray
        Factor in [0, 1] [-].
    """
    d = np.maximum(np.asarray(gap, dtype=float), cutoff_distance)
    return np.where(d < vdw_cutoff, (cutoff_distance / d) ** 2, 0.0)


def lattice_overlap_across(atomic_width, atomic_pitch, atomic_per_side, adhesive_width, offset):
    """Summed overlap width across the face width of two facing rows of atomic blocks [m].

    Each nanoblock carries ``m`` rows of atomic blocks (width ``w_at``, pitch ``atomic_pitch``)
    across the face width; the gear's lattice is shifted by ``offset`` relative to the
    pinion's, and repeats with the nanoblock width. The result is
    sum_i sum_j max(0, w_at - |y_i - y_j - offset|) over the pinion's rows i and the gear's rows
    j (with their periodic images): ``m w_at`` when the lattices are aligned, less when not.
    """
    m = int(atomic_per_side)
    y = (np.arange(m) - 0.5 * (m - 1)) * atomic_pitch
    images = np.array([-adhesive_width, 0.0, adhesive_width])
    gear = (y[:, None] + offset + images[None, :]).ravel()
    return float(np.clip(atomic_width - np.abs(y[:, None] - gear[None, :]), 0.0, None).sum())


def _lattice(roll, w_adh, grid_half):
    """Material indices k of the nanoblocks whose footprint meets the window, per step (steps, slots)."""
    # block k of a flank spans roll coordinates [k w_adh, (k+1) w_adh)
    lo = roll - grid_half - w_adh
    k0 = np.floor(lo / w_adh).astype(int)
    slots = int(math.ceil((2 * grid_half + 2 * w_adh) / w_adh)) + 1
    return k0[:, None] + np.arange(slots)[None, :]


def _run_cycle(setup, params, coating, wear, modulus, beta, mu_previous, progress, warm_start=None):
    from memstribo.physics.nanoblock.mechanics import BlockStiffness, structure_fixed_load
    from memstribo.physics.nanoblock.geometry import adhesive_layer_thickness

    pair = setup.pair
    c = setup.positions
    n_steps = c.size
    r1, r2 = pair.radii_of_curvature(c)
    r_ef = r1 * r2 / (r1 + r2)
    s1 = roll_coordinate(r1, pair.base_radii[0])
    s2 = roll_coordinate(r2, pair.base_radii[1])
    u1, u2 = pair.surface_velocities(c)
    slip = u1 - u2
    sliding = np.abs(slip) * setup.step_time
    sliding_fraction = np.abs(slip) / (u1 + u2)

    w_adh, w_at, m = params["adhesive_width"], params["atomic_width"], int(params["atomic_per_side"])
    pitch = params["atomic_pitch"]
    bond = params["bond_length"]
    dx = setup.grid_spacing
    grid = setup.grid
    half = 0.5 * grid.size * dx
    geometry = _geometry(params)
    stiffness = BlockStiffness.from_geometry(geometry, params["youngs_modulus"], modulus, params["threshold_strain"])
    offsets = (np.arange(m) - 0.5 * (m - 1)) * pitch

    # the published relations, looked up on their modules at call time: a change to a relation
    # changes the meshing cycle (tests/test_mesh.py::test_the_cycle_calls_the_published_relations)
    from memstribo.physics import adhesion, friction
    from memstribo.physics.nanoblock import mechanics

    w_si = _work_of_adhesion(params)
    # thesis interface: one rule with the sliding models (3.5), for bare and coated blocks alike
    layer = adhesive_layer_thickness(params, geometry)
    gap_model = params["interface_model"] == "gap"
    with_cohesive_zone = params["contact_adhesion"] == "maugis"
    if coating is not None:
        w_coat, u_vdw_coat = float(coating.work_of_adhesion), float(coating.vdw_bond_energy)
    c_ns = float(no_slip_coefficient(params["poisson_ratio"]))
    n_rows_solved = len(setup.pinion_profiles)  # every row, each with its own roughness (MODEL 7b)

    pbar = None
    if progress:
        from tqdm.auto import tqdm

        pbar = tqdm(total=n_steps * n_rows_solved, desc="meshing cycle", unit="step", leave=False)

    out = {key: np.zeros(n_steps) for key in ("chem_bonds", "vdw_bonds", "f_chem", "f_vdw", "e_el", "f_adh",
                                              "contact_width", "max_pressure", "unconverged", "residual",
                                              "iterations", "window_exceeded", "approach", "rigid_atomic_blocks",
                                              "vdw_edge", "f_cap", "f_cap_adh", "wetted")}
    humid = params["environment"] == "air"
    if humid:
        from memstribo.physics import capillary

        r_kelvin = capillary.kelvin_radius(params["relative_humidity"], params["temperature"])
        theta_bare = float(params["water_contact_angle"])
        theta_coat = theta_bare
        if coating is not None and math.isfinite(getattr(coating, "water_contact_angle_deg", math.nan)):
            theta_coat = math.radians(coating.water_contact_angle_deg)
        renewal = params["meniscus_renewal_distance"] or params["atomic_pitch"]
    block_loads = []
    surface = params["mesh_contact"] == "surface"
    if surface:
        if beta != 0.0 or params["contact_adhesion"] != "none":
            raise InputError("mesh_contact = 'surface' solves identical, non-adhesive teeth only (Dundurs beta 0 and "
                             "contact_adhesion = 'none': add --set contact_adhesion=none, since the default "
                             "Maugis-Dugdale zone is carried by the line solve only); use mesh_contact = 'line' for "
                             "the others.")
        strip_pressure, strip_gap, strip_info = _solve_contacts_surface(setup, params, modulus, r_ef, s1, s2, pbar)
    for row in range(n_rows_solved):
        zone = None
        if humid and not surface:  # the menisci's Laplace pressure inside the contact solve (docs/humidity.md)
            zone = _capillary_zone(r_kelvin, theta_bare, theta_coat, s2, grid, w_adh, row, coating, wear)
        if surface:
            pressure, gap = strip_pressure[row], strip_gap[row]
            info = strip_info  # one solve for all rows
        elif beta != 0.0 and mu_previous is not None:
            pressure, gap, info = _solve_with_shear(setup, params, modulus, r_ef, s1, s2, row, beta, mu_previous,
                                                    slip, pbar, zone, warm_start)
        else:
            pressure, gap, info = _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, None, pbar, zone,
                                                  warm_start)
        # window check: the contact must stay clear of the window's ends (5 % margin each side)
        edge = max(1, grid.size // 20)
        out["window_exceeded"] += (pressure[:, :edge].any(axis=1) | pressure[:, -edge:].any(axis=1))
        out["unconverged"] += info[:, 0] == 0
        out["residual"] = np.maximum(out["residual"], info[:, 1])
        out["iterations"] += info[:, 2] / n_rows_solved
        out["approach"] += info[:, 3] / n_rows_solved
        # vdW reach: with the gap model the attraction must have faded inside the window
        out["vdw_edge"] += (np.minimum(gap[:, 0], gap[:, -1]) < params["vdw_cutoff"]) if gap_model else 0
        # in contact: the gap closed under a non-zero pressure (with the Maugis-Dugdale zone the pressure is
        # tensile, down to -sigma0, near the contact's edges; the zone outside has an open gap)
        out["contact_width"] += ((gap <= 0.0) & (pressure != 0.0)).sum(axis=1) * dx / n_rows_solved
        out["max_pressure"] = np.maximum(out["max_pressure"], pressure.max(axis=1))
        cumulative = np.concatenate([np.zeros((n_steps, 1)), np.cumsum(pressure, axis=1) * dx], axis=1)
        edges_x = np.concatenate([grid - 0.5 * dx, [grid[-1] + 0.5 * dx]])

        def footprint_load(x_centre):
            """w_adh * integral of p over [x - w_adh/2, x + w_adh/2] for x (steps, slots)."""
            lo = np.clip(x_centre - 0.5 * w_adh, edges_x[0], edges_x[-1])
            hi = np.clip(x_centre + 0.5 * w_adh, edges_x[0], edges_x[-1])
            f_hi = np.stack([np.interp(hi[i], edges_x, cumulative[i]) for i in range(n_steps)])
            f_lo = np.stack([np.interp(lo[i], edges_x, cumulative[i]) for i in range(n_steps)])
            return w_adh * (f_hi - f_lo)

        def local_gap(x):
            """Deformed gap at x (steps, ...) [m]; far outside the window: effectively no contact."""
            flat = x.reshape(n_steps, -1)
            values = np.stack([np.interp(flat[i], grid, gap[i], left=1.0, right=1.0) for i in range(n_steps)])
            return values.reshape(x.shape)

        # lattices: pinion block k centred at sigma = (k + 1/2) w_adh -> x = s1 - sigma; gear: x = sigma - s2
        k1 = _lattice(s1, w_adh, half)
        k2 = _lattice(s2, w_adh, half)
        x1 = s1[:, None] - (k1 + 0.5) * w_adh
        x2 = (k2 + 0.5) * w_adh - s2[:, None]
        flank_states = []
        for x_blocks in (x1, x2):
            loads = footprint_load(x_blocks)
            x_atoms = x_blocks[..., None] - offsets  # pinion: sigma increases -> x decreases; symmetric offsets
            overlap_row = -local_gap(x_atoms)  # (steps, slots, m)
            overlap = np.repeat(overlap_row, m, axis=-1)  # m x m atomic blocks, rows across the width alike
            loaded = loads > 0
            atomic_force = np.zeros(overlap.shape)
            atomic_comp = np.zeros(overlap.shape)
            adhesive_comp = np.zeros(loads.shape)
            if loaded.any():
                state = structure_fixed_load(overlap[loaded][:, None, :], stiffness, loads[loaded])
                atomic_force[loaded] = state.atomic_force[:, 0, :]
                atomic_comp[loaded] = state.atomic_compression[:, 0, :]
                adhesive_comp[loaded] = state.adhesive_compression[:, 0]
                rigid = np.zeros(loads.shape)
                rigid[loaded] = np.asarray(state.rigid).reshape(int(loaded.sum()), -1).sum(axis=1)
                out["rigid_atomic_blocks"] += rigid.sum(axis=1)
            flank_states.append((x_blocks, x_atoms, loads, atomic_force, atomic_comp, adhesive_comp))
        block_loads.append((k1, flank_states[0][2], k2, flank_states[1][2]))

        # gear blocks bare (worn coating) or coated: deterministic low-discrepancy choice
        def gear_bare(k):
            if coating is None:
                return np.ones(k.shape, dtype=bool)
            return np.mod(k * _GOLDEN + row * _SILVER, 1.0) < wear

        bare2 = gear_bare(k2)
        # chemical bonds: overlaps of touching opposing atomic blocks along x (sliding) times their
        # overlap across the face width, where the gear's lattice sits at a random offset (not aligned)
        across = lattice_overlap_across(w_at, pitch, m, w_adh, setup.row_roughness.lattice_offsets[row])
        touch1 = flank_states[0][3][..., :m] > 0  # first row of the m x m array (rows alike)
        touch2 = (flank_states[1][3][..., :m] > 0) & bare2[..., None]
        xa1 = flank_states[0][1].reshape(n_steps, -1)
        xa2 = flank_states[1][1].reshape(n_steps, -1)
        t1 = touch1.reshape(n_steps, -1)
        t2 = touch2.reshape(n_steps, -1)
        overlap_len = np.clip(w_at - np.abs(xa1[:, :, None] - xa2[:, None, :]), 0.0, None)
        overlap_len = overlap_len * (t1[:, :, None] & t2[:, None, :])
        chem = friction.chemical_bond_count(across, overlap_len.sum(axis=(1, 2)), bond)  # (3-10)
        out["chem_bonds"] += chem
        # all bonds break once per bond length of sliding (3.5): the force is that energy per bond length (3-1)
        out["f_chem"] += friction.friction_force(friction.bond_breaking_energy(chem, params["bond_energy"], bond, bond),
                                                 bond)

        # vdW bonds: pinion block footprint inside the adhesive layer (3-12), pull-off (3-32)
        k1_at_x = np.floor((s1[:, None] - grid[None, :]) / w_adh).astype(int)  # pinion block at each element
        k2_at_x = np.floor((s2[:, None] + grid[None, :]) / w_adh).astype(int)
        bare_x = gear_bare(k2_at_x)
        # vdW: the share of a block's contact energy at the local gap (MODEL 7c), or the thesis's band
        inside = vdw_gap_factor(gap, params["cutoff_distance"], params["vdw_cutoff"]) if gap_model \
            else (gap <= layer).astype(float)
        u_vdw_x = np.where(bare_x, params["vdw_bond_energy"], u_vdw_coat) if coating is not None \
            else params["vdw_bond_energy"]
        w_x = np.where(bare_x, w_si, w_coat) if coating is not None else w_si
        n_vdw = friction.vdw_bond_count(w_adh, dx, bond) * inside  # (3-12), bonds per element
        out["vdw_bonds"] += n_vdw.sum(axis=1)
        out["f_vdw"] += friction.friction_force(
            friction.bond_breaking_energy(n_vdw, u_vdw_x, bond, bond).sum(axis=1), bond)
        if humid:  # capillary menisci where the gap is below the condensation height (docs/humidity.md)
            theta_gear = np.where(bare_x, theta_bare, theta_coat) if coating is not None else theta_bare
            height = capillary.condensation_height(r_kelvin, theta_bare, theta_gear)
            wet = (gap <= height) & (height > 0)
            area = wet * (w_adh * dx)
            out["wetted"] += area.sum(axis=1)
            # attraction: the contact solve's meniscus line load over the row (line contact), else the wetted area's
            out["f_cap_adh"] += (info[:, 5] * w_adh if zone is not None
                                 else capillary.laplace_pressure(r_kelvin) * area.sum(axis=1))
            # the meniscus's rupture energy gamma (cos theta_1 + cos theta_2) per wetted area, once per renewal
            rupture = capillary.WATER["surface_tension"] * (np.cos(theta_bare) + np.cos(theta_gear))
            out["f_cap"] += (area * rupture).sum(axis=1) / renewal
        # elastic interlocking (3-25) on material blocks, both flanks, times the sliding fraction
        e_el = np.zeros(n_steps)
        for (k, (_, _, _, _, comp_at, comp_adh)) in zip((k1, k2), flank_states):
            e_el += _interlocking(k, comp_at, comp_adh, stiffness, mechanics.elastic_interlocking_energy)
        out["e_el"] += e_el * sliding_fraction
        if with_cohesive_zone:  # the attraction is the contact solve's cohesive line load over the row
            out["f_adh"] += info[:, 4] * w_adh
            continue
        # pull-off per pinion block: a = half its engaged length, w12 averaged over it
        key = k1_at_x - k1_at_x.min(axis=1, keepdims=True)
        n_keys = int(key.max()) + 1
        flat = (np.arange(n_steps)[:, None] * n_keys + key).ravel()
        length = np.bincount(flat, weights=(inside * dx).ravel(), minlength=n_steps * n_keys)
        work = np.bincount(flat, weights=(inside * dx * w_x).ravel(), minlength=n_steps * n_keys)
        length = length.reshape(n_steps, n_keys)
        work = np.divide(work.reshape(n_steps, n_keys), length, out=np.zeros_like(length), where=length > 0)
        a = 0.5 * np.minimum(length, w_adh)
        engaged = a > 0
        pull_off = np.zeros_like(a)
        if engaged.any():
            pull_off[engaged] = adhesion.pull_off_force(work[engaged], modulus, c_ns, a[engaged])  # (3-32)
        out["f_adh"] += friction.adhesion_force(pull_off, axis=1)  # (3-31)

    if pbar is not None:
        pbar.close()
    return out, block_loads, dict(r_ef=r_ef, s1=s1, s2=s2, u1=u1, u2=u2, slip=slip, sliding=sliding,
                                  sliding_fraction=sliding_fraction)


def _capillary_zone(r_kelvin, theta_bare, theta_coat, s2, grid, w_adh, row, coating, wear):
    """(Laplace pressure gamma / r_K [Pa], h_c [m] per step, or per step and element) of a row's menisci, or None.

    The traction of the menisci inside the line-contact solve (issue #17, docs/humidity.md;
    :mod:`memstribo.physics.capillary`): h_c = r_K (cos theta_1 + cos theta_2) with the pinion bare and
    each gear block bare or coated (the same low-discrepancy choice as the cycle's). None when
    no meniscus forms (dry air, a hydrophobic pair).
    """
    from memstribo.physics import capillary

    stress = float(capillary.laplace_pressure(r_kelvin))
    if coating is None:  # one height per step (a number: the plain Maugis-Dugdale iteration of the solver)
        height = float(capillary.condensation_height(r_kelvin, theta_bare))
        return (stress, np.full(s2.size, height)) if stress > 0.0 and height > 0.0 else None
    k2_at_x = np.floor((s2[:, None] + grid[None, :]) / w_adh).astype(int)
    bare = np.mod(k2_at_x * _GOLDEN + row * _SILVER, 1.0) < wear
    heights = capillary.condensation_height(r_kelvin, theta_bare, np.where(bare, theta_bare, theta_coat))
    if stress == 0.0 or not np.any(heights > 0):
        return None
    return stress, heights


def _interlocking(k, comp_at, comp_adh, stiffness, interlocking_energy):
    """Sum over material blocks of 1/2 k de^2 (3-25, ``interlocking_energy``) between consecutive steps."""
    n_steps = k.shape[0]
    k_min = int(k.min())
    width = int(k.max()) - k_min + 1
    steps = np.repeat(np.arange(n_steps), k.shape[1])
    at = np.zeros((n_steps, width, comp_at.shape[-1]))
    adh = np.zeros((n_steps, width))
    at[steps, (k - k_min).ravel()] = comp_at.reshape(-1, comp_at.shape[-1])
    adh[steps, (k - k_min).ravel()] = comp_adh.ravel()
    d_at = np.diff(at, axis=0, prepend=at[:1])
    d_adh = np.diff(adh, axis=0, prepend=adh[:1])
    return (interlocking_energy(stiffness.atomic, d_at).sum(axis=(1, 2))
            + interlocking_energy(stiffness.adhesive, d_adh).sum(axis=1))


def _solve_with_shear(setup, params, modulus, r_ef, s1, s2, row, beta, mu, slip, pbar, capillary=None,
                      warm_start=None):
    """Contacts with the normal gap change of the friction traction mu p (dissimilar materials).

    ``warm_start`` (a dict kept over the friction passes): the first pass's frictionless pressure of
    the row (it does not depend on mu), and each step's solve starts from the previous pass's
    state: with adhesion a step can have two states, and a cold start would flip between them
    from pass to pass, so the fixed point would never settle.
    """
    # first the frictionless solution gives p; the traction term uses it (one fixed-point sweep per pass)
    if warm_start is not None and row in warm_start and ("frictionless", row) not in warm_start:
        warm_start[("frictionless", row)] = warm_start[row][0]  # the first pass was the frictionless one
    if warm_start is not None and ("frictionless", row) in warm_start:
        pressure = warm_start[("frictionless", row)]
    else:
        pressure, _, _ = _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, None, None, capillary)
    dx = setup.grid_spacing
    integral = np.cumsum(pressure, axis=1) * dx
    integral -= integral.mean(axis=1, keepdims=True)
    shear = (2 * beta / modulus) * (mu * np.sign(slip))[:, None] * integral
    return _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, shear, pbar, capillary, warm_start)


def _geometry(params):
    from memstribo.physics.nanoblock.geometry import NanoblockGeometry

    return NanoblockGeometry.from_parameters(params)


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


def resisting_force(positions, friction_force, first_contact, last_contact, base_pitch):
    """R(c): the friction forces of every tooth pair in mesh when one pair is at c [N] (MODEL 7b).

    The other pairs sit whole base pitches away on the path of contact, at ``c + k p_b`` for
    every integer k with ``c_f <= c + k p_b <= c_l``; each resists the drive with its friction
    force at its own position (taken from the same cycle, interpolated in c).
    """
    c = np.asarray(positions, dtype=float)
    total = np.zeros_like(c)
    k_max = int(math.ceil((last_contact - first_contact) / base_pitch)) + 1
    for k in range(-k_max, k_max + 1):
        other = c + k * base_pitch
        on_path = (other >= first_contact - 1e-15) & (other <= last_contact + 1e-15)
        total += np.where(on_path, np.interp(other, c, friction_force), 0.0)
    return total


@cites("thesis", "model", "johnson_1985", "polonsky_keer_1999", "hu_1986")
def simulate_mesh(params, roughness=None, *, steps=None, coating=None, wear=1.0, progress=False, realisation=0,
                  sliding_axis="x", warm_start=None):
    """Friction, adhesion, COF and the stiction margin of rough teeth over one meshing cycle (thesis 4.6, 4.9).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set (gear, load case, material, nanoblock, interface and ``mesh_*`` parameters).
    roughness : None, "thesis", str or Path, Profile or SurfaceMap
        Roughness of the teeth: ``None``/"thesis" is the seeded synthetic default (labelled
        synthetic); a path is read with :func:`memstribo.surfaces.readers.read_topography`. Every row of
        nanoblocks on each flank gets its own line (:func:`memstribo.surfaces.roughness.row_roughness`):
        map rows one nanoblock apart, or independent lines with the statistics of a profile.
    steps : int, optional
        Number of positions c from c_f to c_l (default ``mesh_steps``).
    coating : memstribo.physics.coating.Coating, optional
        SAM coating of the teeth; ``None`` is bare silicon.
    wear : float
        Worn fraction Omega of the gear's coating, 0..1 (the pinion's is fully worn); only with
        a coating. ``wear=1`` equals the bare result.
    progress : bool
        Show a tqdm progress bar on stderr.
    realisation : int
        Index of the roughness realisation (seeds of the synthesised lines).
    sliding_axis : {"x", "y"}
        Which axis of a 2D map runs along the flank (the sliding direction): ``"x"`` (the scan
        lines, default) or ``"y"`` (the map's columns).
    warm_start : dict, optional
        Contact pressures of a previous cycle of the same case (same steps, roughness and
        geometry) to start each contact solve from, filled in by the call: a humidity sweep
        passes one dict through its points (:func:`sweep`), so each point starts from the
        previous humidity's contacts (the result agrees with a cold start to the contact
        tolerance). Used with the line contact of identical teeth only (Dundurs beta 0).

    Returns
    -------
    xarray.Dataset
        Over ``step`` with coordinate ``c`` [m]: ``friction_force`` (averaged over the sliding
        distance ``friction_averaging_distance``), ``friction_force_instantaneous``,
        ``resisting_force`` R(c) (all pairs in mesh), ``stiction_margin`` F_t - R(c),
        ``mesh_efficiency``, ``adhesion_force``, ``normal_force``, ``cof`` and its split,
        energies by mechanism, ``block_load`` (``step``, ``block``) and more; each variable with
        ``units`` and ``long_name``. Attributes record the load case, interface model, contact
        adhesion, roughness rows, the F_t/F_f iteration and ``warnings`` (JSON list of text).

    Raises
    ------
    InputError
        A pair that cannot mesh, a load beyond the elastic range (Hertz peak pressure above
        ``elastic_limit_pressure``), a wear fraction outside [0, 1], a problem too large for memory.
    """
    import json

    import xarray as xr

    if not 0.0 <= float(wear) <= 1.0:
        raise InputError(f"wear (the worn fraction Omega of the gear's coating) must be within 0..1, got {wear!r}.")
    modulus = contact_modulus_of(params)
    beta = dundurs_beta(params["youngs_modulus"], params["poisson_ratio"], params["counter_youngs_modulus"],
                        params["counter_poisson_ratio"])
    setup = _prepare(params, roughness, steps, realisation, sliding_axis)
    pair = setup.pair
    # smooth-teeth Hertz contact under the line load actually solved (load / L_eff), Eqs. (4-22)-(4-26)
    hertz = hertz_line_contact(setup.load, setup.effective_face_width, pair.effective_radius(setup.positions),
                               modulus)
    f_t = float(tangential_force(params["drive_torque"], pair.pitch_radii[0]))
    share = pair.load_share(setup.positions, params["load_sharing"])

    # friction fixed point for dissimilar materials (thesis 4.6 step 7), under-relaxed so it cannot
    # oscillate; identical materials (beta = 0) uncouple and one pass is exact
    mu = None
    passes = 0
    friction_old = None
    fixed_point_converged = True
    max_passes = 30
    passes_start = {}  # dissimilar materials: each pass starts from the previous one (_solve_with_shear)
    while True:
        passes += 1
        out, block_loads, kin = _run_cycle(setup, params, coating, wear, modulus, beta, mu, progress,
                                           warm_start if beta == 0.0 else passes_start)
        sliding = kin["sliding"]
        f_el = np.divide(out["e_el"], sliding, out=np.zeros_like(sliding), where=sliding > 0)
        friction = out["f_chem"] + out["f_vdw"] + f_el + out["f_cap"]
        mu_new = friction / (setup.load + out["f_adh"] + out["f_cap_adh"])
        if beta == 0.0:
            break
        if friction_old is not None and np.max(np.abs(friction - friction_old)) <= 1e-3 * max(friction.max(), 1e-300):
            break
        if passes >= max_passes:
            fixed_point_converged = False
            break
        mu = mu_new if mu is None else 0.5 * (mu + mu_new)
        friction_old = friction

    out["f_adh"] = out["f_adh"] + out["f_cap_adh"]  # menisci pull the flanks together too (issue #17)
    denominator = setup.load + out["f_adh"]
    e_chem, e_vdw = out["f_chem"] * sliding, out["f_vdw"] * sliding
    e_el = f_el * sliding
    e_cap = out["f_cap"] * sliding
    energy = e_chem + e_vdw + e_el + e_cap
    averaging = params["friction_averaging_distance"] or params["atomic_pitch"]
    # every part averaged alike (the average is linear), so the parts add up to the friction force
    f_chem_avg, f_vdw_avg, f_el_avg, f_cap_avg = (sliding_average(f, sliding, averaging) for f in (
        out["f_chem"], out["f_vdw"], f_el, out["f_cap"]))
    friction_avg = f_chem_avg + f_vdw_avg + f_el_avg + f_cap_avg
    resisting = resisting_force(setup.positions, friction_avg, pair.first_contact, pair.last_contact, pair.base_pitch)
    margin = f_t - resisting
    # mesh efficiency: friction power of all pairs in mesh over the input power T omega1 (MODEL 7b)
    power_pair = np.divide(energy, setup.step_time, out=np.zeros_like(energy), where=setup.step_time > 0)
    power_loss = resisting_force(setup.positions, power_pair, pair.first_contact, pair.last_contact, pair.base_pitch)
    input_power = float(params["drive_torque"]) * float(pair.pinion_speed)
    efficiency = 1.0 - power_loss / input_power
    period = pair.base_pitch / pair.contact_point_speed
    efficiency_mean = 1.0 - float(energy.sum()) / (input_power * period)
    step = np.arange(setup.positions.size)

    def var(name, values, dims=("step",)):
        return xr.Variable(dims, np.asarray(values), attrs=quantity_attrs(name))

    # per-block loads: pinion then gear material blocks, rows
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
    block_flank = np.repeat(np.array(["pinion", "gear"]), n_rows_solved * max(widths))
    block_row = np.tile(np.repeat(np.arange(n_rows_solved), max(widths)), 2)
    block_index = np.concatenate([np.tile(np.arange(max(widths)) + k_min[0], n_rows_solved),
                                  np.tile(np.arange(max(widths)) + k_min[1], n_rows_solved)])

    # mean friction stress over the real contact area, against the ideal shear strength
    contact_area = out["contact_width"] * setup.effective_face_width
    shear_stress = np.divide(friction_avg, contact_area, out=np.zeros_like(friction_avg), where=contact_area > 0)
    warnings = _warnings(params, out, setup, shear_stress, efficiency, fixed_point_converged, passes, beta)

    data = {
        "time": pair.time(setup.positions),
        "load_share": share,
        "normal_force": setup.load,
        "effective_radius": kin["r_ef"],
        "hertz_half_width": hertz.half_width,
        "hertz_peak_pressure": hertz.peak_pressure,
        "sliding_velocity": kin["slip"],
        "sliding_distance": sliding,
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
        "friction_force_elastic": f_el,
        "friction_force_instantaneous": friction,
        "friction_force": friction_avg,
        "resisting_force": resisting,
        "adhesion_force": out["f_adh"],
        "cof": friction_avg / denominator,
        "cof_chemical": f_chem_avg / denominator,
        "cof_vdw": f_vdw_avg / denominator,
        "cof_elastic": f_el_avg / denominator,
        "cof_capillary": f_cap_avg / denominator,
        "friction_force_capillary": out["f_cap"],
        "capillary_force": out["f_cap_adh"],
        "wetted_area": out["wetted"],
        "energy_capillary": e_cap,
        "energy_chemical": e_chem,
        "energy_vdw": e_vdw,
        "energy_elastic": e_el,
        "energy_dissipated": energy,
        "tangential_force": np.full(step.size, f_t),
        "stiction_margin": margin,
        "mesh_efficiency": efficiency,
        "friction_shear_stress": shear_stress,
        "rigid_atomic_blocks": out["rigid_atomic_blocks"],
    }
    # units and long names from the vocabulary (memstribo.quantities), the same in every output
    data = {name: var(name, values) for name, values in data.items()}
    data["load_share"].attrs["long_name"] = f"load share of the pair ({params['load_sharing']}, Figure 4-11)"
    data["block_load"] = var("block_load", block_load, dims=("step", "block"))
    coords = {
        "step": ("step", step, quantity_attrs("step")),
        "c": ("step", setup.positions, quantity_attrs("c")),
        "block_flank": ("block", block_flank, quantity_attrs("block_flank")),
        "block_row": ("block", block_row, quantity_attrs("block_row")),
        "block_index": ("block", block_index, quantity_attrs("block_index")),
    }
    rows_info = setup.row_roughness
    attrs = {
        "title": "memstribo meshing-cycle simulation (thesis 4.6, 4.9)",
        "load_case": params["load_case"],
        "interface_model": params["interface_model"],
        "environment": params["environment"],
        "relative_humidity": float(params["relative_humidity"]) if params["environment"] == "air" else 0.0,
        "contact_adhesion": params["contact_adhesion"],
        "mesh_contact": params["mesh_contact"],
        "vdw_cutoff": float(params["vdw_cutoff"]),
        "friction_averaging_distance": float(averaging),
        "realisation": int(realisation),
        "sliding_axis": sliding_axis,
        "roughness": setup.roughness_name,
        "roughness_synthetic": int(setup.roughness_synthetic),
        "roughness_source": setup.roughness_source,
        "roughness_rows": rows_info.method,
        "roughness_lines_measured": int(rows_info.measured_lines),
        "roughness_lines_synthesised": int(rows_info.synthesised_lines),
        "block_load_variant": BLOCK_LOAD_VARIANT,
        "rows": setup.rows,
        "rows_solved": n_rows_solved,
        "effective_face_width": setup.effective_face_width,
        "dundurs_beta": beta,
        "friction_passes": passes,
        "friction_fixed_point_converged": int(fixed_point_converged),
        "contact_modulus": modulus,
        "coating": "none (bare silicon)" if coating is None else coating.name,
        "wear": float(wear) if coating is not None else 1.0,
        "grid_spacing": setup.grid_spacing,
        "window": setup.grid.size * setup.grid_spacing,
        "tangential_force_total": f_t,
        "normal_force_total": float(normal_force_of_load_case(params, pair)),
        "input_power": input_power,
        "mesh_efficiency_mean": efficiency_mean,
        "elastic_limit_pressure": params["elastic_limit_pressure"],
        "ideal_shear_strength": params["ideal_shear_strength"],
        "warnings": json.dumps(warnings),
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _warnings(params, out, setup, shear_stress, efficiency, fixed_point_converged, passes, beta) -> list[str]:
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
        warnings.append(f"the contact reached the ends of the {setup.grid.size * setup.grid_spacing * 1e6:.3g} um window "
                        f"in {exceeded} step(s): raise mesh_window")
    if params["interface_model"] == "gap" and (out["vdw_edge"] > 0).any():
        warnings.append(f"the gap at the window's ends is below vdw_cutoff in {int((out['vdw_edge'] > 0).sum())} "
                        "step(s): vdW beyond the window is missed; raise mesh_window")
    above = int((out["max_pressure"] > params["elastic_limit_pressure"]).sum())
    if above:
        warnings.append(f"the rough contact's peak pressure exceeds the elastic limit of silicon "
                        f"({params['elastic_limit_pressure'] / 1e9:.3g} GPa) in {above} step(s)")
    rigid = int((out["rigid_atomic_blocks"] > 0).sum())
    if rigid:
        warnings.append(f"atomic blocks are past the threshold strain of the bilinear law "
                        f"({params['threshold_strain']:g}) in {rigid} step(s): they carry load rigidly")
    peak_shear = float(np.max(shear_stress)) if shear_stress.size else 0.0
    if peak_shear > params["ideal_shear_strength"]:
        warnings.append(f"the friction stress over the real contact reaches {peak_shear / 1e9:.3g} GPa, above the ideal "
                        f"shear strength of silicon ({params['ideal_shear_strength'] / 1e9:.3g} GPa): the teeth "
                        "would shear and wear rather than slide")
    if not fixed_point_converged:
        warnings.append(f"the F_t/F_f fixed point of dissimilar materials (Dundurs beta {beta:.3g}) did not converge "
                        f"in {passes} passes: the friction is not reliable")
    if (efficiency <= 0).any():
        warnings.append(f"the instantaneous mesh efficiency is zero or below in {int((efficiency <= 0).sum())} "
                        "step(s): friction takes more power than the drive supplies there")
    if params["environment"] == "air" and 0.0 < params["relative_humidity"] < _LOWEST_MENISCUS_HUMIDITY:
        from memstribo.physics.capillary import kelvin_radius

        warnings.append(f"relative humidity {params['relative_humidity']:g} is below {_LOWEST_MENISCUS_HUMIDITY:g}: the "
                        f"Kelvin radius ({kelvin_radius(params['relative_humidity'], params['temperature']) * 1e9:.2g} "
                        "nm) is about a molecular size, where adsorbed water films, not menisci, dominate; the capillary "
                        "terms are outside their validity (docs/humidity.md)")
    return warnings


def summarize(dataset) -> dict:
    """The summary of a meshing cycle: the keys of ``memstribo mesh --json`` (SI).

    One COF per meaning: ``cof_mean`` is the cycle's dissipated energy over
    ``integral (F_N + F_adh) ds`` (3-7 over the cycle), and its split by mechanism
    (``cof_chemical``, ``cof_vdw``, ``cof_elastic``) is the same ratio per mechanism, so the
    parts add up to ``cof_mean`` exactly. The stiction verdict: ``resisting_force_max`` is the
    largest R(c), ``stiction_margin`` = ``tangential_force`` - ``resisting_force_max`` (MODEL 7b).
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
    return {
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
        "stiction": bool(margin < 0),
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
        "warnings": json.loads(dataset.attrs.get("warnings", "[]")),
    }


def step_convergence(params, roughness=None, *, steps=None, coating=None, wear=1.0, baseline=None, realisation=0):
    """Relative change of the minimum margin and the mean COF at twice the steps (MODEL 7b).

    Parameters
    ----------
    params, roughness, steps, coating, wear, realisation
        As for :func:`simulate_mesh`.
    baseline : dict, optional
        The :func:`summarize` of the run at ``steps`` (computed when not given).

    Returns
    -------
    dict
        ``step_converged`` (both changes below 2 %), ``step_change_margin`` and
        ``step_change_cof`` (relative, [-]; the margin's relative to F_t), ``steps_checked``.
    """
    steps = int(params["mesh_steps"] if steps is None else steps)
    if baseline is None:
        baseline = summarize(simulate_mesh(params, roughness, steps=steps, coating=coating, wear=wear,
                                           realisation=realisation))
    doubled = summarize(simulate_mesh(params, roughness, steps=2 * steps - 1, coating=coating, wear=wear,
                                      realisation=realisation))
    change_margin = abs(doubled["stiction_margin"] - baseline["stiction_margin"]) / max(baseline["tangential_force"],
                                                                                      1e-300)
    change_cof = abs(doubled["cof_mean"] - baseline["cof_mean"]) / max(abs(baseline["cof_mean"]), 1e-300)
    return {"step_converged": bool(change_margin < 0.02 and change_cof < 0.02),
            "step_change_margin": float(change_margin), "step_change_cof": float(change_cof),
            "steps_checked": 2 * steps - 1}


#: Keys of one realisation in ``per_realisation`` of an ensemble.
REALISATION_KEYS = ("seed", "realisation", "stiction_margin", "cof_mean", "stiction", "mesh_efficiency")


def _ensemble_point(params, roughness, steps, coating, wear, realisation):
    summary = summarize(simulate_mesh(params, roughness, steps=steps, coating=coating, wear=wear,
                                      realisation=realisation))
    summary["realisation"] = realisation
    summary["seed"] = [int(params["roughness_seed"]), int(realisation)]
    return summary


def simulate_ensemble(params, roughness=None, *, realisations=None, steps=None, coating=None, wear=1.0,
                      client=None, progress=False):
    """The stiction verdict over independent roughness realisations (MODEL 7b).

    Each realisation is a meshing cycle (:func:`simulate_mesh`) with its own roughness lines
    (seeds ``(roughness_seed, realisation)``; the measured lines, where there are any, in
    realisation 0). With a ``dask.distributed`` ``client`` the realisations run as independent
    tasks on its workers; the result does not depend on how they were scheduled.

    Parameters
    ----------
    params, roughness, steps, coating, wear
        As for :func:`simulate_mesh`.
    realisations : int, optional
        Number of realisations (default the parameter ``realisations``).
    client : distributed.Client, optional
    progress : bool

    Returns
    -------
    dict
        ``realisations``, ``stiction_probability`` (fraction that sticks), ``stiction_margin_median``,
        ``_p05``, ``_p95`` [N], ``cof_mean_median``, ``_p05``, ``_p95``, ``mesh_efficiency_median``,
        ``per_realisation`` (list of dicts with the keys of :data:`REALISATION_KEYS`), and
        ``summaries`` (the full summary of every realisation, in order).
    """
    n = int(params["realisations"] if realisations is None else realisations)
    if n < 1:
        raise InputError(f"realisations must be at least 1, got {n}.")
    if client is not None:
        futures = client.map(_ensemble_point, [params] * n, [roughness] * n, [steps] * n, [coating] * n,
                             [wear] * n, list(range(n)), pure=False)
        summaries = client.gather(futures)
    else:
        iterator = range(n)
        if progress:
            from tqdm.auto import tqdm

            iterator = tqdm(iterator, desc="roughness realisations", unit="cycle")
        summaries = [_ensemble_point(params, roughness, steps, coating, wear, k) for k in iterator]
    return ensemble_summary(summaries)


def ensemble_summary(summaries) -> dict:
    """Stiction probability and 5/50/95 % quantiles over realisation summaries (MODEL 7b)."""
    margins = np.array([s["stiction_margin"] for s in summaries])
    cofs = np.array([s["cof_mean"] for s in summaries])
    efficiency = np.array([s["mesh_efficiency"] for s in summaries])
    out = {"realisations": len(summaries),
           "stiction_probability": float(np.mean(margins < 0))}
    for name, values in (("stiction_margin", margins), ("cof_mean", cofs), ("mesh_efficiency", efficiency)):
        out[f"{name}_median"] = float(np.median(values))
        out[f"{name}_p05"] = float(np.quantile(values, 0.05))
        out[f"{name}_p95"] = float(np.quantile(values, 0.95))
    out["per_realisation"] = [{key: s[key] for key in REALISATION_KEYS} for s in summaries]
    out["summaries"] = list(summaries)
    return out


def sweep(params, parameter, values, roughness=None, *, steps=None, coating=None, wear=1.0, progress=False,
          realisations=1, client=None):
    """Meshing cycles over a list of loads, drive torques or nominal areas (thesis 4.9.3, 4.9.4).

    Parameters
    ----------
    params : Parameters
    parameter : {"load", "torque", "area"}
        ``"load"``: ``values`` are normal loads [N] (the ``thesis`` load case: the normal load is
        given). ``"torque"``: drive torques [N m] (the ``torque`` load case). ``"area"``:
        nominal contact areas in multiples of A_adh = w_adh^2 [-]; the face width is set to
        ``n w_adh`` so that ``n`` rows of nanoblocks share the load (the thesis's "nominal area").
    values : sequence of float
    roughness, steps, coating, wear
        As for :func:`simulate_mesh`.
    progress : bool
        tqdm progress bar over the points (stderr).
    realisations : int
        Roughness realisations per point: above 1 each point also carries the ensemble's
        ``stiction_probability`` and quantiles (:func:`simulate_ensemble`), e.g. the stiction
        probability versus drive torque.
    client : distributed.Client, optional
        Runs each point's realisations on a Dask cluster.

    Returns
    -------
    list of dict
        One summary (:func:`summarize`) per value, with the swept value first under
        ``"normal_load"``, ``"drive_torque"`` or ``"area"`` (and ``"area_multiple"`` for areas).
    """
    values = [float(v) for v in values]
    if not values:
        raise InputError("a sweep needs at least one value.")
    if parameter not in ("load", "torque", "area", "humidity"):
        raise InputError(f"sweep parameter '{parameter}' is unknown: use 'load', 'torque', 'area' or 'humidity'.")
    iterator = values
    if progress:
        from tqdm.auto import tqdm

        iterator = tqdm(values, desc=f"sweep {parameter}", unit="cycle")
    points = []
    warm = None
    for value in iterator:
        if parameter == "load":
            if value <= 0:
                raise InputError(f"sweep load values must be positive forces, got {value!r} N.")
            point_params = params.updated({"normal_load": value, "load_case": "thesis"}, origin="sweep")
            head = {"normal_load": value}
        elif parameter == "humidity":
            if not 0.0 <= value <= 0.99:
                raise InputError(f"sweep humidity values are relative humidities from 0 to 0.99, got {value!r}.")
            point_params = params.updated({"environment": "air", "relative_humidity": value}, origin="sweep")
            head = {"relative_humidity": value}
            # each point starts from the previous one's contacts, where the contact has one solution: with
            # the Maugis-Dugdale zone a step can have two (adhered or not), and the state reached would
            # then depend on the humidity swept before it, so those points start cold
            if params["contact_adhesion"] == "none":
                warm = {} if warm is None else warm
        elif parameter == "torque":
            if value <= 0:
                raise InputError(f"sweep torque values must be positive torques, got {value!r} N m.")
            point_params = params.updated({"drive_torque": value, "load_case": "torque"}, origin="sweep")
            head = {"drive_torque": value}
        else:
            if value < 1 or not float(value).is_integer():
                raise InputError(f"sweep area values are whole multiples of A_adh (1, 2, 3, ...), got {value!r}.")
            w_adh = params["adhesive_width"]
            point_params = params.updated({"face_width": value * w_adh * (1 + 1e-9)}, origin="sweep")
            head = {"area_multiple": int(value), "area": value * w_adh**2}
        if realisations > 1:
            ensemble = simulate_ensemble(point_params, roughness, realisations=realisations, steps=steps,
                                         coating=coating, wear=wear, client=client)
            summary = dict(ensemble["summaries"][0])
            summary.update({k: v for k, v in ensemble.items() if k not in ("summaries", "per_realisation")})
            if parameter == "humidity":  # each realisation's margin, for its critical humidity
                summary["stiction_margin_realisations"] = [r["stiction_margin"] for r in ensemble["per_realisation"]]
        else:
            summary = summarize(simulate_mesh(point_params, roughness, steps=steps, coating=coating, wear=wear,
                                              warm_start=warm))
        points.append({**head, **summary})
    return points


#: Below this relative humidity the Kelvin radius is about a molecular size (0.23 nm at RH 0.1, 25 degC):
#: the meniscus model's lower limit (docs/humidity.md).
_LOWEST_MENISCUS_HUMIDITY = 0.1


def _first_crossing(humidity, margin):
    """RH [-] where ``margin`` first falls to <= 0, linear between sweep points; None without a crossing."""
    for i, value in enumerate(margin):
        if value <= 0.0:
            if i == 0:
                return float(humidity[0])
            before = margin[i - 1]
            return float(humidity[i - 1] + (humidity[i] - humidity[i - 1]) * before / (before - value))
    return None


def critical_humidity(points) -> dict:
    """Relative humidity at which stiction sets in, from a humidity sweep (issue #17, docs/humidity.md).

    The stiction margin M = F_t - max R(c) (MODEL 7b) of each point is interpolated linearly in RH
    between neighbouring sweep points; the critical humidity is the lowest RH where it reaches 0
    (stiction for every RH above, up to the next crossing back, if any). With several roughness
    realisations per point (``sweep(..., realisations=N)``) each realisation's margin gives its own
    critical humidity, and their 5/50/95 % quantiles give the spread.

    Parameters
    ----------
    points : list of dict
        :func:`sweep` ``"humidity"`` points: ``relative_humidity`` [-] and ``stiction_margin`` [N]
        (and ``stiction_margin_realisations`` with realisations).

    Returns
    -------
    dict
        ``critical_humidity`` [-] (None when the margin does not cross zero in the swept range),
        ``critical_humidity_note`` (why, in words), ``critical_humidity_range`` [RH min, RH max];
        with realisations also ``critical_humidity_realisations`` (one value or None each),
        ``critical_humidity_p05``/``_median``/``_p95`` over the realisations that cross and
        ``critical_humidity_crossing_fraction`` and ``critical_humidity_stuck_at_lowest`` (realisations
        that already stick at the lowest RH, counted there). A crossing below RH 0.1 is flagged in the note.
    """
    if not points or any("relative_humidity" not in p or "stiction_margin" not in p for p in points):
        raise InputError("critical_humidity needs the points of a humidity sweep (relative_humidity, "
                         "stiction_margin).")
    ordered = sorted(points, key=lambda p: p["relative_humidity"])
    humidity = np.array([p["relative_humidity"] for p in ordered], dtype=float)
    margin = np.array([p["stiction_margin"] for p in ordered], dtype=float)
    low, high = float(humidity[0]), float(humidity[-1])
    value = _first_crossing(humidity, margin)
    if value is not None and 0.0 < value < _LOWEST_MENISCUS_HUMIDITY:
        low_note = (f"; RH {value:.3f} is below {_LOWEST_MENISCUS_HUMIDITY:g}, where the Kelvin radius is about a "
                    "molecular size and the meniscus model does not hold: read it as 'as soon as menisci form'")
    else:
        low_note = ""
    if value is None:
        note = (f"no stiction in the swept range RH {low:g}-{high:g}: the stiction margin stays positive (smallest "
                f"{margin.min() * 1e6:.4g} uN at RH {humidity[int(np.argmin(margin))]:g}); the critical humidity, if "
                "any, lies above the range")
    elif value == low and margin[0] <= 0.0:
        note = (f"stiction already at the lowest swept humidity RH {low:g}: the critical humidity is at or below it "
                "(extend the sweep downwards)")
    else:
        note = (f"the stiction margin crosses zero at RH {value:.3f} (linear between the sweep points; resolution "
                f"{np.diff(humidity).max() if humidity.size > 1 else 0:.3g})")
    out = {"critical_humidity": value, "critical_humidity_note": note + low_note,
           "critical_humidity_range": [low, high]}
    if all("stiction_margin_realisations" in p for p in ordered):
        per = np.array([p["stiction_margin_realisations"] for p in ordered], dtype=float)  # (points, realisations)
        values = [_first_crossing(humidity, per[:, j]) for j in range(per.shape[1])]
        crossing = np.array([v for v in values if v is not None])
        out["critical_humidity_realisations"] = values
        out["critical_humidity_crossing_fraction"] = float(crossing.size / len(values))
        for name, q in (("p05", 0.05), ("median", 0.5), ("p95", 0.95)):
            out[f"critical_humidity_{name}"] = float(np.quantile(crossing, q)) if crossing.size else None
        stuck = sum(1 for j, v in enumerate(values) if v is not None and v == low and per[0, j] <= 0.0)
        out["critical_humidity_stuck_at_lowest"] = stuck
        if stuck:
            out["critical_humidity_note"] += (f"; {stuck} of {len(values)} realisation(s) already stick at the lowest "
                                              f"RH {low:g} (counted there)")
        if crossing.size == 0:
            out["critical_humidity_note"] += f"; none of the {len(values)} realisations sticks in the range"
        elif crossing.size < len(values):
            out["critical_humidity_note"] += (f"; {len(values) - crossing.size} of {len(values)} realisation(s) do "
                                              "not stick in the range (the quantiles are over those that do)")
    return out
