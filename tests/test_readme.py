"""The numbers the README quotes for the thesis case come from the code (so they cannot drift)."""

from pathlib import Path

README = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")


def test_readme_quotes_the_default_meshing_cycle(params):
    from memstribo.mesh import simulate_mesh, summarize

    summary = summarize(simulate_mesh(params))
    assert summary["stiction"]  # README: bare silicon teeth stick
    assert f"reaches {summary['friction_force_max'] * 1e3:.3g} mN" in README
    assert f"mean apparent COF of {summary['cof_mean']:.3f}" in README
    assert summary["cof_vdw"] > summary["cof_chemical"]  # README: "mostly from van der Waals bonds"


def test_readme_quotes_the_gear_and_roughness_examples(cli):
    gear = cli.json("gear")
    assert f"hertz_half_width        {gear['hertz_half_width'] * 1e9:.4g} nm" in README
    assert f"contact_ratio           {gear['contact_ratio']:.4g}" in README
    rough = cli.json("roughness", Path(__file__).resolve().parent.parent / "data" / "afm" / "si_profile_linescan.txt")
    assert f"Rq              {rough['Rq'] * 1e9:.4g} nm" in README
    assert f"lambda_q        {rough['lambda_q'] * 1e9:.4g} nm" in README
