"""Layer 3, physics: one public function per published relation, by topic.

potentials (Lennard-Jones forms), adhesion (work of adhesion, pull-off, Maugis-Dugdale),
capillary (Kelvin, menisci), nanoblock (geometry and mechanics of the block model), friction
(bond counts, dissipated energy, COF), gear (involute geometry, load sharing, Hertz), contact /
adhesive_contact / surface_contact (boundary-element solvers), closed_form (Hertz, punches,
Westergaard: the solutions the solvers are checked against), asperity, stresses, damage, coating.
Each function states its unit, its equation number and its reference; the simulations call
exactly these functions.
"""
