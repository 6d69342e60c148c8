"""A nanocontact (AFM tip or nano-asperity on a flat): the interfacial shear strength (MODEL 7d, 7e, 7h).

The tip of radius R under the normal force F is the sphere case (:func:`memstribo.laboratory.cases.sphere.sphere_friction`,
smooth unless the row states a roughness); its interfacial shear strength is the friction over the real contact
area, F_f / A_r, the quantity AFM and nano-contact studies report (friction over the JKR/DMT area). In the smooth
limit it is the bonds' shear stress (U_chem + U_vdW) / D^3 (capped at the ideal shear strength) plus the share of
the vdW bonds off the contact: the constant the gear's verdict hangs on (MODEL 7d: tau = U / D^3).
"""

from __future__ import annotations

from memstribo.references import cites

__all__ = ["interfacial_shear_strength"]


@cites("thesis", "model")
def interfacial_shear_strength(params, force, radius, rq=0.0, correlation_length=None, seed=0,
                               relative_humidity=None) -> dict:
    """Interfacial shear strength of a nanocontact [Pa] and its contact: ``{"shear_strength", "real_area",
    "adhesion_force", "kinetic_cof", "note"}`` (module docstring)."""
    from memstribo.laboratory.cases.sphere import sphere_friction

    return sphere_friction(params, force, radius, rq, correlation_length, seed, relative_humidity)
