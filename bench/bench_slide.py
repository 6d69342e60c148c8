"""Benchmark of the sliding models: steps per second for a 1e5-step slide over a 1e5-point profile.

Run: ``python bench/bench_slide.py [--steps N] [--points N] [--repeat R]``. Prints one line per
model with the best wall and CPU times of R runs and the steps per second (the CPU time is the
fairer number on a shared machine); ``--json`` for one object.
The profile is the seeded synthetic thesis roughness (Rq 1.6235 nm, rms slope 0.0241)
sampled at 1 nm; the step is one bond length (0.235 nm), the default of the models.
"""

from __future__ import annotations

import argparse
import json
import time


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=100_000)
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)

    from memstribo.simulations import sliding
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import synthetic_profile

    params = get_parameter_values()
    spacing = 1e-9
    profile = synthetic_profile(args.points * spacing, spacing, params["roughness_rq"],
                                params["roughness_rms_slope"], rng=1)
    step = params["bond_length"]
    distance = (args.steps - 1) * step
    sliding.slide("fixed-load", params, profile, distance=10 * step, step=step)  # imports, caches
    results = {"steps": args.steps, "profile_points": profile.n_points, "step": step}
    for model in ("fixed-gap", "fixed-load"):
        best, best_cpu = float("inf"), float("inf")
        for _ in range(args.repeat):
            start, start_cpu = time.perf_counter(), time.process_time()
            dataset = sliding.slide(model, params, profile, distance=distance, step=step)
            best = min(best, time.perf_counter() - start)
            best_cpu = min(best_cpu, time.process_time() - start_cpu)
        assert dataset.sizes["step"] == args.steps
        results[model] = {"seconds": best, "cpu_seconds": best_cpu, "steps_per_second": args.steps / best}
        if not args.json:
            print(f"{model:>10}: {args.steps} steps over {profile.n_points} profile points in {best:.3f} s wall, "
                  f"{best_cpu:.3f} s CPU ({args.steps / best:,.0f} steps/s, best of {args.repeat})")
    if args.json:
        print(json.dumps(results, indent=2))


if __name__ == "__main__":
    main()
