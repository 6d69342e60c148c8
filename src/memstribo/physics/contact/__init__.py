"""Rough line contact: plane-strain half-plane boundary elements, FFT, constrained conjugate gradient.

The package's rooms (each module opens with one line on what it is):

``settings``   :class:`SolverSettings`, every tolerance, cap, switch and threshold, with what it trades
``halfplane``  the half-plane operator, its FFT products and preconditioner, the solution records
``inputs``     the input checks
``line``       the line solver (periodic and free boundary): active set, PCG, nested grids, Polonsky-Keer
``dense``      the small-grid dense path (Cholesky on contact sets; the compiled zone loop, physics/_zone_kernel.py)
``cohesive``   the cohesive-zone fixed point: Maugis-Dugdale and capillary, load or approach control
``solve``      :func:`solve_line_contact`, the public entry that picks one of the above
``plastic``    :func:`solve_line_contact_capped`, the pressure capped at the hardness (elastic-perfectly-plastic)

The normal contact of two elastic bodies with a rough gap is solved on the half-plane
(docs/model.md, section 7): the combined undeformed gap ``separation`` h(x) [m] is given on a
uniform grid of ``n`` piecewise-constant pressure elements of width ``dx`` [m]; the unknown is
the pressure p >= 0 [Pa] with the gap

    g(x) = h(x) + u(x) - approach >= 0,     p g = 0,     dx * sum(p) = load,

where u is the combined elastic surface displacement (positive: the surfaces move apart) and
``approach`` [m] the rigid-body approach. Two half-planes are offered:

``periodic=False`` (free boundary, the right model for a gear tooth)
    Influence coefficients of uniformly loaded strips (Johnson 1985, Eq. 2.25a), evaluated by
    a linear (zero-padded, non-periodic) FFT convolution. In plane strain the displacement
    under a finite load grows like ``log(distance)``, so it needs a datum: the displacement of
    a point load is taken as zero at ``reference_distance`` (default: the domain length
    n*dx), i.e. the kernel is ``(2/(pi E*)) ln(L/|x|)``; :func:`memstribo.physics.closed_form.hertz_line_approach`
    is exact for this datum.
``periodic=True`` (for comparison with periodic solvers)
    The spectral Green's function u_k = 2 p_k / (E* |q_k|) at the grid wavenumbers, with a
    zero mean displacement (the convention of ContactMechanics and Tamaas, so the same
    problem is solved).

The solver (load control) is a primal-dual active-set iteration: on each contact set a
conjugate gradient preconditioned with the inverse of the half-plane operator in Fourier
space (E*|q|/2), restricted to the set, in the manner of Vollebregt (2014); the initial guess
from nested coarser grids; Polonsky & Keer's (1999) constrained conjugate gradient as the
fallback and alternative. On small grids (FFT size <= 1024) contact sets of up to 256 elements
are solved directly (Cholesky) and the CG uses dense matrices instead of FFTs. The operator is diagonal in Fourier space with a symbol |q|^-1, so
plain CG iteration counts grow quickly with n; here they grow roughly like sqrt(n) and the
measured lead over Tamaas and ContactMechanics widens with n (docs/contact.md,
bench/README-contact.md).

References
----------
.. [1] I. A. Polonsky, L. M. Keer, Wear 231 (1999) 206-219. :doi:`10.1016/S0043-1648(99)00113-1`
.. [2] E. A. H. Vollebregt, 'A new solver for the elastic normal contact problem using conjugate
   gradients, deflation, and an FFT-based preconditioner', J. Comput. Phys. 257 (2014) 333-351.
   :doi:`10.1016/j.jcp.2013.10.005`
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985.
.. [4] V. Rey, G. Anciaux, J.-F. Molinari, 'Normal adhesive contact on rough surfaces: efficient
   algorithm for FFT-based BEM resolution', Comput. Mech. 60 (2017) 69-81.
   :doi:`10.1007/s00466-017-1392-5`
.. [5] M. Bazrafshan, M. B. de Rooij, M. Valefi, D. J. Schipper, 'Numerical method for the
   adhesive normal contact analysis based on a Dugdale approximation', Tribol. Int. 112 (2017)
   117-128. :doi:`10.1016/j.triboint.2017.04.001`
"""

from __future__ import annotations

from memstribo.physics.contact.settings import DEFAULTS, SolverSettings  # first: the other modules read it
from memstribo.physics.contact.halfplane import (ContactSolution, ContactSolve, HalfPlane, elastic_displacement,
                                                 strip_influence)
from memstribo.physics.contact.line import cylinder_on_flat
from memstribo.physics.contact.solve import solve_line_contact
from memstribo.physics.contact.plastic import PlasticContactSolution, solve_line_contact_capped

__all__ = ["ContactSolution", "ContactSolve", "solve_line_contact", "elastic_displacement", "strip_influence",
           "HalfPlane", "cylinder_on_flat", "SolverSettings", "DEFAULTS",
           "PlasticContactSolution", "solve_line_contact_capped"]
