"""Timings of the roughness pipeline: python bench/bench_roughness.py (a few seconds).

Prints the wall time of reading each shipped AFM file (SurfaceTopography's import is counted
once, in the first SurfaceTopography file), of the statistics of each, and of the synthetic
default profile. Single run, time.perf_counter; meant for regressions, not for absolute numbers.
"""

from __future__ import annotations

import time
from pathlib import Path

AFM = Path(__file__).resolve().parent.parent / "data" / "afm"
FILES = ["si_profile_linescan.txt", "topography_in_nanometers.txt", "di-3.di", "example_ps.tiff", "opdx-3.opdx",
         "IgorIBWReader_P0089OP0027.ibw", "container-2.zip"]


def main():
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.readers import SurfaceMap, read_topography
    from memstribo.surfaces.roughness import areal_statistics, default_profile, line_scan_statistics, profile_statistics

    print(f"{'file':<32} {'read [s]':>9} {'stats [s]':>10}  shape")
    for name in FILES:
        start = time.perf_counter()
        surface = read_topography(AFM / name)
        read = time.perf_counter() - start
        start = time.perf_counter()
        if isinstance(surface, SurfaceMap):
            line_scan_statistics(surface.heights, surface.dx)
            areal_statistics(surface.heights, surface.dx, surface.dy)
            shape = surface.shape
        else:
            profile_statistics(surface)
            shape = (surface.n_points,)
        stats = time.perf_counter() - start
        print(f"{name:<32} {read:9.3f} {stats:10.4f}  {shape}")
    params = get_parameter_values()
    start = time.perf_counter()
    profile = default_profile(params)
    print(f"{'default_profile (thesis)':<32} {time.perf_counter() - start:9.3f} {'':>10}  ({profile.n_points},)")
    start = time.perf_counter()
    fine = default_profile(params, spacing=1e-9)
    print(f"{'default_profile, 1 nm step':<32} {time.perf_counter() - start:9.3f} {'':>10}  ({fine.n_points},)")


if __name__ == "__main__":
    main()
