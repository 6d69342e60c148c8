"""The step loop of a meshing cycle: each row's contact, then bonds, menisci, interlocking and adhesion per step."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from memstribo.errors import InputError
from memstribo.materials.pair import no_slip_coefficient
from memstribo.physics.vdw_energy import vdw_bond_energy_of, vdw_site_density_of
from memstribo.simulations.mesh.contacts import (_capillary_zone, _cohesive_zone, _solve_contacts,
                                                _solve_contacts_surface, _solve_with_shear)
from memstribo.simulations.mesh.interface import (_GOLDEN, _SILVER, _interlocking, _lattice, lattice_overlap_across,
                                                 vdw_gap_factor)
from memstribo.simulations.mesh.setup import _geometry, _work_of_adhesion, roll_coordinate
from memstribo.simulations.mesh.threads import ordered_map, row_threads


def _run_cycle(setup, params, coating, wear, modulus, beta, mu_previous, progress, warm_start=None):
    """One meshing cycle: the rough contact of every roughness row at every step, then the bonds, menisci and
    interlocking of the nanoblock lattices on it; (per-step totals, block loads per row, kinematics)."""
    kinematics = _kinematics(setup)
    ctx = _context(setup, params, coating, wear, modulus)
    n_steps = setup.positions.size
    n_rows_solved = len(setup.pinion_profiles)  # every row, each with its own roughness (MODEL 7b)
    pbar = None
    if progress:
        from tqdm.auto import tqdm

        pbar = tqdm(total=n_steps * n_rows_solved, desc="meshing cycle", unit="step", leave=False)
    out = {key: np.zeros(n_steps) for key in _TOTALS}
    # each row's bond counts (chemical, vdW over bare and over coated gear blocks): the start-up force takes the
    # maximum over the sliding offset of the rows' bond forces at their registries (MODEL 7f)
    out["row_bonds"] = np.zeros((3, n_steps, n_rows_solved))
    block_loads = []
    strip = _surface_strip(setup, params, modulus, beta, kinematics, pbar)
    # each row's contacts, the next rows on threads while this one is added up (the same numbers: threads.py)
    threads = row_threads(setup.grid.size, n_rows_solved, compiled=strip is None and ctx.with_cohesive_zone)
    contacts = ordered_map(lambda row: _row_contact(setup, params, ctx, modulus, beta, mu_previous, kinematics, row,
                                                    strip, pbar, warm_start), range(n_rows_solved), threads)
    for row, (pressure, gap, info, zone) in enumerate(contacts):
        before = [out[key].copy() for key in _ROW_BOND_KEYS[coating is not None]]
        _record_solve(out, ctx, pressure, gap, info, n_rows_solved)
        rolls = _row_rolls(setup, kinematics, row)
        k1, k2, flank_states = _flank_blocks(out, ctx, pressure, gap, rolls)
        block_loads.append((k1, flank_states[0][2], k2, flank_states[1][2]))
        bare2 = ctx.gear_bare(k2, row)
        _chemical_bonds(out, ctx, setup, flank_states, bare2, row)
        inside, w_x, k1_at_x = _vdw_and_menisci(out, ctx, pressure, gap, info, zone, rolls, row)
        _interlocking_energy(out, ctx, (k1, k2), flank_states, kinematics["sliding_fraction"])
        for kind, (key, start) in enumerate(zip(_ROW_BOND_KEYS[coating is not None], before)):
            out["row_bonds"][kind, :, row] = out[key] - start
        if ctx.with_cohesive_zone:  # the attraction is the contact solve's tensile traction over the row
            out["f_adh"] += _attraction(pressure, gap, info, zone, ctx)
            continue
        out["f_adh"] += _block_pull_off(ctx, inside, w_x, k1_at_x)
    if pbar is not None:
        pbar.close()
    return out, block_loads, kinematics


def _attraction(pressure, gap, info, zone, ctx):
    """The attraction of the Maugis-Dugdale zone on one row per step [N] (MODEL 7c; issues #25, #28).

    Dry: the whole tensile traction of the solve, ``w_adh dx sum(max(-p, 0))``: the zones outside the contact and
    the contact's tensile edges, where the pressure is between -sigma0 and 0 (the closed form is
    :func:`memstribo.physics.closed_form.maugis_dugdale_line_tension`; tests/test_convergence.py). The zone outside
    the contact alone (the former measure) counts none of a grid element that holds the contact's edge, so on the
    default grid it missed nearly all of the attraction, and fell where the zone narrows. In humid air the menisci's
    traction acts in the same solve: the vdW zone outside the contact (the solve's ``adhesive_load``) and the vdW
    share sigma0 / (sigma0 + gamma / r_K) of the contact's tensile edges, where both tractions act in full (the
    solver's sigma-weighted cohesive fraction); the menisci's part of F_adh is the water bridges' pull-off
    (:func:`_menisci`).
    """
    if zone is not None:
        sigma0 = ctx.zone_work / ctx.zone_range
        heights = np.asarray(zone[1], dtype=float)  # h_c per step, or per step and element (a coated gear)
        laplace = np.where((heights[:, None] if heights.ndim == 1 else heights) > 0.0, zone[0], 0.0)
        edges = np.where(gap <= 0.0, np.maximum(-pressure, 0.0) * sigma0 / (sigma0 + laplace), 0.0)
        return (info[:, 4] + edges.sum(axis=1) * ctx.dx) * ctx.w_adh
    return np.maximum(-pressure, 0.0).sum(axis=1) * ctx.dx * ctx.w_adh


#: The totals whose change over a row gives that row's (chemical, bare-vdW, coated-vdW) bond counts, bare and coated.
_ROW_BOND_KEYS = {False: ("chem_bonds", "vdw_bonds", "_none"), True: ("chem_bonds", "vdw_bonds_bare",
                                                                      "vdw_bonds_coated")}

#: The per-step totals of a cycle, summed over the rows.
_TOTALS = ("chem_bonds", "vdw_bonds", "f_chem", "f_vdw", "e_el", "f_adh", "contact_width", "max_pressure",
           "unconverged", "residual", "iterations", "window_exceeded", "approach", "rigid_atomic_blocks", "vdw_edge",
           "f_cap", "f_cap_adh", "wetted", "f_chem_rigid", "f_vdw_capped", "f_vdw_over",
           "plastic_elements", "contact_elements", "f_cap_pull", "bridged", "f_cap_bridge", "bridged_perimeter",
           "vdw_bonds_bare", "vdw_bonds_coated",  # vdW bonds over bare / coated gear blocks (rescaling, issue 27)
           "_none")  # stays zero: an uncoated gear's coated-vdW bonds per row


def _kinematics(setup):
    """Radii of curvature, roll coordinates, surface speeds and sliding of each step (chapter 4)."""
    pair = setup.pair
    c = setup.positions
    r1, r2 = pair.radii_of_curvature(c)
    r_ef = r1 * r2 / (r1 + r2)
    s1 = roll_coordinate(r1, pair.base_radii[0])
    s2 = roll_coordinate(r2, pair.base_radii[1])
    u1, u2 = pair.surface_velocities(c)
    slip = u1 - u2
    sliding = np.abs(slip) * setup.step_time
    sliding_fraction = np.abs(slip) / (u1 + u2)
    return dict(r_ef=r_ef, s1=s1, s2=s2, u1=u1, u2=u2, slip=slip, sliding=sliding, sliding_fraction=sliding_fraction)


def _row_rolls(setup, kinematics, row):
    """(s1, s2, gear pitch scale) of a row: the roll coordinates less the row's lattice phases (MODEL 7d), so that
    block k of the row spans [k w_adh, (k + 1) w_adh) in them, and its gear lattice's stretch along the sliding."""
    registry = setup.registry
    if registry is None:
        return kinematics["s1"], kinematics["s2"], 1.0
    return (kinematics["s1"] - registry.pinion_phase[row], kinematics["s2"] - registry.gear_phase[row],
            float(registry.gear_pitch_scale[row]))


def _context(setup, params, coating, wear, modulus):
    """The constants of a cycle's step loop: lattice sizes, block stiffness, interface and humidity settings."""
    from memstribo.physics.nanoblock.geometry import adhesive_layer_thickness
    from memstribo.physics.nanoblock.mechanics import BlockStiffness

    ctx = SimpleNamespace(coating=coating, wear=wear, modulus=modulus, params=params)
    ctx.w_adh, ctx.w_at, ctx.m = params["adhesive_width"], params["atomic_width"], int(params["atomic_per_side"])
    ctx.pitch = params["atomic_pitch"]
    ctx.bond = params["bond_length"]
    # one vdW interaction (MODEL 7h): U_vdW by the rule, sites at the set's density (1 / D_chem^2 unless set)
    ctx.u_vdw, ctx.vdw_sites = vdw_bond_energy_of(params), vdw_site_density_of(params)
    ctx.dx = setup.grid_spacing
    ctx.grid = setup.grid
    ctx.half = 0.5 * ctx.grid.size * ctx.dx
    geometry = _geometry(params)
    ctx.stiffness = BlockStiffness.from_geometry(geometry, params["youngs_modulus"], modulus,
                                                 params["threshold_strain"])
    ctx.offsets = (np.arange(ctx.m) - 0.5 * (ctx.m - 1)) * ctx.pitch
    ctx.w_si = _work_of_adhesion(params)
    # thesis interface: one rule with the sliding models (3.5), for bare and coated blocks alike
    ctx.layer = adhesive_layer_thickness(params, geometry)
    ctx.gap_model = params["interface_model"] == "gap"
    ctx.with_cohesive_zone = params["contact_adhesion"] == "maugis"
    if ctx.with_cohesive_zone:  # the zone's reach h0 [m] and its work per area sigma0 h0 = w12 [J/m^2]
        sigma0, ctx.zone_range = _cohesive_zone(params)
        ctx.zone_work = sigma0 * ctx.zone_range
    if coating is not None:
        ctx.w_coat, ctx.u_vdw_coat = float(coating.work_of_adhesion), float(coating.vdw_bond_energy)
    ctx.c_ns = float(no_slip_coefficient(params["poisson_ratio"]))
    ctx.ideal_shear = float(params["ideal_shear_strength"])
    ctx.humid = params["environment"] == "air"
    if ctx.humid:
        from memstribo.physics.vapours import vapour_state

        # the vapour (water or pentanol) at the ambient temperature on the flanks' termination (issue #36): its
        # surface tension sets the Kelvin radius, the Laplace pressure and the rupture energy alike (docs/thermal.md;
        # water: 0.072 N/m exactly at 298.15 K); below one molecular diameter the condensate is an adsorbed film,
        # not a meniscus (MODEL 7g): r_K = 0, no Laplace traction, no bridge, no rupture
        state = vapour_state(params)
        ctx.surface_tension = state["surface_tension"]
        ctx.r_kelvin = state["kelvin"]
        ctx.theta_bare = state["contact_angle"]
        ctx.theta_coat = ctx.theta_bare
        if coating is not None:
            if state["vapour"] != "water":
                raise InputError(f"a coated gear in {state['vapour']} vapour: memstribo has the coatings' water "
                                 "contact angles only; use vapour = 'water' or no coating.")
            if math.isfinite(getattr(coating, "water_contact_angle_deg", math.nan)):
                ctx.theta_coat = math.radians(coating.water_contact_angle_deg)
        ctx.renewal = params["meniscus_renewal_distance"] or params["atomic_pitch"]
        # the liquid-like part of the adsorbed film on the flanks, from the termination's published isotherm (issues
        # #28, #36): the bound (ice-like) layers do not flow into a bridge, as in the microbeam and the flat case
        ctx.film = state["liquid_film"]

    def gear_bare(k, row):
        """Gear blocks bare (worn coating) or coated: a deterministic low-discrepancy choice."""
        if coating is None:
            return np.ones(k.shape, dtype=bool)
        return np.mod(k * _GOLDEN + row * _SILVER, 1.0) < wear

    ctx.gear_bare = gear_bare
    return ctx


def _surface_strip(setup, params, modulus, beta, kinematics, pbar):
    """The surface (3D) solve of all rows at once where ``mesh_contact = 'surface'``, else None."""
    if params["mesh_contact"] != "surface":
        return None
    if beta != 0.0 or params["contact_adhesion"] != "none":
        raise InputError("mesh_contact = 'surface' solves identical, non-adhesive teeth only (Dundurs beta 0 and "
                         "contact_adhesion = 'none': add --set contact_adhesion=none, since the default "
                         "Maugis-Dugdale zone is carried by the line solve only); use mesh_contact = 'line' for "
                         "the others.")
    return _solve_contacts_surface(setup, params, modulus, kinematics["r_ef"], kinematics["s1"], kinematics["s2"],
                                   pbar)


def _row_contact(setup, params, ctx, modulus, beta, mu_previous, kinematics, row, strip, pbar, warm_start):
    """(pressure [Pa], gap [m], solver info, capillary zone) of one roughness row at every step."""
    r_ef, s1, s2 = kinematics["r_ef"], kinematics["s1"], kinematics["s2"]
    zone = None
    if ctx.humid and strip is None:  # the menisci's Laplace pressure inside the contact solve (docs/humidity.md)
        zone = _capillary_zone(ctx.r_kelvin, ctx.theta_bare, ctx.theta_coat, _row_rolls(setup, kinematics, row)[1],
                               ctx.grid, ctx.w_adh, row, ctx.coating, ctx.wear, ctx.surface_tension)
    if strip is not None:
        strip_pressure, strip_gap, strip_info = strip
        return strip_pressure[row], strip_gap[row], strip_info[row], zone  # one solve for all rows
    if beta != 0.0 and mu_previous is not None:
        pressure, gap, info = _solve_with_shear(setup, params, modulus, r_ef, s1, s2, row, beta, mu_previous,
                                                kinematics["slip"], pbar, zone, warm_start)
    else:
        pressure, gap, info = _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, None, pbar, zone,
                                              warm_start)
    return pressure, gap, info, zone


def _record_solve(out, ctx, pressure, gap, info, n_rows_solved):
    """Add a row's solver state to the totals: window and vdW-reach checks, convergence, contact width."""
    grid, dx = ctx.grid, ctx.dx
    # window check: the contact must stay clear of the window's ends (5 % margin each side)
    edge = max(1, grid.size // 20)
    out["window_exceeded"] += (pressure[:, :edge].any(axis=1) | pressure[:, -edge:].any(axis=1))
    out["unconverged"] += info[:, 0] == 0
    out["residual"] = np.maximum(out["residual"], info[:, 1])
    out["iterations"] += info[:, 2] / n_rows_solved
    out["approach"] += info[:, 3] / n_rows_solved
    # vdW reach: with the gap model the attraction must have faded inside the window
    out["vdw_edge"] += (np.minimum(gap[:, 0], gap[:, -1]) < ctx.params["vdw_cutoff"]) if ctx.gap_model else 0
    # in contact: the gap closed under a non-zero pressure (with the Maugis-Dugdale zone the pressure is
    # tensile, down to -sigma0, near the contact's edges; the zone outside has an open gap)
    in_contact = ((gap <= 0.0) & (pressure != 0.0)).sum(axis=1)
    out["contact_width"] += in_contact * dx / n_rows_solved
    # the surface solve counts its elements in contact on its own grid (eighth column): the share of them at the
    # hardness is the plastic fraction (the row's mean gap and pressure see contact only where all its element
    # rows touch)
    out["contact_elements"] += info[:, 7] if info.shape[1] > 7 else in_contact
    if info.shape[1] > 6:  # elements at the hardness (the pressure cap of the line or surface solve, MODEL 7d)
        out["plastic_elements"] += info[:, 6]
    out["max_pressure"] = np.maximum(out["max_pressure"], pressure.max(axis=1))


def _flank_blocks(out, ctx, pressure, gap, rolls):
    """The nanoblock lattices of both flanks on a row's contact: (k1, k2, per flank (x_blocks, x_atoms, loads,
    atomic force, atomic compression, adhesive compression, rigid mask)) by the fixed-load structure model (3.4.2).
    ``rolls``: the row's (s1, s2, gear pitch scale) in its lattice registry (:func:`_row_rolls`)."""
    from memstribo.physics.nanoblock.mechanics import structure_fixed_load

    n_steps = pressure.shape[0]
    grid, dx, w_adh, m = ctx.grid, ctx.dx, ctx.w_adh, ctx.m
    cumulative = np.concatenate([np.zeros((n_steps, 1)), np.cumsum(pressure, axis=1) * dx], axis=1)
    edges_x = np.concatenate([grid - 0.5 * dx, [grid[-1] + 0.5 * dx]])

    def footprint_loads(centres):
        """w_adh * integral of p over [x - w_adh/2, x + w_adh/2] for the x (steps, slots) of each of ``centres``."""
        ends = [np.clip(end, edges_x[0], edges_x[-1]) for x in centres for end in (x + 0.5 * w_adh, x - 0.5 * w_adh)]
        # every flank's ends in one interpolation (the rows of each step alike)
        f = np.split(_interp_rows(np.concatenate(ends, axis=1), edges_x, cumulative, cumulative[:, 0],
                                  cumulative[:, -1]), np.cumsum([x.shape[1] for x in ends])[:-1], axis=1)
        return [w_adh * (f[2 * i] - f[2 * i + 1]) for i in range(len(centres))]

    def local_gaps(points):
        """Deformed gap at each of ``points`` (steps, slots, ...) [m]; far outside the window: effectively no
        contact."""
        values = _interp_rows(np.concatenate(points, axis=1), grid, gap, 1.0, 1.0)
        return np.split(values, np.cumsum([x.shape[1] for x in points])[:-1], axis=1)

    # lattices: pinion block k centred at sigma = (k + 1/2) w_adh -> x = s1 - sigma; gear: x = sigma - s2
    s1, s2, scale = rolls
    k1 = _lattice(s1, w_adh, ctx.half)
    k2 = _lattice(s2, w_adh, ctx.half)
    x1 = s1[:, None] - (k1 + 0.5) * w_adh
    x2 = (k2 + 0.5) * w_adh - s2[:, None]
    # pinion: sigma increases -> x decreases; symmetric offsets; the gear's pitch stretched by its turn
    atoms = [x_blocks[..., None] - ctx.offsets * stretch for x_blocks, stretch in ((x1, 1.0), (x2, scale))]
    flank_states = []
    for x_blocks, x_atoms, loads, gaps in zip((x1, x2), atoms, footprint_loads((x1, x2)), local_gaps(atoms)):
        overlap_row = -gaps  # (steps, slots, m)
        overlap = np.repeat(overlap_row, m, axis=-1)  # m x m atomic blocks, rows across the width alike
        loaded = loads > 0
        atomic_force = np.zeros(overlap.shape)
        atomic_comp = np.zeros(overlap.shape)
        adhesive_comp = np.zeros(loads.shape)
        rigid_mask = np.zeros(overlap.shape, dtype=bool)
        if loaded.any():
            state = structure_fixed_load(overlap[loaded][:, None, :], ctx.stiffness, loads[loaded])
            atomic_force[loaded] = state.atomic_force[:, 0, :]
            atomic_comp[loaded] = state.atomic_compression[:, 0, :]
            adhesive_comp[loaded] = state.adhesive_compression[:, 0]
            rigid_mask[loaded] = np.asarray(state.rigid).reshape(int(loaded.sum()), -1)
            out["rigid_atomic_blocks"] += rigid_mask.sum(axis=(1, 2))
        flank_states.append((x_blocks, x_atoms, loads, atomic_force, atomic_comp, adhesive_comp, rigid_mask))
    return k1, k2, flank_states


def _interp_rows(x, xp, fp, left, right):
    """``np.interp(x[i], xp, fp[i], left[i], right[i])`` of every row i at once [units of fp], value for value.

    ``x`` (rows, ...), ``xp`` (N,) increasing, ``fp`` (rows, N); ``left``, ``right``: a number or one per row. The
    rows of a cycle's step loop (481 steps: ~10^5 calls of np.interp per refined cycle) in a few array operations,
    each value by numpy's own rule (``arr_interp`` in numpy/_core/src/multiarray/compiled_base.c): fp[j] where
    x = xp[j] (j = N - 1 included), else ``slope (x - xp[j]) + fp[j]`` with ``slope = (fp[j+1] - fp[j]) / (xp[j+1] -
    xp[j])`` for xp[j] < x < xp[j+1]; ``left`` below xp[0], ``right`` above xp[N - 1], NaN at NaN. (Where that
    formula gives NaN numpy tries another: such rows are handed to np.interp.)
    """
    rows, n = fp.shape[0], xp.size
    flat = x.reshape(rows, -1)
    j = _bracket(xp, flat)  # xp[j] <= x < xp[j + 1]; N - 1 at x >= xp[N - 1] and NaN
    inner = np.clip(j, 0, n - 2)
    at = inner + (np.arange(rows) * n)[:, None]  # into fp's rows, flattened
    table = np.ravel(fp)
    f0, f1 = table.take(at), table.take(at + 1)
    x0 = xp.take(inner)
    with np.errstate(invalid="ignore"):  # inf - inf: the rows handed to np.interp below
        values = (f1 - f0) / (xp.take(inner + 1) - x0) * (flat - x0) + f0
    np.copyto(values, f0, where=flat == x0)
    high = j >= n - 1
    if high.any():
        np.copyto(values, f1, where=high)  # x = xp[N - 1]: fp[N - 1] (f1 there)
        np.copyto(values, np.reshape(right, (-1, 1)), where=flat > xp[-1])
        np.copyto(values, flat, where=np.isnan(flat))
    low = j < 0
    if low.any():
        np.copyto(values, np.reshape(left, (-1, 1)), where=low)
    odd = np.isnan(values)
    if odd.any():  # numpy's second try where the formula gave NaN: np.interp itself
        left, right = np.broadcast_to(np.reshape(left, -1), (rows,)), np.broadcast_to(np.reshape(right, -1), (rows,))
        for i in np.flatnonzero((odd & ~np.isnan(flat)).any(axis=1)):
            values[i] = np.interp(flat[i], xp, fp[i], left[i], right[i])
    return values.reshape(x.shape)


def _bracket(xp, x):
    """``np.searchsorted(xp, x, side="right") - 1`` [-]: the j with xp[j] <= x < xp[j + 1] (-1 below xp[0], N - 1 from
    xp[N - 1] on and at NaN), for an increasing ``xp`` of N >= 2 points. On a uniform grid (the cycle's) from the
    index x / spacing, corrected by comparing with xp itself until exact (a step or two; binary searches of 10^4
    unsorted points cost ~50 ns each); elsewhere by np.searchsorted."""
    n = xp.size
    with np.errstate(invalid="ignore"):
        guess = np.floor((x - xp[0]) * ((n - 1) / (xp[-1] - xp[0])))
    j = np.fmin(np.fmax(guess, -1.0), n - 1.0).astype(np.intp)  # NaN -> -1, set below
    for _ in range(4):
        down = xp.take(np.maximum(j, 0)) > x
        down &= j >= 0
        up = xp.take(np.minimum(j + 1, n - 1)) <= x
        up &= j < n - 1
        if not (down.any() or up.any()):
            np.copyto(j, n - 1, where=np.isnan(x))
            return j
        j -= down
        j += up
    return np.searchsorted(xp, x, side="right") - 1


def _chemical_bonds(out, ctx, setup, flank_states, bare2, row):
    """Chemical bonds (3-10) and their friction force (3-1) of a row: overlaps of touching opposing atomic blocks
    along x (sliding) times their overlap across the face width, where the gear's lattice sits at a random offset."""
    # the published relations, looked up on their modules at call time: a change to a relation
    # changes the meshing cycle (tests/test_mesh.py::test_the_cycle_calls_the_published_relations)
    from memstribo.physics import friction

    m, w_at, bond = ctx.m, ctx.w_at, ctx.bond
    n_steps = flank_states[0][1].shape[0]
    across = lattice_overlap_across(w_at, ctx.pitch, m, ctx.w_adh, setup.row_roughness.lattice_offsets[row])
    touch1 = flank_states[0][3][..., :m] > 0  # first row of the m x m array (rows alike)
    touch2 = (flank_states[1][3][..., :m] > 0) & bare2[..., None]
    xa1 = flank_states[0][1].reshape(n_steps, -1)
    xa2 = flank_states[1][1].reshape(n_steps, -1)
    t1 = touch1.reshape(n_steps, -1)
    t2 = touch2.reshape(n_steps, -1)
    rigid1 = flank_states[0][6][..., :m].reshape(n_steps, -1)
    rigid2 = flank_states[1][6][..., :m].reshape(n_steps, -1)
    overlap_sum, rigid_sum = _pair_overlaps(ctx, xa1, xa2, t1, t2, rigid1, rigid2, w_at)
    chem = friction.chemical_bond_count(across, overlap_sum, bond)  # (3-10)
    out["chem_bonds"] += chem
    # all bonds break once per bond length of sliding (3.5): the force is that energy per bond length (3-1)
    out["f_chem"] += friction.friction_force(friction.bond_breaking_energy(chem, ctx.params["bond_energy"], bond, bond),
                                             bond)
    # local limits (MODEL 7d): the bonds of pairs of which one atomic block is past the threshold strain
    rigid_bonds = friction.chemical_bond_count(across, rigid_sum, bond)
    out["f_chem_rigid"] += friction.friction_force(
        friction.bond_breaking_energy(rigid_bonds, ctx.params["bond_energy"], bond, bond), bond)


def _pair_overlaps(ctx, xa1, xa2, t1, t2, rigid1, rigid2, w_at):
    """Per step, the summed overlap [m] of the pairs of touching opposing atomic blocks, all pairs and those with a
    block past the threshold strain: sum over i, j of clip(w_at - |x1_i - x2_j|, 0) t1_i t2_j (and (r1_i | r2_j)).

    ``xa1``, ``t1``, ``rigid1``: the pinion's atomic blocks (steps, A), positions [m], touching, rigid; ``xa2``, ...
    the gear's (steps, B). Each step's A x B terms are summed as one array (numpy's pairwise sum, the order the
    numbers were always summed in); only the rows of the pinion's touching blocks (a fifth) are computed, written
    into a zero array kept on ``ctx`` for the cycle's rows (10^6 terms a row of a default cycle) and zeroed again.
    """
    shape = (xa1.shape[0], xa1.shape[1], xa2.shape[1])
    pairs = getattr(ctx, "pair_terms", None)
    if pairs is None or pairs.shape != shape:
        pairs = ctx.pair_terms = np.zeros(shape)
    steps, blocks = np.nonzero(t1)
    terms = np.subtract(xa1[steps, blocks][:, None], xa2[steps])  # clip(w_at - |x1 - x2|, 0) t2
    np.abs(terms, out=terms)
    np.subtract(w_at, terms, out=terms)
    np.maximum(terms, 0.0, out=terms)
    np.multiply(terms, t2[steps], out=terms)
    pairs[steps, blocks] = terms
    overlap = pairs.sum(axis=(1, 2))
    np.multiply(terms, rigid1[steps, blocks][:, None] | rigid2[steps], out=terms)
    pairs[steps, blocks] = terms
    rigid = pairs.sum(axis=(1, 2))
    pairs[steps, blocks] = 0.0
    return overlap, rigid


def _vdw_and_menisci(out, ctx, pressure, gap, info, zone, rolls, row):
    """vdW bonds (3-12) over the adhesive layer and, in humid air, the menisci of a row; returns (the share of each
    element inside the layer, w12 at each element [J/m^2], the pinion block at each element) for the pull-off.
    ``rolls``: the row's roll coordinates in its lattice registry (:func:`_row_rolls`)."""
    from memstribo.physics import friction

    params, grid, dx, w_adh, bond = ctx.params, ctx.grid, ctx.dx, ctx.w_adh, ctx.bond
    coating = ctx.coating
    k1_at_x = np.floor((rolls[0][:, None] - grid[None, :]) / w_adh).astype(int)  # pinion block per element
    k2_at_x = np.floor((rolls[1][:, None] + grid[None, :]) / w_adh).astype(int)
    bare_x = ctx.gear_bare(k2_at_x, row)
    # vdW: the share of a block's contact energy at the local gap (MODEL 7c), or the thesis's band
    inside = vdw_gap_factor(gap, params["cutoff_distance"], params["vdw_cutoff"]) if ctx.gap_model \
        else (gap <= ctx.layer).astype(float)
    u_vdw_x = np.where(bare_x, ctx.u_vdw, ctx.u_vdw_coat) if coating is not None else ctx.u_vdw
    w_x = np.where(bare_x, ctx.w_si, ctx.w_coat) if coating is not None else ctx.w_si
    n_vdw = friction.vdw_bond_count(w_adh, dx, bond, ctx.vdw_sites) * inside  # (3-12), bonds per element
    out["vdw_bonds"] += n_vdw.sum(axis=1)
    if coating is not None:
        out["vdw_bonds_bare"] += np.where(bare_x, n_vdw, 0.0).sum(axis=1)
        out["vdw_bonds_coated"] += np.where(bare_x, 0.0, n_vdw).sum(axis=1)
    per_element = friction.friction_force(friction.bond_breaking_energy(n_vdw, u_vdw_x, bond, bond), bond)
    out["f_vdw"] += per_element.sum(axis=1)
    # local limits (MODEL 7d): an element's bonds transmit at most the ideal shear strength over its area
    strongest = ctx.ideal_shear * w_adh * dx
    out["f_vdw_capped"] += np.minimum(per_element, strongest).sum(axis=1)
    out["f_vdw_over"] += np.where(per_element > strongest, per_element, 0.0).sum(axis=1)
    if ctx.humid:  # capillary menisci where the gap is below the condensation height (docs/humidity.md)
        _menisci(out, ctx, gap, info, zone, bare_x, k1_at_x, _vdw_work_in_f_adh(ctx, pressure, gap, inside, w_x))
    return inside, w_x, k1_at_x


def _vdw_work_in_f_adh(ctx, pressure, gap, inside, w_x):
    """The vdW work of adhesion [J/m^2] that the vdW part of F_adh counts at each element of a row (steps, n).

    With the Maugis-Dugdale zone (the default) F_adh's vdW part is the zone's tensile traction (:func:`_attraction`):
    on the elements outside the contact with 0 < gap <= h0 and on the contact's tensile edges, whose work per area is
    sigma0 h0 = w12; with the thesis's block pull-off (contact_adhesion 'none') it is w12 times each element's share
    ``inside`` (3-32 over the engaged length). The water bridges add only their work beyond this (:func:`_menisci`,
    docs/humidity.md).
    """
    if ctx.with_cohesive_zone:
        acting = ((gap > 0.0) & (gap <= ctx.zone_range)) | ((gap <= 0.0) & (pressure < 0.0))
        return np.where(acting, ctx.zone_work, 0.0)
    return w_x * inside


def _menisci(out, ctx, gap, info, zone, bare_x, k1_at_x, w_vdw):
    """Wetted area, meniscus attraction, rupture force and pull-off of a row (issues #17, #28; docs/humidity.md).

    ``w_vdw``: the vdW work of adhesion [J/m^2] that F_adh's vdW part counts at each element
    (:func:`_vdw_work_in_f_adh`): the bridges' part of F_adh counts, per element, only the bridge's work beyond it
    (``f_cap_bridge``)."""
    from memstribo.physics import capillary

    theta_bare, theta_coat = ctx.theta_bare, ctx.theta_coat
    theta_gear = np.where(bare_x, theta_bare, theta_coat) if ctx.coating is not None else theta_bare
    height = capillary.condensation_height(ctx.r_kelvin, theta_bare, theta_gear)
    wet = (gap <= height) & (height > 0)
    area = wet * (ctx.w_adh * ctx.dx)
    out["wetted"] += area.sum(axis=1)
    # attraction: the contact solve's meniscus line load over the row (line contact), else the wetted area's
    out["f_cap_adh"] += (info[:, 5] * ctx.w_adh if zone is not None
                         else capillary.laplace_pressure(ctx.r_kelvin, ctx.surface_tension) * area.sum(axis=1))
    # the water bridges span every gap of the rough row narrower than h_c + the adsorbed films (issue #28)
    # (the isotherm is the hydrophilic oxide's: a hydrophobic coating, theta >= 90 deg, carries no film)
    films = (np.where(theta_bare < 0.5 * np.pi, ctx.film, 0.0)
             + np.where(np.asarray(theta_gear) < 0.5 * np.pi, ctx.film, 0.0))
    bridge = np.where(height > 0, height + films, 0.0)  # capillary.bridging_height, per gear element
    work = capillary.meniscus_work_of_separation(gap, ctx.r_kelvin, bridge, films, ctx.surface_tension)
    bridged = work > 0
    out["bridged"] += bridged.sum(axis=1) * (ctx.w_adh * ctx.dx)
    # the force to pull the flanks apart against the water bridges (issue #36, MODEL 7g): each pinion block pulls
    # with the smaller of its elastic pull-off (3-32, the bridges' work) and the meniscus bound, the Laplace
    # pressure over its bridged area plus gamma on its contact lines (capillary.bounded_pull_off), summed (3-31)
    ends = _meniscus_ends(bridged)
    out["bridged_perimeter"] += ends.sum(axis=1) * ctx.w_adh
    out["f_cap_pull"] += _block_pull_off(ctx, bridged.astype(float), np.where(bridged, work, 1.0), k1_at_x,
                                         (bridged, ends))
    # the bridges' part of F_adh: one adhesive traction per element, the larger of the vdW's and the bridge's
    # (a wetted contact's work of separation is the solids' own, 2 gamma_SV = W_SLS + 2 gamma cos theta by Young's
    # equation, Israelachvili 2011 ch. 17: not the dry work plus the bridge's); where F_adh's vdW part acts with the
    # larger work the bridge adds nothing, elsewhere its pull-off, bounded as above
    excess = np.maximum(work - w_vdw, 0.0)
    adds = excess > 0
    out["f_cap_bridge"] += _block_pull_off(ctx, adds.astype(float), np.where(adds, excess, 1.0), k1_at_x,
                                           (adds, np.where(adds, ends, 0)))
    # the meniscus's rupture energy gamma (cos theta_1 + cos theta_2) per wetted area, once per renewal
    rupture = ctx.surface_tension * (np.cos(theta_bare) + np.cos(theta_gear))
    out["f_cap"] += (area * rupture).sum(axis=1) / ctx.renewal


def _interlocking_energy(out, ctx, lattices, flank_states, sliding_fraction):
    """Elastic interlocking (3-25) on material blocks, both flanks, times the sliding fraction."""
    from memstribo.physics.nanoblock import mechanics

    e_el = np.zeros(sliding_fraction.size)
    for (k, (_, _, _, _, comp_at, comp_adh, _)) in zip(lattices, flank_states):
        e_el += _interlocking(k, comp_at, comp_adh, ctx.stiffness, mechanics.elastic_interlocking_energy)
    out["e_el"] += e_el * sliding_fraction


def _block_pull_off(ctx, inside, w_x, k1_at_x, meniscus=None):
    """Adhesion force (3-31) of a row from the pull-off (3-32) of each pinion block: a = half its engaged length,
    w12 averaged over it.

    ``meniscus`` (water bridges, MODEL 7g): (wetted elements, contact-line ends per element) of the bridges; each
    block's pull-off is then :func:`memstribo.physics.capillary.bounded_pull_off`, the smaller of (3-32) and the
    Laplace pressure over the block's wetted area plus gamma w_adh per contact-line end in it (the row's wetted runs
    end in lines across the block width)."""
    from memstribo.physics import adhesion, capillary, friction

    n_steps = inside.shape[0]
    dx, w_adh = ctx.dx, ctx.w_adh
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
        pull_off[engaged] = adhesion.pull_off_force(work[engaged], ctx.modulus, ctx.c_ns, a[engaged])  # (3-32)
    if meniscus is not None:
        wet, ends = meniscus
        area = np.bincount(flat, weights=(wet * (dx * w_adh)).ravel(), minlength=n_steps * n_keys)
        perimeter = np.bincount(flat, weights=(ends * w_adh).ravel(), minlength=n_steps * n_keys)
        pull_off = capillary.bounded_pull_off(pull_off, area.reshape(n_steps, n_keys),
                                              perimeter.reshape(n_steps, n_keys), ctx.r_kelvin, ctx.surface_tension)
    return friction.adhesion_force(pull_off, axis=1)  # (3-31)


def _meniscus_ends(wet):
    """Contact-line ends of the wetted runs of a row (steps, n) [-]: per element, 1 where a run starts, 1 where it
    ends (2 for a run of one element). A run reaching the window's end is closed there (an upper bound)."""
    before = np.concatenate([np.zeros((wet.shape[0], 1), dtype=bool), wet[:, :-1]], axis=1)
    after = np.concatenate([wet[:, 1:], np.zeros((wet.shape[0], 1), dtype=bool)], axis=1)
    return (wet & ~before).astype(int) + (wet & ~after).astype(int)
