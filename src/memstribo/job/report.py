"""report.html: one self-contained page of a ``memstribo run`` that a tribologist reads in a minute.

The verdict comes first (a box with the bare pair's three verdicts, running, start-up and over the priors, each as
"k of n (95 % CI ...)", then stiction of the bare and of the coated pair,
margin, coating life), then the verdict's uncertainty and what it hangs on when the run has it
(:func:`_uncertainty_html`, fed by ``summaries["uncertainty"]``), then the figures the verdict is read
from (the others folded), the inputs with their provenance, and, folded (``<details>``), the
question, the stages, the validation table (thesis against memstribo, with tolerances and reasons)
and the references used. The page fits a phone's width: images scale down, wide tables scroll
inside their own box. Figures are embedded as base64 PNG; nothing is loaded from outside the file.
Every text that comes from input files or the user (file names, metadata, parameter sources) is
escaped with :func:`html.escape`.

A small inline script sets ``data-figures`` on ``<body>`` to ``"ok N"`` once all N images
have loaded with a non-zero natural width (or ``"broken K of N"``); the browser test reads it.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import math
import os
from pathlib import Path
from typing import Any

__all__ = ["render_report", "write_report", "validation_rows", "QUESTION"]

QUESTION = (
    "Two silicon MEMS gear teeth mesh in vacuum. From the nanoscale roughness of their surfaces: what friction "
    "force and coefficient of friction act over the meshing cycle, how much of it comes from chemical bonds, "
    "van der Waals bonds and elastic interlocking, will the teeth stick (friction force above the available "
    "tangential force F_t), and, with a self-assembled monolayer coating, how fast does the coating wear and "
    "after how many meshing cycles does stiction return?"
)

_CSS = """
*,*::before,*::after{box-sizing:border-box}
html{-webkit-text-size-adjust:100%;text-size-adjust:100%}
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;max-width:62rem;margin:1.5rem auto;padding:0 1rem;
color:#1b1b1b;line-height:1.45;overflow-wrap:break-word}
h1{font-size:1.5rem;line-height:1.25}h2{font-size:1.25rem;border-bottom:1px solid #ccc;padding-bottom:.2rem;
margin-top:1.8rem}h3{font-size:1.05rem}
table{border-collapse:collapse;font-size:.85rem;margin:0}th,td{border:1px solid #ccc;padding:.2rem .45rem;
vertical-align:top;overflow-wrap:anywhere}th{background:#f2f2f2;text-align:left}
td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
.wide{overflow-x:auto;max-width:100%;margin:.5rem 0;-webkit-overflow-scrolling:touch}
.wide table{font-size:.8rem;min-width:100%}
.verdict{border:2px solid #555;border-radius:6px;padding:.6rem 1rem;background:#fafafa}
.verdict ul{padding-left:1.2rem;margin:.3rem 0}.headline{font-size:1.1rem;margin:.2rem 0 .5rem}
.verdicts{border:2px solid #333;border-radius:6px;padding:.4rem .8rem;margin:.4rem 0 .8rem}
.verdicts ul{padding-left:1.2rem;margin:.2rem 0 .4rem}.verdicts .headline{margin:.2rem 0}
.bad{color:#a00;font-weight:bold}.good{color:#060;font-weight:bold}.warn{color:#a60;font-weight:bold}
.note{color:#555;font-size:.85rem}
figure{margin:1.2rem 0}img{max-width:100%;height:auto}figure img{border:1px solid #ddd;display:block}
figcaption{font-size:.9rem;color:#333}
code{background:#f4f4f4;padding:0 .2rem;overflow-wrap:anywhere;word-break:break-word}
details{margin:.6rem 0;border:1px solid #ddd;border-radius:4px;padding:.3rem .6rem}
details>summary{cursor:pointer;font-weight:600}details[open]>summary{margin-bottom:.4rem}
@media (max-width:40rem){body{margin:.8rem auto;padding:0 .6rem;font-size:15px}h1{font-size:1.25rem}
.verdict{padding:.4rem .6rem}th,td{padding:.15rem .3rem}}
"""

_SCRIPT = """
<script>
(function () {
  function check() {
    var imgs = Array.prototype.slice.call(document.images);
    var pending = imgs.filter(function (i) { return !i.complete; });
    if (pending.length) { setTimeout(check, 50); return; }
    var broken = imgs.filter(function (i) { return !(i.naturalWidth > 0); });
    document.body.setAttribute('data-figures',
      broken.length ? 'broken ' + broken.length + ' of ' + imgs.length : 'ok ' + imgs.length);
  }
  if (document.readyState === 'complete') { check(); } else { window.addEventListener('load', check); }
})();
</script>
"""


def _e(text: Any) -> str:
    return html.escape(str(text), quote=True)


def _quantity(value: Any, unit: str = "") -> str:
    from memstribo.output import format_value

    if value is None:
        return "-"
    if isinstance(value, float) and not math.isfinite(value):
        return "-"
    return _e(format_value(value, unit))


#: the report's words on rows it did not compute (the package's rows.json)
SHIPPED_NOTE = ("the rows of this version as shipped with it (src/memstribo/validation/rows.json, written by `python -m "
                "memstribo.validation`; the test suite checks that they equal a fresh computation); they do not "
                "depend on the run's parameters. `[run] validation = \"recompute\"` computes them again (1-2 min)")


def validation_rows(recompute: bool = False) -> tuple[list, str | None]:
    """The validation rows and a note: those shipped with the package (:func:`memstribo.validation.shipped_rows`),
    or with ``recompute`` (or none shipped) all of them anew (:func:`memstribo.validation.all_rows`), or the error
    that stopped them."""
    from memstribo.validation import all_rows, shipped_rows
    from memstribo.validation.roughness import measured_files_available

    shipped = None if recompute else shipped_rows()
    if shipped:
        return shipped, SHIPPED_NOTE
    try:
        rows = list(all_rows())
    except Exception as exc:  # a topic's rows broke: say so in the page, keep the rest of the report
        return [], f"{type(exc).__name__}: {exc}"
    if not measured_files_available():
        return rows, ("the rows that read the measured AFM files of data/afm/ are left out: memstribo is installed "
                      "outside a checkout of the repository and did not run inside one (run it from the checkout's "
                      "root to include them; docs/validation.md lists them)")
    return rows, None


def _startup_items(v) -> list[str]:
    """The start-up verdict (the torque balance of MODEL 7f), the local limits' capped margins and the plastic fraction
    of the bare pair."""
    if "bare_startup_margin" not in v:
        return []
    cls = "bad" if v["bare_startup_stiction"] else "good"
    word = "does NOT start" if v["bare_startup_stiction"] else "starts"
    text = (f"<li>Bare silicon at rest, its bonds formed: <span class='{cls}'>{word}</span>: start-up margin "
            f"{_quantity(v['bare_startup_margin'], 'N')} (the torque balance of the pair, each friction force with "
            f"its flank's radius of curvature as moment arm), largest start-up COF "
            f"{_quantity(v.get('bare_static_cof_max'))}; failing verdict: {_e(str(v.get('bare_stiction_mode')))}")
    if v.get("bare_startup_load_torque_limit") is not None:
        text += f"; it starts under a load torque on the gear up to {_quantity(v['bare_startup_load_torque_limit'], 'N m')}"
    if "bare_startup_stiction_probability_text" in v:
        text += (f"; start-up stiction {_e(v['bare_startup_stiction_probability_text'])} over the roughness "
                 "realisations")
    items = [text + ".</li>"]
    if "bare_stiction_margin_capped" in v:
        items.append(f"<li>Local limits: with every bond population's shear stress capped at the ideal shear strength "
                     f"of silicon the margins are {_quantity(v['bare_stiction_margin_capped'], 'N')} (running) and "
                     f"{_quantity(v['bare_startup_margin_capped'], 'N')} (start-up); failing verdict: "
                     f"{_e(str(v.get('bare_stiction_mode_capped')))}.</li>")
    if v.get("bare_plastic_fraction"):
        items.append(f"<li>Plastic flow: {v['bare_plastic_fraction'] * 100:.3g} % of the contact at the hardness; "
                     f"margin {_quantity(v['bare_stiction_margin'], 'N')} with the cap, "
                     f"{_quantity(v.get('bare_stiction_margin_uncapped'), 'N')} purely elastic.</li>")
    return items


def _verdict_html(result) -> str:
    v = result.verdict
    items = []
    case = v.get("load_case")
    case_text = ("load case 'torque': the tooth normal force F<sub>t</sub>/cos &alpha; that the drive torque implies"
                 if case == "torque" else "load case 'thesis': the normal load F<sub>ext</sub> as given, which is not "
                 "the normal force the torque implies")
    if "bare_stiction_probability" in v:
        p = v["bare_stiction_probability"]
        cls = "bad" if p >= 0.5 else ("warn" if p > 0 else "good")
        probability = (_e(v["bare_stiction_probability_text"]) if v.get("bare_stiction_probability_text")
                       else f"{p * 100:.0f} %")  # k of n with its 95 % interval (MODEL 7d)
        items.append(f"<li><b>Bare silicon: <span class='{cls}'>running stiction {probability}</span></b> over "
                     f"{v['bare_realisations']} independent roughness realisations; the smallest margin "
                     f"F<sub>t</sub> &minus; R lies between {_quantity(v['bare_stiction_margin_p05'], 'N')} and "
                     f"{_quantity(v['bare_stiction_margin_p95'], 'N')} (5&ndash;95 %, median "
                     f"{_quantity(v['bare_stiction_margin_median'], 'N')}); mean COF "
                     f"{_quantity(v['bare_cof_mean_p05'])} to {_quantity(v['bare_cof_mean_p95'])} ({case_text}).</li>")
    if "bare_stiction" in v:
        word = "STICTION" if v["bare_stiction"] else "no stiction"
        cls = "bad" if v["bare_stiction"] else "good"
        items.append(f"<li>Bare silicon, first realisation: <span class='{cls}'>{word}</span>: the largest resisting "
                     f"force R(c) (friction of every pair in mesh) is {_quantity(v['bare_resisting_force_max'], 'N')} "
                     f"against the tangential force F<sub>t</sub> = {_quantity(v.get('tangential_force'), 'N')}; margin "
                     f"F<sub>t</sub> &minus; R = {_quantity(v['bare_stiction_margin'], 'N')}; mean COF "
                     f"{_quantity(v['bare_cof_mean'])}; mesh efficiency {_quantity(v.get('bare_mesh_efficiency'))}.</li>")
        items.extend(_startup_items(v))
        if "bare_step_converged" in v:
            grid = (f"; at twice the grid's resolution the margin by {v['bare_grid_change_margin'] * 100:.2g} %"
                    if "bare_grid_change_margin" in v else "")
            items.append(f"<li>Numerics: at twice the steps the margin changes by "
                         f"{v['bare_step_change_margin'] * 100:.2g} % of |margin| and the mean COF by "
                         f"{v['bare_step_change_cof'] * 100:.2g} %{grid} "
                         f"({'converged' if v['bare_step_converged'] else '<span class=bad>NOT converged</span>'}, "
                         "goal &lt; 2 %, MODEL 7d).</li>")
        if v.get("bare_roughness_rows"):
            items.append(f"<li>Roughness of the nanoblock rows (first realisation): {_e(v['bare_roughness_rows'])}.</li>")
        for text in v.get("bare_warnings", []):
            items.append(f"<li><span class='bad'>Warning</span>: {_e(text)}.</li>")
    if "coated_stiction" in v:
        word = "STICTION" if v["coated_stiction"] else "no stiction"
        cls = "bad" if v["coated_stiction"] else "good"
        coating = _e(result.options.coating)
        items.append(f"<li>{coating}-coated pair, intact coating: <span class='{cls}'>{word}</span>: largest resisting "
                     f"force {_quantity(v['coated_resisting_force_max'], 'N')}, smallest margin "
                     f"{_quantity(v['coated_stiction_margin'], 'N')}; mean COF {_quantity(v['coated_cof_mean'])}.</li>")
    if "wear_at_stiction" in v:
        wear = v["wear_at_stiction"]
        text = ("no worn fraction of the sweep reaches stiction" if wear is None else
                f"stiction returns once a fraction &Omega; = {wear * 100:.0f} % of the gear's coating is worn "
                "(the stiction margin of the wear sweep interpolated to zero)")
        items.append(f"<li>Coating wear: {text}.</li>")
    if v.get("cycles_to_stiction") is not None:
        items.append(f"<li>Coating life: stiction returns after about {_quantity(v['cycles_to_stiction'])} meshing "
                     "cycles.</li>")
    elif "damage_per_cycle_over_c1" in v:
        exponent = v.get("damage_exponent")
        unit = f" Pa<sup>{exponent:g}</sup>" if exponent is not None else ""
        ratio = v.get("life_ratio_corner_to_central")
        relative = (f" The corner asperities' coating lives {ratio:.3g} times as long as the central ones'."
                    if ratio is not None else "")
        items.append("<li>Coating life: the damage constant c<sub>1</sub> is not known from first principles; the "
                     "largest damage per meshing cycle divided by c<sub>1</sub> is "
                     f"{_quantity(v['damage_per_cycle_over_c1'])}{unit}; give an observed life "
                     f"(<code>[run] cycles_observed</code>) or the parameter <code>damage_coefficient</code> to turn it "
                     f"into cycles.{relative}</li>")
    if v.get("nanoblock_geometry") not in (None, "parameters"):
        values = v.get("nanoblock_geometry_values", {})
        listed = ", ".join(f"{_e(k)} {_quantity(val, 'm') if k != 'atomic_per_side' else _e(str(val))}"
                           for k, val in values.items())
        items.append(f"<li>Nanoblock geometry of the meshing stages: derived {_e(v['nanoblock_geometry'])} "
                     f"(<code>memstribo nanoblock --from</code>): {listed}.</li>")
    if not items:
        items.append("<li>No verdict: the meshing stages did not run (see the stages below).</li>")
    return "<div class='verdict'><ul>" + "".join(items) + "</ul></div>"


def _probability_class(k, n) -> str:
    return "bad" if n and k / n >= 0.5 else ("warn" if k else "good")


def _priors_probability(data) -> tuple[str, int, int] | None:
    """(text "k of n (95 % CI ...)", k, n) of P(stiction) over the priors from the uncertainty stage's summary."""
    if not isinstance(data, dict) or data.get("stiction_count") is None or not data.get("samples"):
        return None
    k, n = int(data["stiction_count"]), int(data["samples"])
    text = data.get("stiction_probability_text")
    if not text:
        from memstribo.uncertainty.intervals import format_probability

        ci = data.get("stiction_probability_ci")
        text = format_probability(k, n, interval=tuple(ci) if ci else None)
    return text, k, n


def _count(text, fallback_probability, fallback_n):
    """(k, n) from a "k of n (...)" text, else from a probability and a count."""
    import re

    match = re.match(r"\s*(\d+) of (\d+)", str(text or ""))
    if match:
        return int(match.group(1)), int(match.group(2))
    n = int(fallback_n or 0)
    return round(float(fallback_probability or 0.0) * n), n


def _headline_html(result) -> str:
    """The verdict box at the top of the page: the three verdicts of the bare pair, each as "k of n (95 % CI ...)"
    where the run has it (running, over the roughness realisations; start-up; over the priors of the unmeasured
    constants, from the uncertainty stage), then the coated pair and the coating life (issue 41)."""
    v = result.verdict
    lines = []
    for label, key in (("running", "bare_stiction"), ("start-up", "bare_startup_stiction")):
        probability, text = v.get(f"{key}_probability"), v.get(f"{key}_probability_text")
        if probability is not None or text:
            k, n = _count(text, probability, v.get("bare_realisations"))
            text = text or f"{probability * 100:.0f} %"
            lines.append(f"{label}, over the roughness: <span class='{_probability_class(k, n)}'>stiction in "
                         f"{_e(text)}</span>")
        elif key in v:
            cls = "bad" if v[key] else "good"
            lines.append(f"{label}, one roughness realisation: <span class='{cls}'>"
                         f"{'STICTION' if v[key] else 'no stiction'}</span>")
    priors = _priors_probability(result.summaries.get("uncertainty") or v.get("uncertainty"))
    if priors is not None:
        text, k, n = priors
        lines.append(f"over the priors of the unmeasured constants: <span class='{_probability_class(k, n)}'>"
                     f"stiction in {_e(text)}</span>")
    parts = []
    if "coated_stiction" in v:
        cls = "bad" if v["coated_stiction"] else "good"
        parts.append(f"{_e(result.options.coating)}-coated: <span class='{cls}'>"
                     f"{'STICTION' if v['coated_stiction'] else 'no stiction'}</span> while the coating is intact")
    if v.get("cycles_to_stiction") is not None:
        parts.append(f"stiction returns after about {_quantity(v['cycles_to_stiction'])} meshing cycles")
    if not lines and not parts:
        return ""
    html = ["<div class='verdicts' id='verdicts'>"]
    if lines:
        html.append("<p class='headline'><b>Bare silicon</b></p><ul>"
                    + "".join(f"<li>{line[0].upper() + line[1:]}</li>" for line in lines) + "</ul>")
    if parts:
        text = "; ".join(parts)
        html.append(f"<p class='headline'><b>{text[0].upper() + text[1:]}.</b></p>")
    html.append("</div>")
    return "".join(html)


def _uncertainty_html(result) -> str:
    """The verdict's uncertainty and what it hangs on, right under the verdict; "" when the run has none.

    Hook for an uncertainty stage: put ``summaries["uncertainty"]`` (or ``verdict["uncertainty"]``) into the
    run's results as a dict with any of ``summary`` (text: the verdict's uncertainty in one or two sentences),
    ``interval`` (text, e.g. "stiction margin -1.2 to -0.8 mN (90 %)") and ``drivers`` (a list, largest first,
    of texts or of dicts ``{"name": ..., "effect": ..., "note": ...}``: the inputs the verdict hangs on). Every
    text is escaped. A plain string is shown as the summary.
    """
    data = result.summaries.get("uncertainty") or result.verdict.get("uncertainty")
    if not data:
        return ""
    if isinstance(data, str):
        data = {"summary": data}
    parts = ["<div class='uncertainty' id='uncertainty'><h3>Uncertainty and what the verdict hangs on</h3>"]
    if data.get("summary"):
        parts.append(f"<p>{_e(data['summary'])}</p>")
    if data.get("interval"):
        parts.append(f"<p>Range: {_e(data['interval'])}</p>")
    drivers = data.get("drivers") or []
    if drivers:
        items = []
        for driver in drivers:
            if isinstance(driver, dict):
                text = " &mdash; ".join(_e(driver[k]) for k in ("name", "effect", "note") if driver.get(k) is not None)
            else:
                text = _e(driver)
            items.append(f"<li>{text}</li>")
        parts.append("<p>It hangs on, largest first:</p><ul>" + "".join(items) + "</ul>")
    parts.append("</div>")
    return "".join(parts)


def _inputs_html(result) -> str:
    rows = []
    for item in result.inputs:
        label = "synthetic (generated, seeded)" if item.get("synthetic") else "measured"
        rows.append(f"<tr><td>{_e(item.get('name', ''))}</td><td>{_e(label)}</td><td>{_e(item.get('source', ''))}</td>"
                    f"<td class='num'>{_quantity(item.get('Rq'), 'm')}</td>"
                    f"<td class='num'>{_quantity(item.get('rms_slope'))}</td>"
                    f"<td class='num'>{_quantity(item.get('n_points'))}</td>"
                    f"<td>{'yes' if item.get('meshing') else ''}</td></tr>")
    roughness = ("<div class='wide'><table><tr><th>profile</th><th>kind</th><th>provenance</th><th>Rq</th>"
                 "<th>rms slope</th><th>points</th><th>used by the meshing stages</th></tr>" + "".join(rows) +
                 "</table></div>") if rows else "<p>No roughness input was read.</p>"
    from memstribo.parameters import SPECS

    params = result.params
    param_rows = []
    for name in params:
        spec = SPECS.get(name)
        unit = spec.unit if spec else ""
        value = params[name]
        shown = "unset (derived)" if value is None else _quantity(value, unit)
        param_rows.append(f"<tr><td><code>{_e(name)}</code></td><td class='num'>{shown}</td>"
                          f"<td>{_e(spec.description if spec else '')}</td><td>{_e(params.source(name))}</td></tr>")
    changed = _changed_parameters(params)
    changed_text = (", ".join(f"<code>{_e(n)}</code> ({_e(params.source(n))})" for n in changed)
                    if changed else "none")
    options = result.options
    return (
        "<h3>Roughness</h3>" + roughness +
        f"<h3>Parameters</h3><p>Parameter set <code>{_e(params.name)}</code>; every value with its unit and source "
        f"is in <code>parameters.toml</code>. Changed from that set: {changed_text}.</p>"
        "<details><summary>All parameters with sources</summary><div class='wide'><table><tr><th>name</th>"
        "<th>value</th><th>meaning</th><th>source</th></tr>" + "".join(param_rows) + "</table></div></details>"
        f"<p class='note'>Run options: steps per cycle {_e(options.steps or 'model default')}, coating "
        f"{_e(options.coating)}, {len(options.loads)} loads, {len(options.areas)} areas, {len(options.wear)} worn "
        "fractions.</p>"
    )


def _changed_parameters(params) -> list[str]:
    """Names whose value differs from the named parameter set (the user's overrides)."""
    from memstribo.errors import MemstriboError
    from memstribo.parameters import get_parameter_values

    try:
        base = get_parameter_values(params.name)
    except MemstriboError:
        return list(params)
    return [name for name in params if name not in base or base[name] != params[name]]


def _stages_html(result) -> str:
    rows = "".join(
        f"<tr><td>{_e(s.title)}</td><td>{_e(s.status)}</td><td class='num'>{s.seconds:.1f} s</td>"
        f"<td>{_e(s.message)}</td><td>{'<br>'.join(_e(f) for f in s.files if f.startswith('data/'))}</td></tr>"
        for s in result.stages)
    return ("<p>Datasets are NetCDF (units as attributes) and CSV (units in the column headers) in "
            "<code>data/</code>; figures are PNG and SVG in <code>figures/</code>; <code>parameters.toml</code> holds "
            "the parameters used (a valid <code>--config</code> file), <code>references.txt</code> the references, "
            "<code>run.json</code> every stage's summary.</p><div class='wide'><table><tr><th>stage</th><th>status</th>"
            "<th>time</th><th>note</th><th>datasets</th></tr>" + rows + "</table></div>")


def _figure_html(folder, number, figure) -> str:
    """Figure ``number`` of the run in ``folder``, its PNG inlined, or a line saying it is missing."""
    path = Path(folder) / "figures" / f"{figure.stem}.png"
    try:
        data = base64.b64encode(path.read_bytes()).decode("ascii")
    except OSError:
        return f"<p class='bad'>Figure {number} ({_e(figure.stem)}) is missing.</p>"
    return (f"<figure id='fig-{_e(figure.stem)}'><img alt='{_e(figure.caption)}' "
            f"src='data:image/png;base64,{data}'><figcaption><b>Figure {number}.</b> {_e(figure.caption)} "
            f"<span class='note'>(figures/{_e(figure.stem)}.png and .svg)</span></figcaption></figure>")


#: figures shown open, under the verdict (the others are folded): those the verdict is read from
KEY_FIGURES = ("mesh_bare_ensemble", "uncertainty_sensitivity", "mesh_bare_forces_cof", "wear_sweep")


def _figure_numbers(result) -> dict[str, int]:
    """Figure stem -> its number in the page's order: the key figures, the other figures, the design map's."""
    key = [f for f in result.figures if f.stage != _MAP_STAGE and f.stem in KEY_FIGURES]
    key.sort(key=lambda f: KEY_FIGURES.index(f.stem))
    other = [f for f in result.figures if f.stage != _MAP_STAGE and f.stem not in KEY_FIGURES]
    maps = [f for f in result.figures if f.stage == _MAP_STAGE]
    return {f.stem: number for number, f in enumerate(key + other + maps, start=1)}


def _figures_html(result) -> str:
    # the design map's figures are in its own section (_design_map_html); numbers follow the page
    numbers = _figure_numbers(result)
    numbered = sorted(((numbers[f.stem], f) for f in result.figures if f.stage != _MAP_STAGE), key=lambda p: p[0])
    if not numbered:
        return "<p>No figures: the stages that draw them did not run.</p>"
    key = [_figure_html(result.folder, n, f) for n, f in numbered if f.stem in KEY_FIGURES]
    other = [_figure_html(result.folder, n, f) for n, f in numbered if f.stem not in KEY_FIGURES]
    if other:
        key.append(f"<details><summary>{'All' if not key else 'The other'} {len(other)} figure(s): roughness, gear, "
                   "sliding, sweeps, energy, coating and damage</summary>" + "".join(other) + "</details>")
    return "".join(key)


_MAP_STAGE = "design_map"  # memstribo.job.chain.MAP_STAGE's name (the report does not import the chain)


def _design_map_html(result) -> str:
    """The section of a design map (``[run] map``): what was mapped, what it says, its figures; "" without a map."""
    record = next((s for s in result.stages if s.name == _MAP_STAGE), None)
    if record is None:
        return ""
    head = "<h2>Design map</h2>"
    summary = result.summaries.get(_MAP_STAGE)
    if summary is None and record.status == "pending":
        return head + "<p>The design map runs after the other stages (finished points: <code>map/points/</code>).</p>"
    if summary is None:
        return head + f"<p class='bad'>The design map did not finish: {_e(record.status)} {_e(record.message)}</p>"
    axes = ", ".join(f"<code>{_e(k)}</code> ({_e(n)} values)" for k, n in summary["axes"].items())
    p_min, p_max = summary.get("stiction_probability_min"), summary.get("stiction_probability_max")
    parts = [head, f"<p>Map <b>{_e(summary['name'])}</b> (spec <code>{_e(os.path.basename(summary['spec']))}</code>): "
             f"{_e(summary['points'])} designs over {axes}; every design is an ensemble of "
             f"{_e(summary['realisations'])} roughness realisation(s) of the meshing cycle "
             f"({_e(summary['steps'] or 'the model default')} steps). The whole map, one dimension per axis, is "
             "<code>map/map.nc</code> (and <code>map/map.csv</code>); see docs/design-maps.md for how to read it.</p>"]
    items = []
    if p_min is not None:
        cls = "bad" if summary["points_sticking"] else "good"
        items.append(f"<li><span class='{cls}'>{_e(summary['points_sticking'])} of {_e(summary['points'])} designs "
                     "stick more often than not</span> (stiction probability &ge; 50 %); "
                     f"{_e(summary['points_free'])} never stuck in any realisation; the probability ranges from "
                     f"{p_min * 100:.0f} % to {p_max * 100:.0f} %.</li>")
    if summary.get("mesh_efficiency_median_min") is not None:
        items.append(f"<li>Mesh efficiency (median over the realisations) from "
                     f"{_quantity(summary['mesh_efficiency_median_min'])} to "
                     f"{_quantity(summary['mesh_efficiency_median_max'])}.</li>")
    if summary.get("cycles_to_failure_min") is not None:
        items.append(f"<li>Coated designs: the coating first fails after {_quantity(summary['cycles_to_failure_min'])} "
                     f"to {_quantity(summary['cycles_to_failure_max'])} meshing cycles.</li>")
    if summary.get("failed"):
        items.append(f"<li class='bad'>{_e(summary['failed'])} point(s) failed (the <code>error</code> variable of "
                     "map.nc says why).</li>")
    items += [f"<li class='note'>{_e(note)}</li>" for note in summary.get("notes", [])]
    parts.append("<ul>" + "".join(items) + "</ul>")
    numbers = _figure_numbers(result)
    parts += [_figure_html(result.folder, numbers[figure.stem], figure)
              for figure in result.figures if figure.stage == _MAP_STAGE]
    return "".join(parts)


def _share(part, total) -> str:
    """``part`` as a percentage of ``total`` (text)."""
    return f"{100.0 * part / total:.2g} %" if total else "-"


def _humidity_html(result) -> str:
    """The humid-air section (issue #17): only for a run in air (its ``humidity`` summary), else nothing."""
    humidity = result.summaries.get("humidity")
    if not humidity:
        record = next((s for s in result.stages if s.name == "humidity"), None)
        if record is None:
            return ""
        return (f"<h2>Humid air</h2><p class='bad'>The humid-air section did not finish: {_e(record.message)}</p>")
    temperature = float(result.params["ambient_temperature"])
    model_rh = float(result.params["relative_humidity"])
    parts = ["<h2>Humid air: capillary adhesion and the critical humidity</h2>",
             f"<p>Environment air at T = {temperature:.4g} K (the model's "
             f"relative humidity {model_rh:.2f}). Water condenses where "
             "the local gap is below the condensation height r_K (cos θ1 + cos θ2); the menisci's Laplace pressure "
             "γ/r_K pulls the teeth together inside each contact solve and adds to F_adh, and breaking them "
             "dissipates energy (the capillary part of the COF). Model and limits: docs/humidity.md.</p>"]
    labels = [label for label in ("bare", "coated") if humidity.get(label)]
    head = "".join(f"<th>COF, {_e(humidity[label]['name'])}</th><th>capillary part (share)</th><th>margin [µN]</th>"
                   for label in labels)
    rows = []
    for i, rh in enumerate(humidity["relative_humidity"]):
        cells = "".join(
            f"<td>{humidity[label]['cof_mean'][i]:.4g}</td><td>{humidity[label]['cof_capillary'][i]:.3g} "
            f"({_share(humidity[label]['cof_capillary'][i], humidity[label]['cof_mean'][i])})</td>"
            f"<td>{humidity[label]['stiction_margin'][i] * 1e6:.4g}</td>" for label in labels)
        rows.append(f"<tr><td>{rh:.2f}</td>{cells}</tr>")
    parts.append(f"<div class='wide'><table><tr><th>RH</th>{head}</tr>{''.join(rows)}</table></div>")
    items = []
    for label in labels:
        part = humidity[label]
        value = part.get("critical_humidity")
        verdict = (f"critical humidity RH {value:.3f}" if value is not None
                   else "no critical humidity in the swept range")
        items.append(f"<li><b>{_e(part['name'])}</b>: {_e(verdict)} ({_e(part.get('critical_humidity_note', ''))})"
                     "</li>")
    parts.append(f"<ul>{''.join(items)}</ul>")
    figure = _figure_numbers(result).get("humidity_cof_margin")
    if figure is not None:
        parts.append(f"<p>Figure {figure} draws these curves; the numbers are in <code>data/humidity_sweep.json"
                     "</code>.</p>")
    return "".join(parts)


def _validation_html(validation) -> str:
    if validation is None:
        return ("<p>The validation table is computed at the end of the run (or run "
                "<code>python -m memstribo.validation</code>; it is also <code>docs/validation.md</code>).</p>")
    rows, error = validation
    parts = ["<p>Each memstribo value comes from the command named (the same library call); the table is also "
             "<code>docs/validation.md</code>, generated by <code>python -m memstribo.validation</code>.</p>"]
    if error == SHIPPED_NOTE:  # not an error: where the rows come from
        parts.append(f"<p>These are {_e(error)}.</p>")
    elif error:
        parts.append(f"<p class='bad'>The validation rows could not all be computed: {_e(error)}</p>")
    if rows:
        from memstribo.validation.__main__ import format_number, format_value, summary

        counts = summary(rows)
        known = sum(1 for r in rows if not r.agrees and r.expected == "differs")
        unexpected = [r for r in rows if not r.as_expected]
        parts.append(f"<p><b>{counts['rows']} comparisons: {counts['agree']} agree, {counts['differ']} differ</b> "
                     f"({known} of them known differences, each fixed as such in its source with the band it must stay "
                     "in; the note says why).</p>")
        if unexpected:
            parts.append("<p class='bad'>Not as expected (a row that agreed no longer does, or a known difference "
                         "left its band): " + "; ".join(f"{_e(r.topic)}: {_e(r.quantity)}" for r in unexpected)
                         + ".</p>")
        differ = [r for r in rows if not r.agrees]
        if differ:
            parts.append("<p>Those that differ: " + "; ".join(f"{_e(r.topic)}: {_e(r.quantity)}" for r in differ)
                         + ".</p>")

        body = "".join(
            f"<tr><td>{_e(r.topic)}</td><td>{_e(r.quantity)}</td><td>{_e(r.reference)}</td>"
            f"<td class='num'>{_e(format_number(r.reference_value))}</td><td class='num'>{_e(format_value(r))}</td>"
            f"<td>{_e(r.unit)}</td><td>{_e(r.tolerance)}</td>"
            f"<td class='{'good' if r.agrees else 'bad'}'>"
            f"{'yes' if r.agrees else ('no (known: differs)' if r.expected == 'differs' else 'no')}</td>"
            f"<td><code>{_e(r.command)}</code></td><td>{_e(r.note)}</td></tr>" for r in rows)
        parts.append(f"<details id='validation-table'><summary>The table: {counts['rows']} rows with reference, "
                     "tolerance, command and note</summary><div class='wide'><table><tr><th>topic</th><th>quantity</th>"
                     "<th>reference</th><th>reference value</th><th>memstribo</th><th>unit</th><th>tolerance</th>"
                     "<th>agrees</th><th>command</th><th>note</th></tr>" + body + "</table></div></details>")
    return "".join(parts)


def _references_html() -> str:
    from memstribo.references import used_references

    items = "".join(f"<li id='ref-{_e(k)}'><b>[{_e(k)}]</b> {_e(text)}</li>" for k, text in used_references())
    return f"<ol>{items}</ol>" if items else "<p>No model function recorded a reference.</p>"


def render_report(result, validation=None) -> str:
    """The whole page as text (see the module docstring).

    Parameters
    ----------
    result : memstribo.job.options.RunResult
        The run.
    validation : tuple, optional
        ``(rows, error)`` as :func:`validation_rows` returns; None: the table is not shown (yet).
    """
    from memstribo import __version__

    from memstribo.output import git_commit

    stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    done = sum(1 for s in result.stages if s.status == "done")
    commit = git_commit()
    commit_text = f"git commit <code>{_e(commit[:12])}</code>{_e(commit[40:])}" if not commit.startswith("none") \
        else _e(commit.replace("none: ", ""))
    return "".join([
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
        "<meta name='viewport' content='width=device-width, initial-scale=1'>",
        "<title>memstribo run: friction, stiction and coating wear of silicon microgear teeth</title>",
        f"<style>{_CSS}</style></head><body data-figures='pending'>",
        "<h1>memstribo: friction, stiction and coating wear of silicon MEMS microgear teeth</h1>",
        "<h2 id='verdict'>Verdict</h2>", _headline_html(result), _verdict_html(result), _uncertainty_html(result),
        f"<p class='note'>memstribo {_e(__version__)} ({commit_text}), {stamp}, {result.elapsed:.0f} s; {done} of "
        f"{len(result.stages)} stages done; output folder <code>{_e(os.path.basename(str(result.folder)) or result.folder)}"
        "</code>.</p>",
        f"<details><summary>The question this run answers</summary><p>{_e(QUESTION)}</p></details>",
        "<h2>Figures</h2>", _figures_html(result),
        "<h2>Inputs and their provenance</h2>", _inputs_html(result),
        _humidity_html(result),
        _design_map_html(result),
        "<h2>Stages</h2><details><summary>The stages with their status, time and files</summary>",
        _stages_html(result), "</details>",
        "<h2>Validation: thesis against memstribo</h2>", _validation_html(validation),
        "<h2>References used by this run</h2><details><summary>The papers the models of this run cite</summary>",
        _references_html(), "</details>",
        _SCRIPT, "</body></html>\n",
    ])


def write_report(result, path: str | Path, validation=None) -> Path:
    """Write :func:`render_report` to ``path`` atomically; return the path."""
    from memstribo.output import atomic_write_text

    return atomic_write_text(Path(path), render_report(result, validation))
