"""Design maps on Dask: points per second on 1 and 2 workers, and the time of a 6 x 6 map.

    python bench/bench_map.py [--points 8] [--realisations 8] [--steps N] [--workers 1 2] [--full]
    python bench/bench_map.py --only-full [--workers 2]    # the 6 x 6 map with 8 realisations only
    python bench/bench_map.py --cycle 8                    # seconds per meshing cycle of one map point

Part 1 runs the same map (drive torque axis of the thesis pair, ``--points`` values,
``--realisations`` per point) once per worker count (LocalCluster, processes, one thread
each; timed on a started cluster whose workers have imported the model, and with the
cluster start) and prints points per second, the speed-up relative to the
first count, and whether the maps are identical (they must be). Part 2 (``--full``) times
the 6 x 6 map (drive torque x face width) with 8 realisations per point on the default case
on the largest worker count (goal: under 5 minutes on 2 cores); ``--only-full`` runs part 2
alone. Each map also reports the load average before and after, the workers' busy time per
meshing cycle (the ``seconds`` of every point file over the cycles) and the rest of the wall
time x workers (cluster start, scheduling, serialisation, idle workers at the end).
``--cycle N`` times one map point of the default case with N realisations in this process
(no Dask): wall and CPU seconds per meshing cycle, and the share of the contact solves. On a
machine whose cores are busy with other work the speed-up is lower than the number of workers.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time

import numpy as np


def _warm():
    """Import the model on a worker, and load the compiled zone solve from numba's cache (not part of the timing)."""
    import memstribo.simulations.mesh  # noqa: F401
    from memstribo.physics.contact import solve_line_contact

    x = (np.arange(64) - 32) * 1e-9
    solve_line_contact(x**2 / 2e-5, 1e-9, 1e11, load=1.0, cohesive_stress=1e9, cohesive_range=3e-10)
    return True


def _run(spec, workers):
    """(seconds of the map on a started, warmed-up cluster; seconds with the cluster start; result; busy times)."""
    from distributed import Client

    from memstribo.simulations.design_map import design_map
    from memstribo.simulations.study import local_cluster

    begin = time.perf_counter()
    with local_cluster(workers) as cluster, Client(cluster, set_as_default=False) as client:
        client.run(_warm)
        with tempfile.TemporaryDirectory() as folder:
            start = time.perf_counter()
            result = design_map(spec, os.path.join(folder, "out"), client=client, figures=False)
            seconds = time.perf_counter() - start
            busy = sum(json.loads(p.read_text())["seconds"] for p in (result.folder / "points").glob("*.json"))
    if result.n_failed:
        raise SystemExit(f"{result.n_failed} point(s) failed: {result.errors}")
    cycles = result.n_points * spec.realisations
    busy = {"worker_seconds_per_cycle": round(busy / cycles, 3),
            "overhead_worker_seconds": round(seconds * workers - busy, 1)}
    return seconds, time.perf_counter() - begin, result, busy


def _cycle(realisations, steps=None):
    """Seconds per meshing cycle of one map point (default case) in this process: wall, CPU, contact share."""
    from memstribo.physics import contact
    from memstribo.simulations.design_map import map_point
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values().updated({"drive_torque": 1e-7, "face_width": 2e-6})
    map_point(params.updated({"realisations": 1}), steps=11)  # imports and caches, not timed
    spent = [0.0]
    original = contact.solve_line_contact

    def timed(*args, **kwargs):
        begin = time.perf_counter()
        try:
            return original(*args, **kwargs)
        finally:
            spent[0] += time.perf_counter() - begin

    load = os.getloadavg()
    contact.solve_line_contact = timed
    try:
        cpu, wall = time.process_time(), time.perf_counter()
        values = map_point(params.updated({"realisations": realisations}), steps=steps)
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    finally:
        contact.solve_line_contact = original
    return {"cycle_realisations": realisations, "steps": steps or params["mesh_steps"],
            "cycle_wall_s": round(wall / realisations, 3), "cycle_cpu_s": round(cpu / realisations, 3),
            "contact_solve_share": round(spent[0] / wall, 3), "load_average_before": [round(v, 2) for v in load],
            "load_average_after": [round(v, 2) for v in os.getloadavg()],
            "stiction_margin_median": values["stiction_margin_median"]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=8, help="points of the speed-up map (default 8)")
    parser.add_argument("--realisations", type=int, default=8, help="realisations per point (default 8)")
    parser.add_argument("--steps", type=int, default=None, help="steps per meshing cycle (default: the model's)")
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2], help="worker counts (default 1 2)")
    parser.add_argument("--full", action="store_true", help="also time the 6 x 6 map, 8 realisations per point")
    parser.add_argument("--contact-adhesion", choices=("maugis", "none"), default=None,
                        help="fix contact_adhesion in the maps (default: the model's, maugis)")
    parser.add_argument("--only-full", action="store_true", help="time the 6 x 6 map only (on the largest --workers)")
    parser.add_argument("--cycle", type=int, default=None, metavar="N",
                        help="only time one map point with N realisations in this process (seconds per cycle)")
    args = parser.parse_args(argv)

    from memstribo.simulations.design_map import map_spec
    from memstribo.parameters import get_parameter_values

    if args.cycle:
        print(json.dumps(_cycle(args.cycle, args.steps), indent=2))
        return 0
    extra = {"steps": args.steps} if args.steps else {}
    if args.contact_adhesion:
        extra["fixed"] = {"contact_adhesion": args.contact_adhesion}
    report = {"cores": os.cpu_count(), "steps": args.steps or get_parameter_values()["mesh_steps"],
              "contact_adhesion": args.contact_adhesion or get_parameter_values()["contact_adhesion"]}
    if not args.only_full:
        spec = map_spec({"name": "bench", "realisations": args.realisations, **extra,
                         "grid": {"drive_torque": {"start": "5e-8 N*m", "stop": "3e-7 N*m", "num": args.points}}})
        timings, totals, busy, reference, identical = {}, {}, {}, None, True
        load = os.getloadavg()
        for workers in args.workers:
            seconds, total, result, busy[workers] = _run(spec, workers)
            timings[workers], totals[workers] = seconds, total
            values = result.dataset["stiction_margin_median"].values
            if reference is None:
                reference = values
            else:
                identical &= bool(np.array_equal(reference, values))
        base = timings[args.workers[0]]
        report.update({
            "points": args.points,
            "realisations": args.realisations,
            "wall_time_s": {str(w): round(t, 2) for w, t in timings.items()},
            "wall_time_with_cluster_start_s": {str(w): round(t, 2) for w, t in totals.items()},
            "points_per_second": {str(w): round(args.points / t, 3) for w, t in timings.items()},
            "speedup": {str(w): round(base / t, 2) for w, t in timings.items()},
            "busy": {str(w): b for w, b in busy.items()},
            "identical_results": identical,
            "load_average_before": [round(v, 2) for v in load],
            "load_average_after": [round(v, 2) for v in os.getloadavg()],
        })
    if args.full or args.only_full:
        full = map_spec({"name": "6 x 6", "realisations": 8, **extra, "grid": {
            "drive_torque": {"start": "3e-8 N*m", "stop": "3e-7 N*m", "num": 6},
            "face_width": {"start": "1 um", "stop": "4 um", "num": 6}}})
        load = os.getloadavg()
        seconds, total, result, busy = _run(full, max(args.workers))
        report["map_6x6_8_realisations_s"] = round(seconds, 1)
        report["map_6x6_8_realisations_with_cluster_start_s"] = round(total, 1)
        report["map_6x6_workers"] = max(args.workers)
        report["map_6x6_busy"] = busy
        report["map_6x6_load_average_before"] = [round(v, 2) for v in load]
        report["map_6x6_load_average_after"] = [round(v, 2) for v in os.getloadavg()]
    print(json.dumps(report, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
