"""Grid convergence of the meshing cycle with and without the Maugis-Dugdale zone in the contact solve.

    python bench/bench_grid_adhesion.py [--load-case torque] [--steps 241] [--across 20 40 80 160 320]
                                        [--adhesion maugis none] [--realisations 0] [--zone-elements 2]

For each contact_adhesion and each number of elements across the largest Hertz width 2a
(``mesh_elements_across_contact``, default 40) and each realisation one meshing cycle of the default case
(synthetic roughness) prints one JSON line: grid spacing, stiction margin, mean COF and its split, largest
resisting force R, mean adhesion force F_adh and the CPU seconds. ``--zone-elements``: the contact solver's
``SolverSettings.zone_elements`` (0: the unresolved zone as it was before issue #25). The cohesive zone of a rough
contact is a few nanometres wide: its tensile load F_adh needs a grid of a few nanometres, while
the COF and the margin, which F_N dominates under the torque's load, change little
(docs/interface.md, "Grid convergence").
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--load-case", default="torque", choices=("torque", "thesis"))
    parser.add_argument("--steps", type=int, default=241)
    parser.add_argument("--across", type=int, nargs="+", default=[20, 40, 80, 160, 320])
    parser.add_argument("--adhesion", nargs="+", default=["maugis", "none"], choices=("maugis", "none"))
    parser.add_argument("--realisations", type=int, nargs="+", default=[0])
    parser.add_argument("--zone-elements", type=float, default=None)
    args = parser.parse_args(argv)

    import dataclasses

    from memstribo.physics.contact import settings

    if args.zone_elements is not None:
        settings.DEFAULTS = dataclasses.replace(settings.DEFAULTS, zone_elements=args.zone_elements)

    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh, summarize

    print(json.dumps({"load_average": os.getloadavg()}), flush=True)
    for adhesion in args.adhesion:
        for across, realisation in ((a, r) for a in args.across for r in args.realisations):
            params = get_parameter_values().updated({"load_case": args.load_case, "contact_adhesion": adhesion,
                                                     "mesh_elements_across_contact": across})
            start = time.process_time()
            dataset = simulate_mesh(params, steps=args.steps, realisation=realisation)
            summary = summarize(dataset)
            print(json.dumps({"load_case": args.load_case, "contact_adhesion": adhesion, "across": across,
                              "realisation": realisation, "zone_elements": settings.DEFAULTS.zone_elements,
                              "stiction_margin_mN": round(summary["stiction_margin"] * 1e3, 4),
                              "grid_spacing_nm": round(dataset.attrs["grid_spacing"] * 1e9, 2),
                              "cof_mean": round(summary["cof_mean"], 4), "cof_chemical": round(summary["cof_chemical"], 4),
                              "cof_vdw": round(summary["cof_vdw"], 4),
                              "resisting_force_max_mN": round(summary["resisting_force_max"] * 1e3, 4),
                              "adhesion_force_mean_uN": round(summary["adhesion_force_mean"] * 1e6, 2),
                              "cpu_seconds": round(time.process_time() - start, 1)}), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
