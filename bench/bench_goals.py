"""Benchmark: the goals of issue 40, each against one default cycle measured in the same run of this script.

Cases (``--case``, several allowed; each a command of its own, timed from outside with its start-up):

- ``cycle``: ``memstribo mesh --no-refine --no-step-check --json`` (one default cycle): the baseline every other
  case is divided by.
- ``run``: ``memstribo run --out TMP`` (``--keep DIR``: into DIR) with its defaults. Goal: <= 90 s wall on an idle 2-core machine.
- ``uncertainty256``: ``memstribo mesh --uncertainty 256 --json``. Goal: <= 30 x the baseline cycle.
- ``sobol481``: Sobol' of the decisive constants at the verdict's 481 steps
  (``bench/bench_uncertainty.py --case sobol --steps 481 --sobol-samples 32 --workers 2 --decision regional``: the
  Sobol' indices and the dominant constant's curve; the decision's end points and bands, ``--decision full``, are
  not Sobol'). Goal: <= 5 min.
- ``thesis8um``: ``memstribo mesh --load-case thesis --set face_width=8um --json`` (with its refinement).
  Goal: <= 60 s.
- ``validate-lab``: ``memstribo validate-lab`` (the whole page). Goal: <= 2 min.
- ``ci``: ``python -m pytest -q -m "not slow" -p no:cacheprovider`` (the CI suite). Goal: <= 8 min.

Each line gives the wall time, the ratio to the baseline cycle, the goal, and the load average before and after
(on a shared machine compare the ratios, not the seconds).

Run:  python bench/bench_goals.py --case cycle run uncertainty256 [--timeout 1500]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CLI = [sys.executable, "-m", "memstribo.cli.main"]

#: case -> (command, goal in seconds or None, goal in baseline cycles or None)
CASES = {
    "cycle": (CLI + ["mesh", "--no-refine", "--no-step-check", "--json"], None, None),
    "run": (CLI + ["run", "--out", "{tmp}/run", "--progress", "off"], 90.0, None),
    "uncertainty256": (CLI + ["mesh", "--uncertainty", "256", "--json"], None, 30.0),
    "sobol481": ([sys.executable, str(ROOT / "bench" / "bench_uncertainty.py"), "--case", "sobol", "--steps", "481",
                  "--sobol-samples", "32", "--workers", "2", "--decision", "regional"], 300.0, None),
    "thesis8um": (CLI + ["mesh", "--load-case", "thesis", "--set", "face_width=8um", "--json"], 60.0, None),
    "validate-lab": (CLI + ["validate-lab"], 120.0, None),
    "ci": ([sys.executable, "-m", "pytest", "-q", "-m", "not slow", "-p", "no:cacheprovider"], 480.0, None),
}


def _time(command, timeout):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    load = os.getloadavg()[0]
    start = time.perf_counter()
    try:
        done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True, timeout=timeout)
        code = done.returncode
    except subprocess.TimeoutExpired:
        code = "timeout"
    return time.perf_counter() - start, code, load, os.getloadavg()[0]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", nargs="+", default=["cycle"], choices=list(CASES))
    parser.add_argument("--timeout", type=float, default=1500.0, help="per case [s]")
    parser.add_argument("--keep", default=None, help="write the run's results folder here (its run.json has the "
                        "stages' times) instead of a temporary folder")
    args = parser.parse_args(argv)
    cases = args.case if "cycle" in args.case else ["cycle"] + args.case  # the baseline first
    print(f"cpus {os.cpu_count()}, python {sys.version.split()[0]}")
    baseline = None
    with tempfile.TemporaryDirectory() as tmp:
        for name in cases:
            command, goal_s, goal_cycles = CASES[name]
            command = [part.replace("{tmp}/run", args.keep or f"{tmp}/run") for part in command]
            wall, code, before, after = _time(command, args.timeout)
            baseline = wall if name == "cycle" else baseline
            ratio = wall / baseline if baseline else float("nan")
            goal = (f"goal <= {goal_s:g} s: {'met' if wall <= goal_s else 'NOT met'}" if goal_s else
                    f"goal <= {goal_cycles:g} cycles: {'met' if ratio <= goal_cycles else 'NOT met'}" if goal_cycles
                    else "baseline")
            print(f"{name:15s} wall {wall:8.1f} s = {ratio:6.1f} cycles  exit {code}  {goal}  "
                  f"(load {before:.2f} -> {after:.2f})", flush=True)


if __name__ == "__main__":
    main()
