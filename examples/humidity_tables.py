"""The humid-air tables of docs/humidity.md that are not a CLI sweep (issue #36): prints them, writes nothing.

Run: ``python examples/humidity_tables.py`` (about a minute on one core).

1. A rough microbeam's adhesion energy Gamma(RH) (the laboratory's DelRio row: two surfaces Rq 3 nm, correlation
   length 100 nm, silicon_oxide_air), oxide and hydrogen termination, water and pentanol, with the threshold RH.
2. The laboratory's flat case (Srinivasan et al. 1998, bare oxide, 17 kPa): the menisci's pressure and the static
   COF against RH.
"""

from __future__ import annotations

import copy

from memstribo.laboratory import data, predict
from memstribo.parameters import get_parameter_values
from memstribo.physics.rough_capillary import capillary_threshold_humidity

HUMIDITIES = (0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.95)


def microbeam():
    params = get_parameter_values("silicon_oxide_air")
    gaps = predict._beam_gap(3e-9, 100e-9, 20260528)
    cases = (("water, oxide", params), ("water, hydrogen", params.updated({"surface_termination": "hydrogen"})),
             ("pentanol, oxide", params.updated({"vapour": "pentanol"})))
    print("Microbeam adhesion energy Gamma [mJ/m^2] (Rq 3 nm each, 100 nm, 5.12 um map, silicon_oxide_air)")
    print("| RH (p/p_sat) | " + " | ".join(label for label, _ in cases) + " |")
    print("|---" * (len(cases) + 1) + "|")
    for rh in HUMIDITIES:
        values = [predict.beam_work_of_separation(gaps, p, rh)[0] * 1e3 for _, p in cases]
        print(f"| {rh:g} | " + " | ".join(f"{v:.4g}" for v in values) + " |")
    threshold = capillary_threshold_humidity(gaps, params["hamaker_constant"], params["cutoff_distance"],
                                             params["water_contact_angle"])
    print(f"threshold RH (Gamma twice its dry value), water on the oxide: {threshold:.3f}")


def flat():
    row = next(r for r in data.load_measurements() if r.id == "srinivasan1998_static_oxide")
    params = get_parameter_values("silicon_oxide_air")
    print("\nFlat case (srinivasan1998_static_oxide, 17 kPa, realisation 0): menisci's pressure and static COF")
    print("| RH | menisci [kPa] | static COF |")
    print("|---|---|---|")
    rq, corr = params["roughness_rq"], 2**0.5 * params["roughness_rq"] / params["roughness_rms_slope"]
    for rh in (0.0, 0.3, 0.5, 0.7, 0.9, 0.95):
        case = copy.deepcopy(row)
        case.conditions["relative_humidity"] = rh
        pressure = predict._flat_capillary_pressure(case, params, rq, corr, 20260528)
        cof = predict.row_values(case, realisations=1)[0][0, 0]
        print(f"| {rh:g} | {pressure / 1e3:.4g} | {cof:.4g} |")


if __name__ == "__main__":
    microbeam()
    flat()
