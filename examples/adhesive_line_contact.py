"""Adhesive line contact of the Si/Si gear teeth: the Maugis-Dugdale BEM against JKR and Hertz.

The thesis's teeth (E* = 85 GPa, R_ef = 10 um, w = A/(12 pi D0^2) = 0.445 J/m^2, sigma0 and h0
from ``memstribo constants``: Maugis parameter 3.55) as a smooth cylinder on a flat:

* left: load per unit length against contact half-width, from the solver (load control at
  positive loads, the approach-controlled unloading curve of ``line_contact_pull_off`` below),
  with Hertz, JKR and the Maugis-Dugdale cylinder (Baney & Hui 1997) closed forms;
* right: the net pressure at zero load (compressive in the contact, -sigma0 in the cohesive
  zone) against the Hertz pressure at the same contact width.

Writes ``examples/output/adhesive_line_contact/adhesive_line_contact.png`` (the documentation's copy in
docs/figures/ with ``--out docs/figures``). Run:  python examples/adhesive_line_contact.py [--out FOLDER]
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from memstribo.physics.adhesion import nanoscale_constants  # noqa: E402
from memstribo.physics.adhesive_contact import line_contact_pull_off  # noqa: E402
from memstribo.physics.contact import solve_line_contact  # noqa: E402
from memstribo.parameters import get_parameter_values  # noqa: E402
from memstribo.physics.closed_form import (hertz_line_pressure, jkr_line_load, jkr_line_pull_off_load,  # noqa: E402
                                 maugis_dugdale_line_load, maugis_dugdale_line_pull_off, maugis_line_parameter)

OUTPUT = Path(__file__).resolve().parent / "output" / "adhesive_line_contact" / "adhesive_line_contact.png"


def main(output=OUTPUT, points=2048):
    constants = nanoscale_constants(get_parameter_values())
    modulus, w = constants.contact_modulus, constants.work_of_adhesion
    sigma0, h0 = constants.maugis_stress, constants.maugis_range
    radius = 10e-6
    lam = float(maugis_line_parameter(radius, modulus, w, sigma0))

    # unloading from zero load to separation (approach control) ...
    pull = line_contact_pull_off(radius, modulus, w, sigma0, points=points)
    length, dx = pull.length, pull.dx
    x = (np.arange(points) - 0.5 * (points - 1)) * dx
    separation = x**2 / (2 * radius)
    # ... and loading to positive loads (load control, warm-started)
    loads = np.linspace(10.0, 100.0, 7)
    widths, previous = [], None
    for load in loads:
        sol = solve_line_contact(separation, dx, modulus, load=load, cohesive_stress=sigma0, cohesive_range=h0,
                                 initial_pressure=previous)
        widths.append(sol.contact_length / 2)
        previous = sol.pressure
    zero = solve_line_contact(separation, dx, modulus, load=0.0, cohesive_stress=sigma0, cohesive_range=h0)

    a = np.linspace(5e-9, 260e-9, 120)
    hertz = np.pi * modulus * a**2 / (4 * radius)
    jkr = jkr_line_load(a, radius, modulus, w)
    md = maugis_dugdale_line_load(a, radius, modulus, w, sigma0)[0]

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
    left.plot(a * 1e9, hertz, "k:", label="Hertz (w = 0)")
    left.plot(a * 1e9, jkr, "C0--", label="JKR line contact")
    left.plot(a * 1e9, md, "C1-", label=f"Maugis-Dugdale cylinder, $\\lambda$ = {lam:.2f}")
    contact = pull.curve.half_width > 0
    left.plot(pull.curve.half_width[contact] * 1e9, pull.curve.load[contact], "C3o", ms=3.5,
              label="BEM, approach-controlled unloading")
    left.plot(np.array(widths) * 1e9, loads, "C3s", ms=4, mfc="none", label="BEM, load control")
    left.axhline(-pull.pull_off_line_load, color="C3", lw=0.6)
    jkr_po = float(jkr_line_pull_off_load(radius, modulus, w))
    md_po = maugis_dugdale_line_pull_off(radius, modulus, w, sigma0)[0]
    left.annotate(f"pull-off: BEM {pull.pull_off_line_load:.1f}, M-D {-md_po:.1f}, JKR {-jkr_po:.1f} N/m",
                  (100, -pull.pull_off_line_load - 14), fontsize=8)
    left.set_xlabel("contact half-width a [nm]")
    left.set_ylabel("load per unit length P [N/m]")
    left.set_ylim(-120, 120)
    left.set_xlim(0, 260)
    left.grid(alpha=0.3)
    left.legend(fontsize=8, loc="upper left")
    left.set_title(f"Si/Si tooth: E* = {modulus / 1e9:.0f} GPa, R = 10 um, w = {w:.3f} J/m$^2$", fontsize=9)

    a0 = zero.contact_length / 2
    right.plot(x * 1e9, zero.pressure / 1e9, "C3-", lw=1.2, label="BEM, net pressure at P = 0")
    right.plot(x * 1e9, hertz_line_pressure(x, np.pi * modulus * a0**2 / (4 * radius), radius, modulus) / 1e9,
               "k:", label="Hertz pressure, same half-width")
    right.axhline(-sigma0 / 1e9, color="C1", lw=0.6, ls="--", label=f"$-\\sigma_0$ = {-sigma0 / 1e9:.2f} GPa")
    right.set_xlim(-1.3 * a0 * 1e9, 1.3 * a0 * 1e9)
    right.set_xlabel("x [nm]")
    right.set_ylabel("pressure [GPa]")
    right.grid(alpha=0.3)
    right.legend(fontsize=8, loc="lower center")
    right.set_title(f"zero load: a = {a0 * 1e9:.1f} nm, cohesive zone {zero.cohesive.sum() * dx / 2 * 1e9:.1f} nm "
                    f"each side, h0 = {h0 * 1e9:.3f} nm", fontsize=9)
    fig.tight_layout()
    output = Path(output)
    output.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(output, dpi=130)
    print(f"wrote {output}; lambda = {lam:.3f}, pull-off {pull.pull_off_line_load:.2f} N/m "
          f"(Maugis-Dugdale {-md_po:.2f}, JKR {-jkr_po:.2f}), half-width at zero load {a0 * 1e9:.1f} nm")


if __name__ == "__main__":
    import sys

    if len(sys.argv) == 3 and sys.argv[1] == "--out":  # a folder, e.g. docs/figures for the documentation
        main(Path(sys.argv[2]) / OUTPUT.name)
    else:
        main()
