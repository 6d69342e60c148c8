"""The Python API on a real measured profile: roughness -> nanoblocks -> one meshing cycle.

    python examples/api_afm_profile.py [PROFILE]

Default PROFILE: data/afm/opdx-3.opdx, a 50 um Bruker Dektak stylus profile (see data/afm/README.md:
a very smooth reference sample of undocumented material, so this shows the workflow, not
silicon's numbers). The meshing cycle needs a scan longer than the flank travel (about 9 um).
"""

from __future__ import annotations

import sys
from pathlib import Path

import memstribo
from memstribo.physics.nanoblock.geometry import nanoblock_geometry_from_profile
from memstribo.surfaces.roughness import profile_statistics

ROOT = Path(__file__).resolve().parent.parent


def main(path: str | Path = ROOT / "data" / "afm" / "opdx-3.opdx", refine: bool = True) -> dict:
    """The profile's statistics and nanoblocks, and a bare and a coated meshing cycle on it (``refine``: the
    cycles refine themselves in steps and grid, the API's default as memstribo mesh's; False: one cycle each)."""
    params = memstribo.parameter_set(mesh_steps=120)
    profile = memstribo.read_surface(path)                    # Profile (x, z in m) with provenance
    stats = profile_statistics(profile)                  # ISO 4287 parameters (levelled)
    print(f"profile {profile.name}: {profile.source}")
    print(f"  Rq = {stats.Rq * 1e9:.3f} nm, rms slope = {stats.rms_slope:.3f}, lambda_q = {stats.lambda_q * 1e9:.1f} nm")
    try:  # H_at = 0.5 Rq, H_adh = 1.2 Rq, widths cut at those levels, pitch = lambda_q (thesis 3.4)
        geometry = nanoblock_geometry_from_profile(profile)
    except memstribo.InputError as exc:  # e.g. a smooth long-wavelength profile: no atomic block fits
        geometry = None
        print(f"  (no nanoblock geometry from this profile: {exc})")
    bare = memstribo.mesh_cycle(params, profile, refine=refine).summary  # self-refining, as memstribo mesh
    coated = memstribo.mesh_cycle(params, profile, coating="OTS", wear=0.0, refine=refine).summary
    if geometry is not None:
        print(f"  nanoblock from the profile: w_at = {geometry.atomic_width * 1e9:.1f} nm, "
              f"H_at = {geometry.atomic_height * 1e9:.2f} nm, w_adh = {geometry.adhesive_width * 1e9:.1f} nm")
    print("  (the meshing cycles below use the parameter set's nanoblocks and this profile's heights)")
    for label, summary in (("bare silicon", bare), ("OTS, intact", coated)):
        print(f"  {label:<13} COF {summary['cof_mean']:.3f}, max friction {summary['friction_force_max'] * 1e6:.1f} uN, "
              f"F_t {summary['tangential_force'] * 1e6:.0f} uN, verdict: {summary['verdict']}")  # running and start-up
    return {"bare": bare, "coated": coated, "Rq": stats.Rq}


if __name__ == "__main__":
    main(*sys.argv[1:])
