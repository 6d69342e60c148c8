"""The rough contact of each step: the line (or surface) solve of every row, with the Maugis-Dugdale zone, the
menisci of humid air and, for dissimilar materials, the normal-gap change of the friction traction."""

from __future__ import annotations

import dataclasses

import numpy as np

from memstribo.simulations.mesh.interface import _GOLDEN, _SILVER
from memstribo.simulations.mesh.setup import _heights


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


# With the Maugis-Dugdale zone a step's contact can have two states (an asperity adhered or not). Each step's solve
# starts from the previous step's contact set (on grids past SolverSettings.loading_start_max from none: issue 40),
# but its zone starts empty: the state is the loading-branch state
# (the one reached from the non-adhesive contact at the same load), whatever state the step before was in. Following
# the states from step to step made the verdict depend on the step size: the roughness moves by about two grid
# elements per step at 481 steps, and the default margin fell by 7.6 % (realisation 1: 13.6 %) over four times the
# steps; with the loading branch it changes by at most 2.8 % (issue #25, docs/interface.md).
def _loading_branch():
    """The contact solver's settings (read now: tests may swap them) with ``cohesive_start = "loading"``."""
    from memstribo.physics.contact import settings

    return dataclasses.replace(settings.DEFAULTS, cohesive_start="loading")


def _solve_contacts(setup, params, modulus, r_ef, s1, s2, row, shear_term, pbar, capillary=None, warm_start=None):
    """Rough contact of every step of one row: pressure, deformed gap, solver info, cohesive line load.

    ``capillary``: (Laplace pressure [Pa], condensation height per step and element [m], shape
    (steps, n)) of the menisci in humid air, a second Dugdale-type traction inside the solve
    (:func:`memstribo.physics.contact.solve_line_contact`, docs/humidity.md); the sixth info column is
    then the menisci's line load [N/m], the seventh the elements at the hardness (pressure capped where
    ``hardness`` is set, :func:`memstribo.physics.contact.solve_line_contact_capped`). ``warm_start``: a dict
    of each row's pressures (steps, n) of a previous cycle, the initial pressure of each step's solve where
    present (:func:`simulate_mesh`); this row's pressures are stored in it.
    """
    from memstribo.physics.contact import solve_line_contact, solve_line_contact_capped

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
    # converged, residual, iterations, approach, cohesive line load, capillary line load, plastic elements
    info = np.zeros((n_steps, 7))
    sigma0, h0 = _cohesive_zone(params)
    hardness = params["hardness"]
    adhesive = {} if sigma0 is None else {"cohesive_stress": sigma0, "cohesive_range": h0,
                                          "settings": _loading_branch()}
    previous = None
    start = None
    stress = (sigma0 or 0.0) + (capillary[0] if capillary is not None else 0.0)  # the tensile traction's limit
    key = None
    if warm_start is None:  # a cold start: the same inputs give the same solve (solve_cache, issue 40)
        from memstribo.physics.contact import settings
        from memstribo.simulations.mesh.solve_cache import lookup, solve_digest

        key = solve_digest([separation, np.asarray(line_load, dtype=float)]
                           + ([np.asarray(capillary[1], dtype=float)] if capillary is not None else []),
                           (float(dx), float(modulus), params["mesh_contact_tolerance"], sigma0, h0, hardness,
                            None if capillary is None else float(capillary[0]), repr(settings.DEFAULTS)))
        kept = lookup(key)
        if kept is not None:
            if pbar is not None:
                pbar.update(n_steps)
            return kept
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
        if hardness is not None and solution.pressure.max() > hardness:  # plastic flow (MODEL 7d)
            capped = solve_line_contact_capped(separation[i], dx, modulus, hardness=hardness, load=line_load[i],
                                               tolerance=params["mesh_contact_tolerance"], elastic=solution,
                                               initial_pressure=previous, **adhesive)
            solution = capped.solution
            info[i, 6] = np.count_nonzero(capped.plastic)
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
    if key is not None:
        from memstribo.simulations.mesh.solve_cache import store

        store(key, (pressure, gap, info))
    return pressure, gap, info


def _solve_contacts_surface(setup, params, modulus, r_ef, s1, s2, pbar):
    """The strip of the face width under the window as one surface (3D) contact per step (rows interact).

    Each nanoblock row is ``k = round(w_adh / dx)`` element rows wide across the face width and
    carries its own roughness line (the same line over its k element rows); the free-boundary
    half-space solve (:func:`memstribo.physics.surface_contact.solve_surface_contact`) carries the pair's
    whole load, with the pressure capped at ``hardness`` where it is set (elastic-perfectly-plastic, as the line
    solve's :func:`memstribo.physics.contact.solve_line_contact_capped`; MODEL 7d). Returns per-row pressure and
    gap (means over each row's element rows), shapes (rows, steps, n), and the solver info per row and step,
    shape (rows, steps, 8), in the columns of :func:`_solve_contacts` (converged, residual, iterations,
    approach, 0, 0, the row's elements at the hardness) and an eighth, the row's elements in contact; the last two
    counted on the surface grid, its element rows' elements over k (the contact of the row's mean gap and
    pressure counts an element only where all k element rows touch, and would overstate the plastic share).
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
    info = np.zeros((rows, n_steps, 8))
    hardness = params["hardness"]
    previous = None
    for i in range(n_steps):
        separation = np.repeat(lines[:, i, :], k, axis=0)  # (rows * k, n)
        solution = solve_surface_contact(separation, dx, dy, modulus, load=float(setup.load[i]), periodic=False,
                                         tolerance=params["mesh_contact_tolerance"], initial_pressure=previous,
                                         hardness=hardness)
        field_p = solution.pressure.reshape(rows, k, n)
        field_g = solution.gap.reshape(rows, k, n)
        pressure[:, i, :] = field_p.mean(axis=1)
        gap[:, i, :] = field_g.mean(axis=1)
        info[:, i, :4] = (solution.converged, solution.residual, solution.iterations, solution.approach)
        info[:, i, 7] = solution.contact.reshape(rows, k, n).sum(axis=(1, 2)) / k
        if solution.plastic is not None:  # elements at the hardness, per row in units of the row's elements
            info[:, i, 6] = solution.plastic.reshape(rows, k, n).sum(axis=(1, 2)) / k
        previous = solution.pressure if solution.converged and np.any(solution.pressure > 0) else None
        if pbar is not None:
            pbar.update(rows)
    return pressure, gap, info


def _capillary_zone(r_kelvin, theta_bare, theta_coat, s2, grid, w_adh, row, coating, wear, surface_tension=None):
    """(Laplace pressure gamma / r_K [Pa], h_c [m] per step, or per step and element) of a row's menisci, or None.

    The traction of the menisci inside the line-contact solve (issue #17, docs/humidity.md;
    :mod:`memstribo.physics.capillary`): h_c = r_K (cos theta_1 + cos theta_2) with the pinion bare and
    each gear block bare or coated (the same low-discrepancy choice as the cycle's). None when
    no meniscus forms (dry air, a hydrophobic pair).
    """
    from memstribo.physics import capillary

    gamma = capillary.WATER["surface_tension"] if surface_tension is None else surface_tension
    stress = float(capillary.laplace_pressure(r_kelvin, gamma))
    if coating is None:  # one height per step (a number: the plain Maugis-Dugdale iteration of the solver)
        height = float(capillary.condensation_height(r_kelvin, theta_bare))
        return (stress, np.full(s2.size, height)) if stress > 0.0 and height > 0.0 else None
    k2_at_x = np.floor((s2[:, None] + grid[None, :]) / w_adh).astype(int)
    bare = np.mod(k2_at_x * _GOLDEN + row * _SILVER, 1.0) < wear
    heights = capillary.condensation_height(r_kelvin, theta_bare, np.where(bare, theta_bare, theta_coat))
    if stress == 0.0 or not np.any(heights > 0):
        return None
    return stress, heights


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
