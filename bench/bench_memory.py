"""Peak memory of the five heaviest commands of memstribo, each in its own process.

    python bench/bench_memory.py [--quick] [--only NAME ...] [--json]

Each command runs as a child process (``python -m memstribo.cli.main ...``) into a fresh temporary
folder; its peak resident memory is the ``ru_maxrss`` that ``os.wait4`` returns for it (the child and
every descendant it waited for: the Dask workers of ``map`` and ``study`` are children of the command
and are counted when they end before it). Wall time and exit status are printed with it. ``--quick``
runs each command at a small size (a check that the script works, not the numbers to quote). The
numbers are this machine's: the memory does not depend on the load of the machine, the times do.

The five commands (issue #29, "peak memory of the five heaviest commands"):

- ``damage``: the default damage stage (its second pass over the x grid of every block);
- ``run``: the whole chain, the default job of the README (``memstribo run``);
- ``mesh --realisations 4``: an ensemble of meshing cycles with the step check;
- ``sweep humidity``: 20 humid-air meshing cycles;
- ``map``: a 6 x 6 design map (drive torque x face width, 4 realisations a point) on one worker.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def commands(folder: Path, quick: bool) -> dict[str, list[str]]:
    """name -> command-line arguments of ``memstribo`` (full size, or small with ``quick``)."""
    steps = ["--steps", "41"] if quick else []
    small_run = folder / "run.toml"
    small_run.write_text('[run]\nstages = ["roughness", "gear", "mesh"]\nvalidation = false\nrealisations = 2\n'
                         'steps = 41\n' if quick else "[run]\n")
    map_spec = folder / "map.toml"
    n = 2 if quick else 6
    map_spec.write_text(f'[map]\nname = "bench"\nrealisations = {2 if quick else 4}\n' + ("steps = 41\n" if quick else "")
                        + f'[map.grid]\ndrive_torque = {{start = "5e-8 N*m", stop = "2e-7 N*m", num = {n}}}\n'
                        f'face_width = {{start = "1 um", stop = "3 um", num = {n}}}\n')
    return {
        "damage": ["damage", "--json"] + (["--steps", "41", "--wear-points", "2"] if quick else []),
        "run": ["run", str(small_run), "--out", str(folder / "run-out"), "--progress", "off", "--quiet"],
        "mesh --realisations 4": ["mesh", "--realisations", "2" if quick else "4", "--json"] + steps,
        "sweep humidity": ["sweep", "humidity", "--values", "0:0.95:0.3" if quick else "0:0.95:0.05",
                           "--set", "environment=air", "--json"] + steps,
        "map": ["map", str(map_spec), "--out", str(folder / "map-out"), "--workers", "1", "--progress", "off",
                "--json"],
    }


def measure(argv: list[str]) -> dict:
    """Run ``memstribo argv`` as a child process: peak RSS [bytes], wall time [s], exit status."""
    start = time.perf_counter()
    process = subprocess.Popen([sys.executable, "-m", "memstribo.cli.main", *argv], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True, cwd=REPO)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    stderr = process.stderr.read() if process.stderr else ""
    process.returncode = os.waitstatus_to_exitcode(status)
    scale = 1 if sys.platform == "darwin" else 1024  # ru_maxrss: bytes on macOS, KiB on Linux
    return {"peak_rss_bytes": usage.ru_maxrss * scale, "wall_seconds": wall, "exit_status": process.returncode,
            "stderr_tail": stderr.strip().splitlines()[-1:] if process.returncode else []}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes: check the script, not numbers to quote")
    parser.add_argument("--only", nargs="+", metavar="NAME", help="measure only these commands (names as listed)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    args = parser.parse_args(argv)
    results = {}
    with tempfile.TemporaryDirectory(prefix="memstribo-bench-memory-") as tmp:
        table = commands(Path(tmp), args.quick)
        for name, command in table.items():
            if args.only and name not in args.only:
                continue
            results[name] = {"command": "memstribo " + " ".join(command).replace(tmp, "TMP"), **measure(command)}
    conditions = {"python": platform.python_version(), "machine": platform.machine(), "cpus": os.cpu_count(),
                  "quick": args.quick, "date_utc": time.strftime("%Y-%m-%d %H:%M", time.gmtime())}
    if args.json:
        print(json.dumps({"conditions": conditions, "results": results}, indent=2))
        return 0
    print(f"peak memory of the heaviest commands ({conditions})")
    print(f"{'command':<24} {'peak RSS':>10} {'wall':>9} {'exit':>5}")
    for name, r in results.items():
        print(f"{name:<24} {r['peak_rss_bytes'] / 2**30:>8.2f} GiB {r['wall_seconds']:>7.1f} s {r['exit_status']:>5}")
        if r["exit_status"]:
            print(f"  failed: {r['stderr_tail']}")
    return 0 if all(r["exit_status"] == 0 for r in results.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
