"""Benchmark of a verdict that holds still (issue #25): the self-refining cycle, the step and grid changes, the
adhesion force against the grid, dissimilar teeth, and the thesis's load case on an 8 um face.

    OMP_NUM_THREADS=1 python bench/bench_convergence.py [--parts refine steps grid adhesion dissimilar thesis spot]
        [--realisations 0 1] [--thesis-steps 25] [--sets silicon_thesis silicon_oxide_air]

Every part prints one JSON line with its numbers, the CPU and wall time, and the machine's load average at its
start and end (the development machine is shared: the CPU time is the fairer number). One core per process
(SolverSettings.fft_workers = 1, OMP_NUM_THREADS=1). Also the benchmark named by SolverSettings.cohesive_start:
``steps`` compares the margin at 481, 961 and 1921 steps (the loading-branch state makes it hold still).
``spot`` compares the spot check (:mod:`memstribo.simulations.mesh.spot`) with the whole finer cycle on each
comparison the refined cycle makes first (481 -> 961 steps, 48 -> 96 elements across 2a at 481 steps), for each
parameter set of ``--sets`` and realisation: the changes of the margin and the mean COF both give, and the CPU time of
each. ``refine`` runs the self-refining cycle (``memstribo mesh``) of each set; ``thesis --thesis-steps 481`` the
whole thesis load case without the refinement (``memstribo mesh --load-case thesis --set face_width=8um
--no-refine``); ``thesis-refined`` the same case with its refinement (``memstribo mesh --load-case thesis --set
face_width=8um``) at each ``--thesis-across`` (mesh_elements_across_contact), with the CPU time of each whole cycle and
each spot check of the chain.
"""

from __future__ import annotations

import argparse
import json
import os
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")


def _timed(function):
    load = os.getloadavg()
    cpu, wall = time.process_time(), time.perf_counter()
    result = function()
    return result, {"cpu_s": round(time.process_time() - cpu, 2), "wall_s": round(time.perf_counter() - wall, 2),
                    "load_before": [round(x, 2) for x in load],
                    "load_after": [round(x, 2) for x in os.getloadavg()]}


def _line(part, **values):
    print(json.dumps({"part": part, **values}), flush=True)


def main(argv=None):
    from memstribo.api import parameter_set
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.simulations.mesh.convergence import refined_cycle

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--parts", nargs="+", default=["refine", "steps", "dissimilar"],
                        choices=("refine", "steps", "grid", "adhesion", "dissimilar", "thesis", "thesis-refined",
                                 "spot"))
    parser.add_argument("--sets", nargs="+", default=["silicon_thesis"],
                        help="parameter sets of the parts refine and spot")
    parser.add_argument("--realisations", nargs="+", type=int, default=[0, 1])
    parser.add_argument("--thesis-steps", type=int, default=25)
    parser.add_argument("--thesis-across", nargs="+", type=int, default=[40, 48],
                        help="mesh_elements_across_contact of the part thesis-refined")
    args = parser.parse_args(argv)
    params = parameter_set()
    default = int(params["mesh_elements_across_contact"])  # the default grid (48 elements across 2a)
    simulate_mesh(params, steps=11)  # the compiled zone loop: loaded (and compiled once per machine) before timing

    def summary(p, steps, realisation=0):
        return summarize(simulate_mesh(p, steps=steps, realisation=realisation))

    if "spot" in args.parts:  # the spot check against the whole finer cycle, on the refined cycle's first comparisons
        from memstribo.simulations.mesh.spot import spot_check
        from memstribo.simulations.mesh.verdict import compare_cycles

        for name in args.sets:
            base = parameter_set(name)
            for k in args.realisations:
                coarse, t_coarse = _timed(lambda: simulate_mesh(base, steps=481, realisation=k))
                for what, finer, steps in (("steps", base, 961),
                                           ("grid", base.updated({"mesh_elements_across_contact": 2 * default}),
                                            481)):
                    fine, t_full = _timed(lambda: summarize(simulate_mesh(finer, steps=steps, realisation=k)))
                    full = compare_cycles(fine, summarize(coarse))
                    spot, t_spot = _timed(lambda: spot_check(coarse, finer, None, steps, realisation=k))
                    _line("spot", set=name, realisation=k, check=what, full_margin=full["margin"], full_cof=full["cof"],
                          full_adhesion=full["adhesion"], full_passed=full["passed"],
                          spot_margin=None if spot is None else spot["margin"],
                          spot_cof=None if spot is None else spot["cof"],
                          spot_adhesion=None if spot is None else spot["adhesion"],
                          spot_passed=None if spot is None else spot["passed"],
                          spot_solved=None if spot is None else spot["solved"], finer_steps=steps,
                          full_cpu_s=t_full["cpu_s"], spot_cpu_s=t_spot["cpu_s"], coarse_cpu_s=t_coarse["cpu_s"],
                          load_before=t_full["load_before"], load_after=t_spot["load_after"])
    if "refine" in args.parts:  # the default cycle with its refinement (memstribo mesh)
        for name in args.sets:
            chosen = parameter_set(name)
            for k in args.realisations:
                (_, s), t = _timed(lambda: refined_cycle(chosen, realisation=k))
                _line("refine", set=name, realisation=k, converged=s["converged"], steps=s["steps"],
                      elements_across_contact=s["elements_across_contact"], margin_mN=s["stiction_margin"] * 1e3,
                      cof_mean=s["cof_mean"], adhesion_force_uN=s["adhesion_force_mean"] * 1e6,
                      refinement=s["refinement"], **t)
    if "steps" in args.parts:  # the margin at 2x and 4x the steps (the first measurement)
        for k in args.realisations:
            for across in (default, 2 * default):
                p = params.updated({"mesh_elements_across_contact": across})
                rows = []
                for steps in (481, 961, 1921):
                    s, t = _timed(lambda: summary(p, steps, k))
                    rows.append({"steps": steps, "margin_mN": s["stiction_margin"] * 1e3, "cof_mean": s["cof_mean"],
                                 "adhesion_force_uN": s["adhesion_force_mean"] * 1e6, **t})
                _line("steps", realisation=k, elements_across_contact=across, rows=rows,
                      change_2x=abs(rows[1]["margin_mN"] / rows[0]["margin_mN"] - 1),
                      change_4x=abs(rows[2]["margin_mN"] / rows[0]["margin_mN"] - 1))
    if "grid" in args.parts or "adhesion" in args.parts:  # the grid (adhesion: up to 320 elements across 2a)
        largest = 320 if "adhesion" in args.parts else 4 * default
        steps = 481 if "grid" in args.parts else 121
        for k in args.realisations[:1] if "adhesion" in args.parts else args.realisations:
            rows = []
            for across in (default, 2 * default, 4 * default, 320):
                if across > largest:
                    break
                s, t = _timed(lambda: summary(params.updated({"mesh_elements_across_contact": across}), steps, k))
                rows.append({"elements_across_contact": across, "margin_mN": s["stiction_margin"] * 1e3,
                             "cof_mean": s["cof_mean"], "adhesion_force_uN": s["adhesion_force_mean"] * 1e6, **t})
            _line("grid", realisation=k, steps=steps, rows=rows)
    if "dissimilar" in args.parts:  # the F_t/F_f fixed point at the default steps
        for counter in (20e9, 400e9):
            ds, t = _timed(lambda: simulate_mesh(params.updated({"counter_youngs_modulus": counter})))
            s = summarize(ds)
            _line("dissimilar", counter_youngs_modulus=counter, beta=ds.attrs["dundurs_beta"],
                  passes=ds.attrs["friction_passes"], converged=bool(ds.attrs["friction_fixed_point_converged"]),
                  verdict=s["verdict"], margin_mN=s["stiction_margin"] * 1e3, cof_mean=s["cof_mean"], **t)
    if "thesis" in args.parts:  # memstribo mesh --load-case thesis --set face_width=8um, a few steps
        p = params.updated({"load_case": "thesis", "face_width": 8e-6})
        ds, t = _timed(lambda: simulate_mesh(p, steps=args.thesis_steps))
        per_step = t["cpu_s"] / args.thesis_steps
        _line("thesis", steps=args.thesis_steps, rows=int(ds.attrs["rows"]),
              grid_spacing_nm=ds.attrs["grid_spacing"] * 1e9,
              elements=int(round(ds.attrs["window"] / ds.attrs["grid_spacing"])),
              updates_per_solve=float(ds["contact_iterations"].mean()),
              cpu_per_step_s=round(per_step, 3), cpu_481_steps_estimate_s=round(481 * per_step, 1), **t)

    if "thesis-refined" in args.parts:  # memstribo mesh --load-case thesis --set face_width=8um (the refinement on)
        for across in args.thesis_across:
            p = params.updated({"load_case": "thesis", "face_width": 8e-6, "mesh_elements_across_contact": across})
            with _parts_timed() as parts:
                (_, s), t = _timed(lambda: refined_cycle(p))
            _line("thesis-refined", elements_across_contact=across, converged=s["converged"], steps=s["steps"],
                  elements_checked=s["elements_checked"], margin_mN=s["stiction_margin"] * 1e3,
                  cof_mean=s["cof_mean"], adhesion_force_uN=s["adhesion_force_mean"] * 1e6, verdict=s["verdict"],
                  refinement=s["refinement"], parts=parts, **t)


class _parts_timed:
    """The CPU time of each whole cycle and each spot check the refined cycle runs (a list of dicts)."""

    def __enter__(self):
        import memstribo.simulations.mesh.cycle as cycle
        import memstribo.simulations.mesh.spot as spot

        self.parts, self.modules = [], (cycle, spot)
        self.saved = (cycle.simulate_mesh, spot.spot_check)
        simulate, check = self.saved

        def timed_simulate(params, *args, **kwargs):
            start = time.process_time()
            dataset = simulate(params, *args, **kwargs)
            self.parts.append({"what": "cycle", "steps": kwargs.get("steps"),
                               "across": int(params["mesh_elements_across_contact"]),
                               "cpu_s": round(time.process_time() - start, 2)})
            return dataset

        def timed_check(dataset, params, roughness, steps, **kwargs):
            start = time.process_time()
            change = check(dataset, params, roughness, steps, **kwargs)
            self.parts.append({"what": "spot check", "steps": steps,
                               "across": int(params["mesh_elements_across_contact"]), "applied": change is not None, "passed": None if change is None else change["passed"],
                               "solved": None if change is None else change["solved"],
                               "cpu_s": round(time.process_time() - start, 2)})
            return change

        cycle.simulate_mesh, spot.spot_check = timed_simulate, timed_check
        return self.parts

    def __exit__(self, *exc):
        self.modules[0].simulate_mesh, self.modules[1].spot_check = self.saved
        return False


if __name__ == "__main__":
    main()
