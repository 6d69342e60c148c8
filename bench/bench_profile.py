"""Benchmark: where the time goes (issue 40 item 1), cProfile of three jobs.

Cases (``--case``, several allowed):

- ``cycle``: one default meshing cycle (``simulate_mesh`` of the default parameters, 481 steps), as
  ``memstribo mesh`` runs it before its refinement.
- ``uncertainty16``: ``uncertainty_study`` with 16 samples and the defaults of ``memstribo mesh --uncertainty 16``
  (Sobol' N = 32 at the study's steps, the decision analysis).
- ``run-uncertainty``: the uncertainty stage of ``memstribo run`` with the run's settings (64 samples, Sobol' N = 8
  at 121 steps, the decision analysis), in this process.
- ``phases``: the same stage (``--steps``, ``--sobol-steps`` to shrink it) without cProfile, its cycles counted by
  the phase that asked for them, with the rows whose contact solve was reused (``solve_cache``).

Each case prints its wall and CPU time, the load average before and after, and the cumulative time of the study's
phases (the samples, the Sobol' rows, critical values, the decision's end points and robust-Bayes bands), the
number of contact solves and rescalings; ``--top N`` prints the N functions with the largest cumulative time.

Run:  python bench/bench_profile.py --case cycle uncertainty16 run-uncertainty [--top 25]
"""

from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import sys
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

#: (module file tail, function name) -> label of the study's phases
PHASES = (("study.py", "_sample", "samples (realisations x constant sets)"),
          ("study.py", "_sensitivity", "Sobol' rows + critical values + curve"),
          ("study.py", "critical_value", "critical values (Brent)"),
          ("decision.py", "critical_value", "critical values (Brent)"),
          ("decision.py", "_regional", "regional sensitivity (KS, bootstrap)"),
          ("decision.py", "_end_points", "decision: end points of each prior"),
          ("decision.py", "_band", "decision: robust-Bayes bands"),
          ("study.py", "_solve_cycle", "contact solves (all)"),
          ("rescale.py", "rescale_cycles", "rescalings (all)"),
          ("study.py", "summarize", "summaries"))


def _case(name):
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    if name == "cycle":
        from memstribo.simulations.mesh import simulate_mesh

        simulate_mesh(params, None)  # imports, compiled kernels, the first synthesis: not the cycle's own cost
        return lambda: simulate_mesh(params, None)
    from memstribo.uncertainty.study import uncertainty_study

    if name == "uncertainty16":
        return lambda: uncertainty_study(params, None, samples=16)
    if name == "run-uncertainty":
        return lambda: uncertainty_study(params, None, samples=64, sobol_samples=8, sobol_steps=121,
                                         decision={"band_samples": 16})
    if name == "phases":
        return lambda: _phases(params, uncertainty_study)
    raise SystemExit(f"unknown case {name}")


def _phases(params, uncertainty_study, steps=None, sobol_steps=121):
    """The run's uncertainty stage with its cycles counted by the phase that asked for them (``--steps``)."""
    import collections
    import inspect

    import memstribo.uncertainty.study as study
    from memstribo.simulations.mesh import solve_cache

    counts, seconds = collections.Counter(), collections.Counter()
    original = study._Runner.summaries
    labels = {"_end_points": "decision: end points", "under": "decision: robust-Bayes bands",
              "_sample": "samples", "uncertainty_study": "nominal realisations"}

    def summaries(self, points):
        names = [f.function for f in inspect.stack()[1:6]]
        label = "critical values (Brent)" if names[0] == "median_margin" else \
            next((labels[n] for n in names if n in labels), "Sobol' rows, curve")
        before, hits, start = self.solves, solve_cache.kept_solves()["hits"], time.perf_counter()
        out = original(self, points)
        counts[label] += self.solves - before
        counts[label + ": rows reused"] += solve_cache.kept_solves()["hits"] - hits
        seconds[label] += time.perf_counter() - start
        return out

    study._Runner.summaries = summaries
    try:
        result = uncertainty_study(params, None, samples=64, steps=_phases.steps, sobol_samples=8,
                                   sobol_steps=_phases.sobol_steps, decision={"band_samples": 16})
    finally:
        study._Runner.summaries = original
    for label in sorted(counts):
        print(f"  {label:45s} {counts[label]:5d} cycles  {seconds.get(label, 0.0):7.1f} s")
    return result


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", nargs="+", default=["cycle"])
    parser.add_argument("--top", type=int, default=0)
    parser.add_argument("--steps", type=int, default=None, help="phases: steps of the study's cycles (default 481)")
    parser.add_argument("--sobol-steps", type=int, default=121, help="phases: steps of the Sobol' rows")
    parser.add_argument("--out", default=None, help="write each case's profile to OUT.<case>.prof")
    args = parser.parse_args(argv)
    _phases.steps, _phases.sobol_steps = args.steps, args.sobol_steps
    print(f"cpus {os.cpu_count()}, OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS')}")
    for name in args.case:
        job = _case(name)
        load0 = os.getloadavg()[0]
        profile = cProfile.Profile()
        wall, cpu = time.perf_counter(), time.process_time()
        profile.enable()
        result = job()
        profile.disable()
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        print(f"\n== {name}: wall {wall:.1f} s, CPU {cpu:.1f} s (under cProfile), load {load0:.2f} -> "
              f"{os.getloadavg()[0]:.2f}")
        if isinstance(result, dict):
            print("  solves", result.get("solves"), "rescalings", result.get("rescalings"),
                  "P(stiction)", result.get("stiction_probability_text"))
        stats = pstats.Stats(profile)
        if args.out:
            stats.dump_stats(f"{args.out}.{name}.prof")
        seen = set()
        for (path, _, function), row in stats.stats.items():
            for tail, fname, label in PHASES:
                if path.endswith(tail) and function == fname and (tail, fname) not in seen:
                    seen.add((tail, fname))
                    print(f"  {label:45s} {row[3]:8.1f} s cumulative, {row[1]:6d} calls  ({tail}:{fname})")
        if args.top:
            stats.sort_stats("cumulative").print_stats(args.top)


if __name__ == "__main__":
    main()
