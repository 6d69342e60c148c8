"""The public API in a few names: read a surface, get and change a parameter set, simulate a
meshing cycle (one or an ensemble of roughness realisations), sweep, run the whole chain.

Every function here is re-exported at the top of the package (``memstribo.read_surface``, ...)
and imported lazily, so ``import memstribo`` stays quick. Physical values may be numbers in SI,
strings with units (``"50 uN"``) or pint quantities (``50 * ureg.uN``); surfaces may be file
paths, memstribo profiles and maps, or SurfaceTopography topographies. Results are labelled:
xarray datasets, or small result objects with ``.to_xarray()``.

Example
-------
>>> import memstribo
>>> params = memstribo.parameter_set(normal_load="50 uN", load_case="thesis")  # doctest: +SKIP
>>> cycle = memstribo.mesh_cycle(params, "data/afm/opdx-3.opdx", steps=121)     # doctest: +SKIP
>>> cycle.summary["cof_mean"], cycle.summary["verdict"]                        # doctest: +SKIP
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from memstribo.errors import InputError

__all__ = ["read_surface", "parameter_set", "mesh_cycle", "MeshCycle", "sweep", "run", "design"]


def _plain(value: Any) -> Any:
    """A pint quantity as a string pint can read back (``"50.0 micronewton"``); anything else unchanged.

    The magnitude may be a Python number, a numpy scalar (``np.float64(50) * ureg.uN``) or a 1-D array
    (``[25, 50] * ureg.uN``, which gives a list of strings, one per value). ``repr`` of a numpy scalar is
    ``np.float64(50.0)`` under numpy 2, which no unit parser reads, so every magnitude goes through ``float``.
    """
    if not (hasattr(value, "magnitude") and hasattr(value, "units")):
        return value
    import numpy as np

    magnitude = value.magnitude
    try:
        array = np.asarray(magnitude, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"quantity {_shown(value)}: its magnitude is not a number; give a number or a list of "
                         "numbers times a unit (e.g. 50 * ureg.uN, [25, 50] * ureg.uN).") from None
    if array.ndim == 0:
        return f"{float(array)!r} {value.units}"
    if array.ndim == 1:
        return [f"{float(m)!r} {value.units}" for m in array]
    raise InputError(f"quantity {_shown(value)}: a {array.ndim}-D array of values; give one value or a flat list "
                     "(e.g. [25, 50] * ureg.uN).")


def _shown(value: Any) -> str:
    """``value`` for a message: printable, cut short."""
    from memstribo.units import printable

    return printable(repr(value), 60)


def read_surface(surface, *, channel: str | None = None, unit: str | None = None):
    """A measured surface as a memstribo :class:`~memstribo.surfaces.roughness.Profile` or
    :class:`~memstribo.surfaces.readers.SurfaceMap` (heights in m).

    Parameters
    ----------
    surface : str, Path, Profile, SurfaceMap or SurfaceTopography topography
        A file of any format :func:`memstribo.surfaces.readers.read_topography` reads, or an object
        already in memory. A SurfaceTopography ``Topography`` (2D) or ``UniformLineScan`` (1D)
        is converted with its ``physical_sizes`` and ``unit``.
    channel, unit : str, optional
        Channel of a multi-channel file; height unit of a file that does not say it (e.g. ``"nm"``).

    Returns
    -------
    Profile or SurfaceMap
        Heights ``z`` [m] over positions ``x`` [m] (a profile), or a map of heights [m] with its spacings
        ``dx``, ``dy`` [m].

    Examples
    --------
    >>> import numpy as np, memstribo
    >>> from memstribo.surfaces.roughness import Profile
    >>> line = Profile(x=np.arange(5) * 1e-9, z=np.array([0.0, 1.0, 0.0, -1.0, 0.0]) * 1e-9, name="a line")
    >>> memstribo.read_surface(line) is line  # objects in memory pass through; files are read by format
    True
    """
    from memstribo.surfaces.roughness import Profile

    if isinstance(surface, (str, Path)):
        from memstribo.surfaces.readers import read_topography

        return read_topography(surface, channel=channel, unit=unit)
    if isinstance(surface, Profile) or hasattr(surface, "line_scans"):
        return surface
    if hasattr(surface, "heights") and hasattr(surface, "physical_sizes"):
        return _from_surface_topography(surface)
    raise InputError(f"a surface must be a file path, a memstribo Profile or SurfaceMap, or a SurfaceTopography "
                     f"topography; got {type(surface).__name__}.")


def _from_surface_topography(topography):
    """A SurfaceTopography topography (1D or 2D, uniform grid) as a Profile or SurfaceMap [m]."""
    import numpy as np

    from memstribo.surfaces.readers import SurfaceMap
    from memstribo.surfaces.roughness import Profile
    from memstribo.units import to_si

    unit = getattr(topography, "unit", None) or "m"
    scale = to_si(f"1 {unit}", "m", "unit of the topography")
    heights = np.asarray(topography.heights(), dtype=float) * scale
    sizes = np.atleast_1d(np.asarray(topography.physical_sizes, dtype=float)) * scale
    name = str(getattr(topography, "info", {}).get("name", "SurfaceTopography topography")) \
        if isinstance(getattr(topography, "info", None), dict) else "SurfaceTopography topography"
    if heights.ndim == 1:
        x = np.arange(heights.size) * sizes[0] / heights.size
        return Profile(x=x, z=heights, name=name, source=f"SurfaceTopography object ({type(topography).__name__})")
    # SurfaceTopography stores heights as (nx, ny); memstribo maps are (ny, nx) with rows along x
    nx, ny = heights.shape
    return SurfaceMap(heights.T.copy(), sizes[0] / nx, sizes[1] / ny, name=name,
                      source=f"SurfaceTopography object ({type(topography).__name__})")


def parameter_set(name: str = "silicon_thesis", overrides: dict | None = None, **values):
    """A parameter set with changes: ``parameter_set(normal_load=50 * ureg.uN, load_case="thesis")``.

    Parameters
    ----------
    name : str
        The parameter set (``memstribo parameters`` lists them).
    overrides : dict, optional
        Changes by name (for names that are not Python identifiers, or from a config).
    **values
        Changes by name: numbers in SI, strings with units, or pint quantities.

    Returns
    -------
    memstribo.parameters.Parameters
        Every value validated and in SI (``params["normal_load"]`` in N, ``params["drive_torque"]`` in N m, ...),
        with its source (``"Python API"`` for the changes); ``memstribo parameters`` lists names and units.

    Examples
    --------
    >>> import memstribo
    >>> params = memstribo.parameter_set(normal_load="50 uN")
    >>> round(params["normal_load"], 12)  # N
    5e-05
    """
    from memstribo.checks import check_parameter_set_arguments
    check_parameter_set_arguments(name, overrides)
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values(name)
    changes = {**(overrides or {}), **values}
    if changes:
        params = params.updated({key: _plain(value) for key, value in changes.items()}, origin="Python API")
    return params


@dataclass
class MeshCycle:
    """A simulated meshing cycle: the time series, its summary, and the ensemble when there is one.

    Attributes
    ----------
    dataset : xarray.Dataset
        The first realisation over the path of contact (``memstribo.simulations.mesh.simulate_mesh``), its
        dimension ``position``: the position of the contact point along the line of action [m] (0: the pitch
        point), so that ``cycle.dataset.friction_force.plot()`` draws over it; the step number stays a
        coordinate (``step``) along it.
    summary : dict
        Its summary (the keys of ``memstribo mesh --json``). ``summary["verdict"]`` is the verdict in one word:
        ``"no stiction"``, ``"running stiction"``, ``"start-up stiction"`` or ``"undetermined"``;
        ``summary["stiction"]`` is the running verdict alone (False for a pair that does not start:
        ``summary["startup_stiction"]`` says that one).
    ensemble : dict or None
        The verdict over the realisations (``memstribo.simulations.mesh.simulate_ensemble``), without the
        per-realisation summaries, or None for one realisation.

    The dataset's dimension is ``position``, the position of the contact point along the line of action [m]
    (0: the pitch point), the x-axis of :meth:`plot` and of xarray's own ``.plot()``.

    Examples
    --------
    >>> import memstribo
    >>> cycle = memstribo.mesh_cycle(steps=31, refine=False)  # one cycle as asked (the default refines)
    >>> figure = cycle.plot()  # friction, R(c) against F_t, the COF split over the position
    >>> [ax.get_ylabel() for ax in figure.axes]
    ['force [uN]', 'force [uN]', 'COF [-]']
    """

    dataset: Any
    summary: dict
    ensemble: dict | None = field(default=None)

    def to_xarray(self):
        """The dataset, with the ensemble's scalars as attributes and its realisations over ``realisation``."""
        import json

        import numpy as np
        import xarray as xr

        from memstribo.quantities import attrs as quantity_attrs

        dataset = self.dataset.copy()
        if self.ensemble:
            rows = self.ensemble["per_realisation"]
            index = np.array([r["realisation"] for r in rows])
            for key in ("stiction_margin", "cof_mean", "mesh_efficiency"):  # the ensemble's spread, by realisation
                dataset[f"realisation_{key}"] = xr.DataArray(
                    np.array([r[key] for r in rows], dtype=float), dims="realisation", coords={"realisation": index},
                    attrs=quantity_attrs(f"realisation_{key}"))
            dataset.attrs["ensemble"] = json.dumps({k: v for k, v in self.ensemble.items() if k != "per_realisation"})
        return dataset

    def plot(self, axes=None):
        """Friction force, R(c) against F_t, and the COF split over the position along the line of action.

        Parameters
        ----------
        axes : sequence of three matplotlib Axes, optional
            Where to draw; default a new figure of three panels sharing the position axis.

        Returns
        -------
        matplotlib.figure.Figure
            Panels: the friction force F_f [uN]; the resisting force R(c) of all pairs in mesh and the
            tangential force F_t [uN] (stiction where R reaches F_t); the COF and its split by mechanism [-];
            all over the position along the line of action [um].
        """
        import matplotlib.pyplot as plt

        if axes is None:
            figure, axes = plt.subplots(3, 1, sharex=True, figsize=(7.0, 8.0), constrained_layout=True)
        else:
            figure = axes[0].figure
        ds = self.dataset
        x = ds["position"].values * 1e6
        axes[0].plot(x, ds["friction_force"].values * 1e6, label="friction force F_f")
        axes[0].set_ylabel("force [uN]")
        axes[1].plot(x, ds["resisting_force"].values * 1e6, label="R(c), all pairs in mesh")
        axes[1].plot(x, ds["tangential_force"].values * 1e6, "--", label="tangential force F_t")
        axes[1].set_ylabel("force [uN]")
        axes[2].plot(x, ds["cof"].values, "k", label="COF")
        for part in ("chemical", "vdw", "elastic", "capillary"):
            values = ds[f"cof_{part}"].values
            if values.any():
                axes[2].plot(x, values, label=f"COF {part}")
        axes[2].set_ylabel("COF [-]")
        axes[2].set_xlabel("position along the line of action [um]")
        for ax in axes:
            ax.legend(fontsize="small")
        return figure


def mesh_cycle(params=None, surface=None, *, realisations: int = 1, steps: int | None = None, coating=None,
               wear: float | None = None, client=None, progress: bool = False, refine: bool = True) -> MeshCycle:
    """Friction, adhesion, COF and the stiction verdict over one meshing cycle (thesis 4.6-4.9, MODEL 7b).

    Parameters
    ----------
    params : Parameters, optional
        Default: :func:`parameter_set` (the thesis pair, torque load case).
    surface : optional
        Roughness of the teeth, anything :func:`read_surface` takes; None is the synthetic default.
    realisations : int
        Independent roughness realisations; more than 1 gives the stiction probability and bands.
    steps : int, optional
        Positions along the path of contact (default ``mesh_steps``).
    coating : str or Coating, optional
        SAM coating ("OTS", "FDTS"); None is bare silicon.
    wear : float, optional
        Worn fraction Omega [-] of the gear's coating, 0 (intact) to 1 (bare), with a coating; None: the
        parameter ``coating_wear`` (0 unless set). A ``wear`` that disagrees with a ``coating_wear`` set in
        ``params`` is refused, as is either one without a coating.
    client : distributed.Client, optional
        Runs the realisations on a Dask cluster.
    progress : bool
        Show a progress bar on stderr.
    refine : bool
        The self-refining cycle of ``memstribo mesh`` (MODEL 7d), on by default as in the command line: refined in
        steps, then in grid, until the margin and the mean COF hold
        (:func:`memstribo.simulations.mesh.convergence.refined_cycle`); the summary then has ``converged`` and the
        changes (and a warning where the caps stop it first), and the realisations run at the settings reached.
        ``refine=False`` (``memstribo mesh --no-refine``): one cycle as asked, its convergence unchecked; with
        fewer steps than the parameter ``mesh_steps`` it warns (``UserWarning`` and the summary's ``warnings``).

    Returns
    -------
    MeshCycle
        ``.dataset`` over ``position`` [m] along the line of action (``step`` a coordinate along it): forces [N],
        pressures [Pa], energies [J], COF [-], each variable with ``units``; ``.summary`` (the keys of
        ``memstribo mesh --json``, SI: ``summary["verdict"]`` the verdict in one word, running and start-up,
        ``summary["stiction"]`` the running one alone); ``.ensemble`` (stiction probability, quantiles) for
        realisations > 1.

    Examples
    --------
    >>> import memstribo
    >>> cycle = memstribo.mesh_cycle(steps=31, refine=False)  # quick: one cycle of 31 steps, unchecked
    >>> cycle.dataset["position"].attrs["units"], cycle.dataset.sizes["position"]
    ('m', 31)
    >>> cycle.summary["verdict"], cycle.summary["stiction"], cycle.summary["startup_stiction"]
    ('no stiction', False, False)
    >>> sorted(k for k in cycle.summary if k.startswith("cof_m"))
    ['cof_max', 'cof_mean', 'cof_mean_uncapped']
    """
    from memstribo.checks import check_coating_wear, check_mesh_arguments, check_unused_values, coating_wear_of
    check_mesh_arguments(params, steps, realisations, 1.0 if wear is None else wear)
    check_unused_values(params or parameter_set())
    check_coating_wear(params or parameter_set(), coating)
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_ensemble, simulate_mesh, summarize

    params = parameter_set() if params is None else params
    wear = coating_wear_of(params, coating, wear, option="wear")  # else coating_wear was ignored (issue #41)
    roughness = None if surface is None else read_surface(surface)
    coating_object = get_coating(coating, params) if isinstance(coating, str) else coating
    if refine:
        from memstribo.simulations.mesh.convergence import refined_cycle, settings_of

        dataset, summary = refined_cycle(params, roughness, steps=steps, coating=coating_object, wear=wear,
                                         progress=progress)
        params, steps = settings_of(params, summary)
    else:
        dataset = simulate_mesh(params, roughness, steps=steps, coating=coating_object, wear=wear, progress=progress)
        summary = summarize(dataset)
        if steps is not None and steps < int(params["mesh_steps"]):
            import warnings

            text = (f"refine=False with steps={steps}, fewer than mesh_steps = {int(params['mesh_steps'])}: the "
                    "margin's convergence in steps and grid is not checked (the default refine=True checks it, as "
                    "memstribo mesh does)")
            summary["warnings"] = [*summary.get("warnings", []), text]
            warnings.warn(text, UserWarning, stacklevel=2)
    ensemble = None
    if realisations > 1:
        ensemble = simulate_ensemble(params, roughness, realisations=realisations, steps=steps,
                                     coating=coating_object, wear=wear, client=client, progress=progress)
        ensemble = {k: v for k, v in ensemble.items() if k != "summaries"}
    # position along the line of action as the dimension, so that xarray's own plots draw over it (issue 41)
    return MeshCycle(dataset.swap_dims({"step": "position"}), summary, ensemble)


def sweep(params, parameter: str, values, surface=None, *, steps: int | None = None, coating=None,
          wear: float | None = None, progress: bool = False):
    """Meshing cycles over loads, drive torques or nominal areas, as one labelled dataset.

    Parameters
    ----------
    params : Parameters
    parameter : {"load", "torque", "area"}
    values : sequence
        Loads [N], torques [N m] (numbers, strings with units or pint quantities) or area multiples; or one
        pint quantity holding an array (``[25, 50] * ureg.uN``).
    surface, steps, coating, wear, progress
        As for :func:`mesh_cycle`.

    Returns
    -------
    xarray.Dataset
        One dimension named after the swept quantity (``normal_load`` [N], ``drive_torque`` [N m] or
        ``area_multiple`` [-]), a variable per numeric summary key, each with ``units``.

    Examples
    --------
    >>> import memstribo
    >>> params = memstribo.parameter_set(load_case="thesis")
    >>> points = memstribo.sweep(params, "load", ["25 uN", "50 uN"], steps=31)
    >>> points["normal_load"].values.tolist(), points["cof_mean"].attrs["units"]
    ([2.5e-05, 5e-05], '1')
    """
    from memstribo.checks import check_coating_wear, check_mesh_arguments, coating_wear_of
    check_mesh_arguments(params, steps, 1, 1.0 if wear is None else wear)
    params = parameter_set() if params is None else params
    check_coating_wear(params, coating)
    wear = coating_wear_of(params, coating, wear, option="wear")
    import numpy as np
    import xarray as xr

    from memstribo.physics.coating import get_coating
    from memstribo.quantities import attrs as quantity_attrs
    from memstribo.simulations.mesh import sweep as mesh_sweep
    from memstribo.units import to_si

    units = {"load": "N", "torque": "N*m", "area": ""}
    if parameter not in units:
        raise InputError(f"sweep parameter '{parameter}' is unknown: use 'load', 'torque' or 'area'.")
    plain = _plain(values)  # a pint quantity with an array magnitude: one string per value
    if isinstance(plain, str) or not hasattr(plain, "__iter__"):
        raise InputError(f"sweep values {_shown(values)}: give a list of values to sweep (e.g. ['25 uN', '50 uN'] "
                         "or [25, 50] * ureg.uN), not one value.")
    numbers = [to_si(_plain(v), units[parameter], parameter) for v in plain]
    roughness = None if surface is None else read_surface(surface)
    coating_object = get_coating(coating, params) if isinstance(coating, str) else coating
    points = mesh_sweep(params, parameter, numbers, roughness, steps=steps, coating=coating_object, wear=wear,
                        progress=progress)
    dim = {"load": "normal_load", "torque": "drive_torque", "area": "area_multiple"}[parameter]
    keys = [k for k, v in points[0].items() if k != dim and isinstance(v, (int, float)) and not isinstance(v, bool)]
    data = {k: (dim, np.array([p[k] for p in points], dtype=float),
                quantity_attrs(k)) for k in keys}
    data["stiction"] = (dim, np.array([bool(p["stiction"]) for p in points]), quantity_attrs("stiction"))
    coordinate = np.array([p[dim] for p in points], dtype=float)
    return xr.Dataset(data, coords={dim: (dim, coordinate, {"units": units[parameter] or "1",
                                                            "long_name": dim.replace("_", " ")})},
                      attrs={"load_case": points[0]["load_case"]})


def run(config: str | Path | None = None, out: str | Path = "memstribo-results", params=None, **options):
    """The whole chain (``memstribo run``): roughness to damage, with ``report.html``.

    Parameters
    ----------
    config : str or Path, optional
        A TOML config (``[parameters]`` and ``[run]`` tables), as for the command line.
    out : str or Path
        Results folder.
    params : Parameters, optional
        Parameters instead of (or on top of the defaults without) a config file.
    **options
        ``[run]`` options by name (``realisations=4``, ``stages=["roughness", "mesh"]``, ...).

    Returns
    -------
    memstribo.job.options.RunResult
        The folder written (``report.html``, one NetCDF/CSV set per stage, figures) and each stage's summary (SI).

    Examples
    --------
    >>> import tempfile, memstribo
    >>> result = memstribo.run(out=tempfile.mkdtemp(), stages=["roughness"], validation=False)  # doctest: +ELLIPSIS
    >>> (result.folder / "report.html").is_file()
    True
    """
    from memstribo.job.chain import RunChain
    from memstribo.job.options import RunOptions
    from memstribo.parameters import read_config

    table: dict[str, Any] = {}
    base = None
    if config is not None:
        loaded = read_config(config)
        params = parameter_set(overrides=loaded.get("parameters", {})) if params is None else \
            params.updated(loaded.get("parameters", {}), origin=f"config file {config}")
        table.update(loaded.get("run", {}))
        base = Path(config).parent
    table.update({k: _plain(v) for k, v in options.items()})
    return RunChain(parameter_set() if params is None else params, out, RunOptions.from_table(table, base)).run()


def design(spec, out: str | Path = "memstribo-design", params=None, *, workers: int | None = None,
           scheduler: str | None = None, client=None, resume: bool = False, progress: bool = False,
           figures: bool = True):
    """The design search (``memstribo design``): NSGA-II for the widest safe torque window (issue #39).

    Parameters
    ----------
    spec : str, Path, dict or memstribo.simulations.design_spec.DesignSpec
        A design spec TOML file, its ``[design]`` table as a dict (base overrides under the key
        ``"parameters"``), or a spec already built. Validated whole before any cycle runs.
    out : str or Path
        Results folder (``pareto.nc``/``.csv``, ``evaluations/``, ``figures/``).
    params : Parameters, optional
        Base parameters (default: the thesis set).
    workers, scheduler, client, resume, progress, figures
        As :func:`memstribo.simulations.design_search.run_design` (``workers=1``: in this process).

    Returns
    -------
    memstribo.simulations.design_search.DesignResult
        ``.dataset`` (the Pareto set, xarray), ``.default`` and ``.best`` (records), counts and cycles spent.

    Examples
    --------
    >>> import memstribo
    >>> result = memstribo.design("examples/design_thesis_pair.toml", out="design-out", workers=2)  # doctest: +SKIP
    >>> result.best["values"]["torque_window"]  # the widest safe window [N m]  # doctest: +SKIP
    >>> memstribo.design({"torque": {"min": "30 nN*m", "max": "1 uN*m"},
    ...                   "variables": {"face_width": {"min": "3 um", "max": "1 um"}}})  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    memstribo.errors.InputError: design spec python [design.variables]: face_width: the bounds are in the wrong order...
    """
    from memstribo.simulations.design_search import run_design
    from memstribo.simulations.design_spec import DesignSpec, design_spec, load_design_spec

    if isinstance(spec, (str, Path)):
        spec = load_design_spec(spec, params)
    elif isinstance(spec, dict):
        table = dict(spec)
        spec = design_spec(table, table.pop("parameters", None), params) if "parameters" in table else \
            design_spec(table, None, params)
    elif not isinstance(spec, DesignSpec):
        raise InputError(f"spec: give a design spec file, a [design] table (dict) or a DesignSpec, not "
                         f"{type(spec).__name__}.")
    return run_design(spec, out, params, client=client, scheduler=scheduler, workers=workers, resume=resume,
                      progress=progress, figures=figures)
