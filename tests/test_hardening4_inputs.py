"""Round four of the bad inputs (issue #41, item 2 without the file readers): contradictions refused, sizes
refused before any work, physics inputs cross-checked. One test per input, each failing without its fix;
every refusal is exit 2 with one message naming the options (under --json one JSON object on stdout)."""

from __future__ import annotations

import argparse
import json

import pytest

from memstribo.errors import InputError


@pytest.fixture
def cli(capsys):
    """As conftest's ``cli``, with a usage error (argparse's SystemExit) returned as its exit code too."""
    from memstribo.cli.main import main

    class Runner:
        def __call__(self, *argv):
            try:
                code = main([str(a) for a in argv])
            except SystemExit as exc:
                code = exc.code
            out, err = capsys.readouterr()
            return code, out, err

        def json(self, *argv):
            code, out, err = self(*argv, "--json")
            assert code == 0, err
            return json.loads(out)

    return Runner()


def _refused(cli, *argv, match=()):
    """Run the CLI: exit 2, no traceback, nothing on stdout, and every string of ``match`` in the message."""
    code, out, err = cli(*argv)
    assert code == 2, (code, out, err)
    assert "Traceback" not in err and "internal error" not in err and out == ""
    for text in match:
        assert text in err, err
    return err


# --- contradictions: refused, not "the last one wins" ------------------------------------------------------------

def test_refine_and_no_refine_contradict(cli):
    _refused(cli, "mesh", "--refine", "--no-refine", "--steps", "5", match=("--refine", "--no-refine", "contradict"))


def test_the_same_flag_twice_is_harmless():
    from memstribo.cli.main import build_parser

    args = build_parser().parse_args(["mesh", "--no-refine", "--no-refine", "--steps", "5", "--steps", "5"])
    assert args.refine is False and args.steps == 5


def test_config_twice_is_refused(cli, tmp_path):
    first, second = tmp_path / "a.toml", tmp_path / "b.toml"
    first.write_text('normal_load = "30 uN"\n')
    second.write_text('normal_load = "40 uN"\n')
    _refused(cli, "gear", "--config", first, "--config", second, match=("--config", "a.toml", "b.toml", "give it once"))


def test_config_twice_under_json_is_one_object(cli):
    code, out, err = cli("gear", "--config", "a.toml", "--config", "b.toml", "--json")
    assert code == 2
    error = json.loads(out)
    assert error["parameter"] == "--config" and "contradict" in error["error"]


def test_set_twice_with_different_values_is_refused(cli):
    _refused(cli, "gear", "--set", "normal_load=30uN", "--set", "normal_load=40uN",
             match=("--set normal_load", "'30uN'", "'40uN'"))


def test_parameter_at_the_top_level_and_in_parameters_is_refused(cli, tmp_path):
    config = tmp_path / "twice.toml"
    config.write_text('normal_load = "50 uN"\n[parameters]\nnormal_load = "30 uN"\n')
    _refused(cli, "gear", "--config", config, match=("normal_load", "twice", "[parameters]"))


def test_parameter_at_the_top_level_and_in_a_table_entry_is_refused(tmp_path):
    from memstribo.parameters import read_config

    config = tmp_path / "twice.toml"
    config.write_text('youngs_modulus = "150 GPa"\n[parameters.youngs_modulus]\nvalue = 1.6e11\nunit = "Pa"\n')
    with pytest.raises(InputError, match="youngs_modulus' is given twice"):
        read_config(config)


@pytest.mark.parametrize("argv,match", [
    (("sweep", "load", "--load-case", "torque"), ("load_case = 'torque'", "sweep load", "'thesis'")),
    (("sweep", "torque", "--load-case", "thesis"), ("load_case = 'thesis'", "sweep torque")),
    (("sweep", "load", "--set", "normal_load=50uN"), ("normal_load", "--values")),
    (("sweep", "humidity", "--set", "environment=vacuum"), ("environment = 'vacuum'", "'air'")),
])
def test_sweep_refuses_what_it_would_replace(cli, argv, match):
    _refused(cli, *argv, "--values", "25uN" if argv[1] == "load" else "0.5" if argv[1] == "humidity" else "1e-7",
             "--steps", "5", match=match)


def test_sweep_load_with_its_own_load_case_is_accepted():
    from memstribo.cli.sweep import check_sweep_contradictions
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values().updated({"load_case": "thesis"}, origin="--load-case")
    check_sweep_contradictions("load", params)  # the thesis load case is what 'sweep load' runs
    check_sweep_contradictions("load", get_parameter_values())  # the default is replaced as documented


def test_sliding_axis_y_on_a_profile_is_refused(cli, afm_dir):
    _refused(cli, "mesh", "--roughness", afm_dir / "si_profile_linescan.txt", "--sliding-axis", "y", "--steps", "5",
             match=("--sliding-axis y", "profile"))


def test_sliding_axis_y_on_the_default_profile_is_refused(cli):
    _refused(cli, "mesh", "--sliding-axis", "y", "--steps", "5", match=("--sliding-axis y", "'thesis'"))


def test_orient_map_refuses_y_for_a_profile():
    from memstribo.simulations.mesh import orient_map
    from memstribo.surfaces.roughness import default_profile
    from memstribo.parameters import get_parameter_values

    with pytest.raises(InputError, match="needs a 2D map"):
        orient_map(default_profile(get_parameter_values()), "y")


@pytest.mark.parametrize("option", [("--workers", "2"), ("--scheduler", "tcp://127.0.0.1:1")])
def test_parallel_options_with_one_realisation_are_refused(cli, option):
    _refused(cli, "mesh", *option, "--steps", "5", match=(option[0], "one realisation", "--realisations N"))


def test_workers_above_the_bound_are_refused(cli):
    _refused(cli, "mesh", "--workers", "100000", "--realisations", "2", "--steps", "5",
             match=("--workers", "4,096", "100,000"))


def test_workers_above_the_cores_are_capped_with_a_note(monkeypatch, capsys):
    from memstribo.cli import mesh

    monkeypatch.setattr(mesh, "machine_cores", lambda: 2)
    args = argparse.Namespace(workers=64, scheduler=None, quiet=False)
    mesh._check_parallel(args, None, 4)
    assert args.workers == 2 and "more than this machine's 2 core(s): using 2" in capsys.readouterr().err


def test_outer_diameters_in_the_wrong_order_are_refused(cli):
    _refused(cli, "gear", "--outer-diameters", "303um,81um", match=("--outer-diameters", "wrong order"))
    values = cli.json("gear", "--outer-diameters", "81um,303um")
    assert values["module"] == pytest.approx(3.8788e-6, rel=1e-4)


def test_outer_diameters_that_fit_no_pair_are_refused():
    from memstribo.physics.gear import module_from_outer_diameters

    with pytest.raises(InputError, match="do not fit a standard pair"):
        module_from_outer_diameters(81e-6, 81e-6, 19, 76)


@pytest.mark.parametrize("argv,option", [
    (("mesh", "--coating", ""), "--coating"),
    (("sweep", "load", "--values", ""), "--values"),
    (("mesh", "--out", ""), "--out"),
    (("mesh", "--out", "  "), "--out"),
    (("gear", "--config", ""), "--config"),
    (("roughness", ""), "PATH"),
])
def test_empty_values_are_refused(cli, argv, option, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # without the check, --out '  ' wrote a folder named '  ' here
    _refused(cli, *argv, match=(f"argument {option}", "empty value"))


def test_parameters_toml_and_json_contradict(cli):
    code, out, err = cli("parameters", "--toml", "--json")
    assert code == 2
    error = json.loads(out)  # one JSON object, not TOML
    assert "--toml and --json contradict" in error["error"]


# --- sizes refused before any work ------------------------------------------------------------------------------

@pytest.mark.parametrize("count", [1001, 15_000, 100_000])
def test_long_sweep_value_lists_are_refused_before_reading(cli, count, monkeypatch):
    import memstribo.units

    def never(*args, **kwargs):  # no value may be converted before the count is checked
        raise AssertionError("a value was converted")

    monkeypatch.setattr(memstribo.units, "to_si", never)
    _refused(cli, "sweep", "load", "--values", ",".join(["25uN"] * count), match=(f"{count:,} values", "at most 1000"))


def test_long_wear_lists_are_refused(cli):
    _refused(cli, "coating", "--wear", ",".join(["0.5"] * 20_000), match=("--wear", "20,000", "at most 1000"))


def test_contact_points_above_the_solver_bound_are_refused(cli):
    _refused(cli, "contact", "--flat", "--points", str(10**9), match=("--points 1,000,000,000", "1,000,000"))
    _refused(cli, "contact", "--flat", "--pull-off", "--points", str(10**9), match=("--points", "at most"))


@pytest.mark.parametrize("samples,match", [(str(2**40), "above the limit of 16,384"), ("12", "power of two")])
def test_sobol_samples_are_refused_before_the_first_cycle(cli, samples, match):
    _refused(cli, "mesh", "--uncertainty", "4", "--sobol-samples", samples, "--steps", "5", match=(match,))


def test_uncertainty_study_refuses_a_huge_sobol_design_before_running():
    from memstribo.parameters import get_parameter_values
    from memstribo.uncertainty.study import uncertainty_study

    with pytest.raises(InputError, match="above the limit"):
        uncertainty_study(get_parameter_values(), samples=2, steps=5, sobol_samples=2**40)


def test_text_file_above_the_size_limit_is_refused_by_its_size(tmp_path, monkeypatch):
    from pathlib import Path

    from memstribo.errors import DataFileError
    from memstribo.surfaces.readers import read_topography

    big = tmp_path / "huge.txt"
    with open(big, "wb") as handle:  # a sparse 1.9 GB file: nothing written, only its size
        handle.truncate(1_900_000_000)

    def never(self):
        raise AssertionError("the file was read")

    monkeypatch.setattr(Path, "read_bytes", never)
    with pytest.raises(DataFileError, match="1,900,000,000 bytes; memstribo reads text files of at most"):
        read_topography(big)


# --- physics inputs cross-checked -------------------------------------------------------------------------------

def test_derived_work_of_adhesion_above_its_bound_is_refused(cli):
    _refused(cli, "gear", "--set", "hamaker_constant=1e-17", "--set", "cutoff_distance=5e-11",
             match=("work_of_adhesion derived", "106.1 J/m^2", "bound of 10 J/m^2"))


def test_a_given_work_of_adhesion_is_not_derived():
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values().updated({"work_of_adhesion": 1.0, "hamaker_constant": 1e-17,
                                             "cutoff_distance": 5e-11})
    assert params["work_of_adhesion"] == 1.0


def test_contact_modulus_above_diamond_is_refused(cli):
    err = _refused(cli, "gear", "--set", "poisson_ratio=-0.999",
                   match=("E* =", "40.3 TPa", "poisson_ratio -0.999", "counter_poisson_ratio -0.999", "1.2 TPa"))
    assert "diamond" in err


def test_one_auxetic_body_against_silicon_is_allowed():
    from memstribo.materials.pair import contact_modulus_of
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values().updated({"poisson_ratio": -0.999, "counter_poisson_ratio": 0.23})
    assert contact_modulus_of(params) < 0.2e12


@pytest.mark.parametrize("overrides,match", [
    (("bond_length=0.6nm",), "longer than lattice_constant"),
    (("atomic_pitch=0.2nm", "lattice_constant=0.15nm", "bond_length=0.14nm", "atomic_width=0.1nm"), None),
    (("atomic_pitch=0.2nm", "bond_length=0.3nm", "atomic_width=0.1nm"), "longer than atomic_pitch"),
])
def test_bond_length_longer_than_the_lattice_is_refused(cli, overrides, match):
    argv = ["gear"] + [item for text in overrides for item in ("--set", text)]
    if match is None:
        code, out, err = cli(*argv)
        assert code == 0, err
    else:
        _refused(cli, *argv, match=(match, "bond_length"))


@pytest.mark.parametrize("addendum,dedendum", [("1.0", "1.0"), ("1.2", "1.1")])
def test_dedendum_not_below_the_mating_addendum_is_refused(cli, addendum, dedendum):
    _refused(cli, "gear", "--set", f"addendum_coefficient={addendum}", "--set", f"dedendum_coefficient={dedendum}",
             match=(f"dedendum_coefficient ({float(dedendum):g} x module)", "tip clearance",
                    "dedendum_coefficient > addendum_coefficient"))


@pytest.mark.parametrize("distance", ["0", "0.1nm"])
def test_slide_over_no_distance_is_refused(cli, distance):
    _refused(cli, "slide", "--distance", distance, match=("--distance", "shorter than one sliding step"))
