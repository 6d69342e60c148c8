"""The roughness a laboratory row states or assumes (shared by :mod:`memstribo.laboratory.predict` and the cases)."""

from __future__ import annotations

__all__ = ["SIDEWALL_ROUGHNESS", "stated_roughness"]

#: the sidewall roughness when the source gives none: AFM of a polysilicon MEMS sidewall (van Spengen 2010)
SIDEWALL_ROUGHNESS = {"rq": 10.3e-9, "correlation_length": 83e-9,
                      "reason": "not in the cited record; polysilicon sidewall AFM, Rq 10.3 nm, exponential "
                                "correlation length 83 nm (van Spengen et al. 2010, doi:10.3762/bjnano.1.20)"}


def stated_roughness(row):
    """(rq, correlation_length, note) of the row's surfaces, or None for the parameter set's default."""
    for key in ("roughness", "roughness_assumed"):
        value = row.condition(key)
        if isinstance(value, dict) and "rq" in value:
            note = "stated" if key == "roughness" else f"assumed: {value.get('reason', '')}"
            return float(value["rq"]), float(value["correlation_length"]), note
    if row.condition("geometry") == "sidewall":
        r = SIDEWALL_ROUGHNESS
        return r["rq"], r["correlation_length"], "assumed: " + r["reason"]
    return None
