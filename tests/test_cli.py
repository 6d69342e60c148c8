"""The CLI framework: help, version, --set/--config, errors without tracebacks."""

import subprocess
import sys

import pytest

from memstribo import __version__


def test_help_lists_subcommands(cli, capsys):
    import pytest

    with pytest.raises(SystemExit) as exc:
        from memstribo.cli.main import main

        main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert "parameters" in out


def test_version():
    out = subprocess.run([sys.executable, "-m", "memstribo.cli.main", "--version"], capture_output=True, text=True)
    assert out.returncode == 0
    assert __version__ in out.stdout


def test_parameters_json_and_set(cli):
    values = cli.json("parameters", "--set", "normal_load=50 uN", "--set", "poisson_ratio=0.5")
    assert values["normal_load"] == 50e-6
    assert values["poisson_ratio"] == 0.5


def test_config_file(cli, tmp_path):
    config = tmp_path / "c.toml"
    config.write_text('[parameters]\nnormal_load = "100 uN"\nface_width = "4 um"\n')
    values = cli.json("parameters", "--config", config)
    assert values["normal_load"] == 100e-6
    assert values["face_width"] == 4e-6


def test_bad_parameter_exits_2_without_traceback(cli):
    code, out, err = cli("parameters", "--set", "youngs_modulus=-1")
    assert code == 2
    assert "youngs_modulus" in err and "Traceback" not in err
    code, out, err = cli("parameters", "--set", "poisson")
    assert code == 2 and "NAME=VALUE" in err


def test_no_command_prints_help(cli):
    code, out, err = cli()
    assert code == 2
    assert "usage" in out


def test_format_quantity_handles_every_kind_of_value():
    from memstribo.cli.common import format_quantity, format_value

    assert format_quantity(2.5e-5, "N") == "25 µN"
    assert format_quantity(195.5e-9, "m") == "195.5 nm"
    assert format_quantity("OTS") == "OTS"
    assert format_quantity(True) == "yes"
    assert format_quantity(None, "N") == "-"
    assert format_value([36.85e-6, 147.4e-6], "m") == "[36.85 µm, 147.4 µm]"
    assert format_value({"corner": 1.0}, "") == "corner: 1"
    assert format_quantity(0.3490658503988659, "rad") == "20 deg"  # angles read in degrees


# --- one --progress auto|on|off on every long command (issue #15) -------------------------------------------------
@pytest.mark.parametrize("command", ["mesh", "sweep", "coating", "damage", "study", "run"])
@pytest.mark.parametrize("argv, expected", [
    ((), "auto"), (("--progress",), "on"), (("--progress", "on"), "on"), (("--progress=off",), "off"),
    (("--progress", "auto"), "auto"),
])
def test_every_long_command_takes_the_same_progress_option(command, argv, expected):
    from memstribo.cli.main import build_parser

    positional = {"sweep": ["load"], "study": ["spec.toml"]}.get(command, [])
    args = build_parser().parse_args([command, *positional, *argv])
    assert args.progress == expected


def test_progress_enabled_follows_the_choice_and_the_terminal():
    import argparse
    import io

    from memstribo.cli.common import progress_enabled

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    for choice, terminal, expected in (("on", False, True), ("off", True, False), ("auto", True, True),
                                       ("auto", False, False)):
        stream = Terminal() if terminal else io.StringIO()
        assert progress_enabled(argparse.Namespace(progress=choice), stream) is expected
    assert progress_enabled(argparse.Namespace(progress=True), io.StringIO()) is True  # the old flag's namespace
    assert progress_enabled(argparse.Namespace(), io.StringIO()) is False  # no option: auto, not a terminal


def test_a_bad_progress_value_is_a_clean_usage_error(capsys):
    from memstribo.cli.main import main

    with pytest.raises(SystemExit) as exc:
        main(["mesh", "--progress", "sometimes"])
    err = capsys.readouterr().err
    assert exc.value.code == 2 and "--progress" in err and "choose from 'auto', 'on', 'off'" in err
