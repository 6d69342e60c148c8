"""The common MEMS test structures as cases of the model's physics (issue 37 item 2, MODEL 7e).

One module per structure, each through the rough contact solve, the bonds' friction and the menisci
(:mod:`._interface`, :mod:`._menisci`), each checked against its smooth closed form (tests/test_laboratory_cases.py):

- :mod:`.flat_pad`: pads on a substrate under a nominal pressure (real contact area from the rough contact solve);
- :mod:`.sidewall`: a sidewall tribometer (normal load, static and kinetic friction);
- :mod:`.sphere`: a sphere or pin on a flat of any radius (Hertz plus roughness);
- :mod:`.cantilever`: a cantilever beam array (crack length <-> adhesion energy, de Boer and Michalske 1999);
- :mod:`.pull_off`: pull-off of a probe or a plate (Maugis-Dugdale, from DMT to JKR, smooth);
- :mod:`.nanocontact`: an AFM tip or nano-asperity (interfacial shear strength).

:func:`case_values` dispatches a measurement row by its ``geometry`` and ``quantity``; :func:`check_conditions`
refuses conditions outside the model's range, naming the field.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError

__all__ = ["CASE_GEOMETRIES", "case_values", "check_conditions", "row_roughness"]

#: the geometries the cases build, with the quantities each predicts
CASE_GEOMETRIES = {
    "flat": ("static_cof", "kinetic_cof", "pull_off_force"),
    "flat_pad": ("static_cof", "kinetic_cof", "pull_off_force"),
    "sidewall": ("static_cof", "kinetic_cof"),
    "sphere_on_flat": ("static_cof", "kinetic_cof", "pull_off_force", "interfacial_shear_strength"),
    "cantilever_array": ("adhesion_energy", "crack_length"),
    "pull_off": ("pull_off_force",),
    "nanocontact": ("interfacial_shear_strength", "static_cof", "kinetic_cof", "pull_off_force"),
}

#: (lowest, highest) of each condition the cases accept, SI, with the reason
RANGES = {
    "contact_pressure": (0.0, None, "Pa", "at least 0 and at most the softer body's hardness"),
    "normal_force": (0.0, 1.0, "N", "0 to 1 N (a MEMS or AFM contact)"),
    "sphere_radius": (1e-9, 0.1, "m", "1 nm (an AFM tip) to 10 cm"),
    "pad_area": (1e-16, 1e-2, "m^2", "1e-16 to 1e-2 m^2"),
    "beam_thickness": (1e-8, 1e-3, "m", "10 nm to 1 mm"),
    "beam_gap": (1e-9, 1e-3, "m", "1 nm to 1 mm"),
    "beam_length": (1e-7, 1e-1, "m", "0.1 um to 10 cm"),
    "crack_length": (1e-7, 1e-1, "m", "0.1 um to 10 cm"),
    "sliding_amplitude": (0.0, 1e-2, "m", "0 to 1 cm"),
    "relative_humidity": (0.0, 0.99, "", "0 to 0.99 (the Kelvin equation's range)"),
    "temperature": (200.0, 500.0, "K", "200 to 500 K (water's surface tension and the bonds' energies at room "
                                       "temperature)"),
}

#: the fields each geometry needs for its quantity (any one of a tuple)
NEEDS = {
    ("sphere_on_flat", None): (("sphere_radius",), ("normal_force",)),
    ("nanocontact", None): (("sphere_radius",), ("normal_force",)),
    ("cantilever_array", None): (("beam_thickness",), ("beam_gap",)),
    ("cantilever_array", "adhesion_energy"): (),  # the work of separation needs no beam dimensions
    ("pull_off", None): (("sphere_radius", "pad_area"),),
    ("flat_pad", "pull_off_force"): (("pad_area",),),
    ("flat", "pull_off_force"): (("pad_area",),),
    ("sidewall", None): (("contact_pressure", "sphere_radius", "pad_area"),),
}


def _number(row, name):
    return row.number(name)


def check_conditions(row, hardness=None) -> None:
    """Refuse a row whose conditions are outside the model's range or lack what its case needs; names the field."""
    where = f"measurement row {row.id!r}"
    geometry, quantity = row.condition("geometry"), row.quantity
    if (geometry in ("flat", "flat_pad") and quantity != "pull_off_force" and _number(row, "contact_pressure") is None
            and _number(row, "normal_force") is None):
        raise InputError(f"{where}: field contact_pressure (or normal_force with pad_area) is missing: the load is not "
                         "stated, and the friction of a rough contact depends on it.")
    if geometry in CASE_GEOMETRIES:
        needs = NEEDS.get((geometry, quantity), NEEDS.get((geometry, None), ()))
        for options in needs:
            if not any(_number(row, o) is not None for o in options):
                raise InputError(f"{where}: field {' or '.join(options)} is missing; a {geometry} row for {quantity} "
                                 f"needs it (a number in SI units).")
    if row.environment == "air" and _number(row, "relative_humidity") is None:
        raise InputError(f"{where}: field relative_humidity is not stated and no relative_humidity_assumed is "
                         "declared: the menisci need it.")
    for name, (low, high, unit, allowed) in RANGES.items():
        value = _number(row, name)
        if value is None:
            continue
        if name == "contact_pressure" and hardness is not None:
            high = hardness
        if value < low or (high is not None and value > high) or not math.isfinite(value):
            raise InputError(f"{where}: field {name} = {value:g}{' ' + unit if unit else ''} is outside the model's range ({allowed}"
                             f"{f', here {high:g} {unit}' if name == 'contact_pressure' and high else ''}).")
    material = row.condition("material", "polysilicon"), row.condition("counter_material", "polysilicon")
    from memstribo.laboratory.materials import MATERIALS

    for field, value in zip(("material", "counter_material"), material):
        if value not in MATERIALS:
            raise InputError(f"{where}: field {field} = {value!r} is not a material memstribo knows; allowed: "
                             f"{', '.join(MATERIALS)}.")
    termination = row.condition("surface_termination", "oxide")
    if termination not in ("oxide", "hydrogen"):
        raise InputError(f"{where}: field surface_termination = {termination!r}; allowed: oxide, hydrogen.")


def _not_modelled(row):
    """Why the cases cannot predict a row whose stated conditions they do not model (None: they can)."""
    vapour = row.condition("vapour", "water")
    if vapour != "water" and row.environment != "air":
        return f"vapour {vapour!r} in {row.environment}: a condensable vapour acts only in air (MODEL 7g)"
    return None


def row_roughness(row, params):
    """(rq of each surface [m], correlation length [m], note) of a row: stated, assumed, the sidewall's, or the
    parameter set's (nanocontact: smooth unless stated)."""
    from memstribo.laboratory.cases._roughness import stated_roughness

    found = stated_roughness(row)
    if found is not None:
        return found
    if row.condition("geometry") == "nanocontact":
        return 0.0, None, "smooth (no roughness stated for the tip's contact)"
    rq = float(params["roughness_rq"])
    return rq, math.sqrt(2.0) * rq / float(params["roughness_rms_slope"]), "the parameter set's roughness (none stated)"


def _said(out):
    """The case's notes: the real area's resolution, an unconverged solve, a capped shear stress."""
    notes = [out["note"]] if out.get("note") else []
    if out.get("converged") is False:
        notes.append("the contact solve or its adhesion fixed point did not converge")
    if out.get("capped"):
        notes.append("the bonds' shear stress capped at the ideal shear strength")
    return "".join(f"; {n}" for n in notes)


def _one(row, params, rough, seed):
    """One predicted value of ``row`` and the words of its case."""
    from memstribo.laboratory.cases import cantilever, flat_pad, nanocontact, pull_off, sidewall, sphere

    geometry, quantity = row.condition("geometry"), row.quantity
    rq, corr, _ = rough
    rh = float(params["relative_humidity"]) if params["environment"] == "air" else None
    force, radius, area = _number(row, "normal_force"), _number(row, "sphere_radius"), _number(row, "pad_area")
    pressure = _number(row, "contact_pressure")
    if quantity == "pull_off_force":
        if radius is not None:
            return pull_off.probe_pull_off(params, radius, rq, corr, seed, rh)
        return pull_off.plate_pull_off(params, area, rq, corr, seed, rh)
    if geometry == "cantilever_array":
        energy = cantilever.work_of_separation(cantilever.beam_gap_field(rq, corr, seed), params, rh)[0]
        if quantity == "adhesion_energy":
            return energy, "work of separation of the rough interface under the beam"
        s = cantilever.beam_crack_length(float(params["youngs_modulus"]), _number(row, "beam_thickness"),
                                         _number(row, "beam_gap"), energy)
        return s, f"crack length of the beam's adhesion energy {energy:.3g} J/m^2 (de Boer and Michalske 1999)"
    if quantity == "interfacial_shear_strength":
        out = nanocontact.interfacial_shear_strength(params, force, radius, rq, corr, seed, rh)
        return out["shear_strength"], f"friction over real area of a tip R {radius:.3g} m at {force:.3g} N" + _said(out)
    key = "static_cof" if quantity == "static_cof" else "kinetic_cof"
    if geometry == "sidewall":
        out = sidewall.sidewall_friction(params, rq, corr, seed, rh, contact_pressure=pressure, normal_force=force,
                                         pad_area=area, sphere_radius=radius,
                                         sliding_amplitude=_number(row, "sliding_amplitude"))
        return out[key], out["load_text"] + _said(out)
    if geometry in ("sphere_on_flat", "nanocontact"):
        out = sphere.sphere_friction(params, force, radius, rq, corr, seed, rh)
        return out[key], f"sphere R {radius:.3g} m at {force:.3g} N" + _said(out)
    if pressure is None:
        pressure = force / area
    out = flat_pad.flat_pad_friction(params, pressure, rq, corr, seed, rh)
    return out[key], f"flat pad at {pressure:.3g} Pa, A_r/A {out['real_area_fraction']:.3g}" + _said(out)


def _reused_or_new(done, row, params, rough, seed):
    """``_one(row, params, rough, seed)``, or the stored result of an earlier evaluation that read the same values
    (:mod:`memstribo.laboratory.cases._memo`: exact); ``done`` is updated."""
    from memstribo.laboratory.cases._memo import ReadRecorder, read_key

    for names, table in done.items():
        found = table.get(read_key(params, names))
        if found is not None:
            return found
    recorder = ReadRecorder(params)
    found = _one(row, recorder, rough, seed)
    done.setdefault(recorder.names(), {})[read_key(params, recorder.names())] = found
    return found


def case_values(row, samples, realisations, base=None, calibration_coating="OTS", seed=20260528):
    """The predicted values of ``row`` over constant samples x roughness realisations, with the case in words.

    Returns
    -------
    tuple
        (ndarray (n_samples, realisations), case text); (None, reason) when no case builds this row; NotImplemented
        for a geometry the cases leave to :mod:`memstribo.laboratory.predict` (microbeam, gear, micromotor).
    """
    from memstribo.laboratory.materials import row_parameters

    geometry, quantity = row.condition("geometry"), row.quantity
    if geometry not in CASE_GEOMETRIES:
        return NotImplemented
    if quantity not in CASE_GEOMETRIES[geometry]:
        return None, (f"a {geometry} case predicts {', '.join(CASE_GEOMETRIES[geometry])}, not {quantity}")
    reason = _not_modelled(row)
    if reason:
        return None, reason
    values = np.zeros((len(samples), realisations))
    text = ""
    done: dict = {}  # (realisation, roughness) -> {names an evaluation read: {their values: (value, words)}}
    for i, sample in enumerate(samples):
        params, set_name = row_parameters(row, base, sample, calibration_coating)
        try:
            check_conditions(row, float(params["hardness"]))
        except InputError as error:
            return None, str(error)
        rough = row_roughness(row, params)
        for k in range(realisations):
            found = _reused_or_new(done.setdefault((k, rough), {}), row, params, rough, seed + k)
            values[i, k], words = found
            text = text or (f"{geometry} case ({words}); {set_name}"
                            f"{' + ' + row.coating if row.coating else ''}; roughness: "
                            + (f"Rq {rough[0] * 1e9:.3g} nm, correlation length {rough[1] * 1e9:.3g} nm ({rough[2]})"
                               if rough[0] > 0 else rough[2]))
    return values, text
