"""The report section "What the verdict hangs on" (MODEL 7d): an HTML fragment from a study's result."""

from __future__ import annotations

import html

__all__ = ["report_section"]


def _pct(x) -> str:
    return "–" if x is None else f"{100 * float(x):.3g} %"


def report_section(result, figures=None) -> str:
    """HTML fragment: probability with its interval, the sensitivity ranking, critical values, the designer's sentence.

    Parameters
    ----------
    result : dict
        Of :func:`memstribo.uncertainty.study.uncertainty_study`.
    figures : list of str, optional
        Relative paths of the study's figures (:func:`memstribo.uncertainty.figures.write_figures`,
        the PNGs) to show in the section.

    Returns
    -------
    str
        ``<section>`` ... ``</section>`` (escaped text; no script).
    """
    e = html.escape
    parts = ['<section class="uncertainty">', "<h2>What the verdict hangs on</h2>"]
    parts.append(
        f"<p><b>P(stiction) = {e(result['stiction_probability_text'])}</b> over {result['realisations']} roughness "
        f"realisations &times; {result['constant_sets']} sets of the uncertain constants drawn from their priors; "
        f"at the nominal constants: {e(result['stiction_probability_nominal_text'])}.</p>")
    if result.get("startup_stiction_probability_text"):  # the start-up verdict over the same samples (MODEL 7f)
        parts.append(f"<p><b>P(start-up stiction) = {e(result['startup_stiction_probability_text'])}</b> (at the "
                     f"nominal constants: {e(result['startup_stiction_probability_nominal_text'])}).</p>")
    q = result.get("margin_quantiles")
    if q:
        parts.append(f"<p>Stiction margin 5 / 50 / 95 %: {q['p05'] * 1e3:+.3g} / {q['p50'] * 1e3:+.3g} / "
                     f"{q['p95'] * 1e3:+.3g} mN (negative: stiction).</p>")
    if result.get("designer_sentence"):
        parts.append(f'<p class="designer"><b>{e(result["designer_sentence"])}</b></p>')
    if result.get("decision_sentence"):  # what can flip the verdict, and whether the probability is the prior's
        parts.append(f'<p class="decision">{e(result["decision_sentence"])}</p>')
    sensitivity = result.get("sensitivity") or {}
    if sensitivity:
        parts.append("<table><thead><tr><th>constant</th><th>total index (margin)</th><th>first-order</th>"
                     "<th>total index (mean COF)</th><th>critical value</th><th>note</th></tr></thead><tbody>")
        for name, s in sensitivity.items():
            critical = "" if s.get("critical_value") is None else f"{s['critical_value']:.4g}"
            parts.append(
                f"<tr><td>{e(name)}</td><td>{s['total']:.2f} [{s['total_ci'][0]:.2f}, {s['total_ci'][1]:.2f}]</td>"
                f"<td>{s['first']:.2f}</td><td>{s['cof_total']:.2f}</td><td>{e(critical)}</td>"
                f"<td>{e(s.get('note') or '')}</td></tr>")
        parts.append("</tbody></table>")
        base = (result.get("sobol_design") or {}).get("base_samples")
        parts.append("<p>Sobol' indices (Saltelli's design, SALib"
                     + (f", {int(base)} base samples" if base else "")
                     + ") with 95 % bootstrap intervals, clipped to [0, 1]; the critical value "
                     "is where the median margin over the realisations crosses zero with the other constants at "
                     "nominal.</p>")
    for warning in result.get("warnings") or []:
        parts.append(f'<p class="warning">{e(warning)}.</p>')
    for path in figures or []:
        parts.append(f'<img src="{e(str(path))}" alt="{e(str(path))}" style="max-width:100%">')
    parts.append("</section>")
    return "\n".join(parts)
