"""The public API at the top of the package (#11 item 8): a few names, labelled results, pint quantities."""

import numpy as np
import pytest

import memstribo


def test_the_api_names_are_at_the_top_and_import_lazily():
    for name in ("read_surface", "parameter_set", "mesh_cycle", "sweep", "run"):
        assert name in memstribo.__all__ and callable(getattr(memstribo, name))
    with pytest.raises(AttributeError):
        memstribo.no_such_name  # noqa: B018


def test_parameter_set_takes_pint_quantities_strings_and_numbers():
    import pint

    ureg = pint.UnitRegistry()
    params = memstribo.parameter_set(normal_load=50 * ureg.uN, face_width="3 um", load_case="thesis",
                                     drive_torque=1e-7 * ureg.newton * ureg.meter)
    assert params["normal_load"] == pytest.approx(50e-6) and params["face_width"] == pytest.approx(3e-6)
    assert params["drive_torque"] == pytest.approx(1e-7)
    assert params.source("normal_load") == "Python API"
    with pytest.raises(memstribo.InputError, match="normal_load"):
        memstribo.parameter_set(normal_load=5 * ureg.meter)
    # the parameter layer itself takes a quantity too
    assert memstribo.get_parameter_values().updated({"normal_load": 0.1 * ureg.mN})["normal_load"] == \
        pytest.approx(1e-4)


def test_read_surface_takes_files_objects_and_surface_topography(afm_dir):
    from SurfaceTopography import Topography, UniformLineScan

    profile = memstribo.read_surface(afm_dir / "si_profile_linescan.txt")
    assert memstribo.read_surface(profile) is profile
    line = memstribo.read_surface(UniformLineScan(np.sin(np.arange(256) / 9.0), 2.0, unit="nm"))
    assert line.x[-1] == pytest.approx(2e-9 * 255 / 256) and np.max(line.z) == pytest.approx(1e-9, rel=1e-3)
    surface = memstribo.read_surface(Topography(np.ones((32, 16)), (3.2, 1.6), unit="um"))
    assert surface.heights.shape == (16, 32) and surface.dx == pytest.approx(0.1e-6)
    with pytest.raises(memstribo.InputError, match="a surface must be"):
        memstribo.read_surface(42)


def test_mesh_cycle_and_ensemble_give_labelled_results():
    cycle = memstribo.mesh_cycle(steps=21, realisations=3, refine=False)
    assert cycle.summary["stiction_margin"] == cycle.summary["tangential_force"] - cycle.summary["resisting_force_max"]
    assert cycle.ensemble["realisations"] == 3
    data = cycle.to_xarray()
    assert data["realisation_stiction_margin"].sizes["realisation"] == 3
    assert data["friction_force"].attrs["units"] == "N"


def test_sweep_returns_one_dataset_over_the_swept_quantity():
    import pint

    ureg = pint.UnitRegistry()
    data = memstribo.sweep(memstribo.parameter_set(), "load", [25 * ureg.uN, "50 uN"], steps=11)
    assert list(data.dims) == ["normal_load"] and data["normal_load"].values == pytest.approx([25e-6, 50e-6])
    assert data["cof_mean"].attrs["units"] == "1" and data.attrs["load_case"] == "thesis"


def test_run_takes_options_by_name(tmp_path):
    result = memstribo.run(out=tmp_path / "out", stages=["gear"], validation=False)
    assert result.ok and (tmp_path / "out" / "report.html").exists()
    assert result.verdict["tangential_force"] == pytest.approx(2.82e-3, rel=5e-3)


def test_the_api_docstring_examples_run():
    """#24 item 4: every API function's docstring has an example, and the examples run (doctest)."""
    import doctest

    import memstribo.api as api

    for name in api.__all__:
        assert ">>>" in (getattr(api, name).__doc__ or ""), f"memstribo.{name} has no example"
    result = doctest.testmod(api, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 8 and result.failed == 0


def test_dir_and_help_list_the_api():
    import pydoc

    import memstribo

    listed = dir(memstribo)
    for name in ("mesh_cycle", "MeshCycle", "sweep", "run", "read_surface", "parameter_set"):
        assert name in listed and name in memstribo.__all__
        assert name in pydoc.render_doc(memstribo, renderer=pydoc.plaintext)


def test_the_cycle_carries_the_position_along_the_line_of_action_and_plots_over_it(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import memstribo

    cycle = memstribo.mesh_cycle(steps=31, refine=False)
    position = cycle.dataset["position"]
    assert position.dims == ("position",) and position.attrs["units"] == "m"
    # position is the dimension (issue 41), step a coordinate along it
    assert "position" in cycle.dataset.indexes and "step" not in cycle.dataset.indexes
    assert cycle.dataset["step"].dims == ("position",) and cycle.dataset["friction_force"].dims == ("position",)
    assert (position.values == cycle.dataset["c"].values).all()
    # xarray's own plot draws over the position, not the step number
    lines = cycle.dataset.friction_force.plot()
    assert lines[0].axes.get_xlabel().startswith("position")
    assert (lines[0].get_xdata() == position.values).all()
    figure = cycle.plot()
    assert len(figure.axes) == 3
    assert figure.axes[2].get_xlabel().startswith("position along the line of action")
    assert figure.axes[1].get_lines()[1].get_ydata()[0] == cycle.dataset["tangential_force"].values[0] * 1e6


def test_mesh_cycle_defaults_are_the_command_lines(cli):
    """Issue 41: the API refines by default as `memstribo mesh` does, and warns when asked for one short cycle."""
    import argparse
    import inspect
    import warnings

    from memstribo.cli.main import build_parser

    parser = build_parser()
    commands = next(a for a in parser._subparsers._group_actions if isinstance(a, argparse._SubParsersAction))
    mesh = commands.choices["mesh"]
    cli_refine = next(a for a in mesh._actions if a.dest == "refine").default
    assert inspect.signature(memstribo.mesh_cycle).parameters["refine"].default is cli_refine is True
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        cycle = memstribo.mesh_cycle(steps=31, refine=False)
    assert any("refine=False with steps=31" in str(w.message) for w in caught)
    assert any("refine=False with steps=31" in w for w in cycle.summary["warnings"])
    # the one-word verdict beside the running verdict
    assert cycle.summary["verdict"] in ("no stiction", "running stiction", "start-up stiction", "undetermined")
    assert cycle.summary["stiction"] == (cycle.summary["verdict"] == "running stiction")
    doc = memstribo.mesh_cycle.__doc__ + memstribo.MeshCycle.__doc__
    assert 'summary["verdict"]' in doc and "start-up stiction" in doc
