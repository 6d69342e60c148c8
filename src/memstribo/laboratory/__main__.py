"""``python -m memstribo.laboratory [--write docs/experiments.md]``: regenerate docs/experiments.md, its figure and
the calibrated parameter set (run from the repository root)."""

from __future__ import annotations

import argparse
from pathlib import Path


def main(argv=None):
    from memstribo.laboratory.report import write

    parser = argparse.ArgumentParser(prog="python -m memstribo.laboratory", description=__doc__)
    parser.add_argument("--write", default="docs/experiments.md", metavar="FILE", help="page to write")
    parser.add_argument("--calibrated", default=str(Path(__file__).resolve().parent.parent / "parameters" / "sets"
                                                    / "calibrated.toml"),
                        metavar="FILE", help="where to write the calibrated parameter set")
    args = parser.parse_args(argv)
    write(args.write, args.calibrated)
    print(f"wrote {args.write}, its figure and {args.calibrated}")


if __name__ == "__main__":
    main()
