"""Validation rows of the rough line-contact solver against closed forms (MODEL §7)."""

from __future__ import annotations

from memstribo.validation.rows import ValidationRow, compare

HERTZ_ARGS = ["contact", "--flat", "--radius", "20 um", "--load", "1 N/m", "--modulus", "100 GPa",
              "--points", "2048", "--length", "127.7 nm"]
DEFAULT_ARGS = ["contact", "--flat", "--points", "4000", "--length", "400 nm"]


def smooth_cylinder(radius, length, points, modulus, load, **keywords):
    """What ``memstribo contact --flat ...`` solves and prints, through the library (never the command line)."""
    from memstribo.physics.contact import cylinder_on_flat, solve_line_contact

    separation, dx = cylinder_on_flat(radius, length, points)
    solution = solve_line_contact(separation, dx, modulus, load=load, tolerance=1e-8, **keywords)
    return {"contact_length": solution.contact_length, "max_pressure": solution.max_pressure,
            "approach": solution.approach, "load": solution.load, "solution": solution}


def rows() -> list[ValidationRow]:
    from memstribo.physics.gear import pitch_point_line_contact
    from memstribo.parameters import get_parameter_values
    from memstribo.physics.closed_form import hertz_line_approach, hertz_line_half_width, hertz_line_peak_pressure

    R, E, W = 20e-6, 100e9, 1.0
    command = "memstribo " + " ".join(f"'{a}'" if " " in a else a for a in HERTZ_ARGS) + " --json"
    out = smooth_cylinder(R, 127.7e-9, 2048, E, W)
    a = float(hertz_line_half_width(W, R, E))
    rows_ = [
        compare("contact", "contact length 2a, smooth cylinder (2048 elements, 512 across 2a)",
                "Hertz line contact, Johnson (4.43)", 2 * a * 1e9, out["contact_length"] * 1e9, "nm",
                rtol=1e-2, command=command),
        compare("contact", "peak pressure, smooth cylinder", "Hertz line contact, Johnson (4.44)",
                float(hertz_line_peak_pressure(W, R, E)) / 1e6, out["max_pressure"] / 1e6, "MPa", rtol=1e-2,
                command=command),
        compare("contact", "approach, smooth cylinder (datum at the domain length 127.7 nm)",
                "closed form (w/(pi E*))(1 + 2 ln(2L/a)), docs/contact.md",
                float(hertz_line_approach(W, R, E, 127.7e-9)) * 1e12, out["approach"] * 1e12, "pm", rtol=1e-3,
                command=command),
        compare("contact", "load balance dx*sum(p)", "imposed load 1 N/m", W, out["load"], "N/m", rtol=1e-8,
                command=command),
    ]
    params = get_parameter_values()
    modulus, radius, load = pitch_point_line_contact(params)
    out = smooth_cylinder(radius, 400e-9, 4000, modulus, load)
    rows_.append(compare(
        "contact", "contact length 2a, thesis gear case at the pitch point (smooth, 25 uN)",
        "Hertz (4-24) with E*, R_ef, w = F/b of the parameter set", 2 * float(hertz_line_half_width(load, radius, modulus))
        * 1e9, out["contact_length"] * 1e9, "nm", rtol=1e-2, command="memstribo contact --flat --points 4000 --length '400 nm' --json",
        note="the thesis prints 2a = 117.7 nm (a = 58.9 nm), which does not follow from its inputs (MODEL §6)"))
    return rows_
