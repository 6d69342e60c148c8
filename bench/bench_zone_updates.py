"""Cohesive-zone updates per small-grid Maugis-Dugdale solve on the design map's heaviest point.

    python bench/bench_zone_updates.py [--sample 300] [--seed 0]

Runs one meshing cycle (one realisation) of the 6 x 6 map's heaviest point (drive torque
3e-8 N*m, face width 4 um: 20 rows, 481 steps), records every small-grid zone solve
(``memstribo.physics.contact.dense._dense_capillary``), and prints the updates per solve (mean, percentiles), then, on a
random sample of those solves: the time per solve and per update, the same solves started cold
(no previous pressure), and with looser zone tolerances (``_FRACTION_TOLERANCE`` and
``_ZONE_LOAD_TOLERANCE``), with how many solves settle in another state (zone fraction sum
differing by more than 0.05 of an element). bench/results-map.txt, entries 6 (the numpy loop) and 7
(the compiled loop), read these.
"""

from __future__ import annotations

import argparse
import random
import time

import numpy as np


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sample", type=int, default=300, help="solves re-run for the variants (default 300)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the sample (default 0)")
    args = parser.parse_args()
    if args.sample < 1:
        parser.error(f"--sample must be a whole number >= 1, not {args.sample}")

    from memstribo.parameters import get_parameter_values
    import dataclasses

    from memstribo.physics.contact import DEFAULTS
    from memstribo.physics.contact import dense as contact
    from memstribo.simulations.design_map import map_point

    params = get_parameter_values().updated({"drive_torque": 3e-8, "face_width": 4e-6, "realisations": 1})
    map_point(params, steps=11)  # imports and caches, not counted
    problems = []
    original = contact._dense_capillary

    def recorded(*problem, settings):
        state = original(*problem, settings=settings)
        problems.append((problem, state))
        return state

    contact._dense_capillary = recorded
    try:
        begin = time.process_time()
        map_point(params)
        cpu = time.process_time() - begin
    finally:
        contact._dense_capillary = original
    updates = np.array([s[-1] for _, s in problems if s is not None])
    print(f"one cycle: {cpu:.2f} s CPU, {len(problems)} zone solves on grids of "
          f"{sorted({p[0].size for p, _ in problems})} elements, {len(problems) - updates.size} handed on")
    print(f"updates per solve: mean {updates.mean():.1f}, 5/50/95 % {np.percentile(updates, [5, 50, 95])}, "
          f"max {updates.max()}")

    random.seed(args.seed)
    sample = [p for p, s in random.sample(problems, min(args.sample, len(problems))) if s is not None]
    reference = [original(*p, settings=DEFAULTS) for p in sample]

    def run(label, problems_, settings=DEFAULTS):
        begin = time.perf_counter()
        states = [original(*p, settings=settings) for p in problems_]
        seconds = time.perf_counter() - begin
        done = [(s, r) for s, r in zip(states, reference) if s is not None]
        count = np.array([s[-1] for s, _ in done])
        moved = sum(abs(s[3][~s[2]].sum() - r[3][~r[2]].sum()) > 0.05 for s, r in done)
        print(f"  {label:34s} {count.mean():5.1f} updates  {seconds * 1e3 / len(problems_):6.3f} ms/solve  "
              f"{seconds * 1e6 / count.sum():5.1f} us/update  other state: {moved}  failed: {len(states) - len(done)}")

    print(f"sample of {len(sample)} solves:")
    run("as in the cycle (previous pressure)", sample)
    run("cold start", [p[:7] + (None,) + p[8:] for p in sample])
    for tolerance in (3e-4, 1e-3, 3e-3):
        run(f"zone tolerances {tolerance:g}", sample,
            dataclasses.replace(DEFAULTS, fraction_tolerance=tolerance, zone_load_tolerance=tolerance))


if __name__ == "__main__":
    main()
