"""The main job (``memstribo run``): the thesis case end to end, stage by stage.

:class:`RunChain` composes the library in the manner of pvlib's ``ModelChain``: each stage
is a method that calls the topic modules' public functions, stores its result in
:attr:`RunChain.results` and writes its outputs (NetCDF + CSV datasets, PNG + SVG figures)
as soon as they exist, so an interrupted run loses nothing already computed. The stages:

1. ``roughness``   the default profile (seeded, labelled synthetic) and any measured file;
2. ``geometry``    nanoblock geometry, from the parameters and derived from each profile;
   ``sliding``     one nanoblock on a flat (2.6.2) and the hierarchical structure on the rough profile
                   under a fixed load (3.4.2, 3.6);
3. ``gear``        involute pair, Hertz contact at the pitch point, tangential force F_t;
4. ``mesh``        the bare-silicon meshing cycle (:func:`memstribo.simulations.mesh.simulate_mesh`);
5. ``load_sweep``  COF and dissipated energy versus external load (thesis 4.9.3);
6. ``area_sweep``  COF and energy versus nominal contact area (4.9.4);
7. ``coated``      the coated pair, fully functionalised (5.4);
8. ``wear_sweep``  COF and friction versus the worn fraction Omega (5.5.3);
9. ``damage``      damage per meshing cycle of the coating and its lifetime (5.5).

A stage whose inputs failed is skipped and says why; a stage never pretends. Each stage's
figure functions (``plot_*``) and :func:`cycle_summary` work on their own too::

    >>> from memstribo.job.chain import RunChain; from memstribo.job.options import RunOptions  # doctest: +SKIP
    >>> result = RunChain(params, "results", RunOptions(steps=40)).run()  # doctest: +SKIP
"""

from __future__ import annotations

import logging
import sys
import time
import traceback
from collections.abc import Mapping
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from memstribo.errors import InputError, MemstriboError
from memstribo.output import (atomic_write_text, dumps_json, ensure_directory, format_quantity, save_figure,
                              software_provenance, to_jsonable, write_dataset)

from memstribo.job.figures import plot_lives
from memstribo.job.figures import (plot_block_loads, plot_cycle, plot_energy, plot_ensemble, plot_gear, plot_humidity,
                                   plot_map, plot_profiles, plot_sliding, plot_sweep)
from memstribo.job.verdict import uncertainty_summary, verdict  # noqa: F401  (verdict: re-exported)
from memstribo.job.sweeps import columns, cof_above_one, sweep_dataset
from memstribo.job.workers import StageWorkers, coated_cycle, ensemble_point_and_cycle
from memstribo.job.options import (DEPENDS, MAP_STAGE, RELOADED, STAGES, USES, FigureRecord, RunOptions, RunResult,
                                   StageRecord)

__all__ = ["RunChain", "cycle_summary", "verdict"]



def cycle_summary(dataset) -> dict[str, Any]:
    """Scalars of one meshing cycle: :func:`memstribo.simulations.mesh.summarize` (the keys of ``memstribo mesh --json``).

    Units of the keys are in :data:`memstribo.simulations.mesh.SUMMARY_UNITS`.
    """
    from memstribo.simulations.mesh import summarize

    return summarize(dataset)


#: Relative humidities [-] of the humid-air section of a run in air (issue #17).
HUMIDITY_VALUES = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)
#: Title of that section (not a stage of :data:`STAGES`: it runs only when the environment is air).
HUMIDITY_TITLE = "Humid air: COF, capillary share and stiction margin versus relative humidity"


_GEOMETRY_FIELDS = ("atomic_width", "atomic_height", "adhesive_width", "adhesive_height", "atomic_pitch",
                    "atomic_per_side", "bulk_height")


# --- the chain --------------------------------------------------------------------------------------------------

class RunChain:
    """The thesis case end to end; each stage is a method usable on its own.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameters (with the user's overrides).
    out : str or pathlib.Path
        Output folder (created).
    options : RunOptions, optional
        What to run (default: everything, thesis settings).
    progress : bool
        Progress bar over the stages on stderr.
    resume : bool
        Continue the run in ``out`` (``memstribo run --resume``): stages that ``run.json`` records as done are
        not recomputed (their record, figures and summary are read back, and the datasets later stages need,
        ``data/mesh_coated.nc`` and ``data/wear_sweep.nc``); failed, skipped or missing stages run again, and so
        does every stage after one that runs again and uses it (:data:`DEPENDS`, :data:`USES`). The inputs of
        the ``roughness`` and ``geometry`` stages (the default profile, the measured files, the derived
        geometry) are re-read without writing their files. The parameters and options must be those of the
        earlier run.

    Raises
    ------
    InputError
        ``out`` empty (the current folder); with ``resume``: no ``run.json`` in ``out``, a ``run.json`` that lists
        a file outside ``out`` (absolute, with ``..``, or through a symbolic link) or an input file of the run,
        or other parameters or options than the earlier run's. Nothing is deleted then.
    """

    def __init__(self, params, out, options: RunOptions | None = None, progress: bool = False, resume: bool = False):
        (options or RunOptions()).check_with(params)  # every [run] value against the parameters, before any stage
        from memstribo.checks import refuse_unused_coating_wear

        refuse_unused_coating_wear(params, "memstribo run", "the coated stage is the intact coating (Omega = 0, "
                                   "thesis 5.4) and the wear sweep takes the worn fractions of [run] wear (e.g. "
                                   "wear = [0.0, 0.2, 1.0])")
        self.params = params
        #: the parameters of the model stages: ``params`` with the geometry derived from a measured profile
        self.model_params = params
        from memstribo.job.folder import results_folder

        self.folder = ensure_directory(results_folder(out, "out"))  # '' (the current folder) refused
        self.options = options or RunOptions()
        self.progress = progress
        self.workers = StageWorkers()  # the run's local cluster, started by the first stage with work for it
        self.results: dict[str, Any] = {}
        self.summaries: dict[str, Any] = {}
        self.figures: list[FigureRecord] = []
        self.inputs: list[dict[str, Any]] = []
        self.records = {name: StageRecord(name, title) for name, title in STAGES.items()}
        if self.options.map:
            self.records[MAP_STAGE[0]] = StageRecord(*MAP_STAGE)
        self._current: StageRecord | None = None
        self.kept: list[str] = []
        self.previous = self._read_previous() if resume else None

    # resuming ------------------------------------------------------------------------------------
    def _read_previous(self) -> dict[str, Any]:
        """``run.json`` of the earlier run in the folder, checked against these parameters and options."""
        import json

        from memstribo.parameters import read_config

        manifest_path = self.folder / "run.json"
        if not manifest_path.is_file():
            raise InputError(f"--resume: {self.folder} holds no run.json, so there is no run to continue; "
                             "run without --resume.")
        try:
            manifest = json.loads(manifest_path.read_text(encoding="utf-8"))
            stages = {s["name"]: s for s in manifest["stages"]}
        except (ValueError, KeyError, TypeError) as exc:
            raise InputError(f"--resume: {manifest_path} is not a run.json of memstribo ({exc}); run again with "
                             "--overwrite.") from None
        # first, before any other check: a stage's files are deleted when it runs again (_forget), so each
        # must be the run's own, inside the folder, and no input of this run (a crafted run.json deleted files
        # elsewhere, issue #41)
        from memstribo.job.folder import check_inputs_outside, owned_files

        owned = owned_files(self.folder, manifest, "--resume")
        check_inputs_outside(self.folder, [*self.options.roughness_files, self.options.map], "--resume",
                             files=owned.values())
        options = json.loads(dumps_json(to_jsonable(self.options.__dict__)))
        if manifest.get("options") != options:
            changed = sorted(k for k in set(options) | set(manifest.get("options") or {})
                             if options.get(k) != (manifest.get("options") or {}).get(k))
            raise InputError(f"--resume: the run in {self.folder} had other options ({', '.join(changed)}); give the "
                             "same config file and options as the run to continue, or --overwrite.")
        parameters_path = self.folder / "parameters.toml"
        if parameters_path.is_file():
            earlier = self.params.updated(read_config(parameters_path)["parameters"], origin="earlier run")
            changed = [k for k, v in self.params.to_dict().items() if earlier.to_dict().get(k) != v]
            if changed:
                raise InputError(f"--resume: the run in {self.folder} had other parameters ({', '.join(changed[:5])}); "
                                 "give the same parameters as the run to continue, or --overwrite.")
        manifest["stages_by_name"] = stages
        return manifest

    def _keep(self, name: str, rerun: set[str]) -> bool:
        """Whether a resumed run keeps stage ``name`` from the earlier run: done then, and nothing it uses reruns."""
        if self.previous is None or name not in self.options.stages:
            return False
        earlier = self.previous["stages_by_name"].get(name)
        if not earlier or earlier.get("status") != "done":
            return False
        return not (set(DEPENDS[name]) | set(USES.get(name, ()))) & rerun

    def _restore(self, name: str) -> StageRecord:
        """Read stage ``name`` back from the folder: record, figures, summary, and what later stages need."""
        import xarray as xr

        earlier = self.previous["stages_by_name"][name]
        record = StageRecord(name, STAGES[name], earlier["status"], float(earlier.get("seconds", 0.0)),
                             list(earlier.get("files", [])), earlier.get("message", ""))
        self._current = record
        for file in record.files:
            if not (self.folder / file).is_file():
                raise InputError(f"file {file} of the earlier run is missing")
        if name == "roughness":
            profiles, surfaces = self._read_roughness()
            self._set_roughness_results(profiles, surfaces)
            self.inputs = list(self.previous.get("inputs", []))
        if name == "geometry":
            self._restore_geometry(self.previous["summaries"]["geometry"])
        if name in RELOADED:
            key, stem = RELOADED[name]
            with xr.open_dataset(self.folder / "data" / f"{stem}.nc") as dataset:
                self.results[key] = dataset.load()
        if name in self.previous.get("summaries", {}):
            self.summaries[name] = self.previous["summaries"][name]
        self.figures.extend(FigureRecord(**f) for f in self.previous.get("figures", []) if f.get("stage") == name)
        self.records[name] = record
        return record

    def _restore_geometry(self, summary):
        """The model parameters of the geometry stage from its summary (the geometry used downstream)."""
        used = summary.get("used_downstream", "parameters")
        if used == "parameters":
            return
        values = {f: summary[used][f] for f in _GEOMETRY_FIELDS}
        values["atomic_per_side"] = int(values["atomic_per_side"])
        name = used[len("from the meshing surface "):]
        self.model_params = self.params.updated(values, origin=f"derived from the scan '{name}' "
                                                               "(memstribo nanoblock --from)")

    def _forget(self, name: str) -> None:
        """Before a resumed run reruns stage ``name``: remove the earlier attempt's files and traceback."""
        from memstribo.job.folder import listed_path

        earlier = (self.previous or {}).get("stages_by_name", {}).get(name)
        for file in (earlier or {}).get("files", []):
            path = listed_path(self.folder, file, "--resume")  # checked in _read_previous; checked again here
            if path.is_file() or path.is_symlink():
                path.unlink()
        error = self.folder / f"error_{name}.txt"
        if error.is_file():
            error.unlink()

    # writing helpers ---------------------------------------------------------------------------
    def _files(self, paths):
        for path in paths:
            self._current.files.append(str(Path(path).relative_to(self.folder)))

    def _dataset(self, dataset, stem, roughness="mesh"):
        roughness = self.results.get("mesh_profile") if isinstance(roughness, str) else roughness
        self._files(write_dataset(dataset, self.folder / "data", stem, provenance=self._provenance(roughness)))

    def _provenance(self, roughness=None, **extra):
        """Global attributes of a file of the current stage (:func:`memstribo.output.provenance_attributes`)."""
        from memstribo.output import provenance_attributes

        stage = self._current.name if self._current is not None else ""
        doc = (getattr(type(self), stage, None).__doc__ or "") if stage else ""
        extra = {"title": f"memstribo run: {STAGES.get(stage, stage)}", "stage": stage,
                 "models": " ".join(doc.split("\n\n")[0].split()), "run_options": to_jsonable(self.options.__dict__),
                 **extra}
        return provenance_attributes(self.params, roughness=roughness, extra=extra)

    def _figure(self, figure, stem, caption):
        self._files(save_figure(figure, self.folder / "figures", stem))
        self.figures.append(FigureRecord(stem, self._current.name, caption))

    def _json(self, value, stem):
        path = self.folder / "data" / f"{stem}.json"
        ensure_directory(path.parent)
        atomic_write_text(path, dumps_json(value))
        self._files([path])

    # stages --------------------------------------------------------------------------------------
    def roughness(self):
        """Default synthetic profile and measured files: statistics (ISO 4287) and figure."""
        from memstribo.surfaces import roughness
        profiles, surfaces = self._read_roughness()
        statistics = [roughness.profile_statistics(p) for p in profiles]
        import xarray as xr

        keys = [k for k, v in statistics[0].to_dict().items() if isinstance(v, (int, float)) and not isinstance(v, bool)]
        from memstribo.quantities import attrs
        table = xr.Dataset({k: ("profile", np.array([s.to_dict()[k] for s in statistics], dtype=float), attrs(k))
                            for k in keys},
                           coords={"profile": ("profile", np.array([p.name for p in profiles], dtype=object))})
        self._dataset(table, "roughness_statistics", roughness=profiles)
        for i, profile in enumerate(profiles):
            ds = xr.Dataset({"z": ("x", np.asarray(profile.z), {"units": "m", "long_name": "height"})},
                            coords={"x": ("x", np.asarray(profile.x), {"units": "m", "long_name": "position"})},
                            attrs={"name": profile.name, "source": profile.source,
                                   "synthetic": int(bool(profile.synthetic))})
            self._dataset(ds, f"profile_{i}", roughness=profile)
        self.inputs = [{"name": p.name, "source": p.source, "synthetic": bool(p.synthetic),
                        "Rq": s.Rq, "Ra": s.Ra, "rms_slope": s.rms_slope, "n_points": s.n_points,
                        "sample_spacing": s.sample_spacing} for p, s in zip(profiles, statistics)]
        self._figure(plot_profiles(profiles), "roughness_profiles",
                     "Roughness profiles after levelling (the default is synthetic, seeded; measured files as named; "
                     "a map's middle scan line).")
        for i, surface in enumerate(surfaces):
            if surface is not None and hasattr(surface, "line_scans"):
                self._figure(plot_map(surface), f"roughness_map_{i}",
                             f"The measured map '{surface.name}' ({surface.heights.shape[1]} x {surface.heights.shape[0]} "
                             "pixels): its scan lines become nanoblock rows of the meshing cycle when it is the meshing "
                             "surface.")
        self._set_roughness_results(profiles, surfaces)
        self.summaries["roughness"] = {p.name: s.to_dict() for p, s in zip(profiles, statistics)}

    def _read_roughness(self):
        """The default profile and the measured files: (profiles, surfaces); a map gives its middle scan line."""
        from memstribo.surfaces import readers, roughness

        profiles = [roughness.default_profile(self.params)]
        surfaces = [None]  # what the meshing cycle gets: None is the synthetic default, else the file's surface
        for path in self.options.roughness_files:
            surface = readers.read_topography(path)
            if not isinstance(surface, roughness.Profile):
                rows = surface.line_scans()
                profile = rows[len(rows) // 2]
            else:
                profile = surface
            profiles.append(profile)
            surfaces.append(surface)
        return profiles, surfaces

    def _set_roughness_results(self, profiles, surfaces):
        self.results["profiles"] = profiles
        choice = self.options.mesh_roughness
        index = 0 if choice == "synthetic" else 1 + int(choice)
        # the meshing stages get the whole surface (a map's rows become nanoblock rows)
        self.results["mesh_profile"] = profiles[index]  # one line: the sliding stage and the provenance
        # the meshing stages get the whole surface (a map's rows become nanoblock rows), or None for the
        # synthetic default: independent seeded lines, exactly as 'memstribo mesh' makes them
        self.results["mesh_roughness"] = surfaces[index]
        self.results["mesh_profile_measured"] = index > 0
        for i, item in enumerate(self.inputs):
            item["meshing"] = i == index

    def geometry(self):
        """Nanoblock geometry from the parameters, and derived from each profile (with the rules used)."""
        from memstribo.physics.nanoblock import geometry
        rows = {"parameters": geometry.NanoblockGeometry.from_parameters(self.params)}
        notes = []
        for profile in self.results["profiles"]:
            try:
                rows[f"from profile {profile.name}"] = geometry.nanoblock_geometry_from_profile(profile)
            except MemstriboError as exc:
                notes.append(f"geometry from '{profile.name}' not derived: {exc}")
        self._current.message = "; ".join(notes)
        fields = _GEOMETRY_FIELDS
        summary = {label: {**{f: getattr(g, f) for f in fields}, "rules": dict(getattr(g, "rules", {}))}
                   for label, g in rows.items()}
        # the stages feed each other: a measured profile for the meshing cycle sets the nanoblock geometry
        # of every stage after this one (as 'memstribo nanoblock --from' derives it)
        used = "parameters"
        if self.results.get("mesh_profile_measured"):
            surface = self.results["mesh_roughness"]
            name = getattr(surface, "name", "measured surface")
            try:
                derived = geometry.nanoblock_geometry_from_profile(surface)
            except MemstriboError as exc:
                notes.append(f"the meshing surface's geometry could not be derived ({exc}): the parameters' "
                             "geometry is used")
                self._current.message = "; ".join(notes)
            else:
                used = f"from the meshing surface {name}"
                rows[used] = derived
                summary[used] = {**{f: getattr(derived, f) for f in fields}, "rules": dict(derived.rules)}
                values = {f: getattr(derived, f) for f in fields}
                values["atomic_per_side"] = int(values["atomic_per_side"])
                self.model_params = self.params.updated(values, origin=f"derived from the scan '{name}' "
                                                                       "(memstribo nanoblock --from)")
        summary["used_downstream"] = used
        self._json(summary, "nanoblock_geometry")
        self.results["geometry"] = rows[used]
        self.summaries["geometry"] = summary

    def sliding(self):
        """A single nanoblock on a flat at the external load (2.6.2) and the hierarchical structure sliding on
        the rough profile under a fixed load (3.4.2, 3.6): friction, COF and its split over the distance."""
        from memstribo.simulations import sliding
        summaries = {}
        for model, profile, distance, stem in (
                ("single", None, None, "sliding_single"),
                ("fixed-load", self.results["mesh_profile"], self.options.sliding_distance, "sliding_fixed_load")):
            dataset = sliding.slide(model, self.params, profile, distance=distance)
            stored = dataset
            if dataset.sizes["step"] > 20000:  # long slides: keep the per-step series (not per block), NetCDF only
                stored = dataset.drop_vars([n for n, v in dataset.data_vars.items() if v.dims != ("step",)])
            provenance = self._provenance(profile, **({} if profile is not None else
                                                      {"roughness_provenance": "none: one nanoblock on a flat"}))
            self._files(write_dataset(stored, self.folder / "data", stem, csv=stored.sizes["step"] <= 20000,
                                      provenance=provenance))
            summary = sliding.summarize(dataset)
            summaries[model] = dict(summary.__dict__)
            title = ("one nanoblock on a flat" if model == "single" else
                     "hierarchical structure on the rough profile, fixed load")
            self._figure(plot_sliding(dataset, title), stem,
                         f"Sliding of {title} at {self.params['normal_load'] * 1e6:.4g} µN: friction, adhesion and "
                         f"normal force (top), COF and its chemical / vdW / elastic split (bottom); mean COF "
                         f"{summary.cof_mean:.3g}, chemical share of the dissipated energy {summary.fraction_chemical:.0%} "
                         f"(thesis {'2.6.2' if model == 'single' else '3.6'}).")
        self.summaries["sliding"] = summaries

    def gear(self):
        """Gear pair geometry, Hertz contact at the pitch point and F_t (4-27)."""
        from memstribo.physics.gear import gear_summary

        from memstribo.physics import gear
        values, units = gear_summary(self.params)
        self._json({"values": values, "units": units}, "gear")
        self.summaries["gear"] = values
        pair = gear.GearPair.from_parameters(self.params)
        self._figure(plot_gear(pair, self.params["normal_load"], values["contact_modulus"]), "gear_path_of_contact",
                     "Along the path of contact: load share of one tooth pair (dry: half the load in double-tooth "
                     "contact; lubricated, Figure 4-11), effective radius R_ef (4-11), sliding velocity u1 - u2 "
                     "(4-12, signed radii) and Hertz half-width (4-24) at the external load.")

    def _simulate(self, params, coating=None, wear=1.0):
        from memstribo.simulations import mesh
        coating_object = None
        if coating is not None:
            from memstribo.physics.coating import get_coating

            coating_object = get_coating(coating, params)
        return mesh.simulate_mesh(params, self.results["mesh_roughness"], steps=self.options.steps,
                                  coating=coating_object, wear=wear)

    def _tangential_force(self):
        gear = self.summaries.get("gear")
        return gear["tangential_force"] if gear else None

    def mesh(self):
        """The bare-silicon meshing cycle (thesis 4.9, MODEL 7b): forces, COF and its split, energies, the
        stiction verdict over an ensemble of roughness realisations and its step convergence."""
        from memstribo.job.workers import ENSEMBLE_REALISATIONS
        from memstribo.simulations import mesh
        count = self.options.realisations  # keep: the uncertainty stage will take these realisations as its own
        keep = "uncertainty" in self.options.stages and self.options.uncertainty > 0
        one = ensemble_point_and_cycle if keep else mesh._ensemble_point
        point = (self.model_params, self.results["mesh_roughness"], self.options.steps, None, 1.0)
        client = self.workers.client(count - 1, "mesh ensemble", ENSEMBLE_REALISATIONS) if count > 1 else None
        futures = client.map(one, *[[a] * (count - 1) for a in point], list(range(1, count)), pure=False) \
            if client is not None else None  # the other realisations on the cluster while this one runs here
        try:
            dataset = self._simulate(self.model_params)
            self._dataset(dataset, "mesh_bare")  # written at once: a failing check below loses nothing computed
            self.results["mesh"] = dataset
            summary = cycle_summary(dataset)
            summary.update(mesh.run_check(self.model_params, self.results["mesh_roughness"], steps=self.options.steps,
                                          baseline=summary, dataset=dataset))  # 2x the steps and the grid (MODEL 7d)
        except BaseException:  # the stage fails: its realisations must not run on beside the next stages
            if futures is not None:
                client.cancel(futures)
            raise
        if keep:  # the uncertainty stage's nominal realisations are these cycles (issue 40)
            from memstribo.uncertainty.rescale import reduce_cycle

            self.results["nominal_cycles"] = {0: reduce_cycle(dataset)}
        if count > 1:
            first = dict(summary, realisation=0, seed=[int(self.model_params["roughness_seed"]), 0])
            others = client.gather(futures) if futures is not None else \
                [one(*point, k) for k in self._tick(range(1, count), "roughness realisations")]
            if keep:
                self.results["nominal_cycles"].update({k: cycle for k, (_, cycle) in enumerate(others, start=1)})
                others = [s for s, _ in others]
            ensemble = mesh.ensemble_summary([first] + others)
            self.results["ensemble"] = ensemble
            summary.update({key: value for key, value in ensemble.items() if key != "summaries"})
            self._json({key: value for key, value in ensemble.items() if key != "summaries"}, "mesh_bare_ensemble")
        self.summaries["mesh"] = summary
        self._figure(plot_cycle(dataset, self._tangential_force(), "bare silicon"), "mesh_bare_forces_cof",
                     "Bare silicon meshing cycle (first roughness realisation): the resisting force R(c) of all pairs "
                     "in mesh against F_t, the friction of one pair, adhesion and normal force (top), COF and its "
                     "chemical / vdW / elastic split (" + ("middle), and the instantaneous mesh efficiency with its "
                     "mean over a mesh period (bottom)." if "mesh_efficiency" in dataset else "bottom)."))
        if "ensemble" in self.results:
            self._figure(plot_ensemble(self.results["ensemble"], summary["tangential_force"]), "mesh_bare_ensemble",
                         f"Stiction margin and mean COF of {count} independent roughness realisations (5-95 % band "
                         "shaded, median dashed): the verdict's spread.")
        self._figure(plot_energy(dataset, "bare silicon"), "mesh_bare_energy",
                     "Energy dissipated per step by chemical bonds, vdW bonds and elastic interlocking.")

    def uncertainty(self):
        """What the verdict hangs on (MODEL 7d, docs/uncertainty.md): P(stiction) with its 95 % interval over roughness
        realisations x the uncertain constants drawn from their priors, the regional index of the verdict on those
        samples and the dominant constant's critical value where it is rescaled (issue 40: tens of cycles; Sobol'
        indices, end points and bands: ``memstribo mesh --uncertainty N --sobol``)."""
        from memstribo.uncertainty.figures import plot_sensitivity, plot_stiction_curve
        from memstribo.uncertainty.study import uncertainty_study

        samples = self.options.uncertainty
        steps = self.options.steps
        from memstribo.job.workers import RUN_CRITICAL, RUN_DECISION, RUN_SOLVE_SETS

        result = uncertainty_study(self.model_params, self.results["mesh_roughness"], samples=samples, steps=steps,
                                   sensitivity="regional", progress=self.progress,
                                   client=self.workers.client(samples, "uncertainty"), decision=RUN_DECISION,
                                   critical=RUN_CRITICAL, nominal_cycles=self.results.get("nominal_cycles"),
                                   solve_sets=RUN_SOLVE_SETS)
        self._json(result, "uncertainty")
        for stem, plot, caption in (
                ("uncertainty_sensitivity", plot_sensitivity,
                 "What the stiction verdict hangs on: the regional index of each factor, the Kolmogorov-Smirnov "
                 "distance between its values in the samples that stick and in those that do not (bars: 95 % "
                 "bootstrap intervals; ticks: the level noise alone reaches); where every sample gives the same "
                 "verdict, the rank correlation of each factor with the margin. Sobol' indices of the margin at the "
                 "verdict's steps: memstribo mesh --uncertainty 64 --sobol."),
                ("uncertainty_stiction_curve", plot_stiction_curve,
                 "P(stiction) over the roughness realisations against the dominant constant, the others at their "
                 "nominal values, with its 95 % interval; the critical value (median margin zero) is marked.")):
            written = plot(result, self.folder / "figures", stem)
            if written:
                self._files(written)
                self.figures.append(FigureRecord(stem, self._current.name, caption))
        self.summaries["uncertainty"] = uncertainty_summary(result)

    def _sweep_points(self, what, values, stage) -> list[dict]:
        """:func:`memstribo.simulations.mesh.sweep` at each of ``values``: on the run's cluster where it runs, else here."""
        from memstribo.simulations import mesh

        roughness, n = self.results["mesh_roughness"], len(values)
        client = self.workers.existing(stage) if n > 1 else None
        if client is not None:
            return [out[0] for out in client.gather(client.map(
                mesh.sweep, [self.model_params] * n, [what] * n, [[v] for v in values], [roughness] * n,
                steps=self.options.steps, pure=False))]
        return [mesh.sweep(self.model_params, what, [v], roughness, steps=self.options.steps)[0]
                for v in self._tick(values, stage)]

    def load_sweep(self):
        """COF and dissipated energy versus external load (4.9.3; thesis: COF ~0.9 at 25 uN to ~0.45 at 300 uN)."""
        summaries = self._sweep_points("load", self.options.loads, "load sweep")
        dataset = sweep_dataset("normal_load", self.options.loads, "N", "external load", summaries)
        self._dataset(dataset, "load_sweep")
        self.summaries["load_sweep"] = columns(dataset)
        self._figure(plot_sweep(dataset, "normal_load", "external load [µN]", 1e6, title="bare silicon"),
                     "load_sweep", "Time-mean COF and its split into chemical, van der Waals and elastic parts "
                     "(left), and the energy dissipated per meshing cycle (right) versus external load (thesis 4.9.3, "
                     "Figures 4-48 and 4-49)." + cof_above_one(dataset, "normal_load",
                                                               lambda v: format_quantity(v, "N")))

    def area_sweep(self):
        """COF and energy versus nominal contact area, in multiples of A_adh = w_adh^2 (4.9.4).

        As :func:`memstribo.simulations.mesh.sweep` (``"area"``): the face width is set to k w_adh, so that k rows of
        nanoblocks share the load.
        """
        summaries = self._sweep_points("area", self.options.areas, "area sweep")
        dataset = sweep_dataset("area_multiple", self.options.areas, "", "nominal area / A_adh", summaries)
        self._dataset(dataset, "area_sweep")
        self.summaries["area_sweep"] = columns(dataset)
        self._figure(plot_sweep(dataset, "area_multiple", "nominal area [A_adh]", title="bare silicon"),
                     "area_sweep", "Time-mean COF and its split into chemical, van der Waals and elastic parts "
                     "(left), and the energy dissipated per meshing cycle (right) versus nominal contact area (face "
                     "width = k w_adh; thesis 4.9.4, Figures 4-49 and 4-50)."
                     + cof_above_one(dataset, "area_multiple", lambda v: f"k = {v:g}"))

    def coated(self):
        """The coated pair, fully functionalised (Omega = 0; thesis 5.4)."""
        dataset = self._simulate(self.model_params, coating=self.options.coating, wear=0.0)
        self._dataset(dataset, "mesh_coated")
        self.results["coated"] = dataset
        self.summaries["coated"] = cycle_summary(dataset)
        self._figure(plot_cycle(dataset, self._tangential_force(), f"{self.options.coating}-coated, Omega = 0"),
                     "mesh_coated_forces_cof", f"Meshing cycle of the {self.options.coating}-coated pair "
                     "(no chemical bonds, Omega = 0): the resisting force R(c) of all pairs in mesh against F_t, the "
                     "friction of one pair, adhesion and normal force (top), COF and its vdW / elastic split ("
                     + ("middle), and the instantaneous mesh efficiency with its mean over a mesh period (bottom)."
                        if "mesh_efficiency" in dataset else "bottom)."))
        if "block_load" in dataset:
            self._figure(plot_block_loads(dataset, f"{self.options.coating}-coated pair, Omega = 0"),
                         "mesh_coated_block_loads", "Normal load of every nanoblock of both flanks over the meshing "
                         "cycle (top) and the largest one (bottom): the load peaks that damage the coating "
                         "(thesis Figure 5-18).")

    def wear_sweep(self):
        """COF and friction versus the worn fraction Omega of the gear's coating (5.5.3)."""
        from memstribo.physics import coating
        from memstribo.simulations import coating_wear
        known = {0.0: self.results["coated"]} if "coated" in self.results else {}  # the coated stage's cycle
        todo = [float(w) for w in self.options.wear if float(w) not in known]
        client = self.workers.existing("wear sweep") if len(todo) > 1 else None
        if client is not None:  # the other wear states on the run's cluster (the same cycles, issue 40)
            n = len(todo)
            known.update(zip(todo, client.gather(client.map(
                coated_cycle, [self.model_params] * n, [self.options.coating] * n, [self.results["mesh_roughness"]] * n,
                [self.options.steps] * n, todo, pure=False))))
        dataset = coating_wear.wear_sweep(self.model_params, self.options.coating, list(self.options.wear),
                                          roughness=self.results["mesh_roughness"], steps=self.options.steps,
                                          known=known)
        self._dataset(dataset, "wear_sweep")
        self.results["wear_sweep"] = dataset
        self.summaries["wear_sweep"] = {**columns(dataset), "critical_wear": coating.critical_wear(dataset)}
        self._figure(plot_sweep(dataset, "wear", "worn fraction Omega [%]", 100.0, self._tangential_force(),
                                title=self.options.coating), "wear_sweep",
                     "COF and its split (left), and the largest resisting force R over the cycle against F_t (right) "
                     "versus the worn fraction Omega of the gear's coating (thesis 5.5.3, Figure 5-28)."
                     + cof_above_one(dataset, "wear", lambda v: f"Omega = {v * 100:.0f} %"))

    def damage(self):
        """Damage per meshing cycle of the coating, relative lives, cycles until stiction returns (5.5)."""
        from memstribo.physics import damage
        outcome = damage.run_damage(self.model_params, self.results["coated"], wear_sweep=self.results.get("wear_sweep"),
                      cycles_observed=self.options.cycles_observed)
        self.summaries["damage"] = dict(outcome.summary)
        for stem, dataset in getattr(outcome, "datasets", {}).items():
            self._dataset(dataset, stem)
        for stem, (figure, caption) in getattr(outcome, "figures", {}).items():
            self._figure(figure, stem, caption)
        self._lives_figure(outcome.summary)

    def _lives_figure(self, damage_summary):
        """Stiction, coating life and fracture life together (MODEL §10): the coated cycle's tooth strength."""
        from memstribo.errors import InputError
        from memstribo.physics.coating import get_coating
        from memstribo.simulations.tooth_life import tooth_life

        try:
            result = tooth_life(self.results["coated"], self.model_params,
                                coating=get_coating(self.options.coating, self.model_params))
        except InputError as exc:  # a tooth form the root-stress method cannot draw: said, not drawn
            self.summaries["damage"]["lives_note"] = f"fracture life not computed: {exc}"
            return
        life = damage_summary.get("cycles_to_failure")
        stiction = damage_summary.get("cycles_to_stiction")
        self.summaries["damage"].update(fracture_probability=result["fracture_probability"],
                                        cycles_to_fracture_p01=result["cycles_to_fracture_p01"])
        self._figure(plot_lives(result, np.logspace(0, 14, 200), life, stiction, self.options.coating), "lives",
                     "Lives of the coated pair on one axis: the probability that a tooth has broken (Weibull strength "
                     "of polysilicon, delayed failure in air, docs/strength.md) against the meshing cycles, with the "
                     "cycles until the coating wears through and stiction returns where the damage constant c1 is "
                     "known (--observed-life or damage_coefficient; without it only relative coating lives exist).")

    def map_stage(self):
        """Design map of ``[run] map`` (:func:`memstribo.simulations.design_map.design_map`, docs/design-maps.md): every grid
        point an ensemble verdict (stiction probability, margin, COF, mesh efficiency, coating life).

        The points run on Dask's local cluster and are kept point by point in ``DIR/map/points``, so that
        ``--resume`` computes only the missing ones; ``DIR/map/map.nc`` (one dimension per axis) and
        ``map.csv`` hold the map; the figures (stiction probability with its 50 % boundary, efficiency,
        coating life where known) go to ``DIR/figures``. The run's parameters are the map's base
        (its ``[parameters]`` on top); ``[run] steps`` applies when the spec gives no ``steps``.
        """
        from memstribo.simulations.design_map import design_map, load_map_spec, map_figures

        spec = load_map_spec(self.options.map)
        if spec.steps is None and self.options.steps is not None:
            spec = replace(spec, steps=self.options.steps)
        folder = self.folder / "map"
        result = design_map(spec, folder, self.params, resume=self.previous is not None, progress=self.progress,
                            figures=False)
        self._files(path for path in (folder / "map.json", folder / "map.nc", folder / "map.csv") if path.is_file())
        self.results["design_map"] = result.dataset
        written, figure_notes = map_figures(result.dataset, self.folder / "figures", spec.plot)
        self._files(written)
        stems = {path.stem for path in written}
        for stem, caption in _map_captions(spec, result.dataset).items():
            if stem in stems:
                self.figures.append(FigureRecord(stem, self._current.name, caption))
        self.summaries["design_map"] = _map_summary(spec, result, list(result.notes) + figure_notes)
        if result.n_failed:
            first = next(iter(result.errors.items()))
            raise InputError(f"{result.n_failed} of {result.n_points} map points failed (first, {first[0]}: "
                             f"{first[1]}); the others are kept in map/points; --resume runs the failed ones again")

    def _run_map_stage(self, log) -> StageRecord:
        """Run :meth:`map_stage` and record how it went (as :meth:`run_stage` does for the stages of :data:`STAGES`)."""
        name = MAP_STAGE[0]
        record = self.records[name] = StageRecord(*MAP_STAGE)
        self._current = record
        self.figures = [f for f in self.figures if f.stage != name]
        (self.folder / f"error_{name}.txt").unlink(missing_ok=True)  # an earlier attempt's traceback
        log.info("stage %s (the design map of [run] map) ...", name)
        start = time.perf_counter()
        try:
            self.map_stage()
            record.status = "done"
        except MemstriboError as exc:
            record.status, record.message = "failed", f"{type(exc).__name__}: {exc}"
        except Exception as exc:  # a bug: keep the run's other results, say so loudly
            record.status = "failed"
            record.message = f"internal error {type(exc).__name__}: {exc}"
            (self.folder / f"error_{name}.txt").write_text(traceback.format_exc(), encoding="utf-8")
        record.seconds = time.perf_counter() - start
        log.info("stage %s: %s in %.1f s%s", name, record.status, record.seconds,
                 f" ({record.message})" if record.message else "")
        return record

    # running -------------------------------------------------------------------------------------
    def humid_air(self):
        """Humid air (issue #17): COF, its capillary share and the stiction margin versus relative humidity, bare
        and coated (memstribo.simulations.mesh.sweep 'humidity'), and the critical humidity at which stiction sets in
        (memstribo.simulations.mesh.critical_humidity)."""
        from memstribo.simulations import mesh
        from memstribo.physics.coating import get_coating

        values = list(HUMIDITY_VALUES)
        roughness = self.results.get("mesh_roughness")
        summary = {"relative_humidity": values}
        coating = get_coating(self.options.coating, self.model_params)
        for label, kwargs in (("bare", {}), ("coated", {"coating": coating, "wear": 0.0})):
            points = mesh.sweep(self.model_params, "humidity", values, roughness, steps=self.options.steps, **kwargs)
            part = {"name": "bare silicon" if label == "bare" else f"{coating.name}-coated, Omega = 0"}
            for key in ("cof_mean", "cof_capillary", "cof_chemical", "cof_vdw", "adhesion_force_mean",
                        "stiction_margin"):
                part[key] = [float(p[key]) for p in points]
            part.update(mesh.critical_humidity(points))
            summary[label] = part
        self.summaries["humidity"] = summary
        self._json(summary, "humidity_sweep")
        self._figure(plot_humidity(summary, f"environment air, T = {float(self.model_params['ambient_temperature']):.4g} K"),
                     "humidity_cof_margin",
                     "COF over the cycle with its capillary part (breaking menisci), and the stiction margin "
                     "F_t - max R(c), versus relative humidity, bare silicon and the coated pair (Omega = 0); dotted: "
                     "the critical humidity where the margin crosses zero (issue #17, docs/humidity.md).")

    def _run_humid_air(self):
        """Run :meth:`humid_air` as an extra record after the stages (runs in air only; vacuum runs are unchanged)."""
        record = self.records.setdefault("humidity", StageRecord("humidity", HUMIDITY_TITLE))
        self._current = record
        self.figures = [f for f in self.figures if f.stage != "humidity"]
        start = time.perf_counter()
        try:
            self.humid_air()
            record.status, record.message = "done", ""
        except MemstriboError as exc:
            record.status, record.message = "failed", f"{type(exc).__name__}: {exc}"
        except Exception as exc:  # a bug: keep the rest of the run, say so loudly
            record.status, record.message = "failed", f"internal error {type(exc).__name__}: {exc}"
            (self.folder / "error_humidity.txt").write_text(traceback.format_exc(), encoding="utf-8")
        record.seconds = time.perf_counter() - start
        return record

    def _tick(self, values, label):
        if not self.progress:
            return values
        from tqdm.auto import tqdm

        return tqdm(values, desc=f"  {label}", leave=False, file=sys.stderr, unit="pt")

    def run_stage(self, name: str) -> StageRecord:
        """Run one stage (if its inputs exist) and record how it went."""
        record = self.records[name]
        self._current = record
        if name not in self.options.stages:
            record.status, record.message = "skipped", "not requested ([run] stages)"
            return record
        # geometry only feeds the model stages when it was asked for (else: the parameters' geometry)
        missing = [d for d in DEPENDS[name] if self.records[d].status != "done"
                   and not (d == "geometry" and d not in self.options.stages)]
        if missing:
            record.status = "skipped"
            record.message = f"needs stage(s) {', '.join(missing)}, which did not finish"
            return record
        start = time.perf_counter()
        try:
            getattr(self, name)()
            record.status = "done"
        except MemstriboError as exc:
            record.status, record.message = "failed", f"{type(exc).__name__}: {exc}"
        except Exception as exc:  # a bug: keep the other stages, say so loudly
            record.status = "failed"
            record.message = f"internal error {type(exc).__name__}: {exc}"
            (self.folder / f"error_{name}.txt").write_text(traceback.format_exc(), encoding="utf-8")
        record.seconds = time.perf_counter() - start
        return record

    def run(self) -> RunResult:
        """All stages in order; parameters, references, run.json and report.html after each."""
        from tqdm.auto import tqdm

        from memstribo.references import REFERENCES, cites, reset_used_references

        start = time.perf_counter()
        reset_used_references()
        log = logging.getLogger("memstribo.run")
        rerun: set[str] = set()
        if self.previous is None:
            self._write_text("parameters.toml", _toml_with_provenance(self.params.to_toml()))
        else:  # the kept stages' references stay in references.txt
            earlier = [key for key in self.previous.get("references", []) if key in REFERENCES]
            if earlier:
                cites(*earlier)(lambda: None)()
        bar = tqdm(list(STAGES), desc="memstribo run", unit="stage", file=sys.stderr, disable=not self.progress)
        for index, name in enumerate(bar, 1):
            bar.set_postfix_str(name)
            if self._keep(name, rerun):
                try:
                    self._restore(name)
                    self.kept.append(name)
                    log.info("stage %d/%d %s: done in the earlier run, read back", index, len(STAGES), name)
                    continue
                except Exception as exc:  # anything missing or unreadable: compute the stage again
                    log.warning("stage %d/%d %s: could not be read back (%s); running it again", index, len(STAGES),
                                name, exc)
                    self.records[name] = StageRecord(name, STAGES[name])
                    self.figures = [f for f in self.figures if f.stage != name]
            if self.previous is not None and name in self.options.stages:
                rerun.add(name)
                self._forget(name)
            log.info("stage %d/%d %s ...", index, len(STAGES), name)
            record = self.run_stage(name)
            log.info("stage %d/%d %s: %s in %.1f s%s", index, len(STAGES), name, record.status, record.seconds,
                     f" ({record.message})" if record.message else "")
            self._finish(time.perf_counter() - start)
        bar.close()
        self.workers.close()  # the map stage starts its own cluster
        if self.options.map:
            self._run_map_stage(log)
        if self.model_params["environment"] == "air":  # the humid-air section (issue #17)
            log.info("humid air: COF and stiction margin versus relative humidity ...")
            record = self._run_humid_air()
            log.info("humid air: %s in %.1f s%s", record.status, record.seconds,
                     f" ({record.message})" if record.message else "")
            self._finish(time.perf_counter() - start)
        validation = None
        if self.options.validation:
            from memstribo.job.report import validation_rows

            recompute = self.options.validation == "recompute"
            log.info("validation table (every topic's rows%s) ...", ", 1-3 min" if recompute else ", as shipped")
            validation = validation_rows(recompute)
            log.info("validation table: done")
        return self._finish(time.perf_counter() - start, validation)

    def _ordered_figures(self) -> list[FigureRecord]:
        """The figures in stage order (a resumed run adds the rerun stages' figures after the kept ones)."""
        order = {name: i for i, name in enumerate(STAGES)}
        return sorted(self.figures, key=lambda f: order.get(f.stage, len(order)))

    def _write_text(self, name, text):
        atomic_write_text(self.folder / name, text)

    def _finish(self, elapsed, validation=None) -> RunResult:
        from memstribo.job.folder import written_files
        from memstribo.references import used_references
        from memstribo.job.report import write_report

        result = RunResult(self.folder, self.params, self.options, list(self.records.values()),
                           self._ordered_figures(), dict(self.summaries), verdict(self.summaries), list(self.inputs),
                           elapsed, list(self.kept))
        references = used_references()
        self._write_text("references.txt", "".join(f"[{key}] {text}\n" for key, text in references))
        self._write_text("run.json", dumps_json({
            "elapsed": elapsed, "options": to_jsonable(self.options.__dict__),
            "stages": [r.__dict__ for r in result.stages], "figures": [f.__dict__ for f in result.figures],
            "verdict": result.verdict, "summaries": result.summaries, "inputs": result.inputs,
            "references": [key for key, _ in references], "kept": list(self.kept),
            "written": written_files(self.folder, self.records, bool(self.options.map)),
            "provenance": software_provenance()}))
        write_report(result, self.folder / "report.html", validation)
        return result


def _toml_with_provenance(text: str) -> str:
    """``parameters.toml`` with ``[meta.provenance]``: what ran (:func:`memstribo.output.software_provenance`).

    ``[meta]`` is ignored when the file is read back as a ``--config`` file."""
    import tomllib

    import tomli_w

    data = tomllib.loads(text)
    data.setdefault("meta", {})["provenance"] = to_jsonable(software_provenance())
    return tomli_w.dumps(data)


def _map_captions(spec, dataset) -> dict[str, str]:
    """Captions of the design map's figures (by file stem)."""
    axes = ", ".join(f"{key} ({len(values)})" for key, values in spec.axes)
    common = (f"Design map '{spec.name}' over {axes}; every point {spec.realisations} roughness realisation(s) of "
              "the meshing cycle (dots: the grid points; other axes than the two plotted: one panel per value).")
    return {
        "design_map_stiction": f"{common} Stiction probability: the fraction of realisations in which the friction of "
                               "the pairs in mesh exceeds F_t somewhere on the path of contact; the black line is the "
                               "50 % boundary (drawn where the map crosses it).",
        "design_map_efficiency": f"{common} Mesh efficiency, median over the realisations.",
        "design_map_coating_life": f"{common} Coated points: log10 of the meshing cycles until the coating first "
                                   "fails (from the damage coefficient c1 or the observed life).",
    }


def _map_summary(spec, result, notes) -> dict[str, Any]:
    """Scalar summary of a design map for run.json and the report."""
    dataset = result.dataset

    def finite(name):
        values = np.asarray(dataset[name].values, dtype=float)
        return values[np.isfinite(values)]

    probability = finite("stiction_probability")
    summary: dict[str, Any] = {
        "spec": spec.source, "name": spec.name, "axes": {key: len(values) for key, values in spec.axes},
        "plot": list(spec.plot), "realisations": spec.realisations, "steps": spec.steps,
        "points": result.n_points, "computed": result.n_computed, "reused": result.n_reused,
        "failed": result.n_failed, "map_netcdf": "map/map.nc", "map_csv": "map/map.csv",
        "points_sticking": int((probability >= 0.5).sum()), "points_free": int((probability == 0).sum()),
        "notes": notes,
    }
    for name in ("stiction_probability", "mesh_efficiency_median", "cycles_to_failure", "cycles_to_stiction"):
        values = finite(name)
        summary[f"{name}_min"] = float(values.min()) if values.size else None
        summary[f"{name}_max"] = float(values.max()) if values.size else None
    return summary


