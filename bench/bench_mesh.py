"""Benchmark of the meshing-cycle simulation: wall/CPU time, peak memory, time per step.

Run: ``python bench/bench_mesh.py [--steps 121 241 481 961] [--across 20 40 80] [--repeat 2] [--profile]
[--ensemble 16 --workers 2] [--json]``, or ``python bench/bench_mesh.py --adhesion maugis none [--repeat 3]``
(only the default cycle's time with and without the Maugis-Dugdale zone, no memory tracing), or
``python bench/bench_mesh.py --cycle --across 40 48 --repeat 3`` (only the CPU time of the default cycle and of the
self-refining cycle of ``memstribo mesh``, issue #25 item 5: under 1.5 s on one core).

1. The default cycle (torque load case, 481 steps, grid sized from the Hertz width: 40 elements
   across 2a, 10 rows each with its own synthetic roughness line)
   with the time of each stage (roughness set-up, contact solves, nanoblocks/bonds) and the peak
   traced memory (``tracemalloc``: numpy's allocations included).
2. How time and memory grow with the number of steps (default grid) and with the grid
   resolution (elements across the Hertz width; default steps).
3. ``--profile``: the 15 most expensive functions of the default cycle (cProfile).
4. ``--ensemble N``: the N-realisation stiction verdict (``mesh.simulate_ensemble``) on Dask's
   local cluster with ``--workers`` single-threaded worker processes (MODEL 7b; goal: 16
   realisations under 60 s on 2 cores).

One core: numpy/scipy are limited to one thread (``OMP_NUM_THREADS=1`` and friends are set
before they are imported; scipy.fft runs with one worker in the contact solver). Imports are
excluded from the timings (a warm-up run comes first). On a shared machine the CPU time is the
fairer number.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402
import tracemalloc  # noqa: E402


def _run(params, steps, repeat):
    from memstribo.simulations.mesh import simulate_mesh

    best = best_cpu = float("inf")
    peak = 0
    for _ in range(repeat):
        tracemalloc.start()
        start, start_cpu = time.perf_counter(), time.process_time()
        dataset = simulate_mesh(params, steps=steps)
        wall, cpu = time.perf_counter() - start, time.process_time() - start_cpu
        peak = max(peak, tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
        best, best_cpu = min(best, wall), min(best_cpu, cpu)
    return dataset, {"steps": steps, "seconds": best, "cpu_seconds": best_cpu, "ms_per_step": 1e3 * best / steps,
                     "peak_memory_mb": peak / 2**20,
                     "mean_iterations": float(dataset.contact_iterations.mean())}


def _stages(params):
    """Time of the stages of one default cycle: set-up, contact solves, nanoblocks and bonds."""
    import cProfile
    import pstats

    from memstribo.simulations.mesh import simulate_mesh

    profiler = cProfile.Profile()
    profiler.enable()
    simulate_mesh(params)
    profiler.disable()
    stats = pstats.Stats(profiler)
    table = {f"{func[0].split('/')[-1]}:{func[2]}": value[3] for func, value in stats.stats.items()}
    total = table.get("mesh.py:simulate_mesh", float("nan"))
    setup = table.get("mesh.py:_prepare", float("nan"))
    contact = table.get("mesh.py:_solve_contacts", float("nan"))
    return stats, {"total": total, "setup_roughness": setup, "contact_solves": contact,
                   "nanoblocks_bonds_output": total - setup - contact}


def _adhesion_only(values, repeat):
    """Wall and CPU seconds of the default cycle per contact_adhesion, without tracemalloc (it slows numpy)."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh, summarize

    base = get_parameter_values()
    simulate_mesh(base, steps=21)  # warm-up
    load = os.getloadavg()
    out = {"load_average_before": load, "cycles": []}
    for value in values:
        params = base.updated({"contact_adhesion": value})
        best = best_cpu = float("inf")
        for _ in range(max(repeat, 1)):
            start, start_cpu = time.perf_counter(), time.process_time()
            dataset = simulate_mesh(params)
            best = min(best, time.perf_counter() - start)
            best_cpu = min(best_cpu, time.process_time() - start_cpu)
        summary = summarize(dataset)
        out["cycles"].append({"contact_adhesion": value, "seconds": round(best, 3), "cpu_seconds": round(best_cpu, 3),
                              "cof_mean": summary["cof_mean"], "unconverged_steps": summary["unconverged_steps"]})
    out["load_average_after"] = os.getloadavg()
    print(json.dumps(out, indent=2))
    return 0


def _cycle_only(across, repeat):
    """CPU seconds (best of ``repeat``) of the default cycle and of the self-refining cycle (``memstribo mesh``:
    :func:`refined_cycle`, realisation 0) at each number of elements across 2a, with the load average."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.simulations.mesh.convergence import refined_cycle

    base = get_parameter_values()
    simulate_mesh(base, steps=base["mesh_steps"])  # warm-up: the compiled zone loop, caches
    out = {"load_average_before": os.getloadavg(), "cycles": []}
    for value in across:
        params = base.updated({"mesh_elements_across_contact": value})
        point = {"elements_across_contact": value}
        for name, run in (("cycle_cpu_seconds", lambda: simulate_mesh(params, steps=params["mesh_steps"])),
                          ("refined_cpu_seconds", lambda: refined_cycle(params))):
            best = float("inf")
            for _ in range(max(repeat, 1)):
                start = time.process_time()
                run()
                best = min(best, time.process_time() - start)
            point[name] = round(best, 3)
        out["cycles"].append(point)
    out["load_average_after"] = os.getloadavg()
    print(json.dumps(out, indent=2))
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, nargs="+", default=[121, 241, 481, 961])
    parser.add_argument("--across", type=int, nargs="+", default=[20, 40, 80],
                        help="contact elements across the largest Hertz width 2a")
    parser.add_argument("--ensemble", type=int, default=0, help="also time an ensemble of N realisations on Dask")
    parser.add_argument("--workers", type=int, default=2, help="Dask worker processes for --ensemble")
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--profile", action="store_true", help="print the 15 most expensive functions")
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--adhesion", nargs="+", choices=("maugis", "none"),
                        help="only time the default cycle with each contact_adhesion (no memory tracing, best of "
                             "--repeat) and stop")
    parser.add_argument("--cycle", action="store_true",
                        help="only the CPU time of the default cycle and of the self-refining cycle (memstribo mesh) "
                             "at each --across (best of --repeat) and stop")
    args = parser.parse_args(argv)
    if args.adhesion:
        return _adhesion_only(args.adhesion, args.repeat)
    if args.cycle:
        return _cycle_only(args.across, args.repeat)

    import numpy as np
    import scipy

    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    _run(params, 21, 1)  # warm-up: imports, FFT plans, caches
    results = {"numpy": np.__version__, "scipy": scipy.__version__, "fft": "scipy.fft (pocketfft), 1 worker",
               "threads": os.environ.get("OMP_NUM_THREADS")}
    _, default = _run(params, params["mesh_steps"], args.repeat)
    results["default_cycle"] = default
    stats, stages = _stages(params)
    results["stages_seconds"] = stages
    results["vs_steps"] = [_run(params, n, args.repeat)[1] for n in args.steps]
    results["vs_grid"] = []
    for across in args.across:
        dataset, point = _run(params.updated({"mesh_elements_across_contact": across}), params["mesh_steps"],
                              args.repeat)
        point["grid_spacing_nm"] = dataset.attrs["grid_spacing"] * 1e9
        point["elements_per_step"] = int(round(dataset.attrs["window"] / dataset.attrs["grid_spacing"]))
        results["vs_grid"].append(point)
    if args.ensemble:
        from distributed import Client

        from memstribo.simulations.mesh import simulate_ensemble
        from memstribo.simulations.study import local_cluster

        with local_cluster(args.workers) as cluster, Client(cluster) as client:
            client.run(lambda: __import__("memstribo.simulations.mesh"))  # warm the workers' imports
            start = time.perf_counter()
            ensemble = simulate_ensemble(params, realisations=args.ensemble, client=client)
            results["ensemble"] = {"realisations": args.ensemble, "workers": args.workers,
                                   "seconds": time.perf_counter() - start,
                                   "stiction_probability": ensemble["stiction_probability"]}
    if args.json:
        print(json.dumps(results, indent=2))
        return 0
    d = default
    print(f"default cycle ({d['steps']} steps, load case {params['load_case']}): "
          f"{d['seconds']:.2f} s wall, {d['cpu_seconds']:.2f} s CPU, "
          f"{d['ms_per_step']:.2f} ms/step, peak memory {d['peak_memory_mb']:.1f} MB, "
          f"{d['mean_iterations']:.1f} CG iterations per solve (mean)")
    print("stages [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in stages.items()) + " (under cProfile)")
    print(f"{'steps':>6} {'wall s':>8} {'CPU s':>8} {'ms/step':>8} {'peak MB':>8}")
    for r in results["vs_steps"]:
        print(f"{r['steps']:>6} {r['seconds']:8.2f} {r['cpu_seconds']:8.2f} {r['ms_per_step']:8.2f} "
              f"{r['peak_memory_mb']:8.1f}")
    print(f"{'grid nm':>7} {'elements':>8} {'wall s':>8} {'CPU s':>8} {'ms/step':>8} {'peak MB':>8} {'CG it':>6}")
    for r in results["vs_grid"]:
        print(f"{r['grid_spacing_nm']:>7g} {r['elements_per_step']:>8} {r['seconds']:8.2f} {r['cpu_seconds']:8.2f} "
              f"{r['ms_per_step']:8.2f} {r['peak_memory_mb']:8.1f} {r['mean_iterations']:6.1f}")
    if "ensemble" in results:
        e = results["ensemble"]
        print(f"ensemble: {e['realisations']} realisations on {e['workers']} Dask workers: {e['seconds']:.1f} s "
              f"(stiction probability {e['stiction_probability']:.2f})")
    print(f"({results['fft']}; numpy {results['numpy']}, scipy {results['scipy']}; "
          f"OMP_NUM_THREADS={results['threads']})")
    if args.profile:
        stats.sort_stats("cumulative").print_stats(15)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
