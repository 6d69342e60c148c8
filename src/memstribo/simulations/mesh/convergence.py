"""Convergence of a meshing cycle on what it decides: the self-refining cycle (MODEL 7d, issue #25).

A verdict must not depend on the numerics. The cycle is compared with itself at twice the steps
(``2 N - 1``: the same positions and one more between each pair) and, once the steps hold, at
twice the contact grid's resolution (``mesh_elements_across_contact`` doubled, or
``mesh_grid_spacing`` halved where it is set). A comparison passes when the stiction margin
changes by less than 2 % of |margin| and the mean COF by less than 2 % of itself (MODEL 7d; the
former check divided the margin's change by F_t, which let a margin drift by 8-14 % over 4x the
steps pass). Each failed comparison refines once more (steps first, then the grid), up to the
caps ``mesh_step_refinements`` and ``mesh_grid_refinements``; the result is the finest cycle
computed in whole, and a cycle that does not converge within its caps says so (``converged: false`` and a
warning naming what did not converge and by how much), never fails.

Each comparison is first a spot check (:func:`memstribo.simulations.mesh.spot.spot_check`): the finer cycle is
solved only at the steps the margin is taken from (its R(c) where R is largest: the finer margin exactly, under the
assumption its docstring states) and on an evenly spaced subsample for the mean COF (an estimate, paired with the
cycle at the same positions). A spot check that passes is the comparison: the cycle is kept (not replaced by the
finer one, which is not computed) and the sentence in ``refinement`` says how many finer steps were solved. One that
fails costs what it solved (a fifth to a third of the finer cycle on the default case, at most ``spot.BUDGET`` of it)
and leads to the whole finer cycle, compared as before; one that does not apply (dissimilar teeth, the surface contact,
over the budget) leads there at once (issue #25: the default ``memstribo mesh`` 19 -> 4 s CPU, realisation 0, then
1.3 s at 48 elements across 2a; bench/bench_convergence.py).

The reported adhesion force is checked on the grid too (< 5 % on grid halving, MODEL 7d); it
does not decide the verdict (it enters the COF, which is checked), so it is reported as resolved
or not (``adhesion_force_resolved``), and does not refine the grid by itself.
"""

from __future__ import annotations

from memstribo.errors import InputError
from memstribo.references import cites
from memstribo.simulations.mesh.verdict import TOLERANCE, compare_cycles, relative_change

__all__ = ["TOLERANCE", "ADHESION_TOLERANCE", "relative_change", "compare_cycles", "refined_cycle", "check_cycle",
           "CHECK_KEYS", "run_check",
           "settings_of", "CONVERGENCE_KEYS"]

#: Largest relative change of the adhesion force on grid halving that counts as resolved (MODEL 7d).
ADHESION_TOLERANCE = 0.05

#: The keys :func:`refined_cycle` adds to a cycle's summary.
CONVERGENCE_KEYS = ("converged", "step_converged", "step_change_margin", "step_change_margin_ft", "step_change_cof",
                    "steps_checked", "grid_converged", "grid_change_margin", "grid_change_cof",
                    "grid_change_adhesion", "elements_checked", "adhesion_force_resolved",
                    "elements_across_contact", "refinement", "step_margin_bound", "step_change_startup",
                    "step_startup_bound", "grid_margin_bound", "grid_change_startup", "grid_startup_bound")


def _elements_across(params) -> int:
    return int(params["mesh_elements_across_contact"])


def _finer_grid(params):
    """The parameter set with twice the grid's resolution (the spacing halved where it is set)."""
    if params["mesh_grid_spacing"] is not None:
        return params.updated({"mesh_grid_spacing": 0.5 * float(params["mesh_grid_spacing"])}, origin="grid check")
    return params.updated({"mesh_elements_across_contact": 2 * _elements_across(params)}, origin="grid check")


def settings_of(params, convergence: dict):
    """(params, steps) of the cycle :func:`refined_cycle` reported: the settings an ensemble should use."""
    steps = int(convergence["steps"])
    if params["mesh_grid_spacing"] is not None:
        spacing = convergence.get("grid_spacing")
        return (params.updated({"mesh_grid_spacing": spacing}, origin="refinement") if spacing else params), steps
    return params.updated({"mesh_elements_across_contact": int(convergence["elements_across_contact"])},
                          origin="refinement"), steps


def _percent(value: float) -> str:
    return "inf" if value == float("inf") else f"{value * 100:.2g} %"


@cites("model")
def refined_cycle(params, roughness=None, *, steps=None, coating=None, wear=1.0, realisation=0, progress=False,
                  step_refinements=None, grid_refinements=None, simulate=None, summarize=None, spot_checks=True):
    """The meshing cycle refined in steps, then in grid, until the margin and the mean COF hold (MODEL 7d).

    Parameters
    ----------
    params, roughness, steps, coating, wear, realisation, progress
        As for :func:`memstribo.simulations.mesh.simulate_mesh`.
    step_refinements, grid_refinements : int, optional
        Most comparisons at doubled steps and at a doubled grid resolution (default: the parameters
        ``mesh_step_refinements`` and ``mesh_grid_refinements``, 0 to 8); 0 skips that check.
    simulate, summarize : callable, optional
        The cycle and its summary (default: those of :mod:`memstribo.simulations.mesh`).
    spot_checks : bool
        Compare first by the spot check (:func:`memstribo.simulations.mesh.spot.spot_check`: the finer cycle solved
        only at the steps that decide the margin, and on a subsample for the mean COF); where it passes, the
        comparison has passed and the cycle is kept; where it fails or does not apply, the whole finer cycle is
        computed and compared (default True; with the default ``simulate`` and ``summarize`` only).

    Returns
    -------
    (xarray.Dataset, dict)
        The finest cycle computed in whole (a comparison passed by the spot check keeps the coarser cycle: its margin
        and mean COF are those of the finer one to within 2 %) and its summary, with the keys of :data:`CONVERGENCE_KEYS`:
        ``converged`` (both checks passed), ``step_converged``, ``step_change_margin`` (of |margin|),
        ``step_change_margin_ft`` (the same change of F_t, the former figure), ``step_change_cof``,
        ``steps_checked`` (steps of the finer cycle of the last step comparison), ``grid_converged``,
        ``grid_change_margin``, ``grid_change_cof``, ``grid_change_adhesion``, ``elements_checked``
        (elements across 2a of the finer grid of the last grid comparison), ``adhesion_force_resolved``
        (its change below 5 %), ``elements_across_contact``, ``steps`` and ``grid_spacing`` [m] of the
        result, and ``refinement`` (one sentence per comparison). A skipped check leaves its keys None.
        A cycle that does not converge within the caps adds a warning to ``warnings`` (and exits 0).

    Raises
    ------
    InputError
        A cap outside 0 to 8.
    """
    spot = None
    if simulate is None and summarize is None and spot_checks:  # the spot check reads the cycle as simulate_mesh makes it
        from memstribo.simulations.mesh.spot import spot_check

        def spot(dataset, p, n):
            return spot_check(dataset, p, roughness, n, coating=coating, wear=wear, realisation=realisation)
    if simulate is None or summarize is None:
        from memstribo.simulations.mesh.cycle import simulate_mesh
        from memstribo.simulations.mesh.verdict import summarize as summary_of

        simulate = simulate or simulate_mesh
        summarize = summarize or summary_of
    caps = []
    for name, value in (("mesh_step_refinements", step_refinements), ("mesh_grid_refinements", grid_refinements)):
        value = int(params[name] if value is None else value)
        if not 0 <= value <= 8:
            raise InputError(f"{name} must be a whole number from 0 to 8 (each one doubles the cost of the finer "
                             f"cycle), got {value}.")
        caps.append(value)
    steps = int(params["mesh_steps"] if steps is None else steps)

    def run(p, n):
        dataset = simulate(p, roughness, steps=n, coating=coating, wear=wear, realisation=realisation,
                           progress=progress)
        return dataset, summarize(dataset)

    state = {"params": params, "steps": steps, "record": {key: None for key in CONVERGENCE_KEYS},
             "sentences": [], "warnings": [], "spot": spot}
    state["dataset"], state["summary"] = run(params, steps)
    _refine_steps(state, run, caps[0])
    _refine_grid(state, run, caps[1])
    record = state["record"]
    checks = [record[key] for key, cap in (("step_converged", caps[0]), ("grid_converged", caps[1])) if cap]
    record["converged"] = bool(checks) and all(checks)
    record["elements_across_contact"] = _elements_across(state["params"])
    record["refinement"] = state["sentences"]
    summary = dict(state["summary"])
    summary.update(record)
    summary["steps"] = int(state["steps"])
    summary["grid_spacing"] = float(state["dataset"].attrs["grid_spacing"])
    summary["warnings"] = list(summary.get("warnings", [])) + state["warnings"]
    return state["dataset"], summary


def _spot(state, params, steps):
    """The spot check of the current cycle against the finer one (``params``, ``steps``) where it applies and passes,
    else None (the whole finer cycle is then computed: a failed spot check says only that it is needed)."""
    if state["spot"] is None:
        return None
    change = state["spot"](state["dataset"], params, steps)
    return change if change is not None and change["passed"] else None


def _startup_words(change) -> str:
    """The start-up margin's change in a refinement's sentence, where it was checked."""
    if change.get("startup") is None:
        return ""
    return f", start-up margin {_percent(change['startup'])} of |margin| (bound: {change['startup_bound']})"


def _refine_steps(state, run, cap):
    """Steps first: N -> 2N - 1 (the same positions and one between each pair) until a comparison passes."""
    record = state["record"]
    for _ in range(cap):
        steps = state["steps"]
        finer = 2 * steps - 1
        spotted = _spot(state, state["params"], finer)
        if spotted is not None:
            change, how = spotted, f" (spot check: {spotted['solved']} of {finer} steps solved)"
        else:
            dataset, fine = run(state["params"], finer)
            change, how = compare_cycles(fine, state["summary"]), ""
        state["sentences"].append(f"steps {steps} -> {finer}: margin {_percent(change['margin'])} of |margin|, mean "
                                  f"COF {_percent(change['cof'])}{_startup_words(change)}{how}")
        record.update(step_converged=change["passed"], step_change_margin=change["margin"],
                      step_change_margin_ft=change["margin_ft"], step_change_cof=change["cof"], steps_checked=finer,
                      step_margin_bound=change.get("margin_bound"), step_change_startup=change.get("startup"),
                      step_startup_bound=change.get("startup_bound"))
        if spotted is not None:
            return  # passed: the cycle is kept
        state.update(dataset=dataset, summary=fine, steps=finer)
        if change["passed"]:
            return
    if cap:
        state["warnings"].append(
            f"the cycle did not converge in the steps within mesh_step_refinements = {cap}: at "
            f"{record['steps_checked']} steps the margin still changes by {_percent(record['step_change_margin'])} "
            f"of |margin| and the mean COF by {_percent(record['step_change_cof'])} (goal < {TOLERANCE:.0%}); raise "
            "mesh_steps or mesh_step_refinements")


def _refine_grid(state, run, cap):
    """Then the grid: twice the resolution at the steps reached, until a comparison passes."""
    record = state["record"]
    for _ in range(cap):
        current = state["params"]
        finer = _finer_grid(current)
        spotted = _spot(state, finer, state["steps"])
        if spotted is not None:
            change, how = spotted, f" (spot check: {spotted['solved']} of {state['steps']} steps solved)"
        else:
            dataset, fine = run(finer, state["steps"])
            change, how = compare_cycles(fine, state["summary"]), ""
        what = (f"grid {_elements_across(current)} -> {_elements_across(finer)} elements across 2a"
                if current["mesh_grid_spacing"] is None else
                f"grid spacing {current['mesh_grid_spacing']:.3g} -> {finer['mesh_grid_spacing']:.3g} m")
        state["sentences"].append(f"{what}: margin {_percent(change['margin'])} of |margin|, mean COF "
                                  f"{_percent(change['cof'])}, adhesion force {_percent(change['adhesion'])}"
                                  f"{_startup_words(change)}{how}")
        record.update(grid_converged=change["passed"], grid_change_margin=change["margin"],
                      grid_change_cof=change["cof"], grid_change_adhesion=change["adhesion"],
                      grid_margin_bound=change.get("margin_bound"), grid_change_startup=change.get("startup"),
                      grid_startup_bound=change.get("startup_bound"),
                      elements_checked=_elements_across(finer),
                      adhesion_force_resolved=bool(change["adhesion"] < ADHESION_TOLERANCE))
        if spotted is not None:
            break  # passed: the cycle is kept
        state.update(dataset=dataset, summary=fine, params=finer)
        if change["passed"]:
            break
    if cap and not record["grid_converged"]:
        state["warnings"].append(
            f"the cycle did not converge in the grid within mesh_grid_refinements = {cap}: at "
            f"{record['elements_checked']} elements across the Hertz width the margin still changes by "
            f"{_percent(record['grid_change_margin'])} of |margin| and the mean COF by "
            f"{_percent(record['grid_change_cof'])} (goal < {TOLERANCE:.0%}); raise mesh_elements_across_contact or "
            "mesh_grid_refinements")
    if cap and record["adhesion_force_resolved"] is False:
        state["warnings"].append(
            f"the adhesion force is not resolved by the grid: it changes by {_percent(record['grid_change_adhesion'])} "
            f"on the last grid halving (goal < {ADHESION_TOLERANCE:.0%}); raise mesh_elements_across_contact where "
            "it is the answer")


#: The keys :func:`check_cycle` gives a sweep or map point.
CHECK_KEYS = ("converged", "step_change_margin", "step_change_cof", "grid_change_margin", "grid_change_cof")


@cites("model")
def check_cycle(params, roughness=None, *, steps=None, coating=None, wear=1.0, realisation=0, baseline=None,
                simulate=None, summarize=None, dataset=None) -> dict:
    """Whether a sweep or map point's cycle is converged: one comparison at twice the steps and one at twice the grid.

    The check of :func:`refined_cycle` without its refinement (a point of a sweep or a map keeps its settings, so
    that its neighbours are comparable, and says whether they hold): ``converged`` is true when the margin (of
    |margin|) and the mean COF change by less than 2 % at ``2 N - 1`` steps and at a doubled grid resolution
    (MODEL 7d). Parameters as for :func:`refined_cycle`; ``baseline`` is the point's own summary where already
    computed, ``dataset`` its cycle: with it (and the default ``simulate`` and ``summarize``) each comparison is first
    the spot check (:func:`memstribo.simulations.mesh.spot.spot_check`), the whole finer cycle run only where that
    fails or does not apply. Returns the keys of :data:`CHECK_KEYS` (changes [-]).
    """
    spotted = {}
    if dataset is not None and simulate is None and summarize is None:
        from memstribo.simulations.mesh.spot import spot_check

        n = int(params["mesh_steps"] if steps is None else steps)
        for key, (p, m) in (("step", (params, 2 * n - 1)), ("grid", (_finer_grid(params), n))):
            change = spot_check(dataset, p, roughness, m, coating=coating, wear=wear, realisation=realisation)
            if change is not None and change["passed"]:
                spotted[key] = change
        if len(spotted) == 2:
            return {"converged": True, "step_change_margin": spotted["step"]["margin"],
                    "step_change_cof": spotted["step"]["cof"], "grid_change_margin": spotted["grid"]["margin"],
                    "grid_change_cof": spotted["grid"]["cof"]}
    if simulate is None or summarize is None:
        from memstribo.simulations.mesh.cycle import simulate_mesh
        from memstribo.simulations.mesh.verdict import summarize as summary_of

        simulate = simulate or simulate_mesh
        summarize = summarize or summary_of
    steps = int(params["mesh_steps"] if steps is None else steps)

    def run(p, n):
        return summarize(simulate(p, roughness, steps=n, coating=coating, wear=wear, realisation=realisation))

    baseline = run(params, steps) if baseline is None else baseline
    step = spotted.get("step") or compare_cycles(run(params, 2 * steps - 1), baseline)
    grid = spotted.get("grid") or compare_cycles(run(_finer_grid(params), steps), baseline)
    return {"converged": bool(step["passed"] and grid["passed"]), "step_change_margin": step["margin"],
            "step_change_cof": step["cof"], "grid_change_margin": grid["margin"], "grid_change_cof": grid["cof"],
            "step_change_startup": step.get("startup"), "grid_change_startup": grid.get("startup"),
            "margin_bound": step.get("margin_bound"), "startup_bound": step.get("startup_bound")}


def run_check(params, roughness=None, *, steps=None, baseline=None, dataset=None) -> dict:
    """:func:`check_cycle` for the run chain's bare cycle (``dataset``, where given, for the spot check), with
    ``step_converged`` the two checks together (the report's key); {} where ``mesh_step_refinements`` or
    ``mesh_grid_refinements`` is 0 (no check)."""
    if not (params["mesh_step_refinements"] and params["mesh_grid_refinements"]):
        return {}
    check = check_cycle(params, roughness, steps=steps, baseline=baseline, dataset=dataset)
    return {**check, "step_converged": check["converged"]}
