"""What the main job runs and what it returns: its stages and their dependencies, the ``[run]`` options
(:class:`RunOptions`), and the records of stages, figures and the whole run."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from memstribo.errors import InputError, did_you_mean

from memstribo.parameters import RUN_DEFAULT_COATING, RUN_DEFAULT_WEAR
from memstribo.parameters import RUN_KEYS as _RUN_KEYS  # the [run] table's keys live with the config reader

#: The stages of the main job, in order, with their titles.
STAGES: dict[str, str] = {
    "roughness": "Roughness of the tooth surfaces",
    "geometry": "Nanoblock geometry",
    "sliding": "Sliding of nanoblocks on a flat and on the rough surface",
    "gear": "Gear pair and macroscopic contact",
    "mesh": "Bare silicon meshing cycle",
    "uncertainty": "What the verdict hangs on: stiction probability over roughness and the constants' priors",
    "load_sweep": "COF and dissipated energy versus external load (thesis load case)",
    "area_sweep": "COF and dissipated energy versus nominal contact area",
    "coated": "Coated pair (functionalised surfaces)",
    "wear_sweep": "Wear of the coating: COF versus worn fraction",
    "damage": "Damage accumulation and lifetime of the coating",
}

#: What each stage needs.
DEPENDS: dict[str, tuple[str, ...]] = {
    "roughness": (), "geometry": ("roughness",), "sliding": ("roughness",), "gear": (),
    "mesh": ("roughness", "geometry"), "uncertainty": ("roughness", "geometry"),
    "load_sweep": ("roughness", "geometry"), "area_sweep": ("roughness", "geometry"),
    "coated": ("roughness", "geometry"), "wear_sweep": ("roughness", "geometry"), "damage": ("coated",),
}

#: Inputs a stage takes when they exist, beyond :data:`DEPENDS` (the damage stage uses the wear sweep when it ran;
#: the meshing stages draw F_t of the gear stage in their figures). ``--resume`` reruns a stage whose
#: dependencies or inputs are run again.
USES: dict[str, tuple[str, ...]] = {"mesh": ("gear",), "coated": ("gear",), "wear_sweep": ("gear",),
                                    "damage": ("gear", "wear_sweep")}

#: The optional last stage, a design map (``[run] map = "SPEC.toml"``, :meth:`RunChain.map_stage`): name and title.
#: It is not one of :data:`STAGES`, so a run without a map has the same stages as before.
MAP_STAGE: tuple[str, str] = ("design_map", "Design map: stiction probability, mesh efficiency and coating life over "
                                            "a grid of designs")

#: The datasets a resumed run reads back from ``DIR/data`` for the stages after them (stage: (result key, stem)).
RELOADED: dict[str, tuple[str, str]] = {"coated": ("coated", "mesh_coated"), "wear_sweep": ("wear_sweep", "wear_sweep")}

@dataclass(frozen=True)
class RunOptions:
    """What the main job runs (the ``[run]`` table of a config file).

    Attributes
    ----------
    steps : int or None
        Positions along the path of contact per meshing simulation (None: the model's default).
    loads : tuple of float
        External loads of the load sweep [N].
    areas : tuple of float
        Nominal contact areas of the area sweep, in multiples of A_adh [-].
    wear : tuple of float
        Worn fractions Omega of the wear sweep [-].
    coating : str
        Coating of the coated stages.
    roughness_files : tuple of str
        Measured profiles or AFM files (absolute paths).
    mesh_roughness : str or int
        ``"synthetic"`` or the index in ``roughness_files`` of the profile the meshing stages use.
    stages : tuple of str
        Stages to run.
    cycles_observed : float or None
        An observed coating life [cycles] to calibrate the damage constant c1.
    sliding_distance : float or None
        Sliding distance [m] of the structure in the ``sliding`` stage (None: the model's default).
    validation : bool or "recompute"
        Put the validation table (every topic's rows) into the report: True, the rows shipped with this version
        (they do not depend on the run's parameters); "recompute", computed again at the end (1-2 min).
    realisations : int
        Independent roughness realisations of the bare verdict (MODEL 7b).
    uncertainty : int
        Samples (roughness realisations x sets of the uncertain constants) of the ``uncertainty`` stage (MODEL 7d;
        0: the stage is left out).
    map : str or None
        A design map spec file (absolute path; :func:`memstribo.simulations.design_map.load_map_spec`) run as
        the last stage (:meth:`RunChain.map_stage`); None: no map.
    """

    steps: int | None = None
    loads: tuple[float, ...] = (25e-6, 50e-6, 100e-6, 150e-6, 200e-6, 300e-6)
    areas: tuple[float, ...] = (1.0, 2.0, 4.0, 8.0, 16.0)
    wear: tuple[float, ...] = RUN_DEFAULT_WEAR
    coating: str = RUN_DEFAULT_COATING
    roughness_files: tuple[str, ...] = ()
    mesh_roughness: Any = "synthetic"
    stages: tuple[str, ...] = tuple(STAGES)
    cycles_observed: float | None = None
    sliding_distance: float | None = None
    validation: bool | str = True
    realisations: int = 16
    uncertainty: int = 64
    map: str | None = None

    def check_with(self, params) -> None:
        """The ``[run]`` values that depend on the parameters, checked before the first stage.
    
        ``sliding_distance`` over the sliding step (``sliding_step``, unset: ``bond_length``) is at most
        1 million steps, the sliding stage's limit; ``steps`` obeys the memory estimate of the meshing cycle.
    
        Raises
        ------
        InputError
            A value the stage would refuse only once the run has reached it.
        """
        from memstribo.parameters import check_mesh_size
    
        if self.sliding_distance is not None:
            step = params["sliding_step"] or params["bond_length"]
            if self.sliding_distance / step > 1_000_000:
                raise InputError(f"[run] sliding_distance = {self.sliding_distance:.4g} m is "
                                 f"{self.sliding_distance / step:.3g} sliding steps of {step:.3g} m; the sliding stage "
                                 "takes at most 1e6 (use a shorter distance, e.g. '0.5 um', or a larger sliding_step).")
        if self.steps is not None:
            if self.steps > 100_000:  # the bound of mesh_steps, before anything is sized from it
                raise InputError(f"[run] steps / --steps = {self.steps:,}: at most 100,000 positions per meshing cycle.")
            check_mesh_size(self.steps, params["mesh_window"], params["mesh_grid_spacing"], what="[run] steps")

    @classmethod
    def from_table(cls, table: Mapping[str, Any] | None, base_folder: str | Path | None = None) -> "RunOptions":
        """Validate a ``[run]`` table (values may carry units: ``loads = ["25 uN", "50 uN"]``).

        Relative file names are taken relative to ``base_folder`` (the config file's folder).

        Raises
        ------
        InputError
            Unknown keys, bad values, missing files.
        """
        from memstribo.units import to_si

        table = dict(table or {})
        unknown = sorted(set(table) - set(_RUN_KEYS))
        if unknown:
            raise InputError(f"[run]: unknown key '{unknown[0]}'; allowed: {', '.join(_RUN_KEYS)}."
                             f"{did_you_mean(unknown[0], _RUN_KEYS)}")
        options: dict[str, Any] = {}
        if "steps" in table:
            steps = table["steps"]
            if not isinstance(steps, int) or isinstance(steps, bool) or steps < 3:
                raise InputError(f"[run] steps = {steps!r}: give an integer >= 3 (a meshing cycle needs 3 positions).")
            options["steps"] = steps
        if "realisations" in table:
            count = table["realisations"]
            if not isinstance(count, int) or isinstance(count, bool) or not 1 <= count <= 10000:
                raise InputError(f"[run] realisations = {count!r}: give an integer from 1 to 10000.")
            options["realisations"] = count
        if "uncertainty" in table:
            count = table["uncertainty"]
            if not isinstance(count, int) or isinstance(count, bool) or not 0 <= count <= 4096:
                raise InputError(f"[run] uncertainty = {count!r}: give an integer from 0 (no uncertainty stage) to "
                                 "4096 samples.")
            options["uncertainty"] = count

        def number_list(key, unit, minimum, maximum=None):
            values = table[key]
            if not isinstance(values, list) or not values:
                raise InputError(f"[run] {key}: give a non-empty list, e.g. {key} = [...].")
            out = [to_si(v, unit, key) for v in values]
            for raw, v in zip(values, out):
                if not math.isfinite(v) or v < minimum or (maximum is not None and v > maximum):
                    allowed = f">= {minimum:g}" + (f" and <= {maximum:g}" if maximum is not None else "")
                    raise InputError(f"[run] {key}: value {raw!r} is outside its range ({allowed}).")
            return tuple(out)

        if "loads" in table:
            options["loads"] = number_list("loads", "N", 0.0)
            if min(options["loads"]) <= 0:
                raise InputError("[run] loads: every load must be > 0.")
        if "areas" in table:
            options["areas"] = number_list("areas", "", 1.0)
            if not all(float(a).is_integer() for a in options["areas"]):
                raise InputError("[run] areas: give whole multiples of A_adh (1, 2, 4, ...).")
        if "wear" in table:
            options["wear"] = number_list("wear", "", 0.0, 1.0)
        if "coating" in table:
            from memstribo.physics.coating import get_coating

            options["coating"] = get_coating(str(table["coating"])).name  # checked before the first stage
        if "roughness_files" in table:
            options["roughness_files"] = _roughness_files(table["roughness_files"], base_folder)
        if "mesh_roughness" in table:
            choice = table["mesh_roughness"]
            n_files = len(options.get("roughness_files", ()))
            if choice != "synthetic" and not (isinstance(choice, int) and 0 <= choice < n_files):
                raise InputError(f"[run] mesh_roughness = {choice!r}: give 'synthetic' or an index 0..{n_files - 1} "
                                 "of roughness_files.")
            options["mesh_roughness"] = choice
        if "stages" in table:
            stages = table["stages"]
            if not isinstance(stages, list) or not stages:
                raise InputError("[run] stages: give a non-empty list of stage names.")
            for name in stages:
                if name not in STAGES:
                    raise InputError(f"[run] stages: unknown stage '{name}'; stages: {', '.join(STAGES)}."
                                     f"{did_you_mean(str(name), STAGES)}")
            options["stages"] = tuple(s for s in STAGES if s in stages)
        if options.get("uncertainty", 1) == 0:  # no samples: the stage is left out
            options["stages"] = tuple(s for s in options.get("stages", STAGES) if s != "uncertainty")
        if "cycles_observed" in table:
            cycles = to_si(table["cycles_observed"], "", "cycles_observed")
            if not cycles > 0:
                raise InputError(f"[run] cycles_observed = {table['cycles_observed']!r}: give a number of cycles > 0.")
            options["cycles_observed"] = cycles
        if "validation" in table:
            if not isinstance(table["validation"], bool) and table["validation"] != "recompute":
                raise InputError(f"[run] validation = {table['validation']!r}: give true (the rows shipped with this "
                                 "version), \"recompute\" (compute them again, 1-2 min) or false.")
            options["validation"] = table["validation"]
        if "sliding_distance" in table:
            distance = to_si(table["sliding_distance"], "m", "sliding_distance")
            if not distance > 0:
                raise InputError(f"[run] sliding_distance = {table['sliding_distance']!r}: give a length > 0.")
            options["sliding_distance"] = distance
        if "map" in table:
            options["map"] = _map_option(table["map"], base_folder)
        return cls(**options)


def _roughness_files(files, base_folder) -> tuple[str, ...]:
    """The ``[run] roughness_files`` (a name or a list), resolved against ``base_folder``; InputError if one is
    missing."""
    if isinstance(files, str):
        files = [files]
    resolved = []
    for name in files:
        path = Path(str(name)).expanduser()
        if not path.is_absolute() and base_folder is not None:
            path = Path(base_folder) / path
        if not path.exists():
            raise InputError(f"[run] roughness_files: '{name}' does not exist.")
        if not path.is_file():
            raise InputError(f"[run] roughness_files: '{name}' is not a regular file (a folder, device or "
                             "pipe); give measurement files.")
        from memstribo.surfaces.readers import read_topography

        try:  # read now, so that a file no reader takes stops the run before its first stage
            read_topography(path)
        except InputError as exc:
            raise InputError(f"[run] roughness_files: {exc}") from None
        resolved.append(str(path.resolve()))
    return tuple(resolved)


def _map_option(value, base_folder) -> str:
    """``[run] map``: the absolute path of a map spec file, read and validated whole before the first stage."""
    from memstribo.simulations.design_map import load_map_spec
    from memstribo.units import printable

    if not isinstance(value, str) or not value.strip():
        raise InputError(f"[run] map = {printable(repr(value), 60)}: give the path of a map spec file (TOML with a "
                         "[map] table, see docs/design-maps.md).")
    path = Path(value).expanduser()
    if not path.is_absolute() and base_folder is not None:
        path = Path(base_folder) / path
    if not path.is_file():
        raise InputError(f"[run] map: '{printable(value, 200)}' does not exist.")
    try:
        load_map_spec(path)
    except InputError as exc:
        raise InputError(f"[run] map: {exc}") from None
    return str(path.resolve())


@dataclass
class StageRecord:
    """How one stage went.

    Attributes
    ----------
    name, title : str
        Stage name (see :data:`STAGES`) and heading.
    status : str
        ``"done"``, ``"skipped"`` (not asked for, or an input stage did not finish) or ``"failed"``.
    seconds : float
        Wall time [s].
    files : list of str
        Files written, relative to the output folder.
    message : str
        Why it was skipped or failed; what it assumed.
    """

    name: str
    title: str
    status: str = "pending"
    seconds: float = 0.0
    files: list[str] = field(default_factory=list)
    message: str = ""


@dataclass(frozen=True)
class FigureRecord:
    """One figure: ``stem`` (files ``stem.png`` and ``stem.svg``), its stage and its caption."""

    stem: str
    stage: str
    caption: str


@dataclass
class RunResult:
    """The main job's outcome (also in ``run.json`` of the output folder).

    Attributes
    ----------
    folder : pathlib.Path
        Output folder.
    params : memstribo.parameters.Parameters
        The parameters used (also ``parameters.toml``).
    options : RunOptions
        What was run.
    stages : list of StageRecord
        Stage by stage.
    figures : list of FigureRecord
        Figures written, in order.
    summaries : dict
        Per stage, its scalar results (SI).
    verdict : dict
        Stiction and coating life (see :func:`verdict`).
    inputs : list of dict
        The roughness inputs with provenance (name, source, synthetic).
    elapsed : float
        Wall time [s].
    """

    folder: Path
    params: Any
    options: RunOptions
    stages: list[StageRecord]
    figures: list[FigureRecord]
    summaries: dict[str, Any]
    verdict: dict[str, Any]
    inputs: list[dict[str, Any]]
    elapsed: float = 0.0
    #: stages a resumed run kept from the earlier run in the folder (read back, not recomputed)
    kept: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """True when every requested stage is done (the design map too, when ``[run] map`` asks for one)."""
        return all(s.status == "done" for s in self.stages
                   if s.name in self.options.stages or s.name == MAP_STAGE[0])


def options_for_test(**changes) -> RunOptions:
    """Small, fast options (few steps and sweep points) exercising every stage."""
    return replace(RunOptions(steps=8, loads=(25e-6, 150e-6), areas=(1.0, 4.0), wear=(0.0, 1.0),
                              sliding_distance=0.5e-6, validation=False, realisations=3, uncertainty=4), **changes)
