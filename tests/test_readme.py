"""The numbers the README quotes for the thesis case come from the code (so they cannot drift)."""

from pathlib import Path

README = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")


def test_readme_quotes_the_default_meshing_cycle(params):
    from memstribo.simulations.mesh import simulate_mesh, summarize

    summary = summarize(simulate_mesh(params))
    assert not summary["stiction"]  # README: the first realisation does not stick
    assert f"largest resisting force {summary['resisting_force_max'] * 1e3:.3g} mN" in README
    assert f"mean apparent COF\n{summary['cof_mean']:.3f}" in README or \
        f"mean apparent COF {summary['cof_mean']:.3f}" in README
    assert f"(chemical {summary['cof_chemical']:.3f}, van der Waals {summary['cof_vdw']:.3f})" in README
    from memstribo.parameters import THESIS_CONDITIONS

    thesis = summarize(simulate_mesh(params.updated(THESIS_CONDITIONS)))
    assert f"gives a mean COF of {thesis['cof_mean']:.3f}" in README
    assert f"the largest resisting force is {thesis['resisting_force_max'] * 1e3:.3g} mN" in README


def test_readme_quotes_the_ensemble(params):
    """The README's ensemble band (16 realisations) comes from the code."""
    from memstribo.simulations.mesh import simulate_ensemble

    ensemble = simulate_ensemble(params, realisations=16)
    assert f"**{ensemble['stiction_probability_text'].replace(' of 16', ' of 16 realisations')}**" in README
    assert (f"between {ensemble['stiction_margin_p05'] * 1e3:.3g} and {ensemble['stiction_margin_p95'] * 1e3:.3g} mN"
            in README)
    assert f"between {ensemble['cof_mean_p05']:.3f} and {ensemble['cof_mean_p95']:.3f}" in README
    # the start-up verdict (MODEL 7f): its count with interval and its margin band
    assert (f"start-up stiction in **{ensemble['startup_stiction_probability_text'].replace(' of 16', ' of 16 realisations')}**"
            in README)
    assert (f"between {ensemble['startup_margin_p05'] * 1e3:.3g} and {ensemble['startup_margin_p95'] * 1e3:.3g} mN"
            in README)


def test_readme_quotes_the_gear_and_roughness_examples(cli):
    gear = cli.json("gear")
    assert f"hertz_half_width        {gear['hertz_half_width'] * 1e9:.4g} nm" in README
    assert f"contact_ratio           {gear['contact_ratio']:.4g}" in README
    rough = cli.json("roughness", Path(__file__).resolve().parent.parent / "data" / "afm" / "si_profile_linescan.txt")
    assert f"Rq              {rough['Rq'] * 1e9:.4g} nm" in README
    assert f"lambda_q        {rough['lambda_q'] * 1e9:.4g} nm" in README
