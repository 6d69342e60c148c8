"""A sidewall tribometer: two etched sidewalls pressed by a normal load and rubbed (static and kinetic friction).

The sidewall contact is the flat pad (:mod:`memstribo.laboratory.cases.flat_pad`) under the row's nominal
``contact_pressure`` (or ``normal_force`` / ``pad_area``), or, where the device presses a rounded post of
``sphere_radius`` against the wall, the sphere (:mod:`memstribo.laboratory.cases.sphere`) under ``normal_force``. The
roughness is the etched sidewall's (the row's, else the AFM of a polysilicon sidewall, van Spengen et al. 2010).
A sliding amplitude shorter than a bond length never breaks the bonds: outside the model's range.
"""

from __future__ import annotations

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["sidewall_friction"]


@cites("van_spengen_2010", "thesis", "model")
def sidewall_friction(params, rq, correlation_length, seed, relative_humidity=None, *, contact_pressure=None,
                      normal_force=None, pad_area=None, sphere_radius=None, sliding_amplitude=None) -> dict:
    """Static and kinetic COF of a sidewall contact (module docstring); the dict of the flat pad or the sphere,
    with ``load_text`` saying how the load was taken."""
    from memstribo.laboratory.cases.flat_pad import flat_pad_friction
    from memstribo.laboratory.cases.sphere import sphere_friction

    if sliding_amplitude is not None and sliding_amplitude < float(params["bond_length"]):
        raise InputError(f"sliding_amplitude {sliding_amplitude:.3g} m is shorter than a bond length "
                         f"({params['bond_length']:.3g} m): the bonds never break (outside the model's range).")
    if contact_pressure is None and normal_force is not None and pad_area is not None:
        contact_pressure = normal_force / pad_area
    if contact_pressure is not None:
        out = flat_pad_friction(params, contact_pressure, rq, correlation_length, seed, relative_humidity)
        out["load_text"] = f"nominal pressure {contact_pressure:.3g} Pa on the sidewall"
        return out
    if normal_force is not None and sphere_radius is not None:
        out = sphere_friction(params, normal_force, sphere_radius, rq, correlation_length, seed, relative_humidity)
        out["load_text"] = f"normal force {normal_force:.3g} N on a post of radius {sphere_radius:.3g} m"
        return out
    raise InputError("a sidewall row needs its load as contact_pressure, or normal_force with pad_area or "
                     "sphere_radius.")
