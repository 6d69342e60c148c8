"""MODEL 7c: every command's JSON has ``warnings`` (a list of sentences), and physical limits appear there."""

import pytest


@pytest.mark.parametrize("argv", [
    ("constants",), ("gear",), ("parameters",), ("nanoblock",), ("roughness", "thesis"),
    ("slide", "--model", "estimate"), ("asperity", "--load", "0.8 uN"),
])
def test_every_command_json_has_warnings(cli, argv):
    values = cli.json(*argv)
    assert isinstance(values["warnings"], list)


def test_slide_past_the_limits_of_silicon_warns(cli):
    values = cli.json("slide", "--model", "fixed-load", "--set", "normal_load=300 uN", "--distance", "20 nm")
    assert any("elastic limit" in text for text in values["warnings"])
    assert values["max_shear_stress"] > 0


def test_mesh_json_lists_warnings_and_the_text_shows_them(cli):
    from memstribo.parameters import THESIS_FLAGS

    values = cli.json("mesh", "--steps", "11", "--no-step-check", *THESIS_FLAGS.split())
    assert any("ideal shear strength" in text for text in values["warnings"])
    code, out, err = cli("mesh", "--steps", "11", "--no-step-check", *THESIS_FLAGS.split())
    assert code == 0 and "WARNING: the friction stress" in out
