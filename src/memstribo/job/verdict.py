"""The verdict of a run from its stages' summaries, and the uncertainty stage's summary (MODEL 7b, 7d).

Kept apart from :mod:`memstribo.job.chain` (which runs the stages) so that the report and the tests read the
verdict's rules in one place.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

__all__ = ["verdict", "uncertainty_summary"]


def verdict(summaries: Mapping[str, Any]) -> dict[str, Any]:
    """Stiction of the bare pair, and of the coated pair over its life, from the stage summaries.

    Returns
    -------
    dict
        ``tangential_force`` F_t [N]; ``load_case``; ``bare_resisting_force_max`` (largest R(c), the friction
        of all pairs in mesh) [N]; ``bare_stiction`` (R > F_t somewhere on the path of contact);
        ``bare_stiction_margin`` = F_t - max R [N]; ``bare_cof_mean``; ``bare_mesh_efficiency``; ``bare_warnings``;
        with an ensemble ``bare_stiction_probability`` and the 5/50/95 % quantiles of the margin and the mean
        COF; ``bare_step_converged`` (step and grid checks, 7d) and the changes (``bare_step_/grid_change_*``);
        the same with ``coated_`` for the intact coating; ``wear_at_stiction`` (the worn fraction Omega at
        which F_f reaches F_t, interpolated in the wear sweep, or None); ``cycles_to_stiction``,
        ``cycles_to_failure`` [meshing cycles] (None while the damage constant c1 is unknown) and
        ``damage_per_cycle_over_c1`` [Pa^m] from the damage stage. Keys whose stage did not run are absent.
    """
    out: dict[str, Any] = {}
    gear = summaries.get("gear")
    if gear:
        out["tangential_force"] = gear["tangential_force"]
    for label, stage in (("bare", "mesh"), ("coated", "coated")):
        summary = summaries.get(stage)
        if summary:
            out["load_case"] = summary.get("load_case")
            out[f"{label}_resisting_force_max"] = summary["resisting_force_max"]
            out[f"{label}_stiction_margin"] = summary["stiction_margin"]
            out[f"{label}_stiction"] = bool(summary["stiction_margin"] < 0.0)
            out[f"{label}_cof_mean"] = summary["cof_mean"]
            out[f"{label}_mesh_efficiency"] = summary.get("mesh_efficiency")
            out[f"{label}_warnings"] = list(summary.get("warnings", []))
            if "roughness_rows" in summary:
                out[f"{label}_roughness_rows"] = summary["roughness_rows"]
            for key in ("step_converged", "step_change_margin", "step_change_cof", "grid_change_margin", "realisations",
                        "stiction_probability", "stiction_probability_ci", "stiction_probability_text",
                        "stiction_margin_median", "stiction_margin_p05", "stiction_margin_p95",
                        "cof_mean_median", "cof_mean_p05", "cof_mean_p95",
                        # what the verdict hangs on (MODEL 7d): start-up, local limits, the hardness cap
                        "startup_margin", "startup_stiction", "static_cof_max", "stiction_mode",
                        "stiction_margin_capped", "startup_margin_capped", "stiction_mode_capped", "plastic_fraction",
                        "stiction_margin_uncapped", "startup_margin_uncapped", "startup_stiction_probability",
                        "startup_stiction_probability_text", "startup_margin_median", "startup_margin_p05",
                        "startup_margin_p95", "converged", "grid_converged", "verdict",
                        # the start-up torque balance (MODEL 7f)
                        "startup_load_torque_limit", "step_change_startup", "grid_change_startup"):
                if key in summary:
                    out[f"{label}_{key}"] = summary[key]
    geometry = summaries.get("geometry")
    if geometry and "used_downstream" in geometry:
        out["nanoblock_geometry"] = geometry["used_downstream"]
        if geometry["used_downstream"] != "parameters":
            used = geometry[geometry["used_downstream"]]
            out["nanoblock_geometry_values"] = {k: v for k, v in used.items() if k != "rules"}
    sweep = summaries.get("wear_sweep")
    if sweep:
        out["wear_at_stiction"] = sweep.get("critical_wear")
    damage = summaries.get("damage")
    if damage:
        for key in ("cycles_to_stiction", "cycles_to_failure", "damage_per_cycle_over_c1", "damage_exponent",
                    "life_ratio_corner_to_central"):
            if key in damage:
                out[key] = damage[key]
    return out


def _regional_drivers(result) -> list[dict]:
    """The constants whose regional index of the verdict is above its noise level (the run's ranking, issue 40)."""
    from memstribo.parameters.definitions import SPECS

    drivers = []
    dominant = result.get("dominant_entry") or {}
    for name, entry in (result.get("decision_sensitivity") or {}).items():
        if entry["index"] is None or entry.get("noise_level") is None or entry["index"] <= entry["noise_level"]:
            continue
        note = ""
        if name == result.get("dominant"):
            critical = dominant.get("critical_value")
            unit = SPECS[name].unit if name in SPECS else ""
            note = (f"critical value {critical:.3g} {unit}".rstrip() if critical is not None
                    else dominant.get("note", ""))
        drivers.append({"name": name, "effect": f"regional index of the verdict {entry['index']:.2f} (noise "
                                                f"{entry['noise_level']:.2f})", "note": note})
    if not drivers:  # a unanimous verdict: what moves the margin
        correlation = result.get("margin_correlation") or {}
        drivers = [{"name": name, "effect": f"rank correlation with the margin {c['rho']:+.2f} (p {c['p_value']:.2g})",
                    "note": dominant.get("note", "") if name == result.get("dominant") else ""}
                   for name, c in sorted(correlation.items(), key=lambda kv: -abs(kv[1]["rho"]))
                   if c["p_value"] < 0.05]
    return drivers


def uncertainty_summary(result) -> dict[str, Any]:
    """The uncertainty stage's summary: its numbers, and the texts of the report's box under the verdict."""
    from memstribo.parameters.definitions import SPECS

    q = result["margin_quantiles"]
    drivers = _regional_drivers(result) if result.get("sensitivity_method") == "regional" else []
    for name, entry in result["sensitivity"].items():
        if entry["total"] < 0.05:
            continue
        critical = entry.get("critical_value")
        unit = SPECS[name].unit if name in SPECS else ""
        drivers.append({"name": name, "effect": f"Sobol' total index of the margin {entry['total']:.2f}",
                        "note": (f"critical value {critical:.3g} {unit}".rstrip() if critical is not None
                                 else entry.get("note", ""))})
    return {
        "summary": (f"P(stiction) = {result['stiction_probability_text']} over {result['realisations']} roughness "
                    f"realisations x {result['constant_sets']} sets of the unmeasured constants drawn from their priors; "
                    f"at the nominal constants {result['stiction_probability_nominal_text']}. "
                    + (f"P(start-up stiction) = {result['startup_stiction_probability_text']} (the torque balance of "
                       "MODEL 7f). " if result.get("startup_stiction_probability_text") else "")
                    + result.get("designer_sentence", "")
                    + (" " + result["decision_sentence"] if result.get("decision_sentence") else "")),
        "interval": (f"stiction margin 5 / 50 / 95 %: {q['p05'] * 1e3:+.3g} / {q['p50'] * 1e3:+.3g} / "
                     f"{q['p95'] * 1e3:+.3g} mN (negative: stiction)"),
        "drivers": drivers,
        **{key: result[key] for key in ("stiction_probability", "stiction_probability_ci", "stiction_count", "samples",
                                        "stiction_probability_text",
                                        "stiction_probability_nominal", "stiction_probability_nominal_ci",
                                        "dominant", "designer_sentence", "solves", "rescalings", "elapsed")},
        "workers": result.get("workers", 1),
        **{key: result[key] for key in ("startup_stiction_probability", "startup_stiction_probability_ci",
                                        "startup_stiction_count", "startup_stiction_probability_text")
           if key in result},
    }
