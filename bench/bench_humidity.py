"""Benchmark of the humidity sweep (issue #17): ``memstribo sweep humidity --values 0:0.95:0.05`` on one core.

Run: ``python bench/bench_humidity.py [--values 0:0.95:0.05] [--coating OTS] [--repeat 1] [--json]``.

1. The command itself, as a user runs it (``python -m memstribo.cli.main sweep humidity ...
   --json`` in a subprocess, ``OMP_NUM_THREADS=1`` and friends): wall time, and CPU time of the
   child (``resource.getrusage``), start-up and imports included. Goal (issue #17): under 1 minute.
2. In process (imports excluded, after a warm-up): the same sweep through
   :func:`memstribo.simulations.mesh.sweep`, with the time per point, and how many contact-solver updates of
   the cohesive/capillary zone each solve needed (from the solver's messages).

On a shared machine the CPU time is the fairer number; the load average is printed beside it.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import json  # noqa: E402
import resource  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402


def _command(values, coating):
    argv = [sys.executable, "-m", "memstribo.cli.main", "sweep", "humidity", "--values", values, "--json"]
    if coating:
        argv += ["--coating", coating, "--wear", "0"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(argv, capture_output=True, text=True, env=dict(os.environ), check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"the command failed ({done.returncode}): {done.stderr[-2000:]}")
    out = json.loads(done.stdout)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return out, {"seconds": wall, "cpu_seconds": cpu, "points": len(out["points"]),
                 "critical_humidity": out.get("critical_humidity")}


def _in_process(values, coating):
    from memstribo.cli.sweep import parse_values
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_mesh, sweep
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.5}), steps=21)  # warm-up
    coat = get_coating(coating, params) if coating else None
    start, start_cpu = time.perf_counter(), time.process_time()
    points = sweep(params, "humidity", parse_values(values, ""), coating=coat, wear=0.0 if coat else 1.0)
    wall, cpu = time.perf_counter() - start, time.process_time() - start_cpu
    return {"seconds": wall, "cpu_seconds": cpu, "points": len(points), "seconds_per_point": wall / len(points)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--values", default="0:0.95:0.05")
    parser.add_argument("--coating", help="e.g. OTS (fully coated gear, wear 0); default bare")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--in-process", action="store_true", help="also time the sweep in process")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)

    import numpy as np
    import scipy

    results = {"numpy": np.__version__, "scipy": scipy.__version__, "threads": os.environ.get("OMP_NUM_THREADS"),
               "load_average_before": os.getloadavg()}
    runs = [_command(args.values, args.coating)[1] for _ in range(args.repeat)]
    results["command"] = min(runs, key=lambda r: r["cpu_seconds"])
    if args.in_process:
        results["in_process"] = _in_process(args.values, args.coating)
    results["load_average_after"] = os.getloadavg()
    if args.json:
        print(json.dumps(results, indent=2))
        return 0
    c = results["command"]
    what = f"memstribo sweep humidity --values {args.values}" + (f" --coating {args.coating} --wear 0"
                                                                 if args.coating else "")
    print(f"{what}: {c['points']} points, {c['seconds']:.1f} s wall, {c['cpu_seconds']:.1f} s CPU "
          f"(goal < 60 s; critical humidity {c['critical_humidity']})")
    if "in_process" in results:
        r = results["in_process"]
        print(f"in process: {r['seconds']:.1f} s wall, {r['cpu_seconds']:.1f} s CPU, "
              f"{r['seconds_per_point']:.2f} s per point")
    print(f"(numpy {results['numpy']}, scipy {results['scipy']}, OMP_NUM_THREADS={results['threads']}; load "
          f"average before {results['load_average_before'][0]:.2f}, after {results['load_average_after'][0]:.2f})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
