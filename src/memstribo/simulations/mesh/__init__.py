"""The meshing-cycle simulation: rough teeth through the whole path of contact (thesis 4.6, 4.9).

The package's rooms, in the order a cycle runs (each module opens with one line on what it is):

``setup``      geometry and load, positions, window, the roughness line of every row (:class:`MeshSetup`)
``contacts``   the rough contact of each step and row (line or surface solve, cohesive zone, menisci, shear)
``interface``  nanoblock lattices, the vdW share at a gap, the lattice overlap, interlocking
``steps``      the step loop: contact, bonds, menisci, interlocking, adhesion of every row and step
``verdict``    friction averaged over sliding, R(c), stiction margin, efficiency, warnings, :func:`summarize`
``limits``     what the verdict hangs on (MODEL 7d): the start-up verdict, the local limits and their margins
``record``     the cycle as an xarray Dataset
``cycle``      :func:`simulate_mesh` top-down, the friction fixed point, :func:`step_convergence`
``ensemble``   :func:`simulate_ensemble` over roughness realisations
``sweeps``     :func:`sweep` (load, torque, area, humidity, ...) and :func:`critical_humidity`


memstribo's version of the thesis's "true gap" algorithm (Figure 4-18, MODEL.md §7), with a
real elastic contact solver in place of the thesis's unpublished one. For every position ``c``
of the contact point on the line of action (every time step) from the first to the last point
of contact:

1. **Roughness at the contact.** Each flank carries its own roughness profile attached to its
   involute roll coordinate ``s_i`` (the arc length from the base circle, ``s = R^2 / (2 r_b)``
   with the radius of curvature ``R`` of (4-20), (4-21)). In a frame moving with the contact
   point (x along the common tangent, 0 at the contact point), the material of flank ``i``
   passes at its own surface speed ``u_i`` (4-12): the pinion's point at roll coordinate
   ``sigma_1`` sits at ``x = s_1(c) - sigma_1``, the gear's at ``x = sigma_2 - s_2(c)``.
   The undeformed gap is ``h(x) = x^2 / (2 R_ef(c)) - z_1(s_1 - x) - z_2(s_2 + x)`` (4-8 to 4-11).
2. **Rough contact.** :func:`memstribo.physics.contact.solve_line_contact` (free-boundary half-plane
   BEM) under the load per unit width of the step, ``w = share(c) F_ext / L_eff`` with the
   dry or lubricated load-sharing function (4.3.1): the single-tooth zone carries the full
   load. The window (``mesh_window``) is checked at every step: the contact must not reach
   its ends. The Hertz contact is only ~90 nm wide (less than one nanoblock, 195.5 nm), so
   the grid is fine (``mesh_grid_spacing`` = 2 nm: ~40 elements across it).
3. **Nanoblocks.** Nanoblocks tile each flank on a square lattice of period ``w_adh`` along the
   flank and across the face width (``floor(L / w_adh)`` rows; the face width covered by whole
   rows, ``L_eff``, carries the load). Each nanoblock carries ``m x m`` atomic blocks at the pitch
   ``atomic_pitch``. A nanoblock's load is the contact pressure integrated over its footprint
   (``w_adh`` times the integral along x); the **fixed-load nanoblock model** (3.4.2,
   :func:`memstribo.physics.nanoblock.mechanics.structure_fixed_load`) then shares it among its atomic
   blocks, whose interference with the counter surface is minus the local deformed gap of the
   contact solution at their centres ("each block sits at the local height of its flank").
   This is the *decoupled* block-load variant (the contact solve does not see the block
   springs); the dataset says so in its ``block_load_variant`` attribute.
4. **Bonds and energies.** Chemical bonds form over the overlap, along x, of opposing atomic
   blocks that both touch (3-10): ``N_chem = m w_at L_chem / D_chem^2`` per overlapping pair
   (``m`` rows of atomic blocks across each nanoblock, aligned across the face width). As the
   two lattices slide past each other the overlaps, bond counts and block loads fluctuate (the
   peaks of Figure 5-18). Each pinion nanoblock holds van der Waals bonds over the length
   ``L_vdW`` of its footprint where the gap is inside the adhesive layer (thickness
   ``adhesive_layer_thickness``; unset: the adhesive-block height ``H_adh``, thesis 3.5, the
   same rule as the flat sliding models, :func:`memstribo.physics.nanoblock.geometry.adhesive_layer_thickness`;
   the Maugis range ``h0 = w / sigma0`` of MODEL §2 is an explicit alternative):
   ``N_vdW = w_adh L_vdW / D_chem^2`` (3-12), and adds its pull-off force
   ``sqrt(8 pi w12 E* C_NS a^3)``, ``a = L_vdW / 2`` (3-31, 3-32). All bonds break and re-form
   every bond length of sliding (3.5): the friction force of the bonds is
   ``(N_chem U_chem + N_vdW U_vdW) / D_chem``; the energy dissipated in a step is that force
   times the step's sliding distance ``|u1 - u2| dt``. Elastic interlocking (3-25):
   ``1/2 k de^2`` for the change of every atomic and adhesive block's compression between
   steps, times the sliding part of the relative motion ``|u1 - u2| / (u1 + u2)`` (pure rolling
   is reversible). Zero sliding at the pitch point gives zero dissipation in that step.
5. **Friction, adhesion, COF, stiction.** ``F_f`` (and its split), ``F_adh``, the apparent COF
   ``mu = F_f / (F_N + F_adh)`` (3-7) split into chemical, vdW and elastic parts (3-8, 3-9), and
   the stiction margin ``F_t - F_f`` with the pair's share of ``F_t = T / r_1`` (4-27). For
   dissimilar materials (Dundurs beta != 0) the friction traction ``mu p`` changes the normal
   gap by ``(2 beta / E*) mu sign(u1 - u2) int p dx``: the cycle is repeated with it until
   ``F_f`` changes by less than 1e-3 (thesis 4.6 step 7); for identical materials one pass
   is exact.

Coatings (thesis 5.5.3): the pinion's coating is fully worn; a fraction ``wear`` (Omega) of the
gear's nanoblocks is bare, chosen deterministically by a low-discrepancy sequence over the
block lattice. A coated gear block forms no chemical bonds; vdW bonds over it use the
coating's bond energy and work of adhesion, inside the same adhesive layer as a bare block
(the layer is a geometric band of the nanoblock model, not a property of the chemistry).
``wear=1`` is bare silicon.
"""

from __future__ import annotations

from memstribo.simulations.mesh.cycle import simulate_mesh, step_convergence
from memstribo.simulations.mesh.convergence import check_cycle, refined_cycle, run_check
from memstribo.simulations.mesh.ensemble import REALISATION_KEYS, _ensemble_point, ensemble_summary, simulate_ensemble
from memstribo.simulations.mesh.interface import lattice_overlap_across, vdw_gap_factor
from memstribo.simulations.mesh.record import BLOCK_LOAD_VARIANT
from memstribo.simulations.mesh.setup import (HERTZ_RATIO_LIMIT, MeshSetup, _read_roughness, normal_force_of_load_case,
                                              orient_map, roll_coordinate)
from memstribo.simulations.mesh.sweeps import critical_humidity, sweep
from memstribo.simulations.mesh.verdict import SUMMARY_KEYS, SUMMARY_UNITS, resisting_force, sliding_average, summarize

__all__ = ["MeshSetup", "simulate_mesh", "summarize", "sweep", "critical_humidity", "SUMMARY_UNITS", "refined_cycle",
           "check_cycle", "run_check",
           "BLOCK_LOAD_VARIANT", "roll_coordinate", "normal_force_of_load_case", "vdw_gap_factor",
           "lattice_overlap_across", "sliding_average", "resisting_force", "step_convergence",
           "simulate_ensemble", "ensemble_summary", "SUMMARY_KEYS", "REALISATION_KEYS", "HERTZ_RATIO_LIMIT",
           "orient_map"]
