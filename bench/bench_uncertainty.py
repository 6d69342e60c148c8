"""Benchmark: the uncertainty study (issue 27 item 6, MODEL 7d).

Cases (``--case``, several allowed):

- ``samples``: P(stiction) over 64 realisations x 16 constant sets (1024 samples) of the default cycle,
  Sobol' indices off; ``--solve-sets G`` gives the constants that need a contact solve G values per
  realisation (default: all 16), ``--energies-only`` samples only the bond energies (the others
  fixed at nominal: 64 solves, 1024 rescalings). Goal: under 2 minutes on 2 cores.
- ``sobol``: Sobol' indices of 8 constants (vdw_bond_energy, bond_energy, adhesive_width, hamaker_constant,
  cutoff_distance, youngs_modulus, atomic_width, threshold_strain; the others fixed) plus the roughness
  realisation, at N = 256 (``--sobol-samples``): N (8 + 1 + 2) rows. Goal: under 10 minutes on 2 cores.
- ``speedup``: the same batch of cycles (``--cycles``, default 32) on one process and on a local Dask
  cluster of 2 workers. Goal: speed-up >= 1.8.
- ``rescale``: one rescaling against one solve of the default cycle.

Each case prints wall time, the number of contact solves and rescalings, and the machine's load
average before and after (the machine may be shared: compare within one run).

Run:  python bench/bench_uncertainty.py --case samples speedup [--workers 2] [--steps 481] [--json FILE]
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


def case_samples(args, params):
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.study import uncertainty_study

    priors = priors_for(params)
    fixed = [n for n in priors if n not in ("bond_energy", "vdw_bond_energy")] if args.energies_only else []
    client = _client(args.workers)
    try:
        start = time.perf_counter()
        result = uncertainty_study(params, samples=64 * 16, realisations=64, steps=args.steps, client=client,
                                   sensitivity=False, fixed=fixed, solve_sets=args.solve_sets)
        wall = time.perf_counter() - start
    finally:
        if client is not None:
            client.close()
    return {"case": "samples", "samples": result["samples"], "solve_sets": args.solve_sets,
            "energies_only": args.energies_only, "wall_s": wall, "solves": result["solves"],
            "rescalings": result["rescalings"], "p": result["stiction_probability_text"],
            "p_nominal": result["stiction_probability_nominal_text"]}


def case_sobol(args, params):
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.study import uncertainty_study

    fixed = [n for n in priors_for(params) if n not in SOBOL_CONSTANTS]
    client = _client(args.workers)
    try:
        start = time.perf_counter()
        result = uncertainty_study(params, samples=16, realisations=16, steps=args.steps, client=client,
                                   fixed=fixed, sobol_samples=args.sobol_samples, sobol_steps=args.sobol_steps,
                                   critical=False)
        wall = time.perf_counter() - start
    finally:
        if client is not None:
            client.close()
    ranking = [(n, round(s["total"], 3)) for n, s in result["sensitivity"].items()]
    return {"case": "sobol", "constants": len(SOBOL_CONSTANTS), "base_samples": args.sobol_samples,
            "rows": result["sobol_design"]["rows"], "sobol_steps": result["sobol_design"]["steps"], "wall_s": wall,
            "solves": result["solves"], "rescalings": result["rescalings"], "ranking": ranking}


def _warm_up():
    """One short cycle: imports and the compiled zone kernel (numba) ready, as in a long study."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh

    simulate_mesh(get_parameter_values(), steps=5)
    return True


def case_speedup(args, params):
    from memstribo.uncertainty.study import _Runner

    points = [(r, {}) for r in range(args.cycles)]
    timings = {}
    for workers in (0, 2):
        client = _client(workers)
        try:
            if client is not None:  # start-up of the workers (imports, compilation) is not the speed-up
                client.run(_warm_up)
            else:
                _warm_up()
            runner = _Runner(params, None, args.steps, None, 1.0, client, False)
            start = time.perf_counter()
            runner.summaries(points)
            timings[workers] = time.perf_counter() - start
        finally:
            if client is not None:
                client.close()
    return {"case": "speedup", "cycles": args.cycles, "serial_s": timings[0], "two_workers_s": timings[2],
            "speedup": timings[0] / timings[2]}


def case_rescale(args, params):
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.uncertainty.rescale import reduce_cycle, rescale_cycle

    start = time.perf_counter()
    cycle = reduce_cycle(simulate_mesh(params, steps=args.steps))
    solve = time.perf_counter() - start
    start = time.perf_counter()
    for k in range(20):
        rescale_cycle(cycle, params, {"vdw_bond_energy": 1e-20 * (1 + k / 20)})
    return {"case": "rescale", "solve_s": solve, "rescale_s": (time.perf_counter() - start) / 20}


CASES = {"samples": case_samples, "sobol": case_sobol, "speedup": case_speedup, "rescale": case_rescale}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", nargs="+", choices=sorted(CASES), default=["rescale", "speedup", "samples"])
    parser.add_argument("--workers", type=int, default=2, help="Dask workers of the samples and sobol cases (0: none)")
    parser.add_argument("--steps", type=int, default=None, help="steps of each cycle (default mesh_steps, 481)")
    parser.add_argument("--solve-sets", type=int, default=None)
    parser.add_argument("--energies-only", action="store_true")
    parser.add_argument("--sobol-samples", type=int, default=256)
    parser.add_argument("--sobol-steps", type=int, default=None)
    parser.add_argument("--cycles", type=int, default=32)
    parser.add_argument("--json", metavar="FILE", help="append one JSON line per case")
    args = parser.parse_args()
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    for name in args.case:
        before = _load()
        out = CASES[name](args, params)
        out.update({"load_before": before, "load_after": _load(), "cpus": os.cpu_count(),
                    "time": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "workers": args.workers})
        print(json.dumps(out))
        if args.json:
            with open(args.json, "a", encoding="utf-8") as handle:
                handle.write(json.dumps(out) + "\n")


if __name__ == "__main__":
    main()
