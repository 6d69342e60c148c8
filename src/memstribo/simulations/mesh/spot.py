"""The spot check of a meshing cycle's convergence: the finer cycle solved only where the verdict is decided.

:func:`memstribo.simulations.mesh.convergence.refined_cycle` compares a cycle with the same cycle at twice the steps
and at twice the grid's resolution (MODEL 7d, issue #25). What is compared is the stiction margin F_t - max R(c) and
the mean COF. A whole finer cycle costs 2x (steps) to 4-10x (grid) the cycle; :func:`spot_check` solves the finer
cycle's contacts only at the steps these two numbers are taken from:

* **the margin**: R(c) is the sum of the sliding-averaged friction of every pair in mesh (at c + k p_b), so R at a
  position needs the steps whose sliding intervals meet the averaging window around each of those pairs' positions.
  The finer R is computed exactly (the same averages and interpolation as the whole cycle) at every position whose
  coarse R lies within a band below the largest; the band is widened until it holds every position whose coarse R
  is within ``2 delta`` of the largest finer R found, ``delta`` being the largest change of R measured at the
  positions solved. The check's assumption, the one thing it does not verify: **R changes nowhere by more than
  twice the largest change measured where R is largest.** Under it the largest finer R, and so the finer margin, is
  the one computed.
* **the mean COF** (and the mean adhesion force): estimated on an evenly spaced subsample of the finer steps (about
  :data:`COF_SAMPLES`, each solved with the step before it), paired with the coarse cycle at the same positions
  (interpolated linearly at the finer cycle's new positions): the relative change of sum(F_f s) / sum((F_N + F_adh)
  s) over the subsample. A statistical estimate, not an exact one: it reads the same roughness at the same places,
  so the noise of the roughness largely cancels; its spread is measured in bench/bench_convergence.py
  (``--parts spot``).

Each step's contact is solved as in the whole cycle (its state does not depend on the step before it: the loading
branch, :func:`memstribo.simulations.mesh.contacts._loading_branch`), and each step is solved with the step before it
(the elastic interlocking energy of a step is that of the change since the step before), so the steps solved give the
numbers the whole finer cycle has there (to the solver's tolerance; tests/test_convergence.py). The check is given up (None: the caller runs the whole finer
cycle) for dissimilar teeth (the F_t/F_f fixed point couples the steps), for the surface contact, where a checked
step's contact reaches the ends of its window, or where the steps needed exceed :data:`BUDGET` of the finer cycle
(the margin's and the subsample's together, each step counted once).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from memstribo.references import cites
from memstribo.simulations.mesh.verdict import (RESISTING_TOLERANCE, TOLERANCE, margin_check, relative_change,
                                                sliding_average)

__all__ = ["spot_check", "COF_SAMPLES", "BUDGET"]

#: About this many finer steps, evenly spaced, are solved for the mean COF and the mean adhesion force.
COF_SAMPLES = 48

#: The spot check is given up where it would solve more than this fraction of the finer cycle's steps (each counted
#: once). A spot check that fails or gives up costs at most this much on top of the whole finer cycle; one that passes
#: saves the rest. At 0.35 the grid check of the thesis load case on an 8 um face (40 -> 80 and 48 -> 96 elements
#: across 2a at 481 steps: 167 steps, 85 of them for the margin where R(c) is flat) fitted by one step, and the whole
#: 2172-element cycle it otherwise runs costs ~0.8 s of CPU per step (issue #25 item 5, bench/README.md).
BUDGET = 0.5

#: Rounds of widening the band of positions whose R is computed.
_ROUNDS = 4


class _Finer:
    """The finer cycle's set-up and the steps solved so far (per-step friction, load, adhesion force)."""

    def __init__(self, params, roughness, steps, coating, wear, realisation, window):
        from memstribo.materials.pair import contact_modulus_of, dundurs_beta
        from memstribo.simulations.mesh.setup import _prepare
        from memstribo.simulations.mesh.steps import _kinematics

        self.params, self.coating, self.wear = params, coating, wear
        self.modulus = contact_modulus_of(params)
        self.beta = dundurs_beta(params["youngs_modulus"], params["poisson_ratio"], params["counter_youngs_modulus"],
                                 params["counter_poisson_ratio"])
        self.setup = _prepare(params, roughness, steps, realisation, "x", window=window)
        kinematics = _kinematics(self.setup)
        self.sliding = kinematics["sliding"]
        self.positions = self.setup.positions
        self.edges = np.concatenate([[0.0], np.cumsum(self.sliding)])
        self.friction = np.full(steps, np.nan)
        self.static = np.full(steps, np.nan)  # the start-up friction force of each step (MODEL 7f)
        self.denominator = np.full(steps, np.nan)
        self.adhesion = np.full(steps, np.nan)
        self.exceeded = False
        self.solves = 0  # steps solved, those solved only for the step after them included

    def solve(self, indices):
        """Solve the steps ``indices`` not solved yet (one partial cycle), each with the step before it: the elastic
        interlocking energy of a step is that of the change of the blocks' compression since the step before
        (:func:`memstribo.simulations.mesh.interface._interlocking`), so a step's friction is known only where the step
        before it was solved with it."""
        from memstribo.simulations.mesh.cycle import _friction_fixed_point

        wanted = {int(i) for i in indices if math.isnan(self.friction[int(i)])}
        if not wanted:
            return
        indices = np.array(sorted(wanted | {i - 1 for i in wanted if i > 0}), dtype=int)
        self.solves += indices.size
        setup = self.setup
        part = dataclasses.replace(setup, positions=setup.positions[indices], step_time=setup.step_time[indices],
                                   load=setup.load[indices])
        cycle = _friction_fixed_point(part, self.params, self.coating, self.wear, self.modulus, self.beta, False, None)
        out = cycle["out"]
        known = np.concatenate([[indices[0] == 0], np.diff(indices) == 1])  # the step before was solved with it
        self.friction[indices[known]] = cycle["friction"][known]
        self.static[indices[known]] = self._static(part, cycle)[known]
        self.adhesion[indices] = out["f_adh"]
        self.denominator[indices] = part.load + out["f_adh"]
        self.exceeded = self.exceeded or bool((out["window_exceeded"] > 0).any())

    def _static(self, part, cycle):
        """The start-up friction force of the solved steps [N] (:func:`memstribo.simulations.mesh.limits`)."""
        from memstribo.simulations.mesh.limits import bond_energies, formed_share, row_bond_forces, static_friction_force

        out, params = cycle["out"], self.params
        registry = part.registry
        rows = out["row_bonds"].shape[-1]
        phases = registry.bond_phase if registry is not None and registry.bond_phase is not None else np.zeros(rows)
        forces = row_bond_forces(out["row_bonds"], bond_energies(params, self.coating), params["bond_length"])
        return static_friction_force(forces, phases, formed_share(params), cycle["f_el"] + out["f_cap"])

    def solved(self) -> int:
        return self.solves

    def cost(self, indices, then=()) -> int:
        """Steps :meth:`solve` would solve for ``indices`` (those not known yet, each with the step before it), and
        then for ``then`` in a second call (a step of ``then`` right after one of ``indices`` is solved again with it:
        a step's friction is known only where the step before it was solved in the same call)."""
        wanted = {int(i) for i in indices if math.isnan(self.friction[int(i)])}
        first = wanted | {i - 1 for i in wanted if i > 0}
        known = {i for i in first if i == 0 or i - 1 in first}
        later = {int(i) for i in then if math.isnan(self.friction[int(i)]) and int(i) not in known}
        return len(first) + len(later | {i - 1 for i in later if i > 0})

    def window_steps(self, b, distance):
        """The steps whose sliding intervals meet the averaging window of step b (the steps its average reads)."""
        edges = self.edges
        centre = 0.5 * (edges[b] + edges[b + 1])
        lo = min(max(centre - 0.5 * distance, edges[0]), edges[-1])
        hi = min(max(centre + 0.5 * distance, edges[0]), edges[-1])
        first = max(int(np.searchsorted(edges, lo, side="right")) - 1, 0)
        last = min(int(np.searchsorted(edges, hi, side="left")), self.friction.size - 1)
        return range(max(first, 0), last + 1)

    def averaged(self, b, distance):
        """The sliding-averaged friction of step b from the solved steps of its window (the whole cycle's number)."""
        steps = self.window_steps(b, distance)
        first, last = steps.start, steps.stop - 1
        block = slice(first, last + 1)
        values = sliding_average(self.friction[block], self.sliding[block], distance)
        # the block's window is the whole cycle's (clipped only at the ends of the path, where the cycle's is too)
        return float(values[b - first])


def _partners(pair, position):
    """(k, c + k p_b) of the pairs in mesh with R(c) (:func:`memstribo.simulations.mesh.verdict.resisting_force`)."""
    k_max = int(math.ceil((pair.last_contact - pair.first_contact) / pair.base_pitch)) + 1
    for k in range(-k_max, k_max + 1):
        other = position + k * pair.base_pitch
        if pair.first_contact - 1e-15 <= other <= pair.last_contact + 1e-15:
            yield other


def _brackets(positions, other):
    """The steps np.interp reads at ``other``: (i, weight of i), (j, weight of j)."""
    j = int(np.searchsorted(positions, other, side="right"))
    if j <= 0:
        return ((0, 1.0),)
    if j >= positions.size:
        return ((positions.size - 1, 1.0),)
    i = j - 1
    if positions[i] == other:
        return ((i, 1.0),)
    t = (other - positions[i]) / (positions[j] - positions[i])
    return ((i, 1.0 - t), (j, t))


def _steps_for(finer, checked, distance):
    """The steps the finer R at the positions ``checked`` reads."""
    pair = finer.setup.pair
    needed = set()
    for i in checked:
        for other in _partners(pair, float(finer.positions[i])):
            for b, _ in _brackets(finer.positions, other):
                needed.update(finer.window_steps(b, distance))
    return needed


def _resisting(finer, i, distance, cache):
    """R at the finer position i from the solved steps."""
    total = 0.0
    for other in _partners(finer.setup.pair, float(finer.positions[i])):
        value = 0.0
        for b, weight in _brackets(finer.positions, other):
            if b not in cache:
                cache[b] = finer.averaged(b, distance)
            value += weight * cache[b]
        total += value
    return total


def _startup_steps(finer, checked):
    """The steps the finer start-up R_s at the positions ``checked`` reads (no averaging: each position's own)."""
    needed = set()
    for i in checked:
        for other in _partners(finer.setup.pair, float(finer.positions[i])):
            needed.update(b for b, _ in _brackets(finer.positions, other))
    return needed


def _startup_resisting(finer, i):
    """R_s at the finer position i from the solved steps [N] (the start-up torque balance,
    :func:`memstribo.simulations.mesh.limits.startup_resisting_force`)."""
    from memstribo.physics.static_friction import friction_lever

    pair = finer.setup.pair
    rb1, rb2 = (float(r) for r in pair.base_radii)
    total = 0.0
    for other in _partners(pair, float(finer.positions[i])):
        rho1, rho2 = pair.radii_of_curvature(min(max(other, pair.first_contact), pair.last_contact))
        static = sum(weight * finer.static[b] for b, weight in _brackets(finer.positions, other))
        total += static * float(friction_lever(float(rho1), float(rho2), rb1, rb2))
    return (float(finer.params["load_torque"]) / rb2 + total) * rb1 / float(pair.pitch_radii[0])


def _startup_margin(finer, dataset, f_t, budget):
    """The finer cycle's start-up margin from the steps where the coarse R_s is near its largest [N], the band
    widened as for the running margin; None where the steps needed exceed ``budget`` or reach the window's ends."""
    coarse = np.interp(finer.positions, np.asarray(dataset["position"]), np.asarray(dataset["startup_resisting_force"]))
    largest = float(coarse.max())
    # a narrow first band (R_s is flat near its largest, and the widening below adds what the change requires)
    checked = set(np.flatnonzero(coarse >= largest * (1.0 - RESISTING_TOLERANCE)).tolist())
    checked.add(int(np.argmax(coarse)))
    for _ in range(_ROUNDS):
        needed = _startup_steps(finer, checked)
        if finer.solved() + finer.cost(needed) > budget:
            return None
        finer.solve(needed)
        if finer.exceeded:
            return None
        fine = {i: _startup_resisting(finer, i) for i in checked}
        delta = max(abs(fine[i] - coarse[i]) for i in checked)
        required = set(np.flatnonzero(coarse >= max(fine.values()) - 2.0 * delta).tolist())
        if required <= checked:
            return f_t - max(fine.values())
        checked |= required
    return None


@cites("model")
def spot_check(dataset, params, roughness, steps, *, coating=None, wear=1.0, realisation=0) -> dict | None:
    """The changes of the margin and the mean COF from a cycle to a finer one, from the finer steps that decide them.

    Parameters
    ----------
    dataset : xarray.Dataset
        The coarser cycle (:func:`memstribo.simulations.mesh.simulate_mesh`).
    params, steps
        The finer cycle's parameter set and number of steps [-] (twice the steps, or twice the grid's resolution).
    roughness, coating, wear, realisation
        As for :func:`memstribo.simulations.mesh.simulate_mesh` (the coarser cycle's).

    Returns
    -------
    dict or None
        ``margin`` (its change, of |margin| of the coarser cycle), ``margin_ft`` (of F_t), ``cof`` (estimated change of
        the mean COF), ``adhesion`` (estimated change of the mean adhesion force), all [-], ``passed`` (margin and COF
        below 2 %), ``solved`` (finer steps solved), ``steps`` (of the finer cycle), ``positions_checked`` (finer
        positions whose R was computed) and ``stiction_margin`` (the finer cycle's margin [N]); None where the spot
        check does not apply (module docstring): the whole finer cycle is then needed.
    """
    if params["mesh_contact"] != "line" or float(dataset.attrs.get("dundurs_beta", 0.0)) != 0.0:
        return None
    finer = _Finer(params, roughness, steps, coating, wear, realisation, None)
    window = float(dataset.attrs["window"])
    if window > 1.01 * finer.setup.grid.size * finer.setup.grid_spacing:  # the coarser cycle's window grew: keep it
        finer = _Finer(params, roughness, steps, coating, wear, realisation, window)
    budget = BUDGET * steps
    distance = params["friction_averaging_distance"] or params["atomic_pitch"]
    coarse_c = np.asarray(dataset["position"])
    coarse_r = np.asarray(dataset["resisting_force"])
    f_t = float(dataset.attrs["tangential_force_total"])
    r_max = float(coarse_r.max())
    margin = f_t - r_max
    coarse_at = np.interp(finer.positions, coarse_c, coarse_r)  # coarse R at the finer positions
    band = TOLERANCE * abs(margin)
    checked = set(np.flatnonzero(coarse_at >= r_max - band).tolist())
    # and the finer position where the coarser R reads largest: with a margin near 0 the band is narrower than the
    # interpolation's error where the finer positions do not fall exactly on the coarser ones (a 4 um face at 84 nN m)
    checked.add(int(np.argmax(coarse_at)))
    stride = max(1, steps // COF_SAMPLES)
    sample = np.arange(stride // 2, steps, stride)
    cache = {}
    finer_r = {}
    for _ in range(_ROUNDS):
        needed = _steps_for(finer, checked, distance)
        # the steps still to solve for the margin and for the mean COF's subsample (each step with the one before it;
        # a subsample step the margin's steps hold already costs nothing more)
        if finer.solved() + finer.cost(needed, then=sample.tolist()) > budget:
            return None
        finer.solve(needed)
        if finer.exceeded:
            return None
        cache.clear()  # new steps: averages near them may read them
        finer_r = {i: _resisting(finer, i, distance, cache) for i in checked}
        delta = max(abs(finer_r[i] - coarse_at[i]) for i in checked)
        largest = max(finer_r.values())
        required = set(np.flatnonzero(coarse_at >= largest - 2.0 * delta).tolist())
        if required <= checked:
            break
        checked |= required
    else:
        return None
    largest = max(finer_r.values())
    fine_margin = f_t - largest
    # the mean COF and the mean adhesion force on an evenly spaced subsample, paired with the coarser cycle
    finer.solve(sample)
    if finer.exceeded:
        return None
    s = finer.sliding[sample]
    c = finer.positions[sample]
    coarse_f = np.interp(c, coarse_c, np.asarray(dataset["friction_force_instantaneous"]))
    coarse_adh = np.interp(c, coarse_c, np.asarray(dataset["adhesion_force"]))
    coarse_d = np.interp(c, coarse_c, np.asarray(dataset["normal_force"])) + coarse_adh
    fine_cof = float((finer.friction[sample] * s).sum() / (finer.denominator[sample] * s).sum())
    coarse_cof = float((coarse_f * s).sum() / (coarse_d * s).sum())
    weights = finer.setup.step_time[sample]
    cof = relative_change(fine_cof, coarse_cof)
    running = margin_check(fine_margin, margin, r_max)
    result = {"margin": running["change"], "margin_ft": abs(fine_margin - margin) / max(abs(f_t), 1e-300), "cof": cof,
              "margin_bound": running["bound"],
              "adhesion": relative_change(float((finer.adhesion[sample] * weights).sum()),
                                          float((coarse_adh * weights).sum())),
              "solved": finer.solved(), "steps": int(steps), "positions_checked": len(checked),
              "stiction_margin": fine_margin}
    passed = running["passed"] and cof < TOLERANCE
    if "startup_resisting_force" in dataset:  # the start-up margin is checked as well (MODEL 7h, issue #35)
        coarse_startup = f_t - float(np.max(dataset["startup_resisting_force"]))
        fine_startup = _startup_margin(finer, dataset, f_t, budget)
        if fine_startup is None:
            return None
        startup = margin_check(fine_startup, coarse_startup, f_t - coarse_startup)
        result.update(startup=startup["change"], startup_bound=startup["bound"], startup_margin=fine_startup,
                      solved=finer.solved())
        passed = passed and startup["passed"]
    result["passed"] = bool(passed)
    return result
