"""report.html: self-contained, escaped, and every figure renders in a real (headless) browser."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from memstribo.job.options import FigureRecord, RunOptions, RunResult, StageRecord
from memstribo.job.report import render_report, write_report
from memstribo.validation import ValidationRow, compare

EVIL = "<script>alert('x')</script>&\"scan\".txt"


def make_result(folder: Path, params, n_figures=2, verdict=None) -> RunResult:
    from memstribo.output import new_figure, save_figure

    figures = []
    for i in range(n_figures):
        figure, ax = new_figure(figsize=(3, 2))
        ax.plot([0, 1], [0, i])
        save_figure(figure, folder / "figures", f"fig{i}")
        figures.append(FigureRecord(f"fig{i}", "mesh", f"caption {i} with <b>markup</b>"))
    stages = [StageRecord("roughness", "Roughness", "done", 0.1), StageRecord("mesh", "Mesh", "failed", 0.2, [],
                                                                             f"bad file {EVIL}")]
    inputs = [{"name": EVIL, "source": f"file {EVIL}", "synthetic": False, "Rq": 1.6e-9, "rms_slope": 0.024,
               "n_points": 100},
              {"name": "synthetic profile", "source": "synthetic: seed 1", "synthetic": True, "Rq": 1.6e-9,
               "rms_slope": 0.024, "n_points": 100, "meshing": True}]
    verdict = verdict if verdict is not None else {
        "tangential_force": 2.82e-3, "bare_resisting_force_max": 4e-3, "bare_stiction_margin": -1.18e-3,
        "bare_stiction": True, "bare_cof_mean": 0.8, "coated_resisting_force_max": 1e-3,
        "coated_stiction_margin": 1.82e-3, "coated_stiction": False, "coated_cof_mean": 0.19,
        "wear_at_stiction": 0.8, "damage_per_cycle_over_c1": 8.5e8, "damage_exponent": 1.0,
        "life_ratio_corner_to_central": 0.92}
    return RunResult(folder, params.updated({"normal_load": "50 uN"}, origin=f"--set {EVIL}"), RunOptions(),
                     stages, figures, {}, verdict, inputs, 12.0)


ROWS = ([compare("gear", "tangential force F_t", "thesis 4.7 (4-27)", 2.82e-3, 2.82e-3, "N", rtol=1e-3,
                  command="memstribo gear --json"),
          ValidationRow("mesh", "COF <falls> with load", "thesis 4.9.3", None, None, "", "trend", False,
                        "memstribo sweep load --json", "differs: see docs/mesh.md")], None)


def test_report_is_self_contained_and_escapes_input_text(tmp_path, params):
    text = render_report(make_result(tmp_path, params), ROWS)
    assert "<script>alert" not in text
    assert "&lt;script&gt;alert(&#x27;x&#x27;)&lt;/script&gt;&amp;&quot;scan&quot;.txt" in text
    assert "caption 0 with &lt;b&gt;markup&lt;/b&gt;" in text
    # nothing loaded from outside the file
    assert not re.search(r"""(src|href)\s*=\s*['"](https?:|//|file:)""", text)
    assert "<link" not in text
    assert text.count("src='data:image/png;base64,") == 2
    # the verdict, the question, provenance and the validation table are there
    assert "STICTION" in text and "no stiction" in text and "&Omega; = 80 %" in text
    assert "850 M Pa<sup>1</sup>" in text or "8.5e+08 Pa<sup>1</sup>" in text
    assert "0.92 times as long" in text
    assert text.count("<td>yes</td></tr>") == 1  # the profile used by the meshing stages
    assert "The question" in text and "synthetic (generated, seeded)" in text and "measured" in text
    assert "Validation: thesis against memstribo" in text and "<th>tolerance</th>" in text
    assert "COF &lt;falls&gt; with load" in text and "thesis 4.7 (4-27)" in text
    assert "<td class='bad'>no</td>" in text and "<td class='good'>yes</td>" in text
    assert "Changed from that set: <code>normal_load</code> (--set &lt;script&gt;" in text


def test_report_without_meshing_says_there_is_no_verdict(tmp_path, params):
    text = render_report(make_result(tmp_path, params, n_figures=0, verdict={}))
    assert "No verdict: the meshing stages did not run" in text
    assert "No figures" in text
    assert "computed at the end of the run" in text  # no validation table passed


def test_broken_validation_rows_are_reported_in_the_page(tmp_path, params):
    text = render_report(make_result(tmp_path, params), ([], "KeyError: 'x'"))
    assert "could not all be computed: KeyError: &#x27;x&#x27;" in text


def test_missing_figure_file_is_reported_not_hidden(tmp_path, params):
    result = make_result(tmp_path, params)
    (tmp_path / "figures" / "fig1.png").unlink()
    text = render_report(result)
    assert "Figure 2 (fig1) is missing" in text


def chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def browser_dom(path: Path, profile: Path) -> str:
    """The DOM of ``path`` after load, as headless Chromium sees it."""
    browser = chromium()
    if browser is None:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail("chromium is not installed, and CI=true: the browser test must run in CI")
        pytest.skip("chromium is not installed (apt-get install chromium)")
    run = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                          "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-extensions",
                          f"--user-data-dir={profile}", "--virtual-time-budget=10000", "--dump-dom",
                          path.resolve().as_uri()], capture_output=True, text=True, timeout=90)
    assert run.returncode == 0, run.stderr[-2000:]
    return run.stdout


#: Injected at the top of <head> of a copy of the page: collects script errors, failed loads and
#: console.error calls, then (after load) the widths, the height and the images into body[data-probe].
PROBE = """<script>
window.__errors = [];
window.addEventListener('error', function (e) {
  window.__errors.push('error: ' + (e.message || (e.target && (e.target.src || e.target.href)) || '?')); }, true);
(function () { var orig = console.error; console.error = function () {
  window.__errors.push('console.error: ' + Array.prototype.join.call(arguments, ' ')); orig.apply(console, arguments); }; })();
window.addEventListener('load', function () { setTimeout(function () {
  var imgs = Array.prototype.slice.call(document.images), d = document.documentElement;
  document.body.setAttribute('data-probe', JSON.stringify({scrollWidth: d.scrollWidth, innerWidth: window.innerWidth,
    height: d.scrollHeight, images: imgs.length,
    verdicts: (function () { var e = document.getElementById('verdicts'), r = e && e.getBoundingClientRect();
      return e ? {top: r.top, bottom: r.bottom, text: e.innerText} : null; })(),
    broken: imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); }).length,
    errors: window.__errors}));
}, 100); });
</script>"""


def browser_probe(page: Path, width: int, tmp_path: Path, height: int = 900) -> dict:
    """Load ``page`` in headless Chromium in a viewport ``width`` CSS px wide; return what PROBE saw.

    The page runs in an iframe of exactly that width (a headless window is at least 500 px wide), so its
    media queries and its ``innerWidth`` are the phone's. Console messages at error level in
    Chromium's log count as errors too.
    """
    import html
    import json

    browser = chromium()
    if browser is None:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail("chromium is not installed, and CI=true: the browser test must run in CI")
        pytest.skip("chromium is not installed (apt-get install chromium)")
    text = page.read_text(encoding="utf-8")
    inner = tmp_path / f"probe-{width}-{page.name}"
    inner.write_text(text.replace("<head>", "<head>" + PROBE, 1), encoding="utf-8")
    frame = tmp_path / f"frame-{width}-{page.name}"
    frame.write_text(f"""<!DOCTYPE html><html><head><meta charset='utf-8'></head><body style='margin:0'>
<iframe id='f' src='{inner.name}' style='border:0;width:{width}px;height:{height}px'></iframe><script>
function poll() {{ var d = document.getElementById('f').contentDocument;
  var v = d && d.body && d.body.getAttribute('data-probe');
  if (v) {{ document.body.setAttribute('data-probe', v); }} else {{ setTimeout(poll, 50); }} }}
document.getElementById('f').addEventListener('load', function () {{ setTimeout(poll, 50); }});
</script></body></html>""", encoding="utf-8")
    run = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                          "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-extensions",
                          "--hide-scrollbars", "--allow-file-access-from-files", f"--window-size={width + 100},{height + 100}",
                          f"--user-data-dir={tmp_path / f'chromium-{width}'}", "--virtual-time-budget=10000",
                          "--enable-logging=stderr", "--v=0", "--dump-dom", frame.resolve().as_uri()],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]
    match = re.search(r'data-probe="([^"]*)"', run.stdout)
    assert match, run.stdout[:1000]
    probe = json.loads(html.unescape(match.group(1)))
    probe["errors"] += [line for line in run.stderr.splitlines() if ":CONSOLE" in line and "ERROR" in line]
    return probe


def wide_validation_rows(n=80):
    """Rows as long as the real table's (long commands and notes, no spaces in some)."""
    rows = [compare("mesh", f"quantity {i} with a long name that wraps", "thesis 4.9.3, Figure 4-46 (about 0.45)",
                    0.45, 0.5 + i * 1e-3, "", rtol=0.2,
                    command="memstribo sweep load --values 25uN,300uN --set interface_model=thesis --set "
                            "contact_adhesion=none --steps 481 --json",
                    note="data/afm/" + "x" * 120 + f".txt, differs on purpose {i}") for i in range(n)]
    return rows, None


@pytest.fixture(scope="module")
def run_report(tmp_path_factory):
    """report.html of a small real run (every stage, few steps), with a validation table as long as the real one."""
    from memstribo.job.chain import RunChain
    from memstribo.job.options import options_for_test
    from memstribo.parameters import get_parameter_values

    out = tmp_path_factory.mktemp("report-run")
    result = RunChain(get_parameter_values(), out, options_for_test()).run()
    assert result.ok
    return result, write_report(result, out / "report-with-table.html", wide_validation_rows())


@pytest.mark.browser
@pytest.mark.parametrize("width", [1280, 390])
def test_report_reads_at_desktop_and_phone_width(run_report, tmp_path, width):
    """No sideways scroll, no console error, every image loaded, at a desktop's and a phone's width."""
    result, page = run_report
    probe = browser_probe(page, width, tmp_path)
    assert probe["innerWidth"] == width
    assert probe["scrollWidth"] <= probe["innerWidth"], probe
    assert probe["errors"] == [], probe["errors"]
    assert probe["images"] == len(result.figures) >= 10 and probe["broken"] == 0, probe
    text = page.read_text(encoding="utf-8")
    # the verdict first; the long parts folded
    assert text.index("id='verdict'") < text.index("<h2>Figures") < text.index("Inputs and their provenance")
    assert "<details id='validation-table'>" in text


@pytest.mark.browser
def test_the_three_verdicts_are_on_the_first_screen_of_a_phone(run_report, tmp_path):
    """Issue 41: at 390 x 844 CSS px (a phone) the verdict box at the top holds the running verdict over the
    roughness, the start-up verdict and P(stiction) over the priors, each as "k of n (95 % CI ...)", above the fold."""
    result, page = run_report
    probe = browser_probe(page, 390, tmp_path, height=844)
    box = probe["verdicts"]
    assert box is not None, probe
    assert 0 <= box["top"] < box["bottom"] <= 844, box
    text = " ".join(box["text"].split())
    for label in ("Running, over the roughness: stiction in", "Start-up, over the roughness: stiction in",
                  "Over the priors of the unmeasured constants: stiction in"):
        assert re.search(re.escape(label) + r" \d+ of \d+ \(95 % CI \d+(\.\d+)?–\d+(\.\d+)? %\)", text), (label, text)
    # the counts are the run's: the ensemble's realisations and the uncertainty stage's samples
    assert f"of {result.options.realisations} (95 % CI" in text
    assert f"of {result.summaries['uncertainty']['samples']} (95 % CI" in text


@pytest.mark.browser
def test_browser_probe_sees_sideways_scroll_errors_and_broken_images(tmp_path):
    """The probe is not a formality: a too-wide block, a script error and a broken image are each seen."""
    page = tmp_path / "bad.html"
    page.write_text("<!DOCTYPE html><html><head><meta charset='utf-8'>"
                    "<meta name='viewport' content='width=device-width, initial-scale=1'></head><body>"
                    "<table><tr><td style='white-space:nowrap'>" + "wide " * 200 + "</td></tr></table>"
                    "<img src='data:image/png;base64,bm90IGEgcG5n'><script>undefinedFunction();</script>"
                    "</body></html>", encoding="utf-8")
    probe = browser_probe(page, 390, tmp_path)
    assert probe["scrollWidth"] > probe["innerWidth"] == 390
    assert probe["broken"] == 1 and any("undefinedFunction" in e for e in probe["errors"]), probe


@pytest.mark.browser
def test_every_figure_renders_in_headless_chromium(tmp_path, params):
    result = make_result(tmp_path, params, n_figures=3)
    page = write_report(result, tmp_path / "report.html", ROWS)
    dom = browser_dom(page, tmp_path / "chromium-profile")
    marker = re.search(r"<body[^>]*data-figures=\"([^\"]*)\"", dom)
    assert marker, dom[:500]
    assert marker.group(1) == "ok 3"
    assert "<script>alert" not in dom


@pytest.mark.browser
def test_browser_check_detects_a_broken_figure(tmp_path, params):
    """The marker is not a formality: a corrupt image is reported as broken."""
    result = make_result(tmp_path, params, n_figures=2)
    (tmp_path / "figures" / "fig1.png").write_bytes(b"not a png")
    page = write_report(result, tmp_path / "report.html")
    dom = browser_dom(page, tmp_path / "chromium-profile")
    assert 'data-figures="broken 1 of 2"' in dom


def test_validation_rows_without_a_checkout_keep_the_other_topics(monkeypatch, tmp_path):
    # an installed wheel has no data/afm/: the measured-file rows are left out, with a note, not the whole table
    import importlib

    import memstribo.validation.roughness as roughness_rows
    from memstribo.job.report import validation_rows
    from memstribo.validation import TOPICS, ValidationRow

    for topic in TOPICS:  # the other topics' rows are stand-ins (computing them all twice takes minutes)
        if topic != "roughness":
            monkeypatch.setattr(importlib.import_module(f"memstribo.validation.{topic}"), "rows",
                                lambda topic=topic: [ValidationRow(topic, "stand-in", "test", 1.0, 1.0, "", "exact",
                                                                   True, "memstribo gear --json")])

    with_files, note = validation_rows(recompute=True)
    assert note is None
    # an installed wheel (no data/afm/ beside the package) run from the repository root still finds the scans
    from memstribo import output

    monkeypatch.setattr(roughness_rows, "AFM", tmp_path / "no-such-folder")
    monkeypatch.setattr(output, "__file__", str(tmp_path / "site-packages" / "memstribo" / "output.py"))
    monkeypatch.chdir(Path(__file__).resolve().parent.parent)
    from_root, note = validation_rows(recompute=True)
    assert note is None and len(from_root) == len(with_files)
    # ... and run anywhere else it leaves those rows out, with a note
    monkeypatch.chdir(tmp_path)
    rows, note = validation_rows(recompute=True)
    assert "data/afm" in note and "checkout" in note
    assert 0 < len(rows) < len(with_files)
    assert not any(row.command.startswith("memstribo roughness data/afm/") for row in rows)
    assert {row.topic for row in rows} == {row.topic for row in with_files}


def test_uncertainty_hook_shows_under_the_verdict_when_the_run_has_one(tmp_path, params):
    """summaries['uncertainty'] (an uncertainty stage's output) is shown right after the verdict, escaped."""
    result = make_result(tmp_path, params)
    assert "Uncertainty and what the verdict hangs on" not in render_report(result)  # none: nothing shown
    result.summaries["uncertainty"] = {
        "summary": "stiction margin -1.2 to -0.8 mN <90 %>", "interval": "COF 0.7 to 0.9",
        "drivers": [{"name": "hamaker_constant", "effect": "60 % of the variance"}, "roughness_rq & seed"]}
    text = render_report(result)
    verdict, uncertainty, figures = (text.index("class='verdict'"), text.index("id='uncertainty'"),
                                     text.index("<h2>Figures"))
    assert verdict < uncertainty < figures
    assert "-1.2 to -0.8 mN &lt;90 %&gt;" in text and "hamaker_constant &mdash; 60 % of the variance" in text
    assert "roughness_rq &amp; seed" in text and "COF 0.7 to 0.9" in text


def test_the_verdict_box_carries_the_three_verdicts_with_their_intervals(tmp_path, params):
    """Issue 41: running (over the roughness), start-up and over the priors, each "k of n (95 % CI ...)", in one box
    before the verdict's details; coloured by the share that sticks."""
    verdict = {"tangential_force": 2.82e-3, "bare_resisting_force_max": 1e-3, "bare_stiction_margin": 1.8e-3,
               "bare_stiction": False, "bare_cof_mean": 0.4, "bare_realisations": 16,
               "bare_stiction_probability": 0.0, "bare_stiction_probability_text": "0 of 16 (95 % CI 0–19 %)",
               "bare_stiction_margin_p05": 1e-3, "bare_stiction_margin_p95": 2e-3,
               "bare_stiction_margin_median": 1.5e-3,
               "bare_cof_mean_p05": 0.4, "bare_cof_mean_p95": 0.5, "bare_startup_margin": -1e-4,
               "bare_startup_stiction": True, "bare_startup_stiction_probability": 0.5625,
               "bare_startup_stiction_probability_text": "9 of 16 (95 % CI 33–77 %)"}
    result = make_result(tmp_path, params, verdict=verdict)
    result.summaries["uncertainty"] = {"summary": "s", "stiction_count": 3, "samples": 64,
                                       "stiction_probability": 3 / 64, "stiction_probability_ci": [0.016, 0.129]}
    text = render_report(result)
    box = text[text.index("id='verdicts'"):text.index("</div>", text.index("id='verdicts'"))]
    assert text.index("id='verdicts'") < text.index("class='verdict'")
    assert "Running, over the roughness: <span class='good'>stiction in 0 of 16 (95 % CI 0–19 %)</span>" in box
    assert "Start-up, over the roughness: <span class='bad'>stiction in 9 of 16 (95 % CI 33–77 %)</span>" in box
    assert re.search(r"Over the priors of the unmeasured constants: <span class='warn'>stiction in 3 of 64 "
                     r"\(95 % CI 2–13 %\)</span>", box), box
    # without an uncertainty stage or an ensemble: the single realisation's verdicts, no invented interval
    single = make_result(tmp_path, params, verdict={"tangential_force": 2.82e-3, "bare_resisting_force_max": 4e-3,
                                                    "bare_stiction_margin": -1e-3, "bare_stiction": True,
                                                    "bare_cof_mean": 0.8, "bare_startup_margin": -2e-3,
                                                    "bare_startup_stiction": True})
    text = render_report(single)
    assert "Running, one roughness realisation: <span class='bad'>STICTION</span>" in text
    assert "Start-up, one roughness realisation: <span class='bad'>STICTION</span>" in text
    assert "over the priors" not in text.lower().split("id='verdicts'")[1].split("</div>")[0]
