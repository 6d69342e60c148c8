"""Condensable vapours and surface terminations as data (issue #36 items 4-5, MODEL 7g).

A vapour is its liquid's surface tension, molar volume, contact angle on each surface termination and adsorption
isotherm on it; a termination is the chemistry of the bare silicon surface: ``oxide`` (the native oxide's silanols,
hydrophilic) or ``hydrogen`` (HF-etched, Si-H, hydrophobic to water). The menisci of the meshing cycle, the
microbeam's adhesion energy and the laboratory's flat contacts take their constants from here
(:func:`vapour_state`). Water on the oxide is the parameter set's (its ``water_contact_angle``) and the published
isotherm of :func:`memstribo.physics.capillary.adsorbed_water_thickness`, so the defaults are today's numbers.

Sources, per entry of :data:`VAPOURS` (each value's own ``source``); what was not found is said so there and in
docs/humidity.md. Mixed vapours (water with pentanol) are refused: co-adsorption displaces the alcohol (measured: Tribol. Lett.
2014, doi:10.1007/s11249-014-0345-9), which the model does not describe.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError
from memstribo.physics import capillary
from memstribo.references import cites

__all__ = ["VAPOURS", "TERMINATIONS", "vapour_properties", "vapour_surface_tension", "vapour_contact_angle",
           "adsorbed_film_thickness", "liquid_film_thickness", "vapour_state"]

#: the surface terminations of bare silicon
TERMINATIONS = ("oxide", "hydrogen")

#: 1-pentanol: molar mass 88.148 g/mol over its liquid density 0.81219 g/cm^3 at 25 degC [m^3/mol]
_PENTANOL_MOLAR_VOLUME = 88.148e-3 / 812.19

VAPOURS = {
    "water": {
        "surface_tension": None,  # capillary.water_surface_tension(T): 0.072 N/m at 25 degC, IAPWS slope
        "molar_volume": capillary.WATER["molar_volume"],
        "contact_angle": {"oxide": None,  # the parameter set's water_contact_angle (30 deg: cleaned native oxide)
                          "hydrogen": math.radians(111.0)},
        # adsorbed film in molecular layers against p / p_sat, and the bound layers that do not flow into a meniscus
        "isotherm": {"oxide": capillary.WATER_ISOTHERM_SIO2, "hydrogen": ((0.0, 0.0), (0.9, 1.0))},
        "bound_layers": {"oxide": 3.0, "hydrogen": 0.0},
        "source": {
            "surface_tension": "IAPWS R1-76(2014), 0.072 N/m at 25 degC (Israelachvili 2011, Table 17.1)",
            "molar_volume": "18.07e-6 m^3/mol at 25 degC (Israelachvili 2011, Table 17.1)",
            "contact_angle": "oxide: the parameter set's water_contact_angle (10-40 deg, Maboudian and Howe 1997); "
                             "hydrogen: 111 +- 1 deg on freshly HF-etched Si-H (PMC2784167, Table 1; 14 treatments of "
                             "silicon span 5-96 deg, Wetting properties of silicon surfaces 2002: a hydrophobic Si-H)",
            "isotherm": "oxide: 3 ice-like layers by RH 0.3 (Asay and Kim 2005), 4.5 at 0.75 and 6.5 at 0.9 "
                        "(Verdaguer et al. 2007); hydrogen: 'less than a monolayer even at RH = 90%' on HF-etched "
                        "Si-H (Chen et al. 2018, J. Phys. Chem. C 122, 11385, ATR-IR): one layer at 0.9 as its upper "
                        "bound, linear from dry",
        },
    },
    "pentanol": {
        "surface_tension": 27.54e-3 - 0.0874e-3 * 25.0,  # 25.36 mN/m at 25 degC
        "molar_volume": _PENTANOL_MOLAR_VOLUME,  # 108.5e-6 m^3/mol
        "contact_angle": {"oxide": 0.0, "hydrogen": 0.0},
        "isotherm": {"oxide": ((0.0, 0.0), (0.5, 1.0)), "hydrogen": ((0.0, 0.0), (0.5, 1.0))},
        "bound_layers": {"oxide": 1.0, "hydrogen": 1.0},
        "source": {
            "surface_tension": "1-pentanol, gamma = 27.54 - 0.0874 t[degC] mN/m (Jasper 1972, The Surface Tension of "
                               "Pure Liquid Compounds, J. Phys. Chem. Ref. Data; the Jasper-Lange table of the "
                               "'chemicals' library): 25.36 mN/m at 25 degC; taken at 25 degC whatever the temperature",
            "molar_volume": "88.148 g/mol over 0.81219 g/cm^3 at 25 degC (DIPPR density equation as tabulated for "
                            "pentan-1-ol): 108.5e-6 m^3/mol",
            "contact_angle": "ASSUMED 0 (complete wetting) on both terminations: no measured angle was found in the "
                             "searched records; a short-chain alcohol (25 mN/m) spreads on silica, and pentanol is the "
                             "vapour lubricant that wets MEMS sidewalls (Asay et al. 2008)",
            "isotherm": "oxide: 'p/p_sat = 0.5 ... sufficient to maintain a monolayer of n-pentanol on a SiO2 surface' "
                        "(Humidity effects on in situ vapor phase lubrication with n-pentanol, Tribol. Lett. 2014, doi:10.1007/s11249-014-0345-9), linear from dry, one layer "
                        "above (a lower bound near saturation); hydrogen: ASSUMED the oxide's (no measurement found)",
        },
    },
}


def vapour_properties(vapour):
    """The data of one vapour of :data:`VAPOURS` (a dict); an unknown name is refused, naming the known ones."""
    if not isinstance(vapour, str) or vapour not in VAPOURS:
        raise InputError(f"unknown vapour {vapour!r}: memstribo knows {', '.join(repr(v) for v in VAPOURS)} (one at a "
                         "time: mixed vapours are not modelled).")
    return VAPOURS[vapour]


def _termination(termination):
    if termination not in TERMINATIONS:
        raise InputError(f"unknown surface_termination {termination!r}: choose one of "
                         f"{', '.join(repr(t) for t in TERMINATIONS)}.")
    return termination


@cites("iapws_2014", "jasper_1972")
def vapour_surface_tension(vapour, temperature=capillary.REFERENCE_TEMPERATURE):
    """Surface tension of the vapour's liquid [N/m]: water's by IAPWS at ``temperature`` [K], pentanol's at 25 degC."""
    data = vapour_properties(vapour)
    if data["surface_tension"] is None:
        return capillary.water_surface_tension(temperature)
    return float(data["surface_tension"])


@cites("maboudian_howe_1997", "si_h_contact_angle")
def vapour_contact_angle(vapour, termination, water_contact_angle=None):
    """Contact angle of the vapour's liquid on a bare surface termination [rad].

    Water on the oxide: ``water_contact_angle`` (the parameter set's, [rad], in [0, pi]); the others from
    :data:`VAPOURS`.
    """
    data = vapour_properties(vapour)
    angle = data["contact_angle"][_termination(termination)]
    if angle is None:
        if water_contact_angle is None:
            raise InputError("water on the oxide takes the parameter set's water_contact_angle: give it.")
        angle = float(water_contact_angle)
    if not (math.isfinite(angle) and 0.0 <= angle <= math.pi):
        raise InputError(f"contact angle {angle!r} rad lies outside [0, pi] (0 to 180 deg).")
    return angle


def _layers(vapour, termination, ratio):
    data = vapour_properties(vapour)
    termination = _termination(termination)
    rh = np.asarray(ratio, dtype=float)
    if np.any(~np.isfinite(rh)) or np.any(rh < 0) or np.any(rh >= 1):
        raise InputError(f"the vapour pressure ratio p/p_sat must lie in [0, 1), got {ratio!r}.")
    return data, termination, rh


@cites("asay_kim_2005", "verdaguer_2007", "chen_2018_water_si", "vpl_humidity_2014")
def adsorbed_film_thickness(vapour, termination, ratio):
    """Thickness of the vapour's film adsorbed on a bare termination [m] at ``ratio`` = p / p_sat in [0, 1).

    The isotherm of :data:`VAPOURS` in molecular layers, interpolated linearly (water on the oxide:
    :func:`memstribo.physics.capillary.adsorbed_water_thickness`, its last slope extended above RH 0.9; the others
    held at their last point), times one molecular layer ``(V_m / N_A)^(1/3)``.
    """
    data, termination, rh = _layers(vapour, termination, ratio)
    if vapour == "water" and termination == "oxide":
        return capillary.adsorbed_water_thickness(rh)
    x, layers = (np.array(c, dtype=float) for c in zip(*data["isotherm"][termination]))
    result = np.interp(rh, x, layers) * capillary.water_monolayer_thickness(data["molar_volume"])
    return float(result) if np.ndim(result) == 0 else result


@cites("asay_kim_2005")
def liquid_film_thickness(vapour, termination, ratio):
    """The part of the adsorbed film that flows into a meniscus [m]: :func:`adsorbed_film_thickness` less its bound
    layers (water on the oxide: three ice-like layers, Asay and Kim 2005; pentanol: its first, hydrogen-bonded
    monolayer), never below 0."""
    data, termination, _ = _layers(vapour, termination, ratio)
    bound = data["bound_layers"][termination] * capillary.water_monolayer_thickness(data["molar_volume"])
    result = np.maximum(adsorbed_film_thickness(vapour, termination, ratio) - bound, 0.0)
    return float(result) if np.ndim(result) == 0 else result


def vapour_state(params):
    """The condensate of a parameter set's environment: a dict of ``vapour``, ``termination``, ``ratio`` (p / p_sat:
    ``vapour_pressure_ratio``, unset: ``relative_humidity``), ``surface_tension`` [N/m], ``molar_volume``
    [m^3/mol], ``kelvin`` r_K [m] (0 below a molecular Kelvin radius: an adsorbed film, no meniscus),
    ``kelvin_raw`` (the Kelvin equation's value), ``contact_angle`` on the bare termination [rad], ``film`` (the
    adsorbed film [m]) and ``liquid_film`` (its part that flows into a meniscus, :func:`liquid_film_thickness` [m])."""
    vapour, termination = params["vapour"], params["surface_termination"]
    data = vapour_properties(vapour)
    ratio = params["vapour_pressure_ratio"]
    ratio = params["relative_humidity"] if ratio is None else ratio
    temperature = params["ambient_temperature"]
    gamma = vapour_surface_tension(vapour, temperature)
    kelvin = capillary.kelvin_radius(ratio, temperature, gamma, data["molar_volume"])
    return {"vapour": vapour, "termination": termination, "ratio": float(ratio), "surface_tension": gamma,
            "molar_volume": data["molar_volume"], "kelvin_raw": kelvin,
            "kelvin": kelvin if capillary.forms_meniscus(kelvin, data["molar_volume"]) else 0.0,
            "contact_angle": vapour_contact_angle(vapour, termination, params["water_contact_angle"]),
            "film": adsorbed_film_thickness(vapour, termination, ratio),
            "liquid_film": liquid_film_thickness(vapour, termination, ratio)}
