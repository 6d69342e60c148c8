"""Validation rows of the power-law asperity, the nanoblock load sharing and the coating damage.

Thesis Tables 5-1 to 5-4 (section 5.5.2) and closed forms (Hertz for d = 2).
"""

from __future__ import annotations

import numpy as np

from memstribo.parameters.thesis_tables import TABLE_5_1, TABLE_5_2, TABLE_5_3, TABLE_5_4
from memstribo.validation.rows import ValidationRow, compare

TABLE_5_2_NM = TABLE_5_2 * 1e9
POSITIONS = ("corner", "side", "central")


def rows() -> list[ValidationRow]:
    from memstribo.materials.pair import contact_modulus_of
    from memstribo.physics.asperity import nanoblock_load_sharing, power_law_contact
    from memstribo.physics.damage import nanoblock_damage
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    modulus = contact_modulus_of(params)
    d, b = params["asperity_degree"], params["asperity_shape_coefficient"]
    out = []
    # --- Hertz limit -----------------------------------------------------------------------------------
    radius, load = 131.3e-9, 0.8275e-6
    hertz = (3 * load * radius / (4 * modulus)) ** (1 / 3)
    c2 = power_law_contact(load, 2, 1 / (2 * radius), modulus)
    out.append(compare("asperity", "d = 2 contact radius, R = 131.3 nm, 0.8275 uN", "Hertz closed form",
                       hertz * 1e9, c2.contact_radius * 1e9, "nm", rtol=1e-12,
                       command="memstribo asperity --load '0.8275 uN' --degree 2 --shape-coefficient 3.80807e6 --json",
                       note="the thesis's text derives 8.95 nm from this Hertz radius; it gives 9.86 nm, while its "
                            "Table 5-2 follows the d = 4 power law (MODEL §9)"))
    # --- Table 5-2 -----------------------------------------------------------------------------------
    radii = power_law_contact(TABLE_5_1[:, 1:], d, b, modulus).contact_radius * 1e9
    for i in (0, 5):
        for j, position in enumerate(POSITIONS):
            out.append(compare(
                "asperity", f"contact radius, {position} asperity, nanoblock load {TABLE_5_1[i, 0] * 1e6:.4g} uN",
                "thesis Table 5-2", TABLE_5_2_NM[i, j], float(radii[i, j]), "nm", rtol=3e-3,
                command=f"memstribo asperity --load '{TABLE_5_1[i, j + 1] * 1e6:.4g} uN' --json",
                note="d = 4, B_4 = 4e22 m^-3, E* = 84.996 GPa, at the thesis's Table 5-1 asperity load; ours are "
                     "0.1-0.2 % smaller than printed"))
    # --- Table 5-1 shares ------------------------------------------------------------------------------
    sharing = nanoblock_load_sharing(TABLE_5_1[:, 0], params["atomic_per_side"], params["atomic_pitch"], d, b,
                                     modulus)
    for j, position in enumerate(POSITIONS):
        out.append(compare(
            "asperity", f"share of the {position} asperity at 7.0165 uN", "thesis Table 5-1",
            100 * TABLE_5_1[-1, j + 1] / TABLE_5_1[-1, 0], 100 * float(sharing.share_of(position)[-1]), "%",
            atol=0.1, command="memstribo asperity --load '7.0165 uN' --nanoblock --json",
            note="rigid adhesive block, power-law asperities at 58.4 nm pitch, Boussinesq cross-influence"))
        printed = 100 * TABLE_5_1[0, j + 1] / TABLE_5_1[0, 0]
        # the side share happens to stay within 0.1 % of the print; the corner's falls and the central's rises
        band = {"corner": (printed - 0.4, printed - 0.15), "side": None, "central": (printed + 0.4, printed + 0.8)}
        out.append(compare(
            "asperity", f"share of the {position} asperity at 0.8166 uN", "thesis Table 5-1",
            printed, 100 * float(sharing.share_of(position)[0]), "%",
            atol=0.1, command="memstribo asperity --load '0.8166 uN' --nanoblock --json", differs=band[position],
            note="the thesis prints the same shares at every load (a linear influence model); with the non-linear "
                 "power-law compliance the shares even out at small loads" + (
                     "; this one stays within the tolerance" if band[position] is None else
                     ": differs on purpose")))
    # --- Tables 5-3 and 5-4 ----------------------------------------------------------------------------
    # Tolerances from the printed digits: Table 5-3 prints 3 significant digits (half a unit of the last: 0.2 %,
    # written as rel 0.005), Table 5-4 six; the locations are compared at 0.15 nm, the x grid of the damage
    # integral near the contact edge (docs/damage.md); the text's 9 % and 18.65 % at half their last digit.
    # memstribo's maxima are 3-5 % (m = 1) and 19-23 % (m = 2) above the print: known differences, with their
    # bands, not tolerances widened to reach agreement (docs/damage.md: mu and the peak sequence are inferred).
    high = {1: (1.02, 1.06), 2: (1.15, 1.27)}
    for m, table, unit in ((1, TABLE_5_3, "Pa"), (2, TABLE_5_4, "Pa^2")):
        result = nanoblock_damage(TABLE_5_1[:, 0], params.updated({"damage_exponent": m}))
        command = f"memstribo damage --loads table5-1 --set damage_exponent={m} --json"
        for position in POSITIONS:
            value, location = table[position]
            out.append(compare(
                "damage", f"max omega/c1 per cycle, {position} asperity, m = {m}",
                f"thesis Table 5-{2 + m}", value, result.maximum[position], unit, rtol=0.005,
                command=command, differs=(high[m][0] * value, high[m][1] * value),
                note="differs: mu = 0.1 (inferred) and the six Table 5-1 loads repeated to k = 48 peaks (inferred) "
                     + ("give maxima 3-5 % above the thesis" if m == 1 else
                        "give maxima 19-23 % above the thesis (docs/damage.md)")))
            out.append(compare(
                "damage", f"location of the maximum, {position} asperity, m = {m}", f"thesis Table 5-{2 + m}",
                location * 1e9, result.location[position] * 1e9, "nm", atol=0.15, command=command,
                differs=None if m == 1 else (location * 1e9 - 1.0, location * 1e9 - 0.6),
                note="" if m == 1 else "differs: the m = 2 maximum sits 0.6-1.0 nm further out (at the edge of the "
                                       "largest contact) than printed"))
        printed, digits = {1: (9.0, 0.5), 2: (18.65, 0.005)}[m]
        out.append(compare(
            "damage", f"corner life shorter than central, m = {m}", "thesis 5.5.2 text", printed,
            100 * (1 - result.life_ratio_corner_to_central), "%", atol=digits, command=command,
            differs=(printed, printed + 1.6),
            note="1 - life_ratio_corner_to_central; differs: follows from the maxima above (corner and central "
                 "not equally high above the print), 0.5-1.2 points more than printed"))
    return out
