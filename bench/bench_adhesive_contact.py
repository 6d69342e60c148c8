"""Benchmark: the adhesive (Maugis-Dugdale) line-contact solve against the non-adhesive one.

The same rough free-boundary problem (the self-affine profile of bench_contact.py, Hurst 0.8,
rms height 1 nm at 2^12 points, grid step 0.244 nm, mean pressure ~16 % contact without
adhesion) is solved at 2^10 to 2^16 points with and without a Maugis-Dugdale zone of the
silicon constants (sigma0 = 16 w / (9 sqrt 3 D0) = 1.78 GPa, h0 = w / sigma0 = 0.249 nm,
w = 0.445 J/m^2; ``memstribo constants``), on one core. The table is the median of
``--repeat`` timed solves after one warm-up solve (the half-plane operator is cached), wall
clock and CPU (process) time; on a shared machine the CPU ratio is the steadier one.

``--former`` also times the former inner solves of the cohesive-zone updates (before commit ca16598:
each inner solve's first contact-set update from the unsolved guess, the last p+ as start), same
process, interleaved. ``--tamaas`` adds an independent cross-check on the periodic version of the
problem: memstribo's adhesive solve (``periodic=True``, load control) against Tamaas 2.9's
PolonskyKeerRey on the gap with a MaugisAdhesionFunctional (the algorithm of Rey, Anciaux &
Molinari 2017; Dugdale stress w / rho, rho = h0) at memstribo's mean gap (Tamaas imposes the mean
gap, not the load): CPU times, iterations, the loads and the pressure difference. Tamaas is in
the benchmark environment only, never a dependency of memstribo.

Run:  python bench/bench_adhesive_contact.py [--sizes 10 12 14 16] [--repeat 3] [--json FILE] [--seed 0] [--former]
      [--tamaas]
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from bench_contact import MODULUS, problem  # noqa: E402

SIGMA0 = 1.78e9  # Dugdale stress [Pa] (silicon, memstribo constants)
RANGE = 0.445 / SIGMA0  # h0 = w / sigma0 [m]


def timed(function, repeat):
    """Median wall-clock and CPU (process) time [s] of ``repeat`` calls after a warm-up, and the last result."""
    function()  # warm-up: operator cache
    times, cpu, result = [], [], None
    for _ in range(repeat):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = function()
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return float(np.median(times)), float(np.median(cpu)), result


def former(h, dx, load, args, current):
    """The former inner solves of the zone updates, timed in turn with the plain and the current adhesive solve."""
    import dataclasses

    from memstribo.physics.contact import DEFAULTS, solve_line_contact

    def run(settle):
        settings = dataclasses.replace(DEFAULTS, settle_first=settle, linear_response_start=settle)
        return solve_line_contact(h, dx, MODULUS, load=load, tolerance=args.tolerance, max_iterations=20000,
                                  cohesive_stress=SIGMA0, cohesive_range=RANGE, settings=settings)

    def plain():
        return solve_line_contact(h, dx, MODULUS, load=load, tolerance=args.tolerance, max_iterations=20000)

    cpu = {"plain": [], "current": [], "former": []}
    result = None
    for repeat in range(args.repeat + 1):  # the first round: warm-up
        for name, function in (("plain", plain), ("current", lambda: run(True)), ("former", lambda: run(False))):
            start = time.process_time()
            solution = function()
            if repeat:
                cpu[name].append(time.process_time() - start)
            if name == "former":
                result = solution
    median = {name: float(np.median(values)) for name, values in cpu.items()}
    same = dict(contact=int(np.count_nonzero(result.contact != current.contact)),
                zone=int(np.count_nonzero(result.cohesive != current.cohesive)),
                adhesive_load=abs(result.adhesive_load / current.adhesive_load - 1) if current.adhesive_load else 0.0)
    print(f"{'':>7} former zone updates: {result.iterations} + {result.coarse_iterations} CG iterations, CPU ratio "
          f"{median['former'] / median['plain']:.2f} against {median['current'] / median['plain']:.2f} now (interleaved, "
          f"plain {1e3 * median['plain']:.1f} ms); states differ by {same['contact']} contact and {same['zone']} zone "
          f"elements, zone load {same['adhesive_load']:.1e}", flush=True)
    return dict(former_cpu_ratio=median["former"] / median["plain"], current_cpu_ratio=median["current"] / median["plain"],
                former_iterations=result.iterations, former_coarse_iterations=result.coarse_iterations,
                former_difference=same)


def tamaas(h, dx, load, args):
    """memstribo's periodic adhesive solve (load control) and Tamaas' at its mean gap: CPU time, iterations, answer."""
    import tamaas as tm

    from bench_contact import solve_tamaas_quietly
    from memstribo.physics.contact import solve_line_contact

    n = h.size
    start = time.process_time()
    ours = solve_line_contact(h, dx, MODULUS, load=load, periodic=True, tolerance=args.tolerance, max_iterations=20000,
                              cohesive_stress=SIGMA0, cohesive_range=RANGE)
    ours_cpu = time.process_time() - start
    model = tm.ModelFactory.createModel(tm.model_type.basic_1d, [n * dx], [n])
    model.E, model.nu = MODULUS, 0.0  # E* = E / (1 - nu^2)
    surface = np.ascontiguousarray(-h)  # Tamaas: heights of the rigid surface
    solver = tm.PolonskyKeerRey(model, surface, args.tolerance, tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    solver.max_iter = 20000
    adhesion = tm.MaugisAdhesionFunctional(surface)
    adhesion.parameters = {"rho": RANGE, "surface_energy": SIGMA0 * RANGE}  # Dugdale stress w / rho = sigma0
    solver.addFunctionalTerm(adhesion)
    start = time.process_time()
    _, iterations = solve_tamaas_quietly(solver, float(ours.gap.mean()))
    tamaas_cpu = time.process_time() - start
    pressure = np.array(model.traction).ravel()
    contact = np.array(model["gap"]).ravel() <= 0.0
    row = dict(periodic_cpu_ms=1e3 * ours_cpu, periodic_iterations=f"{ours.iterations}+{ours.coarse_iterations}",
               tamaas_cpu_ms=1e3 * tamaas_cpu, tamaas_iterations=iterations, periodic_load=ours.load,
               tamaas_load=float(pressure.sum() * dx),
               tamaas_pressure_l2=float(np.linalg.norm(pressure - ours.pressure) / np.linalg.norm(ours.pressure)),
               tamaas_contact_difference=int(np.count_nonzero(contact != ours.contact)))
    print(f"{'':>7} periodic: memstribo {row['periodic_cpu_ms']:.1f} ms CPU ({row['periodic_iterations']} iterations), "
          f"Tamaas {row['tamaas_cpu_ms']:.1f} ms ({iterations} iterations) at the same mean gap: load "
          f"{row['tamaas_load']:.5g} against {row['periodic_load']:.5g} N/m, pressure difference "
          f"{row['tamaas_pressure_l2']:.1e} (L2, relative), {row['tamaas_contact_difference']} contact elements differ",
          flush=True)
    return row


def main(argv=None):
    from memstribo.physics.contact import solve_line_contact
    from memstribo.heap import keep_freed_memory


    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 12, 14, 16], help="exponents of N")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--json", help="write the rows to this file")
    parser.add_argument("--seed", type=int, default=0, help="seed of the rough profile (bench_contact.problem)")
    parser.add_argument("--former", action="store_true",
                        help="also time the former inner solves of the zone updates (CPU ratio to the plain solve)")
    parser.add_argument("--tamaas", action="store_true",
                        help="cross-check against Tamaas' adhesive solve on the periodic problem (needs tamaas)")
    parser.add_argument("--system-malloc", action="store_true",
                        help="leave glibc's allocator as it is (default: memstribo.heap.keep_freed_memory, as the CLI)")
    args = parser.parse_args(argv)
    heap = False if args.system_malloc else keep_freed_memory()
    print(f"freed memory kept in the heap (memstribo.heap): {heap}")
    rows = []
    print(f"{'N':>7} {'plain [ms]':>11} {'adhesive [ms]':>14} {'ratio':>6} {'CPU ratio':>10} {'contact %':>10} "
          f"{'adh. contact %':>15} {'zone %':>7} {'updates':>8} converged")
    for exponent in args.sizes:
        h, dx, mean_pressure = problem(exponent, seed=args.seed)
        load = mean_pressure * h.size * dx
        plain_time, plain_cpu, plain = timed(lambda: solve_line_contact(h, dx, MODULUS, load=load, tolerance=args.tolerance,
                                                             max_iterations=20000), args.repeat)
        adhesive_time, adhesive_cpu, adhesive = timed(lambda: solve_line_contact(
            h, dx, MODULUS, load=load, tolerance=args.tolerance, max_iterations=20000, cohesive_stress=SIGMA0,
            cohesive_range=RANGE), args.repeat)
        updates = adhesive.message.split(" after ")[1].split(" cohesive")[0]
        row = dict(n=h.size, plain_ms=1e3 * plain_time, adhesive_ms=1e3 * adhesive_time,
                   ratio=adhesive_time / plain_time, plain_cpu_ms=1e3 * plain_cpu, adhesive_cpu_ms=1e3 * adhesive_cpu,
                   cpu_ratio=adhesive_cpu / plain_cpu, contact=plain.contact.mean(),
                   adhesive_contact=adhesive.contact.mean(), zone=adhesive.cohesive.mean(), updates=int(updates),
                   converged=bool(plain.converged and adhesive.converged),
                   load_balance=abs(adhesive.load - load) / load)
        row.update(iterations=adhesive.iterations, coarse_iterations=adhesive.coarse_iterations,
                   plain_iterations=plain.iterations, plain_coarse_iterations=plain.coarse_iterations)
        rows.append(row)
        print(f"{row['n']:>7} {row['plain_ms']:>11.2f} {row['adhesive_ms']:>14.2f} {row['ratio']:>6.2f} "
              f"{row['cpu_ratio']:>10.2f} {100 * row['contact']:>10.1f} {100 * row['adhesive_contact']:>15.1f} {100 * row['zone']:>7.1f} "
              f"{row['updates']:>8} {row['converged']}", flush=True)
        print(f"{'':>7} CG iterations (fine + coarse grids): plain {plain.iterations} + {plain.coarse_iterations}, "
              f"adhesive {adhesive.iterations} + {adhesive.coarse_iterations}; CPU plain {row['plain_cpu_ms']:.1f} ms, "
              f"adhesive {row['adhesive_cpu_ms']:.1f} ms", flush=True)
        if args.former:
            row.update(former(h, dx, load, args, adhesive))
        if args.tamaas:
            row.update(tamaas(h, dx, load, args))
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return rows


if __name__ == "__main__":
    main()
