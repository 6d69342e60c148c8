"""What each model parameter is: canonical name, SI unit, type, allowed range.

The *values* live in parameter sets (``sets/*.toml``) with their provenance; this table
says what a value must look like. Each topic has its own section: add a parameter to the
section of the module that uses it, and give it a default in ``sets/silicon_thesis.toml``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: memory a single run may plan to use: a machine with 24 GB holds this and the interpreter
MEMORY_LIMIT_BYTES = 20 * 2**30


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
    prior : dict or None
        Uncertainty of the value for the uncertainty analysis (MODEL 7d): ``distribution``
        (``"uniform"``, ``"loguniform"``, ``"normal"``, ``"lognormal"``), ``bounds`` (low, high) in the
        SI unit (for normal/lognormal: the 2.5 % and 97.5 % quantiles), ``source`` and ``reason``.
    why : str
        Why the range is what it is (shown with the range in ``memstribo parameters`` and in
        the message of a value outside it). Every number has both bounds: a value far outside
        what a MEMS gear or silicon surface can have is a typo or a wrong unit, and sizes
        (steps, spacings, lengths) also bound the memory a run needs.
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
    why: str = ""
    prior: dict | None = None

    @property
    def description_with_bounds(self) -> str:
        """The description, then the allowed range and why."""
        if self.kind in ("str", "bool"):
            return self.description
        return f"{self.description}. Allowed: {self.allowed()}" + (f"; {self.why}" if self.why else "")

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
        if self.unit == "rad" and parts:  # angles: the bounds in degrees too (the unit users give)
            degrees = []
            if self.minimum is not None:
                degrees.append(f"{'>' if self.exclusive_minimum else '>='} {math.degrees(self.minimum):.4g} deg")
            if self.maximum is not None:
                degrees.append(f"{'<' if self.exclusive_maximum else '<='} {math.degrees(self.maximum):.4g} deg")
            text += f", i.e. {' and '.join(degrees)} (SI unit rad, or a value with a unit such as '20 deg')"
        elif self.unit:
            text += f" (SI unit {self.unit}, or a value with a unit)"
        if self.optional:
            text += ", or unset to derive it"
        return text


def _range(name, unit, description, minimum, maximum, why, **kw):
    """A number with both bounds (minimum excluded where it is 0)."""
    kw.setdefault("exclusive_minimum", minimum == 0.0 and kw.get("kind", "float") == "float")
    return ParameterSpec(name, unit, description, minimum=minimum, maximum=maximum, why=why, **kw)


_E = "stiffer than hard polymers (0.1 GPa) and no stiffer than diamond (1.2 TPa): softer bodies leave the small-strain elastic model"
_E_COUNTER = ("from a soft elastomer (1 MPa) to diamond (1.2 TPa); whether a soft counter body suits the half-space "
              "contact model depends on the load and is checked with it (Hertz half-width a/R_ef <= 0.5)")
_NU = "thermodynamic limits of an isotropic solid"
_ATOMIC = "an atomic length: 0.05 nm (shorter than any bond) to 1 nm"

_SPECS = [
    # --- material (potentials, adhesion) ------------------------------------------------
    _range("youngs_modulus", "Pa", "Young's modulus E of the tooth material (silicon)", 1e8, 1.5e12, _E),
    ParameterSpec("poisson_ratio", "", "Poisson's ratio nu of the tooth material",
                  minimum=-1.0, maximum=0.5, exclusive_minimum=True, why=_NU),
    _range("counter_youngs_modulus", "Pa",
           "Young's modulus of the counter body (gear tooth); unset: same as youngs_modulus", 1e6, 1.5e12, _E_COUNTER,
           optional=True),
    ParameterSpec("counter_poisson_ratio", "", "Poisson's ratio of the counter body; unset: same as poisson_ratio",
                  minimum=-1.0, maximum=0.5, exclusive_minimum=True, optional=True, why=_NU),
    _range("lattice_constant", "m", "Lattice constant of the crystal", 1e-10, 2e-9,
           "crystal lattice constants lie between 0.1 nm and 2 nm"),
    _range("bond_length", "m", "Chemical bond length D_chem (also the sliding distance per bond break)", 5e-11, 1e-9,
           _ATOMIC),
    _range("bond_energy", "J", "Energy of one chemical bond U_chem", 1e-21, 2e-18,
           "from a weak bond (0.006 eV) to beyond the strongest chemical bond (11 eV = 1.8e-18 J)"),
    _range("vdw_bond_energy", "J", "Energy of one van der Waals bond U_vdW", 0.0, 1e-19,
           "a van der Waals bond is weaker than 0.6 eV; 0 switches it off", exclusive_minimum=False),
    ParameterSpec("vdw_energy_rule", "", "Friction energy U_vdW of a van der Waals site: 'hysteresis' (MODEL 7h: the "
                  "dissipated fraction of the adhesion energy the site holds, U_vdW = vdw_dissipated_fraction x w12 / "
                  "vdw_site_density, one interaction with the adhesion; vdw_bond_energy is not used) or 'thesis' "
                  "(vdw_bond_energy as given: the thesis's U_chem / 100, 3.5)", kind="str",
                  choices=("hysteresis", "thesis")),
    _range("vdw_dissipated_fraction", "", "Dissipated fraction phi of the adhesion energy a vdW site holds when it "
           "breaks and re-forms while sliding (adhesion hysteresis; vdw_energy_rule 'hysteresis')", 0.0, 1.0,
           "a fraction: more than nothing and at most all of the adhesion energy (phi = 1: every site gives up its "
           "whole share of w12)"),
    _range("vdw_site_density", "1/m^2", "Areal density of van der Waals sites (bonds) of a flank; unset: 1 / "
           "bond_length^2 (the thesis's count, 3-12)", 1e17, 1e20,
           "no negative or zero density; from a sparse adsorbate layer (1e17 m^-2, one site per 10 nm^2) to beyond "
           "any atomic surface (1e20 m^-2, one site per 0.01 nm^2)", optional=True),
    _range("hamaker_constant", "J", "Hamaker constant A", 1e-22, 1e-17,
           "Hamaker constants of solids lie between 1e-21 J and 5e-19 J (metals); a decade of margin each side"),
    _range("cutoff_distance", "m", "Cut-off (contact) separation D0 of the vdW interaction", 5e-11, 1e-9, _ATOMIC),
    _range("work_of_adhesion", "J/m^2", "Work of adhesion w12; unset: A / (12 pi D0^2) (3-34)", 1e-6, 10.0,
           "surface energies of solids are below 5 J/m^2", optional=True),
    ParameterSpec("threshold_strain", "", "Strain at which an atomic block turns rigid (bilinear law)",
                  minimum=0.0, maximum=1.0, exclusive_minimum=True, why="a strain between 0 and 1"),
    # --- nanoblock geometry ---------------------------------------------------------------
    _range("atomic_width", "m", "Width w_at of a square atomic-subscale block", 1e-10, 1e-6,
           "atomic-subscale asperities are 0.1 nm to 1 um wide"),
    _range("atomic_height", "m", "Height H_at of an atomic-subscale block", 1e-11, 1e-6,
           "atomic-subscale asperities are 0.01 nm to 1 um high"),
    _range("adhesive_width", "m", "Width w_adh of a square adhesive-subscale block (the nanoblock)", 1e-9, 1e-4,
           "a nanoblock is 1 nm to 100 um wide (smaller than a gear tooth)"),
    _range("adhesive_height", "m", "Height H_adh of an adhesive-subscale block", 1e-10, 1e-5,
           "a nanoblock is 0.1 nm to 10 um high"),
    _range("atomic_per_side", "", "Atomic blocks per side m of a nanoblock (m x m blocks)", 1, 100,
           "at most 100 x 100 atomic blocks per nanoblock (memory and time grow as m^2)", kind="int"),
    _range("atomic_pitch", "m", "Centre-to-centre pitch of the atomic blocks (about lambda_q)", 1e-10, 1e-4,
           "between an atomic distance and the width of a tooth"),
    _range("bulk_height", "m", "Height of the elastic bulk segment under a nanoblock; unset: adhesive_width",
           1e-10, 1e-3, "smaller than a gear tooth", optional=True),
    _range("slider_blocks", "", "Adhesive blocks in the sliding structure of the flat-friction models", 1, 1000,
           "at most 1000 blocks (memory and time grow with them)", kind="int"),
    # --- roughness (default synthetic profile) -----------------------------------------------
    _range("roughness_rq", "m", "Rq of the default synthetic roughness profile", 1e-12, 1e-5,
           "1 pm (below any instrument's noise) to 10 um (not a MEMS surface)"),
    _range("roughness_rms_slope", "", "rms slope (Delta q) of the default synthetic roughness profile", 1e-6, 10.0,
           "slopes beyond 10 (84 deg) are not a surface profile"),
    _range("roughness_sample_spacing", "m", "Sampling step of the default synthetic profile (as measured)", 1e-11,
           1e-4, "0.01 nm to 100 um; with roughness_length it sets the number of points (at most 10 million)"),
    _range("roughness_resample_spacing", "m", "Step after PCHIP resampling; unset: no resampling", 1e-11, 1e-4,
           "0.01 nm to 100 um; with roughness_length it sets the number of points (at most 10 million)",
           optional=True),
    _range("roughness_seed", "", "Seed of the default synthetic roughness profile", 0, 2**63 - 1,
           "any non-negative 64-bit integer", kind="int"),
    _range("roughness_length", "m", "Length of the default synthetic roughness profile", 1e-8, 1e-1,
           "10 nm to 10 cm"),
    # --- gear geometry and operation ----------------------------------------------------------
    _range("teeth_pinion", "", "Number of teeth z1 of the pinion (driver)", 5, 10000,
           "fewer than 5 teeth cannot mesh continuously; more than 10000 is not a MEMS gear", kind="int"),
    _range("teeth_gear", "", "Number of teeth z2 of the gear (driven)", 5, 10000,
           "fewer than 5 teeth cannot mesh continuously; more than 10000 is not a MEMS gear", kind="int"),
    _range("module", "m", "Module m of the gear pair (pitch diameter / teeth)", 1e-7, 1e-2,
           "0.1 um (smaller than any etched tooth) to 10 mm"),
    _range("pressure_angle", "rad", "Pressure angle (give units: '20 deg')", math.radians(10), math.radians(35),
           "10 to 35 deg: involute gears use 14.5 to 25 deg; beyond, teeth undercut (small angles) or turn "
           "pointed with a contact ratio below 1 or absurdly above it (89 deg gave 36.5)"),
    _range("addendum_coefficient", "", "Addendum in modules (standard: 1)", 0.3, 2.0,
           "stub (0.8) to long (1.25) addenda, with margin; beyond 2 the tooth tips are pointed"),
    _range("face_width", "m", "Face width of the teeth", 1e-8, 1e-2, "10 nm to 10 mm"),
    _range("normal_load", "N", "Normal load F_ext carried by the teeth in contact", 1e-12, 1.0,
           "1 pN to 1 N: a MEMS gear tooth carries uN to mN"),
    _range("drive_torque", "N*m", "Torque on the pinion; F_t = T / r_pitch,pinion (4-27)", 1e-18, 1e-2,
           "MEMS micromotors give pN m to uN m; 0.01 N m would break any microgear"),
    _range("pinion_speed", "rad/s", "Angular speed omega1 of the pinion: sets the time axis and the surface and sliding "
           "speeds, so the friction power and the flash and bulk temperatures (docs/thermal.md); the friction force "
           "itself, from the dissipated energy per distance, does not depend on it", 1e-6, 1e7,
           "from a crawl to 100 million rpm"),
    # --- meshing simulation ---------------------------------------------------------------------
    _range("mesh_steps", "", "Steps (positions c) of the meshing simulation from c_f to c_l", 3, 100_000,
           "3 to 100 000 (memory grows with steps x window/grid spacing: 100 000 steps of the default window "
           "take 6.4 GB)", kind="int"),
    _range("mesh_grid_spacing", "m", "Element width of the rough line-contact solve at each step; unset: the "
           "largest Hertz width 2a of the load case / mesh_elements_across_contact", 1e-11, 1e-6,
           "0.01 nm (below an atomic distance) to 1 um; window / spacing is at most 1 million elements",
           optional=True),
    _range("mesh_window", "m", "Length of the contact window solved at each step, centred on the contact point; "
           "unset: 2.4 a + 6 w_adh of the largest Hertz half-width a of the load case", 1e-8, 1e-3,
           "10 nm to 1 mm; window / grid spacing is at most 1 million elements", optional=True),
    _range("mesh_contact_tolerance", "", "Tolerance of the rough line-contact solver (dimensionless residual)",
           1e-14, 1e-2, "a residual above 1 % is no solution; below 1e-14 round-off stops convergence"),
    ParameterSpec("load_sharing", "", "Load-sharing function over the mesh (Figure 4-11): dry or lubricated",
                  kind="str", choices=("dry", "lubricated")),
    _range("elastic_limit_pressure", "Pa",
           "Hertz peak pressure beyond which the elastic model of silicon no longer holds", 1e6, 1e12,
           "1 MPa to 1 TPa (above the strength of any solid)"),
    # --- coatings and wear ----------------------------------------------------------------------
    ParameterSpec("coating_wear", "", "Worn fraction Omega of the gear tooth's coating (0 coated, 1 bare; 5.5.3)",
                  minimum=0.0, maximum=1.0, why="a fraction"),
    # --- damage and lifetime --------------------------------------------------------------------
    _range("asperity_degree", "", "Degree d of the atomic asperity shape f(r) = B_d r^d (5-6)", 0.0, 50.0,
           "d > 0 (d = 2 paraboloid, 4 punch with rounded edges); beyond 50 the shape is a flat punch"),
    _range("asperity_shape_coefficient", "",
           "B_d of f(r) = B_d r^d, SI number in m^(1-d) (m^-3 for d = 4); give the number without a unit",
           1e-30, 1e200, "its unit depends on d; any positive number a float holds without overflow in B_d a^d"),
    _range("asperity_half_width", "m", "Half width of an atomic asperity (edge of the power-law shape, 5.5.2)",
           1e-11, 1e-6, "an atomic asperity is 0.01 nm to 1 um wide"),
    _range("asperity_friction_coefficient", "",
           "Friction coefficient mu of the traction mu*p on an atomic asperity in the stress solution", 0.0, 2.0,
           "dry friction coefficients of solids lie between 0 and 2", exclusive_minimum=False),
    _range("peaks_per_cycle", "", "Load peaks k on a nanoblock per meshing cycle (Figure 5-18)", 1, 100_000,
           "at least one peak; more than 100 000 per cycle is more than the steps of any mesh", kind="int"),
    _range("damage_exponent", "", "Exponent m of the damage law omega = sum c1 (dtau1)^m (5-10)", 0.0, 20.0,
           "fatigue exponents of brittle solids are below 20; (dtau)^m overflows beyond"),
    _range("damage_coefficient", "",
           "c1 of the damage law (5-10), SI number in Pa^-m; unset: unknown (relative lives only)", 1e-300, 1e300,
           "its unit depends on m: any positive finite number", optional=True),
    # --- sliding (flat-friction models, thesis 2.6.2, 3.4) ------------------------------------
    _range("sliding_gap", "m", "Fixed-gap model: height of the undeformed atomic tips above the counter "
           "profile's mean line (negative: interference); unset: the profile's Rq", -1e-7, 1e-6,
           "-100 nm (an interference deeper than a nanoblock crushes it) to 1 um (far out of contact)",
           optional=True, exclusive_minimum=False),
    _range("sliding_step", "m", "Sliding distance per step of the flat-friction models; unset: bond_length",
           1e-12, 1e-6, "1 pm to 1 um; sliding distance / step is at most 1 million steps", optional=True),
    _range("adhesive_layer_thickness", "m", "Thickness of the adhesive layer inside which an adhesive block "
           "forms vdW bonds and adheres, in the sliding models and the meshing cycle, for bare and coated "
           "blocks alike; unset: adhesive_height (thesis 3.5); the Maugis range h0 = w/sigma0 (MODEL §2, "
           "'memstribo constants') is the explicit alternative", 1e-12, 1e-5,
           "1 pm to 10 um (thicker than any nanoblock)", optional=True),
    # --- version 2: load case, adhesive interface, verdict (MODEL 7b, 7c) --------------------
    ParameterSpec("load_case", "", "Normal load of the meshing cycle: 'torque' (F_n = F_t / cos alpha_w from the "
                  "drive torque, shared by the pairs in mesh, over the whole face width; MODEL 7b) or 'thesis' "
                  "(normal_load as given, 25 uN in 4.9; its normal force is not the one the torque implies)",
                  kind="str", choices=("torque", "thesis")),
    ParameterSpec("interface_model", "", "vdW bonds of the meshing cycle: 'gap' (energy and attraction scaled by "
                  "(D0/max(D, D0))^2 at each block's local gap D, up to vdw_cutoff; MODEL 7c) or 'thesis' (full "
                  "energy inside a band of adhesive_layer_thickness, thesis 3.5)", kind="str",
                  choices=("gap", "thesis")),
    _range("vdw_cutoff", "m", "Local gap beyond which vdW bonds are neglected (interface_model 'gap'); a "
           "numerical parameter: doubling it changes the mean COF by less than 1 %", 1e-10, 1e-6,
           "from about the contact separation D0 to 1 um (the attraction is 1e-9 of its contact value there)"),
    ParameterSpec("environment", "", "Environment of the teeth: 'vacuum' (the thesis) or 'air' (water condenses in "
                  "narrow gaps: capillary menisci, issue #17)", kind="str", choices=("vacuum", "air")),
    _range("relative_humidity", "", "Relative humidity of the air (environment 'air')", 0.0, 0.99,
           "0 (dry) to 0.99 (the Kelvin radius diverges at saturation)", exclusive_minimum=False),
    _range("water_contact_angle", "rad", "Water contact angle of the bare (oxidised) silicon surface; a coating's "
           "own angle replaces it on coated blocks", 0.0, math.pi, "0 to 180 deg", exclusive_minimum=False),
    ParameterSpec("vapour", "", "Condensable vapour of the environment 'air' (issue #36): 'water' or 'pentanol' (the "
                  "alcohol vapour lubricant of MEMS); its surface tension, molar volume, contact angle and isotherm "
                  "are data (memstribo.physics.vapours); one vapour at a time", kind="str",
                  choices=("water", "pentanol")),
    ParameterSpec("surface_termination", "", "Chemistry of the bare silicon flanks (issue #36): 'oxide' (native "
                  "oxide, silanols: hydrophilic) or 'hydrogen' (HF-etched Si-H: hydrophobic to water); sets the "
                  "vapour's contact angle and adsorbed film (memstribo.physics.vapours)", kind="str",
                  choices=("oxide", "hydrogen")),
    _range("vapour_pressure_ratio", "", "p / p_sat of the vapour (environment 'air'); unset: relative_humidity (for "
           "water they are the same)", 0.0, 0.99, "0 (none) to 0.99 (the Kelvin radius diverges at saturation)",
           exclusive_minimum=False, optional=True),
    _range("meniscus_renewal_distance", "m", "Sliding distance after which a meniscus has broken and re-formed "
           "(its rupture energy is dissipated once per distance); unset: atomic_pitch", 1e-10, 1e-5,
           "from an atomic distance to 10 um", optional=True),
    ParameterSpec("mesh_contact", "", "Contact solve of the meshing cycle: 'line' (a plane-strain line contact per "
                  "nanoblock row, rows carry equal line loads) or 'surface' (the strip of the face width under the "
                  "window as one surface contact per step: rows share the load elastically)", kind="str",
                  choices=("line", "surface")),
    ParameterSpec("contact_adhesion", "", "Adhesion inside the rough contact solve of the meshing cycle: 'maugis' "
                  "(the default: Maugis-Dugdale cohesive zone, sigma0 and h0 from the constants; MODEL 7c) or 'none' "
                  "(adhesion as the sum of block pull-off forces, 3-31, as in the thesis)",
                  kind="str", choices=("maugis", "none")),
    _range("mesh_elements_across_contact", "", "Contact elements across the largest Hertz width 2a when "
           "mesh_grid_spacing is unset", 8, 4096,
           "8 resolve nothing finer than the Hertz width; 4096 make a step slow", kind="int"),
    _range("friction_averaging_distance", "m", "Sliding distance over which the friction force of the verdict "
           "averages the dissipated energy (MODEL 7b); unset: atomic_pitch, the distance over which the bond "
           "population renews", 1e-11, 1e-4, "from a bond length to the whole sliding of a cycle", optional=True),
    _range("realisations", "", "Independent roughness realisations of the stiction verdict (ensemble, MODEL 7b)",
           1, 10000, "1 to 10 000 meshing cycles", kind="int"),
    _range("mesh_step_refinements", "", "Most comparisons of the meshing cycle at doubled steps (2N - 1) before the "
           "step check gives up (MODEL 7d: margin within 2 % of |margin|, mean COF within 2 %); 0 skips the check", 0,
           8, "0 (no check) to 8 doublings (the last cycle has 256 times the steps)", kind="int",
           exclusive_minimum=False),
    _range("mesh_grid_refinements", "", "Most comparisons of the meshing cycle at a doubled grid resolution "
           "(mesh_elements_across_contact doubled, or mesh_grid_spacing halved) before the grid check gives up "
           "(MODEL 7d); 0 skips the check", 0, 8, "0 (no check) to 8 doublings (256 times the elements: slow, and "
           "bounded by the memory check)", kind="int", exclusive_minimum=False),
    _range("mesh_friction_passes", "", "Most passes of the F_t/F_f fixed point of dissimilar teeth (thesis 4.6 step "
           "7); a cycle that has not settled by then is 'undetermined'", 1, 1000,
           "at least one pass; settling takes 3 to 6 (docs/interface.md), 1000 is far beyond any that would",
           kind="int"),
    # --- coating properties: unset = the coating's own parameter set (coatings/*.toml) -------------
    _range("coating_vdw_bond_energy", "J", "U_vdW of the coated pair; unset: the coating's parameter set "
           "('memstribo parameters --coating NAME')", 1e-25, 1e-19, "weaker than a silicon vdW bond by up to 4 "
           "decades, never stronger than a chemical bond", optional=True),
    _range("coating_hamaker_constant", "J", "Hamaker constant A of the coated pair; unset: the coating's set",
           1e-22, 1e-17, "Hamaker constants of solids lie between 1e-21 J and 5e-19 J", optional=True),
    _range("coating_cutoff_distance", "m", "Contact separation D0 of the coated pair; unset: the coating's set",
           5e-11, 1e-9, _ATOMIC, optional=True),
    _range("coating_work_of_adhesion", "J/m^2", "Work of adhesion of the coated pair; unset: the coating's set",
           1e-6, 10.0, "surface energies of solids are below 5 J/m^2", optional=True),
    _range("ideal_shear_strength", "Pa", "Ideal shear strength of the tooth material: a friction stress above it is "
           "flagged as a warning (silicon: about 6.8 GPa, Roundy and Cohen 2001)", 1e6, 1e12,
           "1 MPa to 1 TPa (above the strength of any solid)"),
    # --- tooth strength and fatigue (MODEL §10, issue #30; docs/strength.md) -----------------------
    _range("dedendum_coefficient", "", "Dedendum h_f of the teeth in modules (root circle r - h_f m)", 1.0, 2.0,
           "the root must lie below the mating tip (1 m) with clearance; beyond 2 m the tooth is a post",
           prior={"distribution": "uniform", "bounds": (1.2, 1.35), "source": "ISO 53:1998 basic rack (1.25 m)",
                  "reason": "mask layouts use 1.2-1.35 m; the etch moves the root by a fraction of a micron"}),
    _range("root_fillet_coefficient", "", "Root fillet radius rho_f of the teeth in modules (circular fillet "
           "tangent to the flank and the root circle)", 0.05, 0.6,
           "a sharp etched corner (0.05 m) to the largest fillet a standard tooth space holds",
           prior={"distribution": "uniform", "bounds": (0.25, 0.45), "source": "ISO 53:1998 profile A (0.38 m)",
                  "reason": "lithography rounds corners by about the resolution (0.3-1 um at m = 3.9 um)"}),
    _range("strength_characteristic", "Pa", "Weibull characteristic tensile strength sigma_theta of the tooth "
           "material at the reference area (polysilicon)", 1e7, 2e10,
           "a strength must be positive; 10 MPa (a cracked ceramic) to 20 GPa (the ideal strength of silicon)",
           prior={"distribution": "uniform", "bounds": (1.5e9, 3.5e9),
                  "source": "LaVan et al. 2001 (ASTM STP 1413); Jadaan et al. 2003 "
                            "(doi:10.1023/A:1026317303377); Boyce 2010 (doi:10.1007/s11340-009-9286-x)",
                  "reason": "mean tensile strengths of surface-micromachined polysilicon from different labs and "
                            "foundries span 1.2-3.4 GPa; Boyce's threshold 1.45 GPa bounds it below"}),
    _range("weibull_modulus", "", "Weibull modulus m of the tensile strength", 0.0, 100.0,
           "m > 0 (m <= 0 is no distribution); above 100 the scatter is below any measurement's",
           prior={"distribution": "uniform", "bounds": (5.0, 20.0),
                  "source": "Jadaan et al. 2003 (doi:10.1023/A:1026317303377), review of polysilicon MEMS data",
                  "reason": "reported polysilicon Weibull moduli lie between about 5 and 20"}),
    _range("strength_reference_area", "m^2", "Effective stressed (sidewall) area A_0 of the specimens that "
           "measured strength_characteristic", 1e-14, 1e-4, "from a 100 nm square to a square centimetre",
           prior={"distribution": "loguniform", "bounds": (1e-10, 3e-9),
                  "source": "tensile bars of LaVan et al. 2001 and Boyce 2010 (gauge sections of a few um by tens "
                            "to hundreds of um)",
                  "reason": "the sidewall area of the specimens' gauge sections; their lengths differ by a decade"}),
    _range("fatigue_exponent", "", "Exponent n of the strength's fall with load cycles, sigma(N) = sigma N^(-1/n)",
           1.0, 1000.0, "n = 1 is a strength gone in ten cycles; above 1000 there is no fatigue",
           prior={"distribution": "uniform", "bounds": (20.0, 45.0),
                  "source": "Muhlstein, Brown and Ritchie 2001 (Mater. Res. Soc. Symp. Proc.)",
                  "reason": "stress amplitude at failure about 50 % of the low-cycle strength at 1e9-1e11 cycles: "
                            "n = log(N)/log(2) = 30-37; their scatter widens it"}),
    _range("fatigue_humidity_sensitivity", "", "Decades of fatigue life lost per unit of relative humidity above "
           "0.4 (the humidity of the stress-life data)", 0.0, 20.0,
           "0 (no humidity effect) to 20 decades per unit RH (any reported effect is smaller)",
           exclusive_minimum=False,
           prior={"distribution": "uniform", "bounds": (0.0, 8.0),
                  "source": "Alsem et al. 2005 (Appl. Phys. Lett. 86 041914); Theillet and Pierron 2009 "
                            "(doi:10.1063/1.3133357)",
                  "reason": "fatigue stops in high vacuum (Alsem 2005) and runs faster in humid air; no study "
                            "gives one number per unit RH, so the prior spans none to a strong effect"}),
    # --- temperature (MODEL §10, issue #30; docs/thermal.md) ---------------------------------------
    # a measured input (the environment), not sampled (MODEL 7d); in air also the menisci's Kelvin radius and
    # surface tension, which need liquid water (physics/capillary.py refuses temperatures outside its range)
    _range("ambient_temperature", "K", "Temperature of the surroundings and of the teeth away from the contact "
           "(in air also of the water of the menisci)", 0.0, 1687.0,
           "above 0 K and below the melting point of silicon (1687 K)", exclusive_maximum=True),
    _range("thermal_conductivity", "W/m/K", "Thermal conductivity k of the tooth material (polysilicon)", 0.1,
           3000.0, "from a porous insulator to diamond",
           prior={"distribution": "uniform", "bounds": (15.0, 80.0),
                  "source": "Tai, Mastrangelo and Muller 1987 (IEDM); McConnell et al. 2001 (J. Microelectromech. "
                            "Syst. 10 360)",
                  "reason": "doped and undoped LPCVD polysilicon layers at room temperature, set by grain size "
                            "and doping; single-crystal silicon's 148 W/(m K) bounds it above"}),
    _range("thermal_diffusivity", "m^2/s", "Thermal diffusivity kappa = k / (rho c) of the tooth material", 1e-8,
           1e-3, "from polymers to diamond",
           prior={"distribution": "uniform", "bounds": (9.2e-6, 4.9e-5),
                  "source": "thermal_conductivity's range over rho c = 2330 kg/m^3 x 703 J/(kg K) (silicon, "
                            "Incropera et al. 2007, Table A.1)",
                  "reason": "the conductivity's uncertainty; rho c of silicon is known to 1 %"}),
    _range("heat_transfer_coefficient", "W/m^2/K", "In air only (environment 'air'): conductance per unit area "
           "across the air gap from a gear's face to the substrate, in parallel with the hub and radiation (in vacuum "
           "no gas carries heat and it is not used)", 1.0,
           1e7, "from still air to a bonded metal contact",
           prior={"distribution": "loguniform", "bounds": (1e3, 1e5),
                  "source": "conduction across the air gap to the substrate, k_air / g with k_air = 0.026 W/(m K) "
                            "(Incropera et al. 2007, Table A.4)",
                  "reason": "gaps of 0.3 to 20 um between a released gear and its substrate"}),
    # heat in vacuum (issue 38, MODEL 7h): the hub and radiation carry the heat away; informative priors, not sampled
    _range("hub_thermal_conductance", "W/K", "Thermal conductance from a gear's disc through its hub (the bore-hub "
           "contact and the anchor) to the substrate, the same for both gears; 0: the gears lose heat by radiation "
           "only (and, in air, across the air gap)", 0.0, 0.1,
           "no negative conductance; 0.1 W/K is a silicon post 1 mm across and 1 mm tall, far beyond any MEMS anchor",
           exclusive_minimum=False,
           prior={"distribution": "loguniform", "bounds": (1e-8, 1e-4),
                  "source": "contact resistances in vacuum, R''_tc = 0.1e-4 to 25e-4 m^2 K/W (Incropera et al. 2007, "
                            "Table 3.1), over a bore-hub interface of 2 pi r_h b = 6.3e-11 m^2 (r_h = 5 um, b = 2 um): "
                            "2.5e-8 to 6.3e-6 W/K",
                  "reason": "a clearance fit that touches on a few asperities (a 10 nm spot conducts 2 k a = 6e-7 "
                            "W/K) up to the disc's own radial conductance 2 pi k b / ln(r_f / r_h) = 2e-4 W/K"}),
    _range("emissivity", "", "Total hemispherical emissivity of the gears' surfaces (radiation to the surroundings, "
           "h_r = 4 eps sigma T^3 = 3.6 W/(m^2 K) at 0.6 and 298 K)", 0.0, 1.0,
           "a grey surface emits more than nothing and at most as a black body",
           prior={"distribution": "uniform", "bounds": (0.1, 0.7),
                  "source": "Sato 1967 (Jpn. J. Appl. Phys. 6 339); Timans 1993 (J. Appl. Phys. 74 6353)",
                  "reason": "heavily doped silicon emits at 0.6-0.7 in the infrared; a 2 um layer, or a lightly "
                            "doped one, is partly transparent there and emits less"}),
    # --- version 3: what the verdict hangs on (MODEL 7d, issue #26) ------------------------------
    ParameterSpec("lattice_registry", "", "Registry of the atomic-block lattices of the two flanks along the sliding "
                  "direction: 'random' (each nanoblock row its own phase and orientation, seeded like the roughness "
                  "lines: polysilicon grains, flanks cut across crystal planes; MODEL 7d) or 'shared' (every row in "
                  "the same registry: a commensurate single-crystal contact, version 2)", kind="str",
                  choices=("random", "shared")),
    _range("startup_dwell", "s", "Dwell of the teeth at rest before start-up (the start-up verdict); unset: long "
           "enough for every bond to form", 0.0, 1e9, "no negative time; up to 30 years at rest", optional=True,
           exclusive_minimum=False),
    _range("ageing_onset_time", "s", "Onset time t_c of the bonds' ageing at rest: ln(1 + dwell / t_c) / "
           "ln(1 + t_full / t_c) of the bonds has formed after a dwell (linear below t_c, logarithmic above; MODEL 7f)",
           1e-6, 1e6, "a microsecond to 11 days",
           prior={"distribution": "loguniform", "bounds": (0.01, 1.0),
                  "source": "silica nanocontacts age linearly from 5 to 90 ms (Tian et al. 2020) and logarithmically "
                            "from 0.1 to 100 s (Li et al. 2011)",
                  "reason": "the crossover between the two measured regimes, a decade each way of 0.1 s"}),
    _range("ageing_full_time", "s", "Dwell t_full after which every bond has formed (the logarithmic ageing law's "
           "normalisation; MODEL 7f)", 1e-3, 1e9, "a millisecond to 30 years",
           prior={"distribution": "loguniform", "bounds": (1e2, 1e5),
                  "source": "Li et al. 2011: the static friction of silica nanocontacts still grows logarithmically at "
                            "100 s, without saturating",
                  "reason": "no saturation measured: from the longest measured hold (100 s) to a day"}),
    _range("load_torque", "N m", "Load torque on the driven gear at start-up (the start-up torque balance, MODEL 7f); "
           "0: the whole drive torque is free to overcome friction, as in the running verdict", 0.0, 1e-3,
           "no negative torque; up to 1 mN m, beyond any microgear", exclusive_minimum=False),
    _range("hardness", "Pa", "Indentation hardness of the teeth: the rough contact's pressure is capped at it "
           "(elastic-perfectly-plastic; MODEL 7d); unset (--set hardness=unset): no cap (purely elastic, the thesis); "
           "at most 6 times "
           "ideal_shear_strength (Tabor H = 3 Y, Tresca Y = 2 tau)", 1e6, 1e12,
           "1 MPa to 1 TPa (above the strength of any solid)", optional=True),
]

SPECS: dict[str, ParameterSpec] = {spec.name: spec for spec in _SPECS}


#: Keys of the ``[run]`` table of a config file (the main job, ``memstribo run``), with what each sets.
RUN_KEYS = {
    "uncertainty": "samples (roughness realisations x sets of the uncertain constants) of the stage 'What the verdict "
                   "hangs on' (MODEL 7d; default 64, 0 leaves the stage out)",
    "steps": "positions along the path of contact in each meshing simulation (default: the model's)",
    "loads": "external loads of the load sweep (default 25 to 300 uN in 25 uN steps, thesis 4.9.3)",
    "areas": "nominal contact areas of the area sweep, in multiples of A_adh = w_adh^2 (default 1, 2, 4, 8, 16)",
    "wear": "worn fractions Omega of the wear sweep (default 0, 0.2, 0.4, 0.6, 0.8, 1)",
    "coating": "coating of the coated stages (default 'OTS')",
    "roughness_files": "measured profiles / AFM files to analyse besides the default synthetic profile",
    "mesh_roughness": "which profile the meshing stages use: 'synthetic' (default) or the index of roughness_files",
    "stages": "stages to run (default: all)",
    "validation": "put the validation table into report.html (default true; computed at the end of the run)",
    "sliding_distance": "sliding distance of the structure in the sliding stage (default: the model's)",
    "cycles_observed": "observed coating life [meshing cycles] to calibrate c1 (default: none)",
    "realisations": "independent roughness realisations of the bare verdict (default 16: a 5-95 % band)",
    "map": "a design map spec file (memstribo map's TOML) run as the last stage: DIR/map/map.nc, the map figures "
           "and a report section (default: none)",
}

#: Defaults of the ``[run]`` table that other layers need too (the validation of the run's verdict).
RUN_DEFAULT_COATING = "OTS"
RUN_DEFAULT_WEAR = (0.0, 0.2, 0.4, 0.6, 0.8, 1.0)
