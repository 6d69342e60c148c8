"""The start-up verdict of the default case (MODEL 7f, issue #35): its convergence, the dwell, the registry, the load.

    python bench/bench_startup.py [--parts convergence dwell registry load] [--realisations 0 1]

``convergence``: the running and start-up margins of the default cycle (no self-refinement) at 481, 961 and 1921
steps and at twice the grid (96 elements across 2a), per realisation: the numbers of docs/mesh.md's table.
``dwell``: the start-up margin after dwells of 1 ms to a day (the logarithmic ageing law), realisation 0.
``registry``: the start-up resisting force with ``lattice_registry`` random and shared.
``load``: the start-up margin against the load torque on the gear, as a share of the frictionless pair's output.
``lever``: the largest moment arm of a pair's friction over the pitch radius, and the Coulomb self-locking
coefficient at the first point of contact.
Each line is one JSON object (margins in mN, CPU seconds).
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402


def _line(**values):
    print(json.dumps(values), flush=True)


def _cycle(params, steps=481, realisation=0):
    from memstribo.simulations.mesh import simulate_mesh, summarize

    start = time.process_time()
    summary = summarize(simulate_mesh(params, steps=steps, realisation=realisation))
    return summary, round(time.process_time() - start, 1)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--parts", nargs="+", default=["convergence", "dwell", "registry", "load", "lever"],
                        choices=("convergence", "dwell", "registry", "load", "lever"))
    parser.add_argument("--realisations", type=int, nargs="+", default=[0, 1])
    args = parser.parse_args(argv)

    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    _line(load_average=os.getloadavg())
    if "convergence" in args.parts:
        across = int(params["mesh_elements_across_contact"])
        for r in args.realisations:
            base = None
            for steps, p in ((481, params), (961, params), (1921, params),
                             (481, params.updated({"mesh_elements_across_contact": 2 * across}))):
                s, cpu = _cycle(p, steps, r)
                base = base or s
                _line(part="convergence", realisation=r, steps=steps, across=int(p["mesh_elements_across_contact"]),
                      stiction_margin_mN=round(s["stiction_margin"] * 1e3, 4),
                      startup_margin_mN=round(s["startup_margin"] * 1e3, 4),
                      startup_change_percent=round(100 * (s["startup_margin"] / base["startup_margin"] - 1), 3),
                      startup_resisting_mN=round((s["tangential_force"] - s["startup_margin"]) * 1e3, 4),
                      cpu_seconds=cpu)
    if "dwell" in args.parts:
        for dwell in (None, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3, 86400.0):
            s, cpu = _cycle(params.updated({"startup_dwell": dwell}))
            _line(part="dwell", startup_dwell_s=dwell, startup_margin_mN=round(s["startup_margin"] * 1e3, 4),
                  static_cof_max=round(s["static_cof_max"], 4), cpu_seconds=cpu)
    if "registry" in args.parts:
        for registry in ("random", "shared"):
            s, cpu = _cycle(params.updated({"lattice_registry": registry}))
            _line(part="registry", lattice_registry=registry,
                  startup_resisting_mN=round((s["tangential_force"] - s["startup_margin"]) * 1e3, 4),
                  startup_margin_mN=round(s["startup_margin"] * 1e3, 4),
                  stiction_margin_mN=round(s["stiction_margin"] * 1e3, 4), static_cof_max=round(s["static_cof_max"], 4),
                  cpu_seconds=cpu)
    if "load" in args.parts:
        s, _ = _cycle(params)
        from memstribo.physics.gear import GearPair

        pair = GearPair.from_parameters(params)
        output = float(params["drive_torque"]) * float(pair.base_radii[1] / pair.base_radii[0])
        _line(part="load", frictionless_output_Nm=output, startup_load_torque_limit_Nm=s["startup_load_torque_limit"],
              limit_share_of_output=round(s["startup_load_torque_limit"] / output, 4))
        for share in (0.5, 0.8, 0.9, 0.95):
            t, cpu = _cycle(params.updated({"load_torque": share * output}))
            _line(part="load", load_share_of_output=share, startup_margin_mN=round(t["startup_margin"] * 1e3, 4),
                  cpu_seconds=cpu)
    if "lever" in args.parts:
        import numpy as np

        from memstribo.physics.gear import GearPair
        from memstribo.physics.static_friction import friction_lever, self_locking_friction_coefficient

        pair = GearPair.from_parameters(params)
        c = np.linspace(pair.first_contact, pair.last_contact, 2001)
        rho1, rho2 = pair.radii_of_curvature(c)
        lever = friction_lever(rho1, rho2, *pair.base_radii) * pair.base_radii[0] / pair.pitch_radii[0]
        _line(part="lever", lever_first_contact=round(float(lever[0]), 4), lever_last_contact=round(float(lever[-1]), 4),
              lever_min=round(float(lever.min()), 6),
              self_locking_mu_first_contact=round(float(self_locking_friction_coefficient(rho2[0],
                                                                                           pair.base_radii[1])), 4))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
