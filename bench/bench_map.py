"""Design maps on Dask: points per second on 1 and 2 workers, and the time of a 6 x 6 map.

    python bench/bench_map.py [--points 8] [--realisations 8] [--steps N] [--workers 1 2] [--full]

Part 1 runs the same map (drive torque axis of the thesis pair, ``--points`` values,
``--realisations`` per point) once per worker count (LocalCluster, processes, one thread
each; timed on a started cluster whose workers have imported the model, and with the
cluster start) and prints points per second, the speed-up relative to the
first count, and whether the maps are identical (they must be). Part 2 (``--full``) times
the 6 x 6 map (drive torque x face width) with 8 realisations per point on the default case
on the largest worker count (goal: under 5 minutes on 2 cores). On a machine whose cores are
busy with other work the speed-up is lower than the number of workers.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time

import numpy as np


def _warm():
    """Import the model on a worker (not part of the timing)."""
    import memstribo.simulations.mesh  # noqa: F401

    return True


def _run(spec, workers):
    """(seconds of the map on a started, warmed-up cluster; seconds with the cluster start; result)."""
    import logging

    from distributed import Client, LocalCluster

    from memstribo.simulations.design_map import design_map

    begin = time.perf_counter()
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                      silence_logs=logging.ERROR) as cluster, Client(cluster, set_as_default=False) as client:
        client.run(_warm)
        with tempfile.TemporaryDirectory() as folder:
            start = time.perf_counter()
            result = design_map(spec, os.path.join(folder, "out"), client=client, figures=False)
            seconds = time.perf_counter() - start
    if result.n_failed:
        raise SystemExit(f"{result.n_failed} point(s) failed: {result.errors}")
    return seconds, time.perf_counter() - begin, result


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=8, help="points of the speed-up map (default 8)")
    parser.add_argument("--realisations", type=int, default=8, help="realisations per point (default 8)")
    parser.add_argument("--steps", type=int, default=None, help="steps per meshing cycle (default: the model's)")
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2], help="worker counts (default 1 2)")
    parser.add_argument("--full", action="store_true", help="also time the 6 x 6 map, 8 realisations per point")
    args = parser.parse_args(argv)

    from memstribo.simulations.design_map import map_spec
    from memstribo.parameters import get_parameter_values

    extra = {"steps": args.steps} if args.steps else {}
    spec = map_spec({"name": "bench", "realisations": args.realisations, **extra,
                     "grid": {"drive_torque": {"start": "5e-8 N*m", "stop": "3e-7 N*m", "num": args.points}}})
    timings, totals, reference, identical = {}, {}, None, True
    for workers in args.workers:
        seconds, total, result = _run(spec, workers)
        timings[workers], totals[workers] = seconds, total
        values = result.dataset["stiction_margin_median"].values
        if reference is None:
            reference = values
        else:
            identical &= bool(np.array_equal(reference, values))
    base = timings[args.workers[0]]
    report = {
        "points": args.points,
        "realisations": args.realisations,
        "steps": args.steps or get_parameter_values()["mesh_steps"],
        "cores": os.cpu_count(),
        "wall_time_s": {str(w): round(t, 2) for w, t in timings.items()},
        "wall_time_with_cluster_start_s": {str(w): round(t, 2) for w, t in totals.items()},
        "points_per_second": {str(w): round(args.points / t, 3) for w, t in timings.items()},
        "speedup": {str(w): round(base / t, 2) for w, t in timings.items()},
        "identical_results": identical,
    }
    if args.full:
        full = map_spec({"name": "6 x 6", "realisations": 8, **extra, "grid": {
            "drive_torque": {"start": "3e-8 N*m", "stop": "3e-7 N*m", "num": 6},
            "face_width": {"start": "1 um", "stop": "4 um", "num": 6}}})
        seconds, total, _ = _run(full, max(args.workers))
        report["map_6x6_8_realisations_s"] = round(seconds, 1)
        report["map_6x6_8_realisations_with_cluster_start_s"] = round(total, 1)
        report["map_6x6_workers"] = max(args.workers)
    print(json.dumps(report, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
