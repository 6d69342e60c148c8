"""Benchmark: the adhesive (Maugis-Dugdale) line-contact solve against the non-adhesive one.

The same rough free-boundary problem (the self-affine profile of bench_contact.py, Hurst 0.8,
rms height 1 nm at 2^12 points, grid step 0.244 nm, mean pressure ~16 % contact without
adhesion) is solved at 2^10 to 2^16 points with and without a Maugis-Dugdale zone of the
silicon constants (sigma0 = 16 w / (9 sqrt 3 D0) = 1.78 GPa, h0 = w / sigma0 = 0.249 nm,
w = 0.445 J/m^2; ``memstribo constants``), on one core. The table is the median of
``--repeat`` timed solves after one warm-up solve (the half-plane operator is cached), wall
clock and CPU (process) time; on a shared machine the CPU ratio is the steadier one.

Run:  python bench/bench_adhesive_contact.py [--sizes 10 12 14 16] [--repeat 3] [--json FILE]
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


def main(argv=None):
    from memstribo.physics.contact import solve_line_contact
    from memstribo.heap import keep_freed_memory


    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 12, 14, 16], help="exponents of N")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--json", help="write the rows to this file")
    parser.add_argument("--system-malloc", action="store_true",
                        help="leave glibc's allocator as it is (default: memstribo.heap.keep_freed_memory, as the CLI)")
    args = parser.parse_args(argv)
    heap = False if args.system_malloc else keep_freed_memory()
    print(f"freed memory kept in the heap (memstribo.heap): {heap}")
    rows = []
    print(f"{'N':>7} {'plain [ms]':>11} {'adhesive [ms]':>14} {'ratio':>6} {'CPU ratio':>10} {'contact %':>10} "
          f"{'adh. contact %':>15} {'zone %':>7} {'updates':>8} converged")
    for exponent in args.sizes:
        h, dx, mean_pressure = problem(exponent)
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
        rows.append(row)
        print(f"{row['n']:>7} {row['plain_ms']:>11.2f} {row['adhesive_ms']:>14.2f} {row['ratio']:>6.2f} "
              f"{row['cpu_ratio']:>10.2f} {100 * row['contact']:>10.1f} {100 * row['adhesive_contact']:>15.1f} {100 * row['zone']:>7.1f} "
              f"{row['updates']:>8} {row['converged']}", flush=True)
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return rows


if __name__ == "__main__":
    main()
