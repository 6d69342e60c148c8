"""What the verdict hangs on at the default, and where roughness starts to matter (issue 38 item 7, MODEL 7h).

    python bench/bench_roughness_leverage.py [--torque 1 0.25 0.0625] [--rq 1 3 10] [--steps 241]

For each drive torque (as a factor of the default 1.039e-7 N m) and each roughness amplitude (a factor on the
default synthetic profile's Rq = 1.6235 nm, its rms slope scaled alike so that lambda_q stays) one JSON line:

- the Hertz band at the pitch point under the torque's normal force F_n = F_t / cos(alpha): half-width a, peak and
  mean pressure p0 and p = pi p0 / 4 (4-22..4-26), and the vdW friction stress of the hysteresis rule,
  tau_vdW = phi w12 / D_chem (MODEL 7h), with tau_vdW / p: the COF of a smooth band that carries vdW friction on its
  whole width;
- the meshing cycle (realisation 0, ``--steps``, no refinement): stiction margin, mean COF and its split;
- the margin's and the mean COF's elasticity to Rq, (dX / X) / (dRq / Rq), from cycles at Rq +- 10 %.

Roughness matters where the elasticities grow and the COF leaves tau_vdW / p. The default case is the first line.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402


def hertz_band(params) -> dict:
    """Hertz band at the pitch point under the torque's normal force, and tau_vdW / p of the hysteresis rule."""
    from memstribo.physics.gear import gear_summary
    from memstribo.physics.adhesion import nanoscale_constants

    tangential = gear_summary(params)[0]["tangential_force"]
    normal = tangential / math.cos(params["pressure_angle"])
    values = gear_summary(params.updated({"normal_load": normal}))[0]
    p0 = values["hertz_peak_pressure"]
    mean = math.pi * p0 / 4.0
    c = nanoscale_constants(params)
    tau = c.bond_energy_vdw / params["bond_length"] ** 3  # one site per D_chem^2: phi w12 / D_chem
    return {"normal_force_mN": round(normal * 1e3, 4), "hertz_half_width_nm": round(values["hertz_half_width"] * 1e9, 2),
            "hertz_peak_pressure_GPa": round(p0 / 1e9, 4), "hertz_mean_pressure_GPa": round(mean / 1e9, 4),
            "tau_vdw_MPa": round(tau / 1e6, 2), "tau_vdw_over_p": round(tau / mean, 4)}


def cycle(params, steps) -> dict:
    from memstribo.simulations.mesh import simulate_mesh, summarize

    s = summarize(simulate_mesh(params, steps=steps))
    return {"margin": s["stiction_margin"], "startup": s.get("startup_margin"), "cof": s["cof_mean"],
            "cof_vdw": s["cof_vdw"], "cof_chemical": s["cof_chemical"]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--torque", type=float, nargs="+", default=[1.0, 0.25, 0.0625])
    parser.add_argument("--rq", type=float, nargs="+", default=[1.0, 3.0, 10.0])
    parser.add_argument("--steps", type=int, default=241)
    args = parser.parse_args(argv)

    from memstribo.parameters import get_parameter_values

    base = get_parameter_values().updated({"mesh_step_refinements": 0, "mesh_grid_refinements": 0})
    for torque in args.torque:
        for rq in args.rq:
            params = base.updated({"drive_torque": base["drive_torque"] * torque,
                                   "roughness_rq": base["roughness_rq"] * rq,
                                   "roughness_rms_slope": base["roughness_rms_slope"] * rq})
            start = time.process_time()
            nominal = cycle(params, args.steps)
            moved = [cycle(params.updated({"roughness_rq": params["roughness_rq"] * f,
                                           "roughness_rms_slope": params["roughness_rms_slope"] * f}), args.steps)
                     for f in (0.9, 1.1)]
            elastic = {key: (moved[1][key] - moved[0][key]) / (0.2 * nominal[key]) for key in ("margin", "cof")}
            print(json.dumps({"torque_factor": torque, "rq_factor": rq, "rq_nm": round(params["roughness_rq"] * 1e9, 3),
                              **hertz_band(params),
                              "margin_mN": round(nominal["margin"] * 1e3, 4),
                              "startup_margin_mN": round(nominal["startup"] * 1e3, 4),
                              "cof_mean": round(nominal["cof"], 4), "cof_vdw": round(nominal["cof_vdw"], 4),
                              "cof_chemical": round(nominal["cof_chemical"], 4),
                              "elasticity_margin_rq": round(elastic["margin"], 3),
                              "elasticity_cof_rq": round(elastic["cof"], 3),
                              "cpu_s": round(time.process_time() - start, 1)}), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
