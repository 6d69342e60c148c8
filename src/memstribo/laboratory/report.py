"""docs/experiments.md and its figure, generated (``python -m memstribo.laboratory``; MODEL 7e)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

__all__ = ["COMMAND", "SETTINGS", "run_all", "markdown", "figure", "write", "used_by", "coverage_section"]

COMMAND = "python -m memstribo.laboratory --write docs/experiments.md"
#: how much is computed (kept small so that the generator runs in a few minutes on 2 cores)
SETTINGS = {"nominal_realisations": 8, "prior_samples": 128, "calibration_realisations": 3, "seed": 0}


def run_all(settings=None):
    """Load the rows, predict them at nominal constants, calibrate; returns a dict of the results."""
    from memstribo.laboratory.calibration import calibrate, calibrated_set_toml, hit_rate, prior_samples
    from memstribo.laboratory.data import calibration_settings, load_measurements
    from memstribo.laboratory.predict import predict_all
    from memstribo.laboratory.scoring import loso_coverage
    from memstribo.parameters import get_parameter_values
    from memstribo.physics.coating import get_coating

    s = dict(SETTINGS, **(settings or {}))
    rows = load_measurements()
    cal = calibration_settings()
    nominal = predict_all(rows, [{}], s["nominal_realisations"], calibration_coating=cal["coating"])
    params = get_parameter_values("silicon_oxide_air")
    samples, prior_text = prior_samples(params, cal, s["prior_samples"], seed=s["seed"],
                                        coating=get_coating(cal["coating"]))
    result = calibrate(rows, samples, prior_text, s["calibration_realisations"], cal["coating"])
    held = {r.id for r in rows if r.held_out}
    coverage = loso_coverage(rows, {p.id: (p.values if p.status == "predicted" else None)
                                    for p in result.prior_predictions})
    return {"rows": rows, "settings": s, "calibration": cal, "nominal": nominal,
            "nominal_held_out": hit_rate([p for p in nominal if p.id in held]), "result": result,
            "coverage": coverage, "calibrated_toml": calibrated_set_toml(result)}


def _g(x, digits=3):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "–"
    return f"{x:.{digits}g}"


def _scatter(row):
    s = row.scatter
    if s["kind"] == "sd":
        return f"± {_g(s['value'])} (sd)"
    if s["kind"] == "range":
        return f"{_g(s['low'])}–{_g(s['high'])}"
    extra = f", {int(round(100 * s['relative_sd_assumed']))} % assumed" if "relative_sd_assumed" in s else ""
    return f"{s['kind']}{extra}"


def _conditions(row):
    c = row.conditions
    load = c.get("contact_pressure", c.get("normal_force", "–"))
    if isinstance(load, (int, float)):
        load = f"{_g(load)} Pa"
    elif "contact_pressure_assumed" in c:
        load = f"not stated ({_g(c['contact_pressure_assumed'])} Pa assumed)"
    rh = c.get("relative_humidity")
    env = c["environment"]
    if env == "air":
        if isinstance(rh, (int, float)):
            env += f", RH {_g(rh)}"
        else:
            env += f", RH {rh}" + (f" ({_g(c['relative_humidity_assumed'])} assumed)" if "relative_humidity_assumed" in c else "")
    return f"{c['geometry']}; {c['surface']}; load {load}; {env}"


def _measurement_table(rows) -> list:
    """The measurements section: counts (independent rows, groups, held out), then one line per row with its fit."""
    n_cal = sum(r.calibration for r in rows)
    independent = [r for r in rows if r.same_as is None]
    groups = sorted({r.source_group for r in independent})
    n_held = sum(r.held_out for r in rows)
    out = [f"## Measurements ({len(rows)} rows: {len(independent)} independent measurements from {len(groups)} research "
           f"groups; {n_cal} declared for calibration, {n_held} held out)", "",
           "A measurement published twice is one row (`same_as`); a row that any fit used (the laboratory calibration, "
           "or a parameter set's own fit: `fitted_by`) or that the model was designed to reproduce (`design_target`) is "
           "never held out. 'used by' names the fit.", "",
           "| id | quantity | value | scatter | conditions | source | group | used by |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r.id} | {r.quantity} | {_g(r.value)} {'' if r.unit == '1' else r.unit} | {_scatter(r)} | "
                   f"{_conditions(r)} | {r.citation}: {_doi(r.citation)} | {r.source_group} | {used_by(r)} |")
    return out


def used_by(row) -> str:
    """Which fit used the row, or 'held out' (the page's column)."""
    if row.same_as:
        return f"same measurement as {row.same_as} (counted once)"
    if row.design_target:
        return "design target" + (f": {row.condition('design_note')}" if row.condition("design_note") else "")
    if row.fitted_by:
        return row.fitted_by
    return "held out"


def _doi(key):
    from memstribo.references import REFERENCES

    text = REFERENCES[key]
    i = text.find("doi:")
    return text[i:].split()[0].rstrip(".,)") if i >= 0 else text.split("'")[1][:40] + "… (no DOI)"


def markdown(res, figure_name="figures/experiments.png") -> str:
    """The page (a pure function of the results: regenerates identically)."""
    from memstribo.parameters.fitted import fitted_constants
    from memstribo.parameters import get_parameter_values
    from memstribo.references import REFERENCES

    rows, s, result = res["rows"], res["settings"], res["result"]
    out = ["# Against the laboratory: published MEMS measurements predicted with their uncertainty (issue 28)", "",
           f"Generated by `{COMMAND}` (src/memstribo/laboratory/); do not edit by hand. The measurements are data "
           "(`src/memstribo/laboratory/measurements.toml`, one row per measured value, each with its conditions, "
           "scatter and citation); a row without its conditions, unit or citation is refused when the data loads.", "",
           f"Settings (kept small so that the page regenerates in a few minutes on 2 cores): nominal predictions over "
           f"{s['nominal_realisations']} roughness realisations; calibration with {s['prior_samples']} prior samples x "
           f"{s['calibration_realisations']} realisations; the test structures are the cases of memstribo.laboratory.cases.", ""]
    out += _measurement_table(rows)
    out += ["", "Sources:", ""] + [f"- `{k}`: {REFERENCES[k]}" for k in dict.fromkeys(r.citation for r in rows)]
    out += ["", "## Predictions at the nominal constants", "",
            "Median and 90 % band (5th–95th percentile) over roughness realisations at the parameter set's nominal "
            "constants (bare rows: `silicon_oxide_air`; coated rows: the coating's constants, no chemical bonds). "
            "'inside' says whether the measured value lies in the band; 'measured / median' says by how much the model "
            "misses.", "",
            "| id | measured | median | 90 % band | inside | measured / median | case |", "|---|---|---|---|---|---|---|"]
    for p in res["nominal"]:
        if p.status != "predicted":
            out.append(f"| {p.id} | {_g(p.measured)} | not predicted | – | – | – | {p.reason} |")
        else:
            ratio = "– (a trend: inside = the median ratio is on the measured side of 1)" \
                if p.quantity == "adhesion_trend_with_rh" else _g(p.ratio, 2)
            out.append(f"| {p.id} | {_g(p.measured)} | {_g(p.median)} | {_g(p.low)}–{_g(p.high)} | "
                       f"{'inside' if p.inside else 'outside'} | {ratio} | {p.case} |")
    h = res["nominal_held_out"]
    out += ["", f"Held-out rows inside the nominal band: {h['inside']} of {h['predicted']} predicted.", "",
            f"![predicted against measured]({figure_name})", "",
            "Figure: predicted median against measured value, log axes; bars: the 90 % band over roughness x prior "
            "samples (grey) and over roughness x posterior (black); the trend row (a ratio) is left out.", "",
            "## Calibration on the declared subset", "",
            f"Prior: {result.prior}. Likelihood: log-normal on measured / predicted median, with the measurement's "
            "relative scatter and the spread over roughness realisations in quadrature "
            "(`memstribo.laboratory.calibration`). Calibration rows: "
            + ", ".join(r.id for r in rows if r.calibration) + f". Effective sample size of the posterior "
            f"weights: {result.ess:.1f} of {len(result.samples)}."
            + (" That is small: the posterior rests on a few prior samples, its bands are narrower than what is "
               "known, and the 'after' hit rate below should be read with that in mind (more samples, or the "
               "priors of MODEL 7d, are needed)." if result.ess < 10 else ""), "",
            "| constant | prior median | prior 90 % | posterior median | posterior 90 % |", "|---|---|---|---|---|"]
    for c in result.constants:
        out.append(f"| {c['name']} | {_g(c['median'])} | {_g(c['p05'])}–{_g(c['p95'])} | {_g(c['post_median'])} | "
                   f"{_g(c['post_p05'])}–{_g(c['post_p95'])} |")
    b, a = result.held_out_before, result.held_out_after

    def rate(hr):
        text = f"{hr['inside']} of {hr['predicted']}"
        if hr.get("interval"):
            text += f" (95 % CI {100 * hr['interval'][0]:.0f}–{100 * hr['interval'][1]:.0f} %)"
        return text

    out += ["", f"Held-out hit rate (measured value inside the 90 % band over roughness x constants): **before "
            f"calibration {rate(b)}, after {rate(a)}**.", "",
            "| id | used by | prior band | inside | posterior band | inside |", "|---|---|---|---|---|---|"]
    for p0, p1 in zip(result.prior_predictions, result.posterior_predictions):
        if p0.status != "predicted":
            continue
        row = next(r for r in rows if r.id == p0.id)
        out.append(f"| {p0.id} | {used_by(row)} | {_g(p0.low)}–{_g(p0.high)} | "
                   f"{'inside' if p0.inside else 'outside'} | {_g(p1.low)}–{_g(p1.high)} | "
                   f"{'inside' if p1.inside else 'outside'} |")
    better = a["inside"] > b["inside"]
    out += ["", "**Which way it went.** The `calibrated` parameter set (src/memstribo/parameters/sets/calibrated.toml, "
            "written by the same command) carries the posterior medians, with the posterior quantiles as its prior "
            "(`[posterior.NAME]`). The default parameter set stays as it is: "
            + (f"the held-out hit rate rises from {b['inside']} to {a['inside']} of {b['predicted']}, but the rows "
               "come from few sources (the same group's report and chapter), too few to change the default on."
               if better else
               f"the held-out hit rate does not rise ({b['inside']} before, {a['inside']} after, of {b['predicted']})."),
            ""]
    out += coverage_section(res["coverage"])
    out += ["", "## What the comparison says", ""]
    out += _findings(res)
    out += ["", "## Fitted constants and their fit conditions", "",
            "`memstribo.parameters.fitted.fitted_constants(params, coating)` lists the fitted constants a run uses "
            "(from the `fitted = {conditions = ...}` markers of the parameter and coating TOMLs); "
            "`fit_condition_warnings(params, normal_force, coating)` warns when a run is far from them "
            "(normal force off by more than 3x, another environment, RH more than 0.3 away).", "",
            "| constant | value | where | fitted at | conditions |", "|---|---|---|---|---|"]
    from memstribo.physics.coating import get_coating

    seen = set()
    for set_name, coating in (("silicon_oxide_air", "OTS"), ("silicon_thesis", "FDTS")):
        for f in fitted_constants(get_parameter_values(set_name), get_coating(coating)):
            key = (f["name"], f["where"])
            if key in seen:
                continue
            seen.add(key)
            out.append(f"| {f['name']} | {_g(f['value'], 4)} {f['unit']} | {f['where']} | "
                       f"{_g(f['normal_force'])} N, {f['environment']} | {f['conditions']} |")
    out.append("")
    return "\n".join(out)


def coverage_section(cov) -> list:
    """The leave-one-source-out section: coverage with and without the discrepancy, its folds and rows."""
    from memstribo.laboratory.scoring import MIN_ROWS

    def cover(c):
        return (f"{c['inside']} of {c['rows']} = {100 * c['coverage']:.0f} % (Wilson {100 * c['confidence']:.0f} % "
                f"interval {100 * c['interval'][0]:.0f}–{100 * c['interval'][1]:.0f} %)") if c["rows"] else "no row"

    level = int(round(100 * cov["level"]))
    out = ["## Leave-one-source-out coverage, with and without the model discrepancy", "",
           f"Each research group's rows are predicted with the constants importance-weighted on every other group's "
           f"rows (the calibration redone per fold), and counted inside or outside their {level} % band. A calibrated "
           "band that is honest holds the measurement in about "
           f"{level} % of the rows. The model discrepancy (Kennedy and O'Hagan 2001; "
           "`memstribo.laboratory.scoring`) is a multiplicative log-normal factor per quantity whose sigma is fitted "
           f"by maximum likelihood on the training fold (a quantity with fewer than {MIN_ROWS} training rows takes the "
           "pooled sigma); it widens the bands by what the model is known to miss, and is a weakness to shrink by "
           "physics, not a knob.", "",
           f"- **Coverage of the {level} % bands without the discrepancy: {cover(cov['without'])}.**",
           f"- **With the discrepancy: {cover(cov['with'])}.**"]
    if cov["trained_only"]:
        out.append("- Trained on, never scored (their fit is not redone per fold): "
                   + "; ".join(f"{i} ({why})" for i, why in cov["trained_only"]) + ".")
    sig = cov["sigma_all"]
    out.append("- Discrepancy sigma fitted on every row (ln units; a factor exp(1.645 sigma) at the 90 % band's edge): "
               + ", ".join(f"{q} {sig[q]:.2f}" for q in dict.fromkeys(x["quantity"] for x in cov["rows"]))
               + f"; pooled {sig['pooled']:.2f}.")
    out += ["", "| left out | training rows | ESS | sigma of its quantities |", "|---|---|---|---|"]
    for f in cov["folds"]:
        qs = sorted({x["quantity"] for x in cov["rows"] if x["group"] == f["group"]})
        out.append(f"| {f['group']} | {f['train']} | {f['ess']:.1f} | "
                   + ", ".join(f"{q} {f['sigma'][q]:.2f}" for q in qs) + " |")
    out += ["", "| id | group | measured | band | inside | band with discrepancy | inside |", "|---|---|---|---|---|---|---|"]
    for x in cov["rows"]:
        b, d = x["band"], x["band_discrepancy"]
        out.append(f"| {x['id']} | {x['group']} | {_g(x['measured'])} | {_g(b[1])}–{_g(b[2])} | "
                   f"{'inside' if x['inside'] else 'outside'} | {_g(d[1])}–{_g(d[2])} | "
                   f"{'inside' if x['inside_discrepancy'] else 'outside'} |")
    return out


def _findings(res):
    """Plain statements of hits and misses with their factors, computed from the nominal predictions."""
    lines = []
    duplicates = {r.id for r in res["rows"] if r.same_as}
    pred = [p for p in res["nominal"] if p.status == "predicted" and p.quantity != "adhesion_trend_with_rh"
            and p.id not in duplicates]
    for p in pred:
        factor = p.ratio
        word = "above" if factor > 1 else "below"
        lines.append(f"- {p.id}: measured {_g(p.measured)}, model {_g(p.median)} ({'inside' if p.inside else 'outside'} "
                     f"the band); the measurement is {_g(factor if factor > 1 else 1 / factor, 2)}x {word} the model.")
    trend = [p for p in res["nominal"] if p.quantity == "adhesion_trend_with_rh" and p.status == "predicted"]
    for p in trend:
        lines.append(f"- {p.id}: the microbeam's work of separation rises {_g(p.median)}x from the low to the high RH "
                     f"(band {_g(p.low)}–{_g(p.high)}), as measured: for an unloaded rough interface the menisci fill more "
                     "of the gaps as RH rises (the asperity-level model of issue 36, built to show this rise: a design "
                     "target). The loaded gear's adhesion force is a force, not an energy, and falls above RH 0.2 "
                     "(docs/humidity.md).")
    lines.append("- Static friction: the test-structure cases predict a static row from the bonds' sideways peak "
                 "(1.27 U/D per bond, MODEL 7f) over the real contact area, and a kinetic row from the energy the bonds "
                 "dissipate per sliding distance (U/D^3 over the real area); both capped at the ideal shear strength.")
    result = res["result"]
    by_id = {r.id: r for r in res["rows"]}
    lost = [p1 for p0, p1 in zip(result.prior_predictions, result.posterior_predictions)
            if p0.status == "predicted" and p0.inside and not p1.inside and by_id[p0.id].held_out]
    if lost:
        lines.append("- Calibration moves " + ", ".join(p.id for p in lost) + " out of the band. "
                     + _why_lost(lost, by_id, result))
    missing = [p for p in res["nominal"] if p.status != "predicted"]
    lines.append(f"- Not predicted ({len(missing)} rows): " + "; ".join(f"{p.id} ({p.reason})" for p in missing) + ".")
    return lines


def _why_lost(lost, by_id, result):
    """The reason a held-out row leaves the band after calibration, where the data say it."""
    cal = [by_id[p.id] for p in result.posterior_predictions if by_id[p.id].calibration]
    parts = []
    for p in lost:
        row = by_id[p.id]
        same = [c for c in cal if c.coating == row.coating and c.quantity != row.quantity]
        if same:
            parts.append(f"{p.id} is a {row.quantity.replace('_', ' ')} of {row.coating or 'the bare oxide'} "
                         f"({_g(row.value)}) and the calibration row {same[0].id} is its {same[0].quantity.replace('_', ' ')} "
                         f"({_g(same[0].value)}): the same constants set both (their ratio follows from the bond law), so "
                         "fitting one moves the model away from the other")
        elif row.condition("geometry") != "flat":
            parts.append(f"{p.id} is a {row.condition('geometry')} contact at {_g(row.number('contact_pressure'))} Pa, "
                         f"far from the calibration rows' load; the posterior band ({_g(p.low)}–{_g(p.high)}) misses "
                         f"{_g(row.value)} by {_g(p.low / row.value if row.value < p.low else row.value / p.high, 2)}x")
    return "; ".join(parts) + "." if parts else ""


def figure(res, path):
    """Predicted median against measured value (log axes), prior and posterior 90 % bands as error bars."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = res["result"]
    fig, ax = plt.subplots(figsize=(6, 5.2))
    xs = []
    for p0, p1 in zip(result.prior_predictions, result.posterior_predictions):
        if p0.status != "predicted" or p0.quantity == "adhesion_trend_with_rh":
            continue
        xs.append(p0.measured)
        for p, color, dx in ((p0, "0.6", 0.97), (p1, "k", 1.03)):
            ax.errorbar([p.measured * dx], [p.median], yerr=[[p.median - p.low], [p.high - p.median]], fmt="o",
                        color=color, ms=4, capsize=2)
    nominal = [p for p in res["nominal"] if p.status == "predicted" and p.quantity != "adhesion_trend_with_rh"]
    ax.plot([p.measured for p in nominal], [p.median for p in nominal], "x", color="tab:red", label="nominal constants")
    lo, hi = min(xs) / 3, max(xs) * 3
    ax.plot([lo, hi], [lo, hi], "-", color="tab:blue", lw=0.8, label="predicted = measured")
    ax.errorbar([], [], yerr=[], fmt="o", color="0.6", label="prior band (90 %)")
    ax.errorbar([], [], yerr=[], fmt="o", color="k", label="posterior band (90 %)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("measured (COF [-], adhesion energy [J/m²])")
    ax.set_ylabel("predicted median")
    ax.legend(fontsize=8)
    ax.set_title("memstribo against published MEMS measurements")
    fig.tight_layout()
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110, metadata={"Software": None})
    plt.close(fig)


def write(doc_path="docs/experiments.md", calibrated_path=None, settings=None, results=None):
    """Write the page, its figure (docs/figures/experiments.png) and the calibrated parameter set."""
    res = run_all(settings) if results is None else results
    doc = Path(doc_path)
    figure(res, doc.parent / "figures" / "experiments.png")
    doc.write_text(markdown(res), encoding="utf-8")
    if calibrated_path is not None:
        Path(calibrated_path).write_text(res["calibrated_toml"], encoding="utf-8")
    return res
