"""Speed-up of a study from 1 to 2 Dask workers (LocalCluster, processes, one thread each).

    python bench/bench_study.py [--points 8] [--steps N] [--workers 1 2]

Runs the same study of meshing-cycle points (the default point function, ``mesh``: load
sweep of the thesis case) once per worker count, into fresh temporary folders, and prints
the wall time of each run (cluster start included), the speed-up relative to the first, and
whether the results are identical (they must be). On a machine whose cores are busy with
other work the speed-up is lower than the number of workers; the numbers are this machine's.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time

import numpy as np


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=8, help="number of study points (default 8)")
    parser.add_argument("--steps", type=int, default=None, help="steps per meshing cycle (default: the model's)")
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2], help="worker counts (default 1 2)")
    args = parser.parse_args(argv)

    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.study import run_study, study_spec

    loads = [f"{25 * (i + 1)} uN" for i in range(args.points)]
    fixed = {"steps": args.steps} if args.steps else {}
    spec = study_spec({"name": "bench", "function": "mesh", "fixed": fixed, "grid": {"normal_load": loads}})
    params = get_parameter_values()
    timings, reference = {}, None
    identical = True
    for workers in args.workers:
        with tempfile.TemporaryDirectory() as folder:
            start = time.perf_counter()
            result = run_study(spec, os.path.join(folder, "out"), params, workers=workers)
            timings[workers] = time.perf_counter() - start
            values = result.dataset["friction_force_max"].values
            if result.n_failed:
                raise SystemExit(f"{result.n_failed} point(s) failed: {result.errors}")
            if reference is None:
                reference = values
            else:
                identical &= bool(np.array_equal(reference, values))
    base = timings[args.workers[0]]
    report = {
        "points": args.points,
        "steps": args.steps or params["mesh_steps"],
        "cores": os.cpu_count(),
        "wall_time_s": {str(w): round(t, 2) for w, t in timings.items()},
        "speedup": {str(w): round(base / t, 2) for w, t in timings.items()},
        "identical_results": identical,
    }
    print(json.dumps(report, indent=2))
    return 0 if identical else 1


if __name__ == "__main__":
    raise SystemExit(main())
