"""Worked example of a design map: drive torque x face width of the thesis pair, bare and OTS.

Needs the ``parallel`` extra (Dask): ``pip install "memstribo[parallel]"`` (docs/install.md); without it the
map stops at once and says so.

Writes the map to a working folder (a temporary one) and the figures ``design_map_stiction.png``,
``design_map_efficiency.png`` (and SVG) into ``OUT/figures`` (default OUT: ``examples/output/design_map_example``;
``--out docs`` makes the copies that docs/design-maps.md shows)::

    python examples/design_map_example.py            # the documented map: 6 x 6 x 2 points, 4 realisations each
    python examples/design_map_example.py --out docs # the same, into docs/figures/
    python examples/design_map_example.py --tiny --out /tmp/x   # 2 x 2 x 2 points, seconds

The documented map takes minutes, not seconds: 18 min wall on the shared 2-core machine at a load average of 6
(2026-11-28: 72 points, 1068 s for the map, 16 min of CPU over the two workers), so about 8 min on two free cores
(docs/design-maps.md).
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from memstribo.simulations.design_map import design_map, map_figures, map_spec

ROOT = Path(__file__).resolve().parents[1]


def spec(tiny: bool):
    """The map: drive torque x face width x coating (bare silicon, OTS)."""
    n = 2 if tiny else 6
    return map_spec({
        "name": "thesis pair: drive torque x face width",
        "realisations": 2 if tiny else 4,
        "steps": 11 if tiny else 481,  # the default mesh_steps: each point checks that it converged (MODEL 7d)
        "plot": ["drive_torque", "face_width"],
        "grid": {
            "drive_torque": {"start": "3e-8 N*m", "stop": "3e-7 N*m", "num": n},
            "face_width": {"start": "1 um", "stop": "4 um", "num": n},
            "coating": ["none", "OTS"],
        },
    })


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tiny", action="store_true", help="2 x 2 x 2 points, 2 realisations, 11 steps")
    parser.add_argument("--out", default=None,
                        help="folder of figures/ (default: examples/output/design_map_example; 'docs' for the docs)")
    parser.add_argument("--workers", type=int, default=2, help="local Dask worker processes (default 2)")
    args = parser.parse_args(argv)
    out = Path(args.out) if args.out else ROOT / "examples" / "output" / "design_map_example"
    with tempfile.TemporaryDirectory() as work:
        result = design_map(spec(args.tiny), Path(work) / "map", workers=args.workers, figures=False)
        written, notes = map_figures(result.dataset, out / "figures", ["drive_torque", "face_width"])
        p = result.dataset["stiction_probability"]
        print(p.to_series().unstack("coating").to_string())
        print(f"{result.n_points} points in {result.elapsed:.1f} s; figures: {[str(w) for w in written]}")
        for note in notes + result.notes:
            print(note)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
