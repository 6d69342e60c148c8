"""Benchmark: the uncertainty study (issue 27 item 6, MODEL 7d).

Cases (``--case``, several allowed):

- ``samples``: P(stiction) over 64 realisations x 16 constant sets (1024 samples; ``--realisations``,
  ``--sets``) of the default cycle, every constant sampled, Sobol' indices off; ``--solve-sets G`` gives
  the constants that need a contact solve G values per realisation (default: all 16; the interval is
  widened by the design effect of the samples that share a solve), ``--energies-only`` samples only the
  bond energies (the others fixed at nominal: 64 solves, 1024 rescalings). Goal: under 2 minutes on 2 cores.
- ``sobol``: Sobol' indices of 8 constants (vdw_bond_energy, bond_energy, adhesive_width, hamaker_constant,
  cutoff_distance, youngs_modulus, atomic_width, threshold_strain; the others fixed) plus the roughness
  realisation, at N = 256 (``--sobol-samples``): N (8 + 1 + 2) rows. Goal: under 10 minutes on 2 cores.
- ``speedup``: the same batch of cycles (``--cycles``, default 32) on one process and on a local Dask
  cluster of 2 workers. Goal: speed-up >= 1.8. Also the CPU time of the serial run, of each worker and
  of the main process: ``cpu_speedup`` (serial CPU over the busier worker's) is the speed-up an idle
  2-core machine gives if the main process's CPU stays small, whatever the load.
- ``rescale``: one rescaling against one solve of the default cycle, and 16 sets of one cycle at once.
- ``contention``: the CPU time of a cycle alone and in two plain processes at once (no Dask): the part of
  the workers' extra CPU that any two processes pay on the machine.

Each case prints wall time, the number of contact solves and rescalings, and the machine's load
average before and after (the machine may be shared: compare within one run). With ``--workers 0``
the ``samples`` and ``sobol`` cases also give the CPU time of this process split into the contact
solves, the rescalings and the rest (``cpu_*``), and from it the estimated wall time of the full
case on 2 cores (``estimate_2_cores_s``: the CPU time of its solves and rescalings over 2, a perfect
speed-up). ``--profile FILE`` runs the cases under cProfile (write FILE, print the split).

Run:  python bench/bench_uncertainty.py --case samples speedup [--workers 2] [--steps 481] [--json FILE]
      python bench/bench_uncertainty.py --case samples rescale --workers 0 --realisations 8 --sets 16 \
          --solve-sets 2 --profile /tmp/uq.prof
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

SOBOL_CONSTANTS = ("vdw_bond_energy", "bond_energy", "adhesive_width", "hamaker_constant", "cutoff_distance",
                   "youngs_modulus", "atomic_width", "threshold_strain")


def _load():
    return os.getloadavg()[0]


def _client(workers):
    if not workers:
        return None
    from distributed import Client

    from memstribo.simulations.study import local_cluster

    return Client(local_cluster(workers))


class _CpuClock:
    """CPU time of this process in the contact solves and in the rescalings (the study run without workers)."""

    def __init__(self):
        self.solve = self.rescale = 0.0
        self.saved = []

    def __enter__(self):
        import memstribo.uncertainty.rescale as rescale
        import memstribo.uncertainty.study as study

        def timed(module, name, field):
            original = getattr(module, name)

            def wrapper(*a, **k):
                start = time.process_time()
                try:
                    return original(*a, **k)
                finally:
                    setattr(self, field, getattr(self, field) + time.process_time() - start)
            self.saved.append((module, name, original))
            setattr(module, name, wrapper)

        timed(study, "_solve_cycle", "solve")
        timed(rescale, "rescale_cycles", "rescale")
        self.start = time.process_time()
        return self

    def __exit__(self, *exc):
        self.total = time.process_time() - self.start
        for module, name, original in self.saved:
            setattr(module, name, original)
        return False

    def split(self, solves, rescalings) -> dict:
        return {"cpu_s": self.total, "cpu_solves_s": self.solve, "cpu_rescalings_s": self.rescale,
                "cpu_other_s": self.total - self.solve - self.rescale,
                "cpu_per_solve_s": self.solve / max(solves, 1),
                "cpu_per_rescaling_s": self.rescale / max(rescalings, 1)}


def _study(args, params, clock, **kwargs):
    from memstribo.uncertainty.study import uncertainty_study

    client = _client(args.workers)
    try:
        start = time.perf_counter()
        if clock is not None:
            with clock:
                result = uncertainty_study(params, client=client, **kwargs)
        else:
            result = uncertainty_study(params, client=client, **kwargs)
        return result, time.perf_counter() - start
    finally:
        if client is not None:
            client.close()


def case_samples(args, params):
    from memstribo.uncertainty.priors import priors_for

    priors = priors_for(params)
    fixed = [n for n in priors if n not in ("bond_energy", "vdw_bond_energy")] if args.energies_only else []
    R, S = args.realisations, args.sets
    clock = _CpuClock() if not args.workers else None
    result, wall = _study(args, params, clock, samples=R * S, realisations=R, steps=args.steps, sensitivity=False,
                          fixed=fixed, solve_sets=args.solve_sets)
    out = {"case": "samples", "realisations": R, "sets": S, "samples": result["samples"],
           "solve_sets": args.solve_sets, "energies_only": args.energies_only, "wall_s": wall,
           "solves": result["solves"], "rescalings": result["rescalings"], "p": result["stiction_probability_text"],
           "ci": result["stiction_probability_ci"], "design_effect": result["design_effect"],
           "p_nominal": result["stiction_probability_nominal_text"], "margin_quantiles": result["margin_quantiles"]}
    if clock is not None:
        out.update(clock.split(result["solves"], result["rescalings"]))
        # the full case (64 x 16): its solves and rescalings at the measured CPU cost each, on 2 cores
        G = 1 if args.energies_only else min(args.solve_sets or 16, 16)
        solves, rescalings = 64 + 64 * G, 1024
        out["estimate_2_cores_s"] = 0.5 * (solves * out["cpu_per_solve_s"] + rescalings * out["cpu_per_rescaling_s"])
        out["estimate_for"] = f"64 x 16 samples: {solves} solves, {rescalings} rescalings, perfect speed-up"
    return out


def case_sobol(args, params):
    from memstribo.uncertainty.priors import priors_for

    fixed = [n for n in priors_for(params) if n not in SOBOL_CONSTANTS]
    clock = _CpuClock() if not args.workers else None
    result, wall = _study(args, params, clock, samples=16, realisations=16, steps=args.steps, fixed=fixed,
                          sobol_samples=args.sobol_samples, sobol_steps=args.sobol_steps, critical=False,
                          decision={"depth": args.decision})
    ranking = [(n, round(s["total"], 3)) for n, s in result["sensitivity"].items()]
    out = {"case": "sobol", "constants": len(SOBOL_CONSTANTS), "base_samples": args.sobol_samples,
           "rows": result["sobol_design"]["rows"], "sobol_steps": result["sobol_design"]["steps"], "wall_s": wall,
           "solves": result["solves"], "rescalings": result["rescalings"], "ranking": ranking,
           "decision_depth": result.get("decision_depth")}
    if clock is not None:
        out.update(clock.split(result["solves"], result["rescalings"]))
    return out


def _warm_up():
    """One short cycle: imports and the compiled zone kernel (numba) ready, as in a long study."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh

    simulate_mesh(get_parameter_values(), steps=5)
    return True


def _cpu_now():
    return time.process_time()


def case_speedup(args, params):
    """Wall time of the same cycles serial and on 2 workers; and the CPU time each side spent, so that the
    speed-up an idle machine would give can be told from the one a shared machine allows: serial CPU over
    the busier worker's CPU (``cpu_speedup``; the main process's CPU, the scheduler's, is given beside it)."""
    from memstribo.uncertainty.study import _Runner

    points = [(r, {}) for r in range(args.cycles)]
    timings, cpu = {}, {}
    for workers in (0, 2):
        client = _client(workers)
        try:
            if client is not None:  # start-up of the workers (imports, compilation) is not the speed-up
                client.run(_warm_up)
            else:
                _warm_up()
            runner = _Runner(params, None, args.steps, None, 1.0, client, False)
            before = client.run(_cpu_now) if client is not None else {}
            main = time.process_time()
            start = time.perf_counter()
            runner.summaries(points)
            timings[workers] = time.perf_counter() - start
            cpu[workers] = {"main": time.process_time() - main}
            if client is not None:
                after = client.run(_cpu_now)
                cpu[workers]["workers"] = sorted(after[w] - before[w] for w in after)
        finally:
            if client is not None:
                client.close()
    busiest = max(cpu[2]["workers"])
    return {"case": "speedup", "cycles": args.cycles, "serial_s": timings[0], "two_workers_s": timings[2],
            "speedup": timings[0] / timings[2], "serial_cpu_s": cpu[0]["main"], "workers_cpu_s": cpu[2]["workers"],
            "main_cpu_with_workers_s": cpu[2]["main"], "cpu_speedup": cpu[0]["main"] / busiest}


def _cycles_cpu(first, n, steps):
    """CPU time per cycle [s] of ``n`` default cycles (realisations ``first``...) in this process."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh

    params = get_parameter_values()
    _warm_up()
    start = time.process_time()
    for r in range(first, first + n):
        simulate_mesh(params, realisation=r, steps=steps)
    return (time.process_time() - start) / n


def case_contention(args, params):
    """CPU time of a cycle alone and with two plain processes side by side (no Dask): what running two
    at once costs on this machine, apart from Dask (``--cycles`` per process, default 32; 12 is enough)."""
    import multiprocessing

    n = max(1, args.cycles // 2)
    alone = _cycles_cpu(0, n, args.steps)
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        pair = pool.starmap(_cycles_cpu, [(0, n, args.steps), (n, n, args.steps)])
    return {"case": "contention", "cycles_each": n, "cpu_per_cycle_alone_s": alone, "cpu_per_cycle_pair_s": pair,
            "cost_of_a_pair": sum(pair) / 2 / alone - 1.0}


def case_rescale(args, params):
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.uncertainty.rescale import reduce_cycle, rescale_cycle, rescale_cycles

    start = time.process_time()
    cycle = reduce_cycle(simulate_mesh(params, steps=args.steps))
    solve = time.process_time() - start
    sets = [{"vdw_bond_energy": 1e-20 * (1 + k / 16), "bond_energy": 4e-19} for k in range(16)]
    start = time.process_time()
    for overrides in sets:
        rescale_cycle(cycle, params, overrides)
    one = (time.process_time() - start) / len(sets)
    start = time.process_time()
    base = summarize(cycle)
    rescale_cycles(cycle, params, sets, base=base)
    many = (time.process_time() - start) / len(sets)
    return {"case": "rescale", "cpu_solve_s": solve, "cpu_rescale_one_s": one, "cpu_rescale_per_set_of_16_s": many}


CASES = {"samples": case_samples, "sobol": case_sobol, "speedup": case_speedup, "rescale": case_rescale,
         "contention": case_contention}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", nargs="+", choices=sorted(CASES), default=["rescale", "speedup", "samples"])
    parser.add_argument("--workers", type=int, default=2, help="Dask workers of the samples and sobol cases (0: none)")
    parser.add_argument("--steps", type=int, default=None, help="steps of each cycle (default mesh_steps, 481)")
    parser.add_argument("--realisations", type=int, default=64, help="realisations of the samples case")
    parser.add_argument("--sets", type=int, default=16, help="constant sets per realisation of the samples case")
    parser.add_argument("--solve-sets", type=int, default=None)
    parser.add_argument("--energies-only", action="store_true")
    parser.add_argument("--sobol-samples", type=int, default=256)
    parser.add_argument("--sobol-steps", type=int, default=None)
    parser.add_argument("--decision", choices=("regional", "full"), default="regional",
                        help="sobol case: the decision's sensitivity after the Sobol' indices: 'regional' (on the "
                             "samples and rows, no cycle more: the Sobol' analysis alone, issue 40's goal) or 'full' "
                             "(each constant at the ends of its prior and the robust-Bayes bands, as mesh --sobol)")
    parser.add_argument("--cycles", type=int, default=32)
    parser.add_argument("--profile", metavar="FILE", help="run the cases under cProfile, write FILE, print the split")
    parser.add_argument("--json", metavar="FILE", help="append one JSON line per case")
    args = parser.parse_args()
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    profiler = None
    if args.profile:
        import cProfile

        profiler = cProfile.Profile()
        profiler.enable()
    for name in args.case:
        before = _load()
        out = CASES[name](args, params)
        out.update({"load_before": before, "load_after": _load(), "cpus": os.cpu_count(),
                    "time": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "workers": args.workers,
                    "profiled": bool(profiler)})
        print(json.dumps(out))
        if args.json:
            with open(args.json, "a", encoding="utf-8") as handle:
                handle.write(json.dumps(out) + "\n")
    if profiler is not None:
        profiler.disable()
        profiler.dump_stats(args.profile)
        _print_split(args.profile)


def _print_split(path):
    """The profile's time in the meshing cycles (simulate_mesh), the rescalings, and the rest (one process)."""
    import pstats

    stats = pstats.Stats(path)
    cumulative = {}
    for (filename, _, function), (_, _, _, cum, _) in stats.stats.items():
        key = (Path(filename).name, function)
        cumulative[key] = max(cumulative.get(key, 0.0), cum)
    total = stats.total_tt
    solves = cumulative.get(("cycle.py", "simulate_mesh"), 0.0)
    rescale = cumulative.get(("rescale.py", "rescale_cycles"), 0.0)
    print(json.dumps({"profile": path, "total_s": total, "solves_s": solves, "rescalings_s": rescale,
                      "other_s": total - solves - rescale}))
    stats.sort_stats("tottime").print_stats(15)


if __name__ == "__main__":
    main()
