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
2. **Rough contact.** :func:`memstribo.contact.solve_line_contact` (free-boundary half-plane
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
   :func:`memstribo.nanoblock.mechanics.structure_fixed_load`) then shares it among its atomic
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
   same rule as the flat sliding models, :func:`memstribo.nanoblock.geometry.adhesive_layer_thickness`;
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

from .errors import InputError
from .adhesion import contact_modulus
from .gear import GearPair, hertz_line_contact, tangential_force
from .references import cites

__all__ = ["MeshSetup", "simulate_mesh", "summarize", "sweep", "SUMMARY_UNITS", "BLOCK_LOAD_VARIANT",
           "dundurs_beta", "roll_coordinate"]

BLOCK_LOAD_VARIANT = ("decoupled: rough contact solved without the block springs, block loads = pressure over "
                      "each nanoblock's footprint, shared among its atomic blocks by the fixed-load model (3.4.2)")

#: Units of the summary keys (``memstribo mesh --json``).
SUMMARY_UNITS = {
    "cof_mean": "", "cof_max": "", "cof_chemical": "", "cof_vdw": "", "cof_elastic": "",
    "friction_force_mean": "N", "friction_force_max": "N", "adhesion_force_mean": "N", "normal_force_max": "N",
    "tangential_force": "N", "stiction": "", "stiction_margin": "N", "steps": "", "sliding_distance": "m",
    "energy_dissipated": "J", "energy_chemical": "J", "energy_vdw": "J", "energy_elastic": "J",
    "unconverged_steps": "", "window_exceeded_steps": "", "max_contact_pressure": "Pa",
    "steps_above_elastic_limit": "",
}

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


@cites("johnson_1985")
def dundurs_beta(youngs_modulus, poisson_ratio, counter_youngs_modulus=None, counter_poisson_ratio=None):
    """Dundurs' second parameter beta of two elastic bodies (plane strain).

    Parameters
    ----------
    youngs_modulus, counter_youngs_modulus : float
        E1, E2 [Pa] (the counter body defaults to the first).
    poisson_ratio, counter_poisson_ratio : float
        nu1, nu2 [-].

    Returns
    -------
    float
        beta = 1/2 [(1-2nu1)/G1 - (1-2nu2)/G2] / [(1-nu1)/G1 + (1-nu2)/G2] [-]; zero for identical
        materials, where normal and tangential contact problems uncouple (Johnson 1985, 5.4).
    """
    e2 = youngs_modulus if counter_youngs_modulus is None else counter_youngs_modulus
    nu2 = poisson_ratio if counter_poisson_ratio is None else counter_poisson_ratio
    g1, g2 = youngs_modulus / (2 * (1 + poisson_ratio)), e2 / (2 * (1 + nu2))
    return 0.5 * ((1 - 2 * poisson_ratio) / g1 - (1 - 2 * nu2) / g2) / ((1 - poisson_ratio) / g1 + (1 - nu2) / g2)


def _work_of_adhesion(params):
    """w12 of the parameter set, or A / (12 pi D0^2) (3-34) when unset [J/m^2]."""
    from .adhesion import work_of_adhesion

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


def _load_roughness(roughness, params, needed):
    """A list of Profiles (one per line scan) and a name, from whatever the user gave."""
    from . import roughness as rough

    if roughness is None or (isinstance(roughness, str) and roughness == "thesis"):
        length = max(float(params["roughness_length"]), 1.05 * needed + 4 * params["roughness_sample_spacing"])
        profile = rough.default_profile(params, length=length)
        return [profile], profile.name, True, profile.source
    if isinstance(roughness, (str, Path)):
        from .readers import read_topography

        roughness = read_topography(roughness)
    if isinstance(roughness, rough.Profile):
        return [roughness], roughness.name, bool(roughness.synthetic), roughness.source
    if hasattr(roughness, "line_scans"):
        scans = list(roughness.line_scans())
        return scans, getattr(roughness, "name", "surface map"), False, getattr(roughness, "source", "")
    raise InputError(f"roughness must be None, 'thesis', a file path, a Profile or a SurfaceMap; got "
                     f"{type(roughness).__name__}.")


def _prepare(params, roughness, steps) -> MeshSetup:
    from . import roughness as rough

    pair = GearPair.from_parameters(params)
    steps = int(params["mesh_steps"] if steps is None else steps)
    if steps < 3:
        raise InputError(f"a meshing cycle needs at least 3 steps, got {steps}.")
    positions = _positions(pair, steps)
    t = pair.time(positions)
    step_time = np.concatenate([[0.5 * (t[1] - t[0])], 0.5 * (t[2:] - t[:-2]), [0.5 * (t[-1] - t[-2])]])
    share = pair.load_share(positions, params["load_sharing"])
    load = share * params["normal_load"]
    w_adh = params["adhesive_width"]
    rows = int(params["face_width"] // w_adh)
    if rows < 1:
        raise InputError(f"face_width ({params['face_width']:.4g} m) is narrower than one nanoblock "
                         f"(adhesive_width {w_adh:.4g} m).")
    dx, window = params["mesh_grid_spacing"], params["mesh_window"]
    n = int(round(window / dx))
    if n < 64:
        raise InputError(f"mesh_window / mesh_grid_spacing = {n}: at least 64 contact elements are needed.")
    grid = (np.arange(n) - 0.5 * (n - 1)) * dx
    _, _, (lo1, hi1), (lo2, hi2) = _flank_ranges(pair, positions, n * dx + 2 * w_adh)
    needed = max(hi1 - lo1, hi2 - lo2)
    scans, name, synthetic, source = _load_roughness(roughness, params, needed)
    if len(scans) > 1 and len(scans) < rows:
        raise InputError(f"the surface map '{name}' has {len(scans)} line scans but the face width holds {rows} rows "
                         f"of nanoblocks (face_width / adhesive_width); a map needs at least {rows} rows "
                         f"(or give a single profile for all rows).")
    pinion, gear = [], []
    for k in range(rows if len(scans) > 1 else 1):
        p_scan = scans[k]
        g_scan = scans[k + rows] if len(scans) >= 2 * rows else None
        for scan in (p_scan,) + ((g_scan,) if g_scan is not None else ()):
            span = float(scan.x[-1] - scan.x[0])
            if span < needed:
                raise InputError(f"roughness '{name}' is {span * 1e6:.4g} um long, but the flank travel over the path of "
                                 f"contact plus the contact window needs {needed * 1e6:.4g} um on each flank; give a "
                                 f"longer scan (memstribo does not wrap a profile around).")
        # the scan's middle sits at the middle of the flank travel (independent of the window)
        zp = rough.level_profile(p_scan)
        mid_p = 0.5 * (zp.x[0] + zp.x[-1])
        pinion.append((zp.x - mid_p + 0.5 * (lo1 + hi1), zp.z))
        if g_scan is not None:
            zg = rough.level_profile(g_scan)
            gear.append((zg.x - 0.5 * (zg.x[0] + zg.x[-1]) + 0.5 * (lo2 + hi2), zg.z))
        else:  # the same scan read backwards: for a long scan, an independent stretch meets the pinion's
            gear.append((mid_p - zp.x[::-1] + 0.5 * (lo2 + hi2), zp.z[::-1]))
    return MeshSetup(pair, positions, step_time, load, rows, rows * w_adh, grid, pinion, gear, name, synthetic,
                     source)


def _heights(profile, coordinate):
    from scipy.interpolate import PchipInterpolator

    x, z = profile
    return PchipInterpolator(x, z, extrapolate=False)(coordinate)


# --------------------------------------------------------------------------------------------
# the cycle
# --------------------------------------------------------------------------------------------
def _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, shear_term, pbar):
    """Rough contact of every step of one row: pressure, deformed gap and solver info."""
    from .contact import solve_line_contact

    grid = setup.grid
    dx = params["mesh_grid_spacing"]
    z1 = _heights(setup.pinion_profiles[row], s1[:, None] - grid[None, :])
    z2 = _heights(setup.gear_profiles[row], s2[:, None] + grid[None, :])
    separation = grid[None, :] ** 2 / (2 * r_ef[:, None]) - z1 - z2
    if shear_term is not None:
        separation = separation + shear_term
    line_load = setup.load / setup.effective_face_width
    n_steps = separation.shape[0]
    pressure = np.zeros_like(separation)
    gap = np.zeros_like(separation)
    info = np.zeros((n_steps, 4))  # converged, residual, iterations, approach
    previous = None
    for i in range(n_steps):
        solution = solve_line_contact(separation[i], dx, modulus, load=line_load[i],
                                      tolerance=params["mesh_contact_tolerance"], initial_pressure=previous)
        pressure[i], gap[i] = solution.pressure, solution.gap
        info[i] = (solution.converged, solution.residual, solution.iterations, solution.approach)
        previous = solution.pressure
        if pbar is not None:
            pbar.update(1)
    return pressure, gap, info


def _lattice(roll, w_adh, grid_half):
    """Material indices k of the nanoblocks whose footprint meets the window, per step (steps, slots)."""
    # block k of a flank spans roll coordinates [k w_adh, (k+1) w_adh)
    lo = roll - grid_half - w_adh
    k0 = np.floor(lo / w_adh).astype(int)
    slots = int(math.ceil((2 * grid_half + 2 * w_adh) / w_adh)) + 1
    return k0[:, None] + np.arange(slots)[None, :]


def _run_cycle(setup, params, coating, wear, modulus, beta, mu_previous, progress):
    from .nanoblock.mechanics import BlockStiffness, structure_fixed_load
    from .nanoblock.geometry import adhesive_layer_thickness

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
    dx = params["mesh_grid_spacing"]
    grid = setup.grid
    half = 0.5 * grid.size * dx
    geometry = _geometry(params)
    stiffness = BlockStiffness.from_geometry(geometry, params["youngs_modulus"], modulus, params["threshold_strain"])
    offsets = (np.arange(m) - 0.5 * (m - 1)) * pitch

    from .adhesion import no_slip_coefficient, pull_off_force
    from .friction import chemical_bond_count, vdw_bond_count

    w_si = _work_of_adhesion(params)
    # one rule with the sliding models (thesis 3.5), for bare and coated blocks alike
    layer = adhesive_layer_thickness(params, geometry)
    if coating is not None:
        w_coat, u_vdw_coat = float(coating.work_of_adhesion), float(coating.vdw_bond_energy)
    c_ns = float(no_slip_coefficient(params["poisson_ratio"]))
    n_rows_solved = len(setup.pinion_profiles)
    row_weight = setup.rows / n_rows_solved

    pbar = None
    if progress:
        from tqdm import tqdm

        pbar = tqdm(total=n_steps * n_rows_solved, desc="meshing cycle", unit="step", leave=False)

    out = {key: np.zeros(n_steps) for key in ("chem_bonds", "vdw_bonds", "f_chem", "f_vdw", "e_el", "f_adh",
                                              "contact_width", "max_pressure", "unconverged", "residual",
                                              "iterations", "window_exceeded", "approach")}
    block_loads = []
    for row in range(n_rows_solved):
        if beta != 0.0 and mu_previous is not None:
            pressure, gap, info = _solve_with_shear(setup, params, modulus, r_ef, s1, s2, row, beta, mu_previous,
                                                    slip, pbar)
        else:
            pressure, gap, info = _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, None, pbar)
        # window check: the contact must stay clear of the window's ends (5 % margin each side)
        edge = max(1, grid.size // 20)
        out["window_exceeded"] += (pressure[:, :edge].any(axis=1) | pressure[:, -edge:].any(axis=1))
        out["unconverged"] += info[:, 0] == 0
        out["residual"] = np.maximum(out["residual"], info[:, 1])
        out["iterations"] += info[:, 2] / n_rows_solved
        out["approach"] += info[:, 3] / n_rows_solved
        out["contact_width"] += (pressure > 0).sum(axis=1) * dx / n_rows_solved
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
            flank_states.append((x_blocks, x_atoms, loads, atomic_force, atomic_comp, adhesive_comp))
        block_loads.append((k1, flank_states[0][2], k2, flank_states[1][2]))

        # gear blocks bare (worn coating) or coated: deterministic low-discrepancy choice
        def gear_bare(k):
            if coating is None:
                return np.ones(k.shape, dtype=bool)
            return np.mod(k * _GOLDEN + row * _SILVER, 1.0) < wear

        bare2 = gear_bare(k2)
        # chemical bonds: overlaps of touching opposing atomic blocks (along x), m rows across
        touch1 = flank_states[0][3][..., :m] > 0  # first row of the m x m array (rows alike)
        touch2 = (flank_states[1][3][..., :m] > 0) & bare2[..., None]
        xa1 = flank_states[0][1].reshape(n_steps, -1)
        xa2 = flank_states[1][1].reshape(n_steps, -1)
        t1 = touch1.reshape(n_steps, -1)
        t2 = touch2.reshape(n_steps, -1)
        overlap_len = np.clip(w_at - np.abs(xa1[:, :, None] - xa2[:, None, :]), 0.0, None)
        overlap_len = overlap_len * (t1[:, :, None] & t2[:, None, :])
        chem = m * chemical_bond_count(w_at, overlap_len.sum(axis=(1, 2)), bond)  # (3-10), m rows across
        out["chem_bonds"] += row_weight * chem
        out["f_chem"] += row_weight * chem * params["bond_energy"] / bond

        # vdW bonds: pinion block footprint inside the adhesive layer (3-12), pull-off (3-32)
        k1_at_x = np.floor((s1[:, None] - grid[None, :]) / w_adh).astype(int)  # pinion block at each element
        k2_at_x = np.floor((s2[:, None] + grid[None, :]) / w_adh).astype(int)
        bare_x = gear_bare(k2_at_x)
        inside = gap <= layer
        u_vdw_x = np.where(bare_x, params["vdw_bond_energy"], u_vdw_coat) if coating is not None \
            else params["vdw_bond_energy"]
        w_x = np.where(bare_x, w_si, w_coat) if coating is not None else w_si
        n_vdw = vdw_bond_count(w_adh, dx, bond) * inside  # (3-12), bonds per element
        out["vdw_bonds"] += row_weight * n_vdw.sum(axis=1)
        out["f_vdw"] += row_weight * (n_vdw * u_vdw_x).sum(axis=1) / bond
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
            pull_off[engaged] = pull_off_force(work[engaged], modulus, c_ns, a[engaged])  # (3-32)
        out["f_adh"] += row_weight * pull_off.sum(axis=1)  # (3-31)

        # elastic interlocking (3-25) on material blocks, both flanks, times the sliding fraction
        e_el = np.zeros(n_steps)
        for (k, (_, _, _, _, comp_at, comp_adh)) in zip((k1, k2), flank_states):
            e_el += _interlocking(k, comp_at, comp_adh, stiffness)
        out["e_el"] += row_weight * e_el * sliding_fraction

    if pbar is not None:
        pbar.close()
    return out, block_loads, dict(r_ef=r_ef, s1=s1, s2=s2, u1=u1, u2=u2, slip=slip, sliding=sliding,
                                  sliding_fraction=sliding_fraction)


def _interlocking(k, comp_at, comp_adh, stiffness):
    """Sum over material blocks of 1/2 k de^2 between consecutive steps (atomic + adhesive)."""
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
    return 0.5 * stiffness.atomic * (d_at**2).sum(axis=(1, 2)) + 0.5 * stiffness.adhesive * (d_adh**2).sum(axis=1)


def _solve_with_shear(setup, params, modulus, r_ef, s1, s2, row, beta, mu, slip, pbar):
    """Contacts with the normal gap change of the friction traction mu p (dissimilar materials)."""
    # first the frictionless solution gives p; the traction term uses it (one fixed-point sweep per pass)
    pressure, gap, info = _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, None, None)
    dx = params["mesh_grid_spacing"]
    integral = np.cumsum(pressure, axis=1) * dx
    integral -= integral.mean(axis=1, keepdims=True)
    shear = (2 * beta / modulus) * (mu * np.sign(slip))[:, None] * integral
    return _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, shear, pbar)


def _geometry(params):
    try:
        from .nanoblock.geometry import NanoblockGeometry

        return NanoblockGeometry.from_parameters(params)
    except ImportError:  # pragma: no cover - until the geometry module lands
        from types import SimpleNamespace

        return SimpleNamespace(atomic_width=params["atomic_width"], atomic_height=params["atomic_height"],
                               adhesive_width=params["adhesive_width"], adhesive_height=params["adhesive_height"],
                               atomic_per_side=params["atomic_per_side"], bulk_height=params["bulk_height"])


@cites("thesis", "model", "johnson_1985", "polonsky_keer_1999", "hu_1986")
def simulate_mesh(params, roughness=None, *, steps=None, coating=None, wear=1.0, progress=False):
    """Friction, adhesion and COF of two rough silicon teeth over one meshing cycle (thesis 4.6, 4.9).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set (gear, load, material, nanoblock and ``mesh_*`` parameters).
    roughness : None, "thesis", str or Path, Profile or SurfaceMap
        Roughness of the teeth: ``None``/"thesis" is the seeded synthetic default (labelled
        synthetic); a path is read with :func:`memstribo.readers.read_topography`; a SurfaceMap
        gives one line scan per row of nanoblocks (the next rows, if there are enough, for the
        gear; else the same scans read backwards).
    steps : int, optional
        Number of positions c from c_f to c_l (default ``mesh_steps``).
    coating : memstribo.coating.Coating, optional
        SAM coating of the teeth; ``None`` is bare silicon.
    wear : float
        Worn fraction Omega of the gear's coating, 0..1 (the pinion's is fully worn); only with
        a coating. ``wear=1`` equals the bare result.
    progress : bool
        Show a tqdm progress bar on stderr.

    Returns
    -------
    xarray.Dataset
        Over ``step`` with coordinate ``c`` [m]: ``friction_force``, ``adhesion_force``,
        ``normal_force``, ``cof``, ``cof_chemical``, ``cof_vdw``, ``cof_elastic``,
        ``energy_chemical``, ``energy_vdw``, ``energy_elastic``, ``sliding_distance``,
        ``contact_width``, ``stiction_margin``, ``block_load`` (``step``, ``block``) and more;
        each variable with ``units`` and ``long_name``. Attributes record the roughness, the
        block-load variant, the Dundurs beta and the passes of the F_t/F_f iteration.

    Raises
    ------
    InputError
        A pair that cannot mesh, a load beyond the elastic range (Hertz peak pressure above
        ``elastic_limit_pressure``), roughness too short for the flank travel, a map with fewer
        rows than nanoblock rows, a wear fraction outside [0, 1].
    """
    import xarray as xr

    if not 0.0 <= float(wear) <= 1.0:
        raise InputError(f"wear (the worn fraction Omega of the gear's coating) must be within 0..1, got {wear!r}.")
    modulus = contact_modulus(params["youngs_modulus"], params["poisson_ratio"], params["counter_youngs_modulus"],
                              params["counter_poisson_ratio"])
    beta = dundurs_beta(params["youngs_modulus"], params["poisson_ratio"], params["counter_youngs_modulus"],
                        params["counter_poisson_ratio"])
    setup = _prepare(params, roughness, steps)
    pair = setup.pair
    # smooth-teeth Hertz contact under the line load actually solved (load / L_eff), Eqs. (4-22)-(4-26)
    hertz = hertz_line_contact(setup.load, setup.effective_face_width, pair.effective_radius(setup.positions),
                               modulus)
    hertz_peak = hertz.peak_pressure
    if hertz_peak.max() > params["elastic_limit_pressure"]:
        i = int(np.argmax(hertz_peak))
        raise InputError(f"normal_load {params['normal_load'] * 1e6:.4g} uN is beyond the elastic range: the Hertz peak "
                         f"pressure reaches {hertz_peak[i] / 1e9:.3g} GPa at c = {setup.positions[i] * 1e6:.3g} um, above "
                         f"the elastic limit of silicon ({params['elastic_limit_pressure'] / 1e9:.3g} GPa, "
                         f"elastic_limit_pressure); the elastic model of the thesis no longer holds.")
    f_t = tangential_force(params["drive_torque"], pair.pitch_radii[0])
    share = setup.load / params["normal_load"]

    mu = None
    passes = 0
    friction_old = None
    while True:
        passes += 1
        out, block_loads, kin = _run_cycle(setup, params, coating, wear, modulus, beta, mu, progress)
        sliding = kin["sliding"]
        f_el = np.divide(out["e_el"], sliding, out=np.zeros_like(sliding), where=sliding > 0)
        friction = out["f_chem"] + out["f_vdw"] + f_el
        mu = friction / (setup.load + out["f_adh"])
        if beta == 0.0:
            break
        if friction_old is not None and np.max(np.abs(friction - friction_old)) <= 1e-3 * max(friction.max(), 1e-300):
            break
        if passes >= 10:
            break
        friction_old = friction

    denominator = setup.load + out["f_adh"]
    e_chem, e_vdw = out["f_chem"] * sliding, out["f_vdw"] * sliding
    e_el = f_el * sliding
    step = np.arange(setup.positions.size)

    def var(values, units, long_name, dims=("step",)):
        return xr.Variable(dims, np.asarray(values), attrs={"units": units, "long_name": long_name})

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

    data = {
        "time": var(pair.time(setup.positions), "s", "time since the first point of contact (4-18)"),
        "load_share": var(share, "", f"load share of the pair ({params['load_sharing']}, Figure 4-11)"),
        "normal_force": var(setup.load, "N", "normal force on the tooth pair"),
        "effective_radius": var(kin["r_ef"], "m", "radius of relative curvature R_ef (4-11)"),
        "hertz_half_width": var(hertz.half_width, "m", "Hertz half-width a of smooth teeth under the step's load (4-24)"),
        "hertz_peak_pressure": var(hertz.peak_pressure, "Pa", "Hertz peak pressure p0 of smooth teeth (4-26)"),
        "sliding_velocity": var(kin["slip"], "m/s", "sliding velocity u1 - u2 (4-12)"),
        "sliding_distance": var(sliding, "m", "sliding distance of the step |u1 - u2| dt"),
        "contact_width": var(out["contact_width"], "m", "measure of the contact set of the rough contact (row mean)"),
        "max_contact_pressure": var(out["max_pressure"], "Pa", "largest element pressure of the rough contact"),
        "contact_approach": var(out["approach"], "m", "rigid approach of the rough contact solve (row mean)"),
        "contact_converged": var(out["unconverged"] == 0, "", "whether the contact solve converged in every row"),
        "contact_residual": var(out["residual"], "", "largest complementarity residual over the rows"),
        "contact_iterations": var(out["iterations"], "", "mean conjugate-gradient iterations over the rows"),
        "window_exceeded": var(out["window_exceeded"] > 0, "", "contact reached the ends of the contact window"),
        "chemical_bonds": var(out["chem_bonds"], "", "chemical bonds between touching atomic blocks (3-10)"),
        "vdw_bonds": var(out["vdw_bonds"], "", "van der Waals bonds inside the adhesive layer (3-12)"),
        "friction_force_chemical": var(out["f_chem"], "N", "friction force of the chemical bonds"),
        "friction_force_vdw": var(out["f_vdw"], "N", "friction force of the vdW bonds"),
        "friction_force_elastic": var(f_el, "N", "friction force of elastic interlocking (3-25)"),
        "friction_force": var(friction, "N", "friction force F_f (3-1)"),
        "adhesion_force": var(out["f_adh"], "N", "adhesion (pull-off) force F_adh (3-31, 3-32)"),
        "cof": var(friction / denominator, "", "apparent coefficient of friction (3-7)"),
        "cof_chemical": var(out["f_chem"] / denominator, "", "COF from chemical bonds (3-8)"),
        "cof_vdw": var(out["f_vdw"] / denominator, "", "COF from vdW bonds (3-8)"),
        "cof_elastic": var(f_el / denominator, "", "COF from elastic interlocking (3-9)"),
        "energy_chemical": var(e_chem, "J", "energy dissipated by chemical bonds in the step"),
        "energy_vdw": var(e_vdw, "J", "energy dissipated by vdW bonds in the step"),
        "energy_elastic": var(e_el, "J", "energy dissipated by elastic interlocking in the step"),
        "energy_dissipated": var(e_chem + e_vdw + e_el, "J", "energy dissipated in the step"),
        "tangential_force": var(share * f_t, "N", "the pair's share of the tangential force F_t = T/r1 (4-27)"),
        "stiction_margin": var(share * f_t - friction, "N", "stiction margin F_t - F_f (negative: stiction)"),
        "block_load": var(block_load, "N", "normal load of each nanoblock (pinion and gear flanks, rows)",
                          dims=("step", "block")),
    }
    coords = {
        "step": step,
        "c": ("step", setup.positions, {"units": "m", "long_name": "position on the line of action (0: pitch point)"}),
        "block_flank": ("block", block_flank, {"long_name": "flank of the nanoblock"}),
        "block_row": ("block", block_row, {"long_name": "row of nanoblocks across the face width"}),
        "block_index": ("block", block_index, {"long_name": "index of the nanoblock along its flank"}),
    }
    attrs = {
        "title": "memstribo meshing-cycle simulation (thesis 4.6, 4.9)",
        "roughness": setup.roughness_name,
        "roughness_synthetic": int(setup.roughness_synthetic),
        "roughness_source": setup.roughness_source,
        "block_load_variant": BLOCK_LOAD_VARIANT,
        "rows": setup.rows,
        "rows_solved": n_rows_solved,
        "effective_face_width": setup.effective_face_width,
        "dundurs_beta": beta,
        "friction_passes": passes,
        "contact_modulus": modulus,
        "coating": "none (bare silicon)" if coating is None else coating.name,
        "wear": float(wear) if coating is not None else 1.0,
        "grid_spacing": params["mesh_grid_spacing"],
        "window": setup.grid.size * params["mesh_grid_spacing"],
        "tangential_force_total": f_t,
        "elastic_limit_pressure": params["elastic_limit_pressure"],
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def summarize(dataset) -> dict:
    """The summary of a meshing cycle: the keys of ``memstribo mesh --json`` (SI).

    Means are time averages over the cycle (weighted by the step times); the COF split is the
    ratio of the cycle's dissipated energies by mechanism to ``integral (F_N + F_adh) ds``, so
    that ``cof_chemical + cof_vdw + cof_elastic`` equals ``cof_mean``'s energy form
    (``energy / integral (F_N + F_adh) ds``); ``cof_mean`` itself is the time mean of the COF.
    """
    time = np.asarray(dataset["time"])
    weights = np.gradient(time) if time.size > 1 else np.ones(1)
    weights = weights / weights.sum()
    sliding = np.asarray(dataset["sliding_distance"])
    denominator = np.asarray(dataset["normal_force"] + dataset["adhesion_force"])
    work = float((denominator * sliding).sum())
    energy = {k: float(dataset[k].sum()) for k in ("energy_chemical", "energy_vdw", "energy_elastic")}
    friction = np.asarray(dataset["friction_force"])
    margin = np.asarray(dataset["stiction_margin"])
    return {
        "cof_mean": float((np.asarray(dataset["cof"]) * weights).sum()),
        "cof_max": float(dataset["cof"].max()),
        "cof_chemical": energy["energy_chemical"] / work if work > 0 else 0.0,
        "cof_vdw": energy["energy_vdw"] / work if work > 0 else 0.0,
        "cof_elastic": energy["energy_elastic"] / work if work > 0 else 0.0,
        "friction_force_mean": float((friction * weights).sum()),
        "friction_force_max": float(friction.max()),
        "adhesion_force_mean": float((np.asarray(dataset["adhesion_force"]) * weights).sum()),
        "normal_force_max": float(dataset["normal_force"].max()),
        "tangential_force": float(dataset.attrs["tangential_force_total"]),
        "stiction": bool((margin < 0).any()),
        "stiction_margin": float(margin.min()),
        "steps": int(time.size),
        "sliding_distance": float(sliding.sum()),
        "energy_dissipated": float(sum(energy.values())),
        **energy,
        "unconverged_steps": int((~np.asarray(dataset["contact_converged"], dtype=bool)).sum()),
        "window_exceeded_steps": int(np.asarray(dataset["window_exceeded"], dtype=bool).sum()),
        "max_contact_pressure": float(dataset["max_contact_pressure"].max()),
        "steps_above_elastic_limit": int((np.asarray(dataset["max_contact_pressure"])
                                          > dataset.attrs.get("elastic_limit_pressure", np.inf)).sum()),
    }


def sweep(params, parameter, values, roughness=None, *, steps=None, coating=None, wear=1.0, progress=False):
    """Meshing cycles over a list of loads or nominal areas (thesis 4.9.3, 4.9.4).

    Parameters
    ----------
    params : Parameters
    parameter : {"load", "area"}
        ``"load"``: ``values`` are normal loads [N]. ``"area"``: ``values`` are nominal contact
        areas in multiples of A_adh = w_adh^2 [-]; the face width is set to ``n w_adh`` so that
        ``n`` rows of nanoblocks share the load (the thesis's "nominal area").
    values : sequence of float
    roughness, steps, coating, wear
        As for :func:`simulate_mesh`.
    progress : bool
        tqdm progress bar over the points (stderr).

    Returns
    -------
    list of dict
        One summary (:func:`summarize`) per value, with the swept value first under
        ``"normal_load"`` or ``"area"`` (and ``"area_multiple"`` for areas).
    """
    values = [float(v) for v in values]
    if not values:
        raise InputError("a sweep needs at least one value.")
    if parameter not in ("load", "area"):
        raise InputError(f"sweep parameter '{parameter}' is unknown: use 'load' or 'area'.")
    iterator = values
    if progress:
        from tqdm import tqdm

        iterator = tqdm(values, desc=f"sweep {parameter}", unit="cycle")
    points = []
    for value in iterator:
        if parameter == "load":
            if value <= 0:
                raise InputError(f"sweep load values must be positive forces, got {value!r} N.")
            point_params = params.updated({"normal_load": value}, origin="sweep")
            head = {"normal_load": value}
        else:
            if value < 1 or not float(value).is_integer():
                raise InputError(f"sweep area values are whole multiples of A_adh (1, 2, 3, ...), got {value!r}.")
            w_adh = params["adhesive_width"]
            point_params = params.updated({"face_width": value * w_adh * (1 + 1e-9)}, origin="sweep")
            head = {"area_multiple": int(value), "area": value * w_adh**2}
        dataset = simulate_mesh(point_params, roughness, steps=steps, coating=coating, wear=wear)
        points.append({**head, **summarize(dataset)})
    return points
