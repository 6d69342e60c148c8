"""Validation rows of the adhesive (Maugis-Dugdale) line contact against closed forms (MODEL §7c)."""

from __future__ import annotations

from memstribo.validation.contact import smooth_cylinder
from memstribo.validation.rows import ValidationRow, compare

TOPIC = "adhesive contact"
SILICON = ["--modulus", "85 GPa", "--cohesive-stress", "1.78 GPa", "--cohesive-range", "0.25 nm"]
PULL_OFF_ARGS = ["contact", "--flat", "--radius", "10 um", "--points", "1024", "--adhesion", "--pull-off", *SILICON]
JKR_ARGS = ["contact", "--flat", "--radius", "100 um", "--points", "2048", "--length", "3.5 um", "--load", "-100 N/m",
            "--adhesion", *SILICON]
HERTZ_ARGS = ["contact", "--flat", "--radius", "20 um", "--load", "1 N/m", "--modulus", "100 GPa", "--points", "2048",
              "--length", "127.7 nm", "--adhesion", "--cohesive-stress", "1 kPa", "--cohesive-range", "1 pm"]
RIGID_ARGS = ["contact", "--flat", "--radius", "10 um", "--points", "1024", "--adhesion", "--pull-off",
              "--modulus", "85 GPa", "--cohesive-stress", "50 MPa", "--cohesive-range", "8.9 nm"]


def _rounded(value, digits):
    """The cohesive zone settles to ~1e-4: shown to 2-3 significant digits, the same on every machine."""
    return float(f"{value:.{digits}g}")


#: The pull-off state differs by one element between machines (the same code and packages; the round-off
#: differs with the processor): on an AMD EPYC with AVX-512 (2026-11-25) it is 96.233 N/m at a half-width of
#: 66.2 nm; on the machine that generated the table before (which CI reproduced) 96.25-96.35 N/m and
#: 64.5-65.5 nm. The table shows the load to 2 significant digits and the half-width to the nearest 5 nm,
#: so that it is the same on both.
_PULL_OFF_NOTE = ("shown to 2 significant digits: the pull-off state differs by one element (0.85 nm) between "
                  "machines, 96.23 or 96.25-96.35 N/m")


def _nearest(value, step):
    """``value`` rounded to a multiple of ``step``."""
    return float(round(value / step) * step)


def _pull_off(radius, modulus, sigma0, h0, points):
    """What ``memstribo contact --flat --adhesion --pull-off ...`` prints, through the library."""
    from memstribo.physics.adhesive_contact import line_contact_pull_off
    from memstribo.physics.closed_form import maugis_line_parameter

    w = sigma0 * h0
    result = line_contact_pull_off(radius, modulus, w, sigma0, points=points, length=None, tolerance=1e-8,
                                   periodic=False)
    return {"pull_off_line_load": result.pull_off_line_load, "pull_off_half_width": result.pull_off_half_width,
            "maugis_parameter": float(maugis_line_parameter(radius, modulus, w, sigma0))}


def _adhesive(radius, length, points, modulus, load, sigma0, h0):
    """What ``memstribo contact --flat --adhesion --load ...`` prints, through the library."""
    from memstribo.physics.closed_form import maugis_line_parameter

    out = smooth_cylinder(radius, length, points, modulus, load, cohesive_stress=sigma0, cohesive_range=h0)
    out["maugis_parameter"] = float(maugis_line_parameter(radius, modulus, sigma0 * h0, sigma0))
    return out


def _command(argv):
    return "memstribo " + " ".join(f"'{a}'" if " " in a else a for a in argv) + " --json"


def rows() -> list[ValidationRow]:
    from scipy.optimize import brentq

    from memstribo.physics.closed_form import (dugdale_rigid_line_pull_off, hertz_line_half_width, jkr_line_load,
                             jkr_line_pull_off_load, maugis_dugdale_line_pull_off)

    w = 1.78e9 * 0.25e-9
    out = _pull_off(10e-6, 85e9, 1.78e9, 0.25e-9, 1024)
    reference, width = maugis_dugdale_line_pull_off(10e-6, 85e9, w, 1.78e9)
    rows_ = [
        compare(TOPIC, f"pull-off line load, Si/Si cylinder R = 10 um (lambda = {out['maugis_parameter']:.2f})",
                "Maugis-Dugdale cylinder (Baney & Hui 1997), docs/contact.md", -reference,
                _rounded(out["pull_off_line_load"], 2), "N/m", rtol=5e-3, command=_command(PULL_OFF_ARGS),
                note=_PULL_OFF_NOTE),
        compare(TOPIC, "pull-off half-width, same", "Maugis-Dugdale cylinder (Baney & Hui 1997)", width * 1e9,
                _nearest(out["pull_off_half_width"] * 1e9, 5.0), "nm", rtol=5e-2, command=_command(PULL_OFF_ARGS),
                note="to the nearest 5 nm: the contact length counts whole elements (0.85 nm), and the pull-off "
                     "state differs by one element between machines (66.2 or 64.5-65.5 nm)"),
        compare(TOPIC, "pull-off line load, same", "JKR line contact (3/4)(4 pi E* w^2 R)^(1/3)",
                -float(jkr_line_pull_off_load(10e-6, 85e9, w)), _rounded(out["pull_off_line_load"], 2), "N/m",
                rtol=1e-2, command=_command(PULL_OFF_ARGS), note=_PULL_OFF_NOTE),
    ]
    out = _adhesive(100e-6, 3.5e-6, 2048, 85e9, -100.0, 1.78e9, 0.25e-9)
    a_jkr = brentq(lambda a: float(jkr_line_load(a, 100e-6, 85e9, w)) + 100.0, 300e-9, 2e-6)
    rows_.append(compare(TOPIC, f"half-width at -100 N/m, R = 100 um (lambda = {out['maugis_parameter']:.2f})",
                         "JKR line contact P = pi E* a^2/(4R) - (2 pi E* w a)^(1/2)", a_jkr * 1e9,
                         _rounded(out["contact_length"] / 2 * 1e9, 3), "nm", rtol=2e-2, command=_command(JKR_ARGS)))
    rows_.append(compare(TOPIC, "load balance dx*sum(p) with the cohesive zone", "imposed load -100 N/m", -100.0,
                         out["load"], "N/m", rtol=1e-8, command=_command(JKR_ARGS)))
    out = _adhesive(20e-6, 127.7e-9, 2048, 100e9, 1.0, 1e3, 1e-12)
    rows_.append(compare(TOPIC, "contact length 2a at vanishing adhesion (sigma0 = 1 kPa, h0 = 1 pm)",
                         "Hertz line contact, Johnson (4.43)",
                         2 * float(hertz_line_half_width(1.0, 20e-6, 100e9)) * 1e9, out["contact_length"] * 1e9,
                         "nm", rtol=1e-2, command=_command(HERTZ_ARGS)))
    out = _pull_off(10e-6, 85e9, 50e6, 8.9e-9, 1024)
    rows_.append(compare(TOPIC, f"pull-off line load, small Maugis parameter (lambda = {out['maugis_parameter']:.2f})",
                         "rigid Dugdale limit 2 sigma0 (2 R h0)^(1/2)",
                         float(dugdale_rigid_line_pull_off(10e-6, 50e6 * 8.9e-9, 50e6)),
                         _rounded(out["pull_off_line_load"], 3),
                         "N/m", rtol=3e-2, command=_command(RIGID_ARGS),
                         note="the 2D small-lambda limit depends on the law's range; no 'DMT' 2 w R per unit length"))
    return rows_
