"""Tooth root stress (memstribo.physics.tooth_stress) against an independent 2D finite-element solve of one tooth.

The reference: plane-stress linear elasticity of one tooth with its rim (quadratic triangles,
scikit-fem), the tooth outline of :class:`ToothShape`, the rim clamped on its bottom arc at
r_f - 2 m and on the radial cuts through the middles of the neighbouring spaces (the
neighbouring teeth's material holds it there), the contact force applied at the flank node
nearest to the contact point. Its largest tangential stress on the loaded fillet is compared
with ISO 6336-3 method B as memstribo adapts it.
"""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.physics import tooth_stress as ts


def _resample(poly, spacing):
    closed = np.concatenate([poly, poly[:1]])
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(closed, axis=0), axis=1))])

    def at(t):
        return np.stack([np.interp(t, s, closed[:, 0]), np.interp(t, s, closed[:, 1])], -1)

    out, t = [0.0], 0.0
    while True:
        t += spacing(at(t))
        if t >= s[-1] - 0.5 * spacing(at(s[-1])):
            break
        out.append(t)
    return at(np.array(out))


def _tooth_mesh(shape, h_fine, h_coarse, rim=2.0):
    """Triangle mesh of one tooth and its rim: Delaunay of graded boundary and lattice points, smoothed."""
    import skfem
    from matplotlib.path import Path
    from scipy.spatial import Delaunay, cKDTree

    rho = shape.fillet_radius
    right = shape.outline(points_fillet=200, points_flank=200, points_tip=40, points_root=40)
    left = right[::-1] * np.array([-1.0, 1.0])
    r_rim = shape.root_radius - rim * shape.module
    space = math.pi / shape.teeth
    arc = np.linspace(-space, space, 60)
    poly = np.concatenate([np.stack([r_rim * np.sin(arc), r_rim * np.cos(arc)], 1), right, left[1:]])
    poly = poly[np.concatenate([[True], np.linalg.norm(np.diff(poly, axis=0), axis=1) > 1e-12])]
    centres = np.array([shape.fillet_centre, (-shape.fillet_centre[0], shape.fillet_centre[1])])

    def spacing(x):
        d = float(np.min(np.linalg.norm(centres - x, axis=-1))) - rho
        return float(np.clip(h_fine + 0.5 * max(d, 0.0), h_fine, h_coarse))

    boundary = _resample(poly, spacing)
    path = Path(poly)
    lo, hi = poly.min(0), poly.max(0)
    pts = []

    def lattice(x0, x1, y0, y1, h):
        for k, y in enumerate(np.arange(y0, y1, h * math.sqrt(3) / 2)):
            xs = np.arange(x0 + (h / 2 if k % 2 else 0.0), x1, h)
            pts.append(np.stack([xs, np.full_like(xs, y)], 1))

    lattice(lo[0], hi[0], lo[1], hi[1], h_coarse)
    for c in centres:
        lattice(c[0] - 2.5 * rho, c[0] + 2.5 * rho, c[1] - 2.5 * rho, c[1] + 2.5 * rho, 2 * h_fine)
        lattice(c[0] - 1.6 * rho, c[0] + 1.6 * rho, c[1] - 1.6 * rho, c[1] + 1.6 * rho, h_fine)
    inner = np.concatenate(pts)
    inner = inner[path.contains_points(inner)]
    h_loc = np.array([spacing(p) for p in inner])
    far = cKDTree(boundary).query(inner)[0] > 0.7 * h_loc
    inner, h_loc = inner[far], h_loc[far]
    order = np.argsort(h_loc)
    inner, h_loc = inner[order], h_loc[order]
    tree, removed, kept = cKDTree(inner), np.zeros(len(inner), bool), []
    for i in range(len(inner)):
        if not removed[i]:
            kept.append(i)
            removed[[j for j in tree.query_ball_point(inner[i], 0.7 * h_loc[i]) if j != i]] = True
    points = np.concatenate([boundary, inner[kept]])
    tri = Delaunay(points).simplices
    tri = tri[path.contains_points(points[tri].mean(1))]
    p = points[tri]
    area = 0.5 * np.abs((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
                        - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
    tri = tri[area > 1e-4 * np.array([spacing(c) for c in p.mean(1)]) ** 2]
    n_boundary = len(boundary)
    for _ in range(10):  # Laplacian smoothing of the inner points
        acc, cnt = np.zeros_like(points), np.zeros(len(points))
        for a, b in ((0, 1), (1, 2), (2, 0)):
            np.add.at(acc, tri[:, a], points[tri[:, b]])
            np.add.at(cnt, tri[:, a], 1)
            np.add.at(acc, tri[:, b], points[tri[:, a]])
            np.add.at(cnt, tri[:, b], 1)
        points[n_boundary:] = 0.5 * points[n_boundary:] + 0.5 * (acc / np.maximum(cnt, 1)[:, None])[n_boundary:]
    return skfem.MeshTri(points.T.copy(), tri.T.copy())


def fe_fillet_stress(shape, points, forces, h_fine=None, h_coarse=None, youngs_modulus=161e9, poisson_ratio=0.23):
    """Largest tangential stress on the right (loaded) root fillet for each load case [Pa for b = 1 m].

    ``points`` (n, 2) and ``forces`` (n, 2): one load case per row, each a force at the flank node nearest to
    its point; one factorisation serves them all.
    """
    skfem = pytest.importorskip("skfem")
    from skfem.helpers import ddot, eye, sym_grad, trace
    from skfem.models.elasticity import lame_parameters

    rho = shape.fillet_radius
    mesh = _tooth_mesh(shape, h_fine or rho / 20, h_coarse or 0.15 * shape.module)
    lam, mu = lame_parameters(youngs_modulus, poisson_ratio)
    lam = 2 * lam * mu / (lam + 2 * mu)  # plane stress
    element = skfem.ElementVector(skfem.ElementTriP2())
    basis = skfem.Basis(mesh, element, intorder=4)

    @skfem.BilinearForm
    def stiffness(u, v, w):
        strain = sym_grad(u)
        return ddot(2 * mu * strain + lam * eye(trace(strain), 2), sym_grad(v))

    matrix = stiffness.assemble(basis)
    r_rim, r_f, space, tol = np.hypot(*mesh.p).min(), shape.root_radius, math.pi / shape.teeth, 1e-6 * shape.module
    fixed = basis.get_dofs(lambda x: (np.hypot(x[0], x[1]) < r_rim + tol)
                           | ((np.abs(np.abs(np.arctan2(x[0], x[1])) - space) < 1e-6)
                              & (np.hypot(x[0], x[1]) < r_f + tol))).all()
    from scipy.sparse.linalg import splu

    points, forces = np.atleast_2d(points), np.atleast_2d(forces)
    free = np.setdiff1d(np.arange(matrix.shape[0]), fixed)
    lu = splu(matrix[free][:, free].tocsc())
    corners = skfem.Basis(mesh, element, quadrature=(np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), np.ones(3) / 6))
    p = mesh.p.T
    centre = np.array(shape.fillet_centre)
    on = (np.abs(np.linalg.norm(p - centre, axis=1) - rho) < 1e-4 * shape.module) & (p[:, 0] > 0)
    radial = p[on] - centre
    t = np.stack([-radial[:, 1], radial[:, 0]], 1) / np.linalg.norm(radial, axis=1)[:, None]
    count = np.zeros(mesh.p.shape[1])
    np.add.at(count, mesh.t.ravel(), 1)
    result = []
    for point, force in zip(points, forces):
        load = np.zeros(matrix.shape[0])
        k = int(np.argmin(np.linalg.norm(p - point, axis=1)))
        load[basis.nodal_dofs[0, k]], load[basis.nodal_dofs[1, k]] = force
        u = np.zeros(matrix.shape[0])
        u[free] = lu.solve(load[free])
        result.append(_fillet_maximum(corners.interpolate(u).grad, mesh, lam, mu, count, on, t))
    return np.array(result)


def _fillet_maximum(g, mesh, lam, mu, count, on, t):
    """Largest tangential stress at the fillet's vertices: the quadratic field's gradient at each element's
    corners, averaged over the elements of a vertex."""
    tr = g[0, 0] + g[1, 1]
    stress = []
    for comp in (2 * mu * g[0, 0] + lam * tr, 2 * mu * g[1, 1] + lam * tr, mu * (g[0, 1] + g[1, 0])):
        total = np.zeros(mesh.p.shape[1])
        np.add.at(total, mesh.t.T.ravel(), comp.ravel())
        stress.append(total / count)
    sxx, syy, sxy = (s[on] for s in stress)
    return float(np.max(sxx * t[:, 0] ** 2 + syy * t[:, 1] ** 2 + 2 * sxy * t[:, 0] * t[:, 1]))


@pytest.mark.parametrize("teeth, where, friction", [
    (19, "tip", 0.0),      # the pinion, load at its tip (the largest moment)
    (76, "tip", 0.0),      # the gear at its tip
    (19, "tip", 0.3),      # friction along the flank toward the tip (recess), adding to the moment
    (76, "upper", 0.3),    # the gear's upper flank with friction
])
def test_root_stress_matches_finite_elements_within_ten_percent(teeth, where, friction):
    shape = ts.tooth_shape(teeth, 1.0, math.radians(20.0))
    radius = {"tip": shape.tip_radius, "upper": 0.5 * (shape.pitch_radius + shape.tip_radius)}[where]
    point, normal, tangent = ts.flank_load_point(shape, radius)
    reference = fe_fillet_stress(shape, point, -1.0 * normal + friction * tangent)[0]
    formula = float(ts.root_stress(shape, radius, 1.0, friction, 1.0, friction_sign=1.0)["tensile"])
    assert formula == pytest.approx(reference, rel=0.10)


@pytest.mark.parametrize("name", ["pinion", "gear"])
def test_largest_root_stress_of_the_cycle_matches_finite_elements(name):
    """The cycle's root_stress_max (the number fracture rests on) against the FE maximum over the same cycle:
    the thesis pair at unit module, the dry load sharing, COF 0.3, nine positions from c_f to c_l."""
    from memstribo.physics.gear import GearPair

    pair = GearPair(19, 76, 1.0, math.radians(20.0), 1.0)
    c = pair.positions(9)
    normal_force = pair.load_share(c, "dry")
    friction = 0.3 * normal_force
    out = ts.cycle_root_stress(pair, c, normal_force, friction)[name]
    shape, radius = out["shape"], out["radius"]
    sign = np.where(c >= 0, 1.0, -1.0)
    point, normal, tangent = ts.flank_load_point(shape, radius)
    forces = -normal_force[:, None] * normal + (sign * friction)[:, None] * tangent
    reference = fe_fillet_stress(shape, point, forces)
    assert float(np.max(out["tensile"])) == pytest.approx(float(np.max(reference)), rel=0.10)


def test_iso_form_without_friction_is_ft_over_bm_times_yf_ys():
    """For a load on the line of action, sigma_F = F_t/(b m) Y_F Y_S with ISO's Y_F = 6 (h_Fe/m) cos(alpha_Fen) /
    ((s_Fn/m)^2 cos(alpha_n)) (ISO 6336-3 Eqs. (5), (30)): the moment form reproduces it."""
    shape = ts.tooth_shape(19, 1.0, math.radians(20.0))
    radius = shape.tip_radius
    out = ts.root_stress(shape, radius, 1.0, 0.0, 1.0)
    point, normal, _ = ts.flank_load_point(shape, radius)
    cos_load = abs(normal[0])  # the force's component across the centreline over F_n: cos(alpha_Fen)
    s, h = out["section_thickness"], float(out["lever_arm"])
    f_t = math.cos(shape.pressure_angle)  # F_n = 1
    y_f = 6 * h * cos_load / (s**2 * math.cos(shape.pressure_angle))
    assert float(out["bending"]) == pytest.approx(f_t * y_f * float(out["stress_correction"]), rel=1e-9)
    # the tension side adds the direct stress of the force's component along the centreline (compressive here)
    assert float(out["tensile"]) == pytest.approx(float(out["bending"]) + float(out["axial_force"]) / s, rel=1e-12)
    assert float(out["axial_force"]) < 0


def test_stress_correction_factor_formula():
    # ISO 6336-3 Eq. (37) at L = 1, q_s = 2: (1.2 + 0.13) * 2^(1 / 3.51)
    assert ts.stress_correction_factor(2.0, 2.0, 0.5) == pytest.approx(1.33 * 2 ** (1 / 3.51), rel=1e-12)


def test_stress_scales_with_force_and_friction_sign_matters():
    shape = ts.tooth_shape(19, 1.0, math.radians(20.0))
    one = float(ts.root_stress(shape, shape.tip_radius, 1.0, 0.0, 1.0)["tensile"])
    two = float(ts.root_stress(shape, shape.tip_radius, 2.0, 0.0, 1.0)["tensile"])
    assert two == pytest.approx(2 * one, rel=1e-12)
    up = float(ts.root_stress(shape, shape.tip_radius, 1.0, 0.3, 1.0, friction_sign=1.0)["tensile"])
    down = float(ts.root_stress(shape, shape.tip_radius, 1.0, 0.3, 1.0, friction_sign=-1.0)["tensile"])
    assert up > one > down  # friction toward the tip adds bending moment about the root


def test_bad_geometry_is_refused():
    with pytest.raises(InputError, match="fillet"):
        ts.tooth_shape(19, 1.0, math.radians(20.0), fillet_coefficient=1.5)
    shape = ts.tooth_shape(19, 1.0, math.radians(20.0))
    with pytest.raises(InputError, match="flank"):
        ts.root_stress(shape, shape.tip_radius * 1.1, 1.0, 0.0, 1.0)
