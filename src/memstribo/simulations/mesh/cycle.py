"""One meshing cycle, top-down: set-up, the step loop (with the friction fixed point), the verdict, the dataset."""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError
from memstribo.materials.pair import contact_modulus_of, dundurs_beta
from memstribo.references import cites
from memstribo.simulations.mesh.record import cycle_dataset
from memstribo.simulations.mesh.setup import _prepare
from memstribo.simulations.mesh.steps import _run_cycle
from memstribo.simulations.mesh.limits import apply_limits
from memstribo.simulations.mesh.verdict import compare_cycles, cycle_verdict, summarize
from memstribo.simulations.tooth_life import with_tooth_life


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
        Over ``step`` with coordinates ``c`` and ``position`` (the position along the line of action [m]):
        ``friction_force`` (averaged over the sliding distance ``friction_averaging_distance``),
        ``friction_force_instantaneous``, ``resisting_force`` R(c) (all pairs in mesh), ``stiction_margin``
        F_t - R(c), ``mesh_efficiency``, ``adhesion_force``, ``normal_force``, ``cof`` and its split,
        energies by mechanism, ``block_load`` (``step``, ``block``) and more; each variable with
        ``units`` and ``long_name``. Attributes record the load case, interface model, contact
        adhesion, roughness rows, the F_t/F_f iteration and ``warnings`` (JSON list of text).

    Raises
    ------
    InputError
        A pair that cannot mesh, a load beyond the elastic range (Hertz peak pressure above
        ``elastic_limit_pressure``), a wear fraction outside [0, 1], a problem too large for memory.
    """
    if not 0.0 <= float(wear) <= 1.0:
        raise InputError(f"wear (the worn fraction Omega of the gear's coating) must be within 0..1, got {wear!r}.")
    modulus = contact_modulus_of(params)
    beta = dundurs_beta(params["youngs_modulus"], params["poisson_ratio"], params["counter_youngs_modulus"],
                        params["counter_poisson_ratio"])
    setup = _prepare(params, roughness, steps, realisation, sliding_axis)           # set-up: geometry, rows, lines
    setup, cycle = _sized_cycle(setup, params, roughness, steps, realisation, sliding_axis,  # the steps, in a
                                coating, wear, modulus, beta, progress, warm_start)         # window that holds them
    verdict = cycle_verdict(params, setup, cycle)                                   # forces, margin, efficiency
    apply_limits(params, setup, cycle, verdict, coating)                            # start-up, local limits
    dataset = cycle_dataset(params, setup, cycle, verdict, modulus, beta, coating, wear, realisation, sliding_axis)
    dataset = _with_the_elastic_margins(dataset, params, roughness, steps, coating, wear, realisation, sliding_axis)
    dataset = with_tooth_life(dataset, params, coating)                             # root stress, temperature
    return _with_fitted_constants(dataset, params, coating)                         # what was fitted, and where


#: The window grows by this factor when the contact or the vdW range reaches its ends, at most _WINDOW_GROWTHS times.
_WINDOW_GROWTH = 1.6
_WINDOW_GROWTHS = 5


def _sized_cycle(setup, params, roughness, steps, realisation, sliding_axis, coating, wear, modulus, beta, progress,
                 warm_start):
    """(set-up, cycle) in a window that holds the contact and the vdW range at every step (MODEL 7d).

    Unless ``mesh_window`` is set, a cycle whose contact reached the ends of its window (5 % margin) or whose gap at
    the ends is inside ``vdw_cutoff`` (interface model 'gap') is run again in a window 1.6 times longer (the same grid
    spacing and roughness lines), up to 5 times or until the memory bound (``check_mesh_size``) stops it; what
    remains is warned about.
    """
    for _ in range(_WINDOW_GROWTHS + 1):
        cycle = _friction_fixed_point(setup, params, coating, wear, modulus, beta, progress, warm_start)
        out = cycle["out"]
        short = (out["window_exceeded"] > 0).any() or (params["interface_model"] == "gap"
                                                        and (out["vdw_edge"] > 0).any())
        if params["mesh_window"] is not None or not short:
            break
        try:
            setup = _prepare(params, roughness, steps, realisation, sliding_axis, lines=setup.row_roughness,
                             window=_WINDOW_GROWTH * setup.grid.size * setup.grid_spacing)
        except InputError:  # no memory for a longer window: the warnings say so
            break
    return setup, cycle


def _with_the_elastic_margins(dataset, params, roughness, steps, coating, wear, realisation, sliding_axis):
    """The margins and COF of the same cycle without the hardness cap (attributes ``*_uncapped``), solved again
    purely elastically where some element reached the hardness, and one sentence on the plastic flow (MODEL 7d)."""
    import json

    summary = summarize(dataset)
    elastic = summary
    if dataset.attrs["plastic_elements"] > 0:
        elastic = summarize(simulate_mesh(params.updated({"hardness": None}, origin="the margin without the cap"),
                                          roughness, steps=steps, coating=coating, wear=wear, realisation=realisation,
                                          sliding_axis=sliding_axis))
        warnings = json.loads(dataset.attrs["warnings"])
        warnings.append(
            f"the rough contact reaches the hardness of silicon ({params['hardness'] / 1e9:.3g} GPa) in "
            f"{summary['plastic_steps']} of {summary['steps']} steps: {100 * summary['plastic_fraction']:.3g} % of the "
            f"contact over the cycle flows plastically (up to {100 * summary['plastic_fraction_max']:.3g} % in a step; "
            f"pressure capped, elastic-perfectly-plastic); the stiction margin is "
            f"{summary['stiction_margin'] * 1e6:.4g} µN with the cap and {elastic['stiction_margin'] * 1e6:.4g} µN "
            f"purely elastic, the start-up margin {summary['startup_margin'] * 1e6:.4g} µN and "
            f"{elastic['startup_margin'] * 1e6:.4g} µN")
        dataset.attrs["warnings"] = json.dumps(warnings)
    dataset.attrs["stiction_margin_uncapped"] = elastic["stiction_margin"]
    dataset.attrs["startup_margin_uncapped"] = elastic["startup_margin"]
    dataset.attrs["cof_mean_uncapped"] = elastic["cof_mean"]
    return dataset


def _with_fitted_constants(dataset, params, coating):
    """The fitted constants the cycle used (attribute ``fitted_constants``, JSON) and a warning for each whose fit
    conditions are far from this cycle's (another normal force, environment or humidity; issue #28)."""
    import json

    from memstribo.parameters.fitted import fit_condition_warnings, fitted_constants

    dataset.attrs["fitted_constants"] = json.dumps(fitted_constants(params, coating))
    far = fit_condition_warnings(params, float(dataset.attrs["normal_force_total"]), coating)
    if far:
        dataset.attrs["warnings"] = json.dumps(json.loads(dataset.attrs.get("warnings", "[]")) + far)
    return dataset


#: Largest change of the stiction margin (of |margin|) and of the mean COF (of itself) between two passes of the
#: friction fixed point of dissimilar teeth that counts as settled: a quarter of the 2 % of the step and grid checks
#: (issue #25). Not tighter: the passes' margin scatters by about +-0.5 % however many passes run (each pass starts
#: from the last one's contact sets, and single steps' contacts flip between states; 20 GPa counter body, 48 elements
#: across 2a: 0.3-1.3 % between passes 3 to 30), so 1e-3 was met or not by chance.
FIXED_POINT_TOLERANCE = 5e-3


def _friction_fixed_point(setup, params, coating, wear, modulus, beta, progress, warm_start):
    """The step loop, repeated for dissimilar materials until the verdict settles (thesis 4.6 step 7).

    Each pass solves the contacts with the friction traction of the previous passes' mean COF per step
    (under-relaxed by half, so it cannot oscillate); the fixed point has settled when the stiction margin and the
    mean COF change between passes by less than :data:`FIXED_POINT_TOLERANCE` of themselves (what the verdict
    decides; the friction of single steps flips with single grid elements and never settles to 1e-3, which left
    counter bodies of 20 GPa unconverged after 30 passes). At most ``mesh_friction_passes`` passes; identical
    materials (beta = 0) uncouple and one pass is exact. Returns a dict: the per-step totals ``out``,
    ``block_loads``, kinematics ``kin``, the elastic friction force ``f_el`` [N], the instantaneous ``friction``
    [N], ``passes``, ``converged`` and ``changes`` (the last relative changes of margin and COF, or None).
    """
    mu = None
    passes = 0
    decided_old = changes = None
    fixed_point_converged = True
    max_passes = int(params["mesh_friction_passes"])
    passes_start = {}  # dissimilar materials: each pass starts from the previous one's contact sets
    while True:
        passes += 1
        out, block_loads, kin = _run_cycle(setup, params, coating, wear, modulus, beta, mu, progress,
                                           warm_start if beta == 0.0 else passes_start)
        sliding = kin["sliding"]
        f_el = np.divide(out["e_el"], sliding, out=np.zeros_like(sliding), where=sliding > 0)
        friction = out["f_chem"] + out["f_vdw"] + f_el + out["f_cap"]
        denominator = setup.load + out["f_adh"] + out["f_cap_bridge"]
        mu_new = friction / denominator
        if beta == 0.0:
            break
        decided = _decided(params, setup, out, kin, f_el, denominator)
        if decided_old is not None:
            changes = tuple(abs(new - old) / max(abs(old), 1e-300) for new, old in zip(decided, decided_old))
            if max(changes) < FIXED_POINT_TOLERANCE:
                break
        if passes >= max_passes:
            fixed_point_converged = False
            break
        mu = mu_new if mu is None else 0.5 * (mu + mu_new)
        decided_old = decided
    # F_adh in humid air: the vdW part + the pull-off of the rough rows' water bridges beyond the vdW work (thesis
    # 3-31/3-32 for the water too, issue #28; docs/humidity.md); the menisci's line load of the contact solve
    # (f_cap_adh, reported as capillary_force) loads the contact but is no longer added (0 in vacuum and dry air)
    out["f_adh"] = out["f_adh"] + out["f_cap_bridge"]
    return dict(out=out, block_loads=block_loads, kin=kin, f_el=f_el, friction=friction, passes=passes,
                converged=fixed_point_converged, changes=changes)


def _decided(params, setup, out, kin, f_el, denominator):
    """(stiction margin [N], mean COF [-]) of one pass of the friction fixed point, as the verdict computes them."""
    from memstribo.physics.gear import tangential_force
    from memstribo.simulations.mesh.verdict import resisting_force, sliding_average

    pair = setup.pair
    sliding = kin["sliding"]
    friction = out["f_chem"] + out["f_vdw"] + f_el + out["f_cap"]
    averaged = sliding_average(friction, sliding, params["friction_averaging_distance"] or params["atomic_pitch"])
    resisting = resisting_force(setup.positions, averaged, pair.first_contact, pair.last_contact, pair.base_pitch)
    margin = float(tangential_force(params["drive_torque"], pair.pitch_radii[0])) - float(resisting.max())
    work = float((denominator * sliding).sum())
    return margin, (float((friction * sliding).sum()) / work if work > 0 else 0.0)


def step_convergence(params, roughness=None, *, steps=None, coating=None, wear=1.0, baseline=None, realisation=0):
    """Relative change of the minimum margin and the mean COF at twice the steps (MODEL 7b, 7d).

    Parameters
    ----------
    params, roughness, steps, coating, wear, realisation
        As for :func:`simulate_mesh`.
    baseline : dict, optional
        The :func:`summarize` of the run at ``steps`` (computed when not given).

    Returns
    -------
    dict
        ``step_converged`` (both changes below 2 %), ``step_change_margin`` (of |margin|, MODEL 7d),
        ``step_change_margin_ft`` (the same change of F_t, the former figure), ``step_change_cof`` (of the mean
        COF), all [-], and ``steps_checked``. The self-refining cycle is
        :func:`memstribo.simulations.mesh.convergence.refined_cycle`.
    """
    steps = int(params["mesh_steps"] if steps is None else steps)
    if baseline is None:
        baseline = summarize(simulate_mesh(params, roughness, steps=steps, coating=coating, wear=wear,
                                           realisation=realisation))
    doubled = summarize(simulate_mesh(params, roughness, steps=2 * steps - 1, coating=coating, wear=wear,
                                      realisation=realisation))
    change = compare_cycles(doubled, baseline)
    return {"step_converged": change["passed"], "step_change_margin": float(change["margin"]),
            "step_change_margin_ft": float(change["margin_ft"]), "step_change_cof": float(change["cof"]),
            "steps_checked": 2 * steps - 1}
