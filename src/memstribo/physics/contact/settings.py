"""The tuning of the line-contact solvers: every tolerance, cap, switch and threshold, as one frozen object.

Each field says what it trades (mostly speed against accuracy or robustness), its unit, and the benchmark in
``bench/`` whose measurements set it. The defaults (:data:`DEFAULTS`) are the values every result in the
docs was computed with; a caller may pass its own, e.g.
``solve_line_contact(..., settings=dataclasses.replace(DEFAULTS, max_outer=60))``. A field that changes the
answer beyond the solve's ``tolerance`` is a bug: the settings change the path to the answer, not the answer.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["SolverSettings", "DEFAULTS"]


@dataclass(frozen=True)
class SolverSettings:
    """Tolerances, caps, switches and thresholds of :func:`memstribo.physics.contact.solve_line_contact`."""

    # ---------------------------------------------------------------- plain (non-adhesive) line solver
    max_outer: int = 30
    """Contact-set updates of the active-set method before Polonsky-Keer takes over [count]. More: fewer
    fall-backs to the slow constrained CG on sets that cycle, at the cost of time lost on those that never
    settle. Set by bench/bench_contact.py (bench/README-contact.md)."""

    inner_factor: float = 0.2
    """Inner CG tolerance relative to the complementarity violation of the previous contact set
    [dimensionless]. Smaller: more exact inner solves, more CG iterations per set update; larger: more set
    updates. Set by bench/bench_contact.py."""

    start_fraction: float = 0.3
    """Without an initial guess, the uniform start pressure covers this fraction of the grid with the
    smallest gap (1.0: everywhere) [dimensionless]. Points that penetrate join in one set update, points with
    p < 0 leave more slowly, so an under-estimate is cheaper: 1.1-1.5x faster cold solves at 5-20 % contact,
    ~5 % slower at 45-90 %. Set by bench/bench_contact.py (bench/README-contact.md)."""

    small_problem: int = 2**14
    """Problems up to this many elements use the measures for small problems (direct solves on small grids,
    the cold start above, short directly solved coarse levels, the narrower interpolation) [elements]; above,
    the coarse levels' guess matters more than their cost (2^18: 5-9 % slower). Set by bench/bench_contact.py."""

    dense_max: int = 256
    """Contact sets up to this many elements (and n_contact^2 <= 4 x FFT size) use dense influence matrices in
    the CG instead of FFTs [elements]: a BLAS matrix-vector product of this size takes microseconds and stays
    single-threaded; larger ones may go threaded, which is slow on a busy machine. Set by bench/bench_contact.py
    (its dense-threshold sweep)."""

    dense_grid: int = 1024
    """... or, for sets up to ``dense_max``, on grids of at most this FFT size, where the overhead of the FFT
    calls (~7 us each) dominates [FFT points]. Also the grid size up to which contact sets are solved directly
    (``direct_max``) and coarse levels stop after ``coarse_max_outer`` updates. Set by bench/bench_contact.py."""

    direct_max: int = 256
    """On grids of at most ``dense_grid``, contact sets up to this size are solved directly (Cholesky, ~0.15 ms
    at 170 elements) instead of by the CG [elements]: exact solves need fewer contact-set updates. Set by
    bench/bench_contact.py (its dense-threshold sweep)."""

    coarsest: int = 512
    """Grids with fewer elements are solved directly: the coarsest level of the nested grids [elements].
    Smaller: more (cheap) levels, a better guess on large grids. Set by bench/bench_contact.py."""

    coarse_tolerance: float = 1e-3
    """Gap tolerance of the coarse nested levels, relative to the peak-to-valley of the gap [dimensionless];
    only their contact set matters. Set by bench/bench_contact.py."""

    coarse_step_fraction: float = 0.1
    """... and at most this fraction of the rms height step between neighbouring points [dimensionless]: on
    long domains the peak-to-valley alone is too loose to predict the contact set. Set by bench/bench_contact.py."""

    coarse_max_outer: int = 3
    """Coarse levels solved directly stop after this many set updates [count]: only a guess is needed, the fine
    grid settles the set (2^10: 2.15 -> 1.96 ms; 2^12-2^14 no slower). Set by bench/bench_contact.py."""

    fft_workers: int = 1
    """Threads scipy.fft may use in the solver [count] (1 = serial; the benchmarks compare on one core).
    bench/bench_contact.py."""

    # ---------------------------------------------------------------- small-grid dense path
    dense_solve_max: int = 1024
    """Free-boundary grids up to this many elements are solved under load control with dense matrices (plain,
    Maugis-Dugdale and capillary problems) [elements]: a meshing cycle's window (~100 elements, thousands of
    solves) is dominated by the per-call overhead of the FFT-based solver. Set by bench/bench_mesh.py and
    bench/bench_map.py (bench/results-map.txt)."""

    zone_kernel_max: int = 4096
    """Free-boundary grids up to this many elements solve the cohesive-zone problems (Maugis-Dugdale, capillary) under
    load control by the compiled loop (:mod:`memstribo.physics._zone_kernel`; ``dense_solve_max`` still bounds the
    plain problem, which builds the whole matrix) [elements]. The loop reads the n numbers of the Toeplitz influence
    matrix, not the matrix, so its cost grows like n times the contact set: the thesis load case on an 8 um face
    (1116-element windows) took 15 ms per solve by the FFT-based solver and takes 2.8 ms by the loop (issue #25).
    Its state is the one the loop reaches from the non-adhesive solution (the loading branch, ``cohesive_start``);
    the FFT-based solver above 1024 elements started the zone from a coarser grid's adhesive solution instead.
    Set by bench/bench_convergence.py (``--parts thesis``)."""

    sparse_fraction_max: int = 8
    """Cohesive fractions of at most this many candidate elements are evaluated element by element instead of
    vectorised over the grid [elements] (the same numbers; per-call overhead). Set by bench/bench_zone_updates.py."""

    # ---------------------------------------------------------------- cohesive zone (Maugis-Dugdale, capillary)
    adhesive_max_outer: int = 200
    """Set updates of the cohesive zone (load control) or of the contact and cohesive sets (approach control)
    before the adhesive solve gives up (converged=False) [count]. Set by bench/bench_adhesive_contact.py."""

    small_zone_max_updates: int = 1000
    """Cohesive-zone updates allowed on grids of at most ``small_zone`` elements [count] (an update costs
    ~0.3 ms there; damped updates may need several hundred: the thesis load case). bench/bench_zone_updates.py."""

    small_zone: int = 2048
    """Grid size up to which ``small_zone_max_updates`` applies [elements]. bench/bench_zone_updates.py."""

    zone_elements: float = 2.0
    """Grid elements the Maugis-Dugdale zone must span [count]: where its small-scale width d = pi h0 E* / (4 sigma0)
    is narrower, the solve lowers sigma0 and lengthens h0 at the same work of adhesion until it spans this many
    (:func:`memstribo.physics.contact.subgrid.resolved_zone`, issue #25); finer grids are unchanged. 0: off (the
    zone as given, unresolved on coarse grids). Set by bench/bench_grid_adhesion.py."""

    contact_only_range: float = 1e-6
    """Range of the contact-only part of a widened zone (the rest of sigma0 on the elements in contact), relative to
    h0 [dimensionless]: an element outside the contact would need a gap below it to carry that part
    (:func:`memstribo.physics.contact.subgrid.resolved_zones`). Not tuned: only its smallness matters (the widened zone it
    belongs to is measured by bench/bench_grid_adhesion.py). 0: no contact-only part, the contact holds the widened
    sigma too (the pull-off, :func:`memstribo.physics.adhesive_contact.line_contact_pull_off`, issue #41)."""

    fraction_tolerance: float = 1e-4
    """The cohesive zone has settled when no element's cohesive fraction changes by more than this
    [dimensionless]. Looser: fewer zone updates, a less exact front. Set by bench/bench_zone_updates.py."""

    zone_load_tolerance: float = 1e-4
    """... or when the cohesive load changes by less than this relative amount (sum of the changes of the
    fractions over the zone) and no fraction by more than ``zone_max_change`` [dimensionless].
    Set by bench/bench_zone_updates.py."""

    zone_max_change: float = 0.25
    """Largest change of one element's cohesive fraction the load criterion above accepts [dimensionless].
    bench/bench_zone_updates.py."""

    gap_fraction: float = 0.01
    """Gap accuracy of the inner solves, as a fraction of h0 times the last change of the cohesive fraction
    [dimensionless]: looser inner solves while the zone still moves. Set by bench/bench_adhesive_contact.py."""

    stalled_updates: int = 20
    """Updates without a new smallest change of the cohesive fraction after which the update is under-relaxed
    (halved each time, down to ``min_relaxation``) [count]: breaks limit cycles at fronts.
    Set by bench/bench_adhesive_contact.py."""

    min_relaxation: float = 0.25
    """Smallest under-relaxation factor of the zone update [dimensionless]. bench/bench_adhesive_contact.py."""

    improving_updates: int = 5
    """The relaxation is doubled again after this many updates in a row that each reach a new smallest change
    [count]. bench/bench_adhesive_contact.py."""

    loose_tolerance: float = 1e-4
    """Loosest relative tolerance of the inner solves of the zone updates [dimensionless].
    bench/bench_adhesive_contact.py."""

    approach_direct_max: int = 64
    """Contact sets up to this size are solved by Cholesky under approach control (larger: the CG) [elements].
    bench/bench_adhesive_contact.py."""

    coarse_max_updates: int = 15
    """Cohesive-zone updates of a coarse nested level (only a guess) [count]. bench/bench_adhesive_contact.py."""

    largest_adhesive_level: int = 2**13
    """Largest coarse level solved with adhesion; finer grids start from the non-adhesive nested guess instead
    [elements] (2^16: 4.4x the plain solve against 5.3x with adhesive levels up to 2^15).
    Set by bench/bench_adhesive_contact.py."""

    coarse_fraction_tolerance: float = 1e-2
    """Tolerance on the cohesive fraction of the coarse nested levels (only a guess) [dimensionless].
    bench/bench_adhesive_contact.py."""

    settle_first: bool = True
    """Warm-started inner solves of the zone updates first solve on the guess's contact set; False restores the
    former first set update from the unsolved guess (kept for the tests and the benchmark's comparison).
    Set by bench/bench_adhesive_contact.py (docs/contact.md, "Speed")."""

    linear_response_start: bool = True
    """Warm start of each zone update's inner solve (load control) extrapolated along the last change of p+;
    False: the last p+ as it is (the former start). Set by bench/bench_adhesive_contact.py."""

    aitken_max_ratio: float = 0.9
    """Largest convergence ratio used in the Aitken extrapolation of the zone updates [dimensionless]: larger
    extrapolates creeping fronts further, at the risk of overshoot. At 0.95 (until issue #25's grid change) the
    extrapolation of a smooth adhesive contact's front overshot into the Maugis-Dugdale line contact's small-contact
    state in 14 steps of 16 smooth-teeth cycles, at 0.9 in none (tests/test_mesh.py). bench/bench_zone_updates.py."""

    aitken_min_ratio: float = 0.8
    """... applied only where the measured ratio is at least this (slow, creeping fronts) [dimensionless].
    bench/bench_zone_updates.py."""

    cohesive_start: str = "previous"
    """Start of the cohesive zone under load control when an ``initial_pressure`` is given: "previous" (the zone of
    that pressure, its tensile parts and contact set: continuation from a previous state, e.g. along a
    loading-unloading curve) or "loading" (the zone starts empty, the pressure's contact set starts the first,
    non-adhesive update on grids up to ``loading_start_max`` elements and is not used on larger ones: the state
    reached is the loading-branch state, the one reached without a start, whatever state the pressure came from). The meshing cycle uses "loading", so that a step's state does not depend on the step before it
    (issue #25, docs/interface.md; bench/bench_convergence.py measures it)."""


    loading_start_max: int = 512
    """Grids up to this many elements start the loading branch's first zone update (``cohesive_start = "loading"``,
    the non-adhesive problem) from the start pressure's contact set, larger ones from the lowest element [elements].
    A meshing step's start is the step before's adhesive contact set: on the default cycle's ~110-element windows the
    contact moves by a fraction of its width per step and that set is close (0.094 against 0.173 ms per solve from
    the lowest element, the validation table's humid cycles); on the thesis case's 1300- and 2600-element windows
    (8 um face) the adhesive set is several times the non-adhesive one and disjoint from it, and factoring it and
    shrinking it took ~8 contact sets (the case's CPU time 169 -> 88 s from the lowest element). Both starts reach
    the same contact set (unique), the pressures to round-off. Set by bench/bench_convergence.py (issue 40,
    bench/README.md)."""

    # ---------------------------------------------------------------- pressure capped at the hardness (plastic.py)
    max_plastic_updates: int = 60
    """Updates of the plastic set (elements at the hardness) before the capped solve gives up, converged=False
    [count]. The shipped line scan settles in 3-4 updates per solve; more only delays the report of a set that
    cycles. Set by bench/bench_plastic_contact.py."""


#: The settings every solve uses unless given its own (read at call time, so a test may swap it).
DEFAULTS = SolverSettings()


def resolve(settings: SolverSettings | None) -> SolverSettings:
    """``settings``, or :data:`DEFAULTS` (looked up now) where None."""
    return DEFAULTS if settings is None else settings
