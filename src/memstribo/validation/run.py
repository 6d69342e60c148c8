"""Validation rows of the main job's verdict: stiction of the coated pair as its coating wears (thesis 5.5.3).

The values are those ``memstribo run --json`` prints (``coated_stiction``, ``wear_at_stiction``):
the same library calls (:func:`memstribo.simulations.coating_wear.wear_sweep` over the run's default worn
fractions, :func:`memstribo.physics.coating.critical_wear`).
"""

from __future__ import annotations

from memstribo.validation.rows import ValidationRow, compare

COMMAND = "memstribo run --json"


def rows() -> list[ValidationRow]:
    from memstribo.parameters import RUN_DEFAULT_COATING, RUN_DEFAULT_WEAR
    from memstribo.physics.coating import critical_wear
    from memstribo.simulations.coating_wear import wear_sweep
    from memstribo.parameters import get_parameter_values

    # the run's default coating and wear states ([run] coating, wear)
    sweep = wear_sweep(get_parameter_values(), RUN_DEFAULT_COATING, list(RUN_DEFAULT_WEAR))
    margin = sweep["stiction_margin"].values
    coated_free = bool(margin[0] > 0)
    out = [ValidationRow(
        "run", "intact OTS coating (Omega = 0): smallest stiction margin F_t - F_f", "thesis 5.4-5.5 (the coating "
        "removes stiction)", None, float(margin[0]) * 1e6, "uN", "margin > 0", coated_free, COMMAND,
        "the intact coating removes stiction (docs/coating.md)")]
    critical = critical_wear(sweep)
    if critical is None:
        out.append(ValidationRow("run", "worn fraction Omega at which stiction returns", "thesis 5.5.3 (about 80 %)",
                                 80.0, None, "%", "abs 10", False, COMMAND,
                                 "differs: no worn fraction of the sweep reaches stiction", expected="differs"))
    else:
        how = "the margin F_t - F_f of the sweep Omega = 0, 0.2, ..., 1 interpolated linearly to 0"
        row = compare("run", "worn fraction Omega at which stiction returns", "thesis 5.5.3 (F_f close to F_t "
                      "at Omega = 80 %)", 80.0, critical * 100.0, "%", atol=10.0, command=COMMAND, note=how)
        out.append(row)
    return out
