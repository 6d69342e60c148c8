"""What each model parameter is: canonical name, SI unit, type, allowed range.

The *values* live in parameter sets (``sets/*.toml``) with their provenance; this table
says what a value must look like. Each topic has its own section: add a parameter to the
section of the module that uses it, and give it a default in ``sets/silicon_thesis.toml``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class ParameterSpec:
    """Definition of one model parameter.

    Attributes
    ----------
    name : str
        Canonical name, used by ``--set NAME=VALUE``, config files and the library.
    unit : str
        SI unit in pint syntax (``""`` for dimensionless); values are stored in it.
    description : str
        One line saying what it is.
    kind : str
        ``"float"``, ``"int"``, ``"str"`` or ``"bool"``.
    minimum, maximum : float or None
        Allowed range; ``None`` for no bound.
    exclusive_minimum, exclusive_maximum : bool
        Whether the bounds themselves are excluded.
    optional : bool
        Whether the value may be ``None`` ("derive it", see the description).
    choices : tuple of str or None
        Allowed values of a string parameter.
    """

    name: str
    unit: str
    description: str
    kind: str = "float"
    minimum: float | None = None
    maximum: float | None = None
    exclusive_minimum: bool = False
    exclusive_maximum: bool = False
    optional: bool = False
    choices: tuple[str, ...] | None = None

    def allowed(self) -> str:
        """Human-readable description of the allowed values."""
        if self.kind == "str":
            return "one of " + ", ".join(repr(c) for c in self.choices) if self.choices else "a string"
        if self.kind == "bool":
            return "true or false"
        parts = []
        if self.minimum is not None:
            parts.append(f"{'>' if self.exclusive_minimum else '>='} {self.minimum:g}")
        if self.maximum is not None:
            parts.append(f"{'<' if self.exclusive_maximum else '<='} {self.maximum:g}")
        what = "an integer" if self.kind == "int" else "a number"
        text = what + (" " + " and ".join(parts) if parts else "")
        if self.unit:
            text += f" (SI unit {self.unit}, or a value with a unit)"
        if self.optional:
            text += ", or unset to derive it"
        return text


def _positive(name, unit, description, **kw):
    return ParameterSpec(name, unit, description, minimum=0.0, exclusive_minimum=True, **kw)


def _nonnegative(name, unit, description, **kw):
    return ParameterSpec(name, unit, description, minimum=0.0, **kw)


_SPECS = [
    # --- material (potentials, adhesion) ------------------------------------------------
    _positive("youngs_modulus", "Pa", "Young's modulus E of the tooth material (silicon)"),
    ParameterSpec("poisson_ratio", "", "Poisson's ratio nu of the tooth material",
                  minimum=-1.0, maximum=0.5, exclusive_minimum=True),
    _positive("counter_youngs_modulus", "Pa", "Young's modulus of the counter body (gear tooth); unset: same as youngs_modulus",
              optional=True),
    ParameterSpec("counter_poisson_ratio", "", "Poisson's ratio of the counter body; unset: same as poisson_ratio",
                  minimum=-1.0, maximum=0.5, exclusive_minimum=True, optional=True),
    _positive("lattice_constant", "m", "Lattice constant of the crystal"),
    _positive("bond_length", "m", "Chemical bond length D_chem (also the sliding distance per bond break)"),
    _positive("bond_energy", "J", "Energy of one chemical bond U_chem"),
    _nonnegative("vdw_bond_energy", "J", "Energy of one van der Waals bond U_vdW"),
    _positive("hamaker_constant", "J", "Hamaker constant A"),
    _positive("cutoff_distance", "m", "Cut-off (contact) separation D0 of the vdW interaction"),
    _positive("work_of_adhesion", "J/m^2", "Work of adhesion w12; unset: A / (12 pi D0^2) (3-34)", optional=True),
    ParameterSpec("threshold_strain", "", "Strain at which an atomic block turns rigid (bilinear law)",
                  minimum=0.0, maximum=1.0, exclusive_minimum=True),
    # --- nanoblock geometry ---------------------------------------------------------------
    _positive("atomic_width", "m", "Width w_at of a square atomic-subscale block"),
    _positive("atomic_height", "m", "Height H_at of an atomic-subscale block"),
    _positive("adhesive_width", "m", "Width w_adh of a square adhesive-subscale block (the nanoblock)"),
    _positive("adhesive_height", "m", "Height H_adh of an adhesive-subscale block"),
    ParameterSpec("atomic_per_side", "", "Atomic blocks per side m of a nanoblock (m x m blocks)", kind="int",
                  minimum=1),
    _positive("atomic_pitch", "m", "Centre-to-centre pitch of the atomic blocks (about lambda_q)"),
    _positive("bulk_height", "m", "Height of the elastic bulk segment under a nanoblock; unset: adhesive_width",
              optional=True),
    ParameterSpec("slider_blocks", "", "Adhesive blocks in the sliding structure of the flat-friction models",
                  kind="int", minimum=1),
    # --- roughness (default synthetic profile) -----------------------------------------------
    _positive("roughness_rq", "m", "Rq of the default synthetic roughness profile"),
    _positive("roughness_rms_slope", "", "rms slope (Delta q) of the default synthetic roughness profile"),
    _positive("roughness_sample_spacing", "m", "Sampling step of the default synthetic profile (as measured)"),
    _positive("roughness_resample_spacing", "m", "Step after PCHIP resampling; unset: no resampling", optional=True),
    ParameterSpec("roughness_seed", "", "Seed of the default synthetic roughness profile", kind="int", minimum=0),
    _positive("roughness_length", "m", "Length of the default synthetic roughness profile"),
    # --- gear geometry and operation ----------------------------------------------------------
    ParameterSpec("teeth_pinion", "", "Number of teeth z1 of the pinion (driver)", kind="int", minimum=5),
    ParameterSpec("teeth_gear", "", "Number of teeth z2 of the gear (driven)", kind="int", minimum=5),
    _positive("module", "m", "Module m of the gear pair (pitch diameter / teeth)"),
    ParameterSpec("pressure_angle", "rad", "Pressure angle (give units: '20 deg')", minimum=0.0,
                  maximum=math.pi / 2, exclusive_minimum=True, exclusive_maximum=True),
    _positive("addendum_coefficient", "", "Addendum in modules (standard: 1)"),
    _positive("face_width", "m", "Face width of the teeth"),
    _positive("normal_load", "N", "Normal load F_ext carried by the teeth in contact"),
    _positive("drive_torque", "N*m", "Torque on the pinion; F_t = T / r_pitch,pinion (4-27)"),
    _positive("pinion_speed", "rad/s", "Angular speed omega1 of the pinion (sets the time axis only)"),
    # --- meshing simulation ---------------------------------------------------------------------
    ParameterSpec("mesh_steps", "", "Steps (positions c) of the meshing simulation from c_f to c_l", kind="int",
                  minimum=3),
    _positive("mesh_grid_spacing", "m", "Element width of the rough line-contact solve at each step; unset: the "
              "largest Hertz width 2a of the load case / mesh_elements_across_contact", optional=True),
    _positive("mesh_window", "m", "Length of the contact window solved at each step, centred on the contact point; "
              "unset: 2.4 a + 6 w_adh of the largest Hertz half-width a of the load case", optional=True),
    _positive("mesh_contact_tolerance", "", "Tolerance of the rough line-contact solver (dimensionless residual)"),
    ParameterSpec("load_sharing", "", "Load-sharing function over the mesh (Figure 4-11): dry or lubricated",
                  kind="str", choices=("dry", "lubricated")),
    _positive("elastic_limit_pressure", "Pa", "Hertz peak pressure beyond which the elastic model of silicon no longer holds"),
    # --- coatings and wear ----------------------------------------------------------------------
    ParameterSpec("coating_wear", "", "Worn fraction Omega of the gear tooth's coating (0 coated, 1 bare; 5.5.3)",
                  minimum=0.0, maximum=1.0),
    # --- damage and lifetime --------------------------------------------------------------------
    _positive("asperity_degree", "", "Degree d of the atomic asperity shape f(r) = B_d r^d (5-6)"),
    _positive("asperity_shape_coefficient", "",
              "B_d of f(r) = B_d r^d, SI number in m^(1-d) (m^-3 for d = 4); give the number without a unit"),
    _positive("asperity_half_width", "m", "Half width of an atomic asperity (edge of the power-law shape, 5.5.2)"),
    _nonnegative("asperity_friction_coefficient", "",
                 "Friction coefficient mu of the traction mu*p on an atomic asperity in the stress solution"),
    ParameterSpec("peaks_per_cycle", "", "Load peaks k on a nanoblock per meshing cycle (Figure 5-18)", kind="int",
                  minimum=1),
    _positive("damage_exponent", "", "Exponent m of the damage law omega = sum c1 (dtau1)^m (5-10)"),
    _positive("damage_coefficient", "",
              "c1 of the damage law (5-10), SI number in Pa^-m; unset: unknown (relative lives only)", optional=True),
    # --- sliding (flat-friction models, thesis 2.6.2, 3.4) ------------------------------------
    ParameterSpec("sliding_gap", "m", "Fixed-gap model: height of the undeformed atomic tips above the counter "
                  "profile's mean line (negative: interference); unset: the profile's Rq", optional=True),
    _positive("sliding_step", "m", "Sliding distance per step of the flat-friction models; unset: bond_length",
              optional=True),
    _positive("adhesive_layer_thickness", "m", "Thickness of the adhesive layer inside which an adhesive block "
              "forms vdW bonds and adheres, in the sliding models and the meshing cycle, for bare and coated "
              "blocks alike; unset: adhesive_height (thesis 3.5); the Maugis range h0 = w/sigma0 (MODEL §2, "
              "'memstribo constants') is the explicit alternative", optional=True),
    # --- version 2: load case, adhesive interface, verdict (MODEL 7b, 7c) --------------------
    ParameterSpec("load_case", "", "Normal load of the meshing cycle: 'torque' (F_n = F_t / cos alpha_w from the "
                  "drive torque, shared by the pairs in mesh, over the whole face width; MODEL 7b) or 'thesis' "
                  "(normal_load as given, 25 uN in 4.9; its normal force is not the one the torque implies)",
                  kind="str", choices=("torque", "thesis")),
    ParameterSpec("interface_model", "", "vdW bonds of the meshing cycle: 'gap' (energy and attraction scaled by "
                  "(D0/max(D, D0))^2 at each block's local gap D, up to vdw_cutoff; MODEL 7c) or 'thesis' (full "
                  "energy inside a band of adhesive_layer_thickness, thesis 3.5)", kind="str",
                  choices=("gap", "thesis")),
    _positive("vdw_cutoff", "m", "Local gap beyond which vdW bonds are neglected (interface_model 'gap'); a "
              "numerical parameter: doubling it changes the mean COF by less than 1 %"),
    ParameterSpec("contact_adhesion", "", "Adhesion inside the rough contact solve of the meshing cycle: 'maugis' "
                  "(Maugis-Dugdale cohesive zone, sigma0 and h0 from the constants; MODEL 7c) or 'none'",
                  kind="str", choices=("maugis", "none")),
    ParameterSpec("mesh_elements_across_contact", "", "Contact elements across the largest Hertz width 2a when "
                  "mesh_grid_spacing is unset", kind="int", minimum=8, maximum=4096),
    _positive("friction_averaging_distance", "m", "Sliding distance over which the friction force of the verdict "
              "averages the dissipated energy (MODEL 7b); unset: atomic_pitch, the distance over which the bond "
              "population renews", optional=True),
    ParameterSpec("realisations", "", "Independent roughness realisations of the stiction verdict (ensemble, "
                  "MODEL 7b)", kind="int", minimum=1, maximum=10000),
    _positive("ideal_shear_strength", "Pa", "Ideal shear strength of the tooth material: a friction stress above "
              "it is flagged as a warning (silicon: about 6.8 GPa, Roundy and Cohen 2001)"),
]

SPECS: dict[str, ParameterSpec] = {spec.name: spec for spec in _SPECS}
