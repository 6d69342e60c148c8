"""report.html: one self-contained page of a ``memstribo run`` that a tribologist can read.

The page holds the question, the inputs with their provenance, the verdict (stiction of the
bare and of the coated pair, margin, coating life), every figure (embedded as base64 PNG,
with its caption), the stages with their status, the validation table (thesis against
memstribo, with tolerances and reasons) and the references used. Nothing is loaded from
outside the file. Every text that comes from input files or the user (file names,
metadata, parameter sources) is escaped with :func:`html.escape`.

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
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;max-width:62rem;margin:2rem auto;padding:0 1rem;
color:#1b1b1b;line-height:1.45}
h1{font-size:1.6rem}h2{font-size:1.25rem;border-bottom:1px solid #ccc;padding-bottom:.2rem;margin-top:2rem}
table{border-collapse:collapse;font-size:.85rem;margin:.5rem 0}th,td{border:1px solid #ccc;padding:.2rem .45rem;
vertical-align:top}th{background:#f2f2f2;text-align:left}td.num{text-align:right;font-variant-numeric:tabular-nums}
.verdict{border:2px solid #555;border-radius:6px;padding:.6rem 1rem;background:#fafafa}
.bad{color:#a00;font-weight:bold}.good{color:#060;font-weight:bold}.note{color:#555;font-size:.85rem}
figure{margin:1.2rem 0}figure img{max-width:100%;border:1px solid #ddd}figcaption{font-size:.9rem;color:#333}
code{background:#f4f4f4;padding:0 .2rem;overflow-wrap:anywhere}details{margin:.5rem 0}
.wide{overflow-x:auto}.wide table{font-size:.75rem;width:100%}td{overflow-wrap:break-word}
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


def validation_rows() -> tuple[list, str | None]:
    """All validation rows (:func:`memstribo.validation.all_rows`), or the error that stopped them."""
    from memstribo.validation import all_rows
    from memstribo.validation.roughness import measured_files_available

    try:
        rows = list(all_rows())
    except Exception as exc:  # a topic's rows broke: say so in the page, keep the rest of the report
        return [], f"{type(exc).__name__}: {exc}"
    if not measured_files_available():
        return rows, ("the rows that read the measured AFM files of data/afm/ are left out: memstribo is installed "
                      "outside a checkout of the repository and did not run inside one (run it from the checkout's "
                      "root to include them; docs/validation.md lists them)")
    return rows, None


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
        items.append(f"<li><b>Bare silicon: <span class='{cls}'>stiction probability {p * 100:.0f} %</span></b> over "
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
        if "bare_step_converged" in v:
            items.append(f"<li>Numerics: at twice the steps the margin changes by "
                         f"{v['bare_step_change_margin'] * 100:.2g} % of F<sub>t</sub> and the mean COF by "
                         f"{v['bare_step_change_cof'] * 100:.2g} % "
                         f"({'converged' if v['bare_step_converged'] else '<span class=bad>NOT converged</span>'}, "
                         "goal &lt; 2 %).</li>")
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


def _inputs_html(result) -> str:
    rows = []
    for item in result.inputs:
        label = "synthetic (generated, seeded)" if item.get("synthetic") else "measured"
        rows.append(f"<tr><td>{_e(item.get('name', ''))}</td><td>{_e(label)}</td><td>{_e(item.get('source', ''))}</td>"
                    f"<td class='num'>{_quantity(item.get('Rq'), 'm')}</td>"
                    f"<td class='num'>{_quantity(item.get('rms_slope'))}</td>"
                    f"<td class='num'>{_quantity(item.get('n_points'))}</td>"
                    f"<td>{'yes' if item.get('meshing') else ''}</td></tr>")
    roughness = ("<table><tr><th>profile</th><th>kind</th><th>provenance</th><th>Rq</th><th>rms slope</th>"
                 "<th>points</th><th>used by the meshing stages</th></tr>" + "".join(rows) + "</table>") if rows else "<p>No roughness input was read.</p>"
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
        "<details><summary>All parameters with sources</summary><table><tr><th>name</th><th>value</th>"
        "<th>meaning</th><th>source</th></tr>" + "".join(param_rows) + "</table></details>"
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


def _figures_html(result) -> str:
    # the design map's figures are in its own section (_design_map_html); numbers count every figure
    parts = [_figure_html(result.folder, number, figure)
             for number, figure in enumerate(result.figures, start=1) if figure.stage != _MAP_STAGE]
    return "".join(parts) or "<p>No figures: the stages that draw them did not run.</p>"


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
    parts += [_figure_html(result.folder, number, figure)
              for number, figure in enumerate(result.figures, start=1) if figure.stage == _MAP_STAGE]
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
    temperature = float(result.params["temperature"])
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
    parts.append(f"<table><tr><th>RH</th>{head}</tr>{''.join(rows)}</table>")
    items = []
    for label in labels:
        part = humidity[label]
        value = part.get("critical_humidity")
        verdict = (f"critical humidity RH {value:.3f}" if value is not None
                   else "no critical humidity in the swept range")
        items.append(f"<li><b>{_e(part['name'])}</b>: {_e(verdict)} ({_e(part.get('critical_humidity_note', ''))})"
                     "</li>")
    parts.append(f"<ul>{''.join(items)}</ul>")
    figure = next((i for i, f in enumerate(result.figures, start=1) if f.stem == "humidity_cof_margin"), None)
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
    if error:
        parts.append(f"<p class='bad'>The validation rows could not all be computed: {_e(error)}</p>")
    if rows:
        from memstribo.validation.__main__ import format_number, format_value, summary

        counts = summary(rows)
        parts.append(f"<p><b>{counts['rows']} comparisons: {counts['agree']} agree, {counts['differ']} differ</b> "
                     "(on purpose where the tolerance says 'differs'; the note says why).</p>")

        body = "".join(
            f"<tr><td>{_e(r.topic)}</td><td>{_e(r.quantity)}</td><td>{_e(r.reference)}</td>"
            f"<td class='num'>{_e(format_number(r.reference_value))}</td><td class='num'>{_e(format_value(r))}</td>"
            f"<td>{_e(r.unit)}</td><td>{_e(r.tolerance)}</td>"
            f"<td class='{'good' if r.agrees else 'bad'}'>{'yes' if r.agrees else 'no'}</td>"
            f"<td><code>{_e(r.command)}</code></td><td>{_e(r.note)}</td></tr>" for r in rows)
        parts.append("<div class='wide'><table><tr><th>topic</th><th>quantity</th><th>reference</th><th>reference value</th>"
                     "<th>memstribo</th><th>unit</th><th>tolerance</th><th>agrees</th><th>command</th><th>note</th></tr>"
                     + body + "</table></div>")
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

    stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    done = sum(1 for s in result.stages if s.status == "done")
    return "".join([
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
        "<meta name='viewport' content='width=device-width, initial-scale=1'>",
        "<title>memstribo run: friction, stiction and coating wear of silicon microgear teeth</title>",
        f"<style>{_CSS}</style></head><body data-figures='pending'>",
        "<h1>memstribo: friction, stiction and coating wear of silicon MEMS microgear teeth</h1>",
        f"<p class='note'>memstribo {_e(__version__)}, {stamp}, {result.elapsed:.0f} s; {done} of "
        f"{len(result.stages)} stages done; output folder <code>{_e(os.path.basename(str(result.folder)) or result.folder)}"
        "</code>.</p>",
        f"<h2>The question</h2><p>{_e(QUESTION)}</p>",
        "<h2>Verdict</h2>", _verdict_html(result),
        "<h2>Inputs and their provenance</h2>", _inputs_html(result),
        _humidity_html(result),
        "<h2>Figures</h2>", _figures_html(result),
        _design_map_html(result),
        "<h2>Stages</h2>", _stages_html(result),
        "<h2>Validation: thesis against memstribo</h2>", _validation_html(validation),
        "<h2>References used by this run</h2>", _references_html(),
        _SCRIPT, "</body></html>\n",
    ])


def write_report(result, path: str | Path, validation=None) -> Path:
    """Write :func:`render_report` to ``path`` atomically; return the path."""
    from memstribo.output import atomic_write_text

    return atomic_write_text(Path(path), render_report(result, validation))
