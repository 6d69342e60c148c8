"""References as data, and a record of which ones a run used.

Each model function names its sources with :func:`cites`; calling it records the keys,
so a run can list the papers it rests on (:func:`used_references`), as PyBaMM's
``print_citations`` does. Add new sources to :data:`REFERENCES`.

Work done elsewhere (a Dask worker process computing a study or map point) records its keys
in that process: :func:`collect_references` gathers the keys one piece of work used (in this
thread), so that the worker can return them with the result, and :func:`record_references`
adds returned keys to this process's record.
"""

from __future__ import annotations

import contextlib
import functools
import threading

REFERENCES: dict[str, str] = {
    "thesis": (
        "N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and functionalized gear "
        "microelectromechanical systems', PhD thesis, Cardiff University. Equation numbers such as (3-7) in "
        "memstribo's docstrings are this thesis's."
    ),
    "model": "memstribo's specification, docs/model.md (decisions where the thesis is ambiguous).",
    "borodich_savencu_2017": (
        "F. M. Borodich, O. Savencu, 'Hierarchical models of engineering rough surfaces and bio-inspired "
        "adhesives', in Bio-inspired Structured Adhesives, Springer, 2017. doi:10.1007/978-3-319-59114-8_10"
    ),
    "borodich_2014": (
        "F. M. Borodich, 'The Hertz-type and adhesive contact problems for depth-sensing indentation', "
        "Adv. Appl. Mech. 47 (2014) 225-366. doi:10.1016/B978-0-12-800130-1.00003-5"
    ),
    "galin_1961": "L. A. Galin, Contact Problems in the Theory of Elasticity, 1953; transl. NC State College, 1961.",
    "sneddon_1965": (
        "I. N. Sneddon, 'The relation between load and penetration in the axisymmetric Boussinesq problem "
        "for a punch of arbitrary profile', Int. J. Eng. Sci. 3 (1965) 47-57. doi:10.1016/0020-7225(65)90019-4"
    ),
    "johnson_1985": "K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985. doi:10.1017/CBO9781139171731",
    "hamilton_1983": (
        "G. M. Hamilton, 'Explicit equations for the stresses beneath a sliding spherical contact', "
        "Proc. IMechE C 197 (1983) 53-59. doi:10.1243/PIME_PROC_1983_197_076_02"
    ),
    "polonsky_keer_1999": (
        "I. A. Polonsky, L. M. Keer, 'A numerical method for solving rough contact problems based on the "
        "multi-level multi-summation and conjugate gradient techniques', Wear 231 (1999) 206-219. "
        "doi:10.1016/S0043-1648(99)00113-1"
    ),
    "maugis_1992": (
        "D. Maugis, 'Adhesion of spheres: the JKR-DMT transition using a Dugdale model', "
        "J. Colloid Interface Sci. 150 (1992) 243-269. doi:10.1016/0021-9797(92)90285-T"
    ),
    "rey_2017": (
        "V. Rey, G. Anciaux, J.-F. Molinari, 'Normal adhesive contact on rough surfaces: efficient algorithm for "
        "FFT-based BEM resolution', Comput. Mech. 60 (2017) 69-81. doi:10.1007/s00466-017-1392-5"
    ),
    "bazrafshan_2017": (
        "M. Bazrafshan, M. B. de Rooij, M. Valefi, D. J. Schipper, 'Numerical method for the adhesive normal "
        "contact analysis based on a Dugdale approximation', Tribol. Int. 112 (2017) 117-128. "
        "doi:10.1016/j.triboint.2017.04.001"
    ),
    "baney_hui_1997": (
        "J. M. Baney, C.-Y. Hui, 'A cohesive zone model for the adhesion of cylinders', J. Adhes. Sci. Technol. "
        "11 (1997) 393-406. doi:10.1163/156856197X00822"
    ),
    "johnson_greenwood_2008": (
        "K. L. Johnson, J. A. Greenwood, 'A Maugis analysis of adhesive line contact', J. Phys. D: Appl. Phys. "
        "41 (2008) 155315. doi:10.1088/0022-3727/41/15/155315"
    ),
    "kendall_1971": (
        "K. Kendall, 'The adhesion and surface energy of elastic solids', J. Phys. D 4 (1971) 1186. "
        "doi:10.1088/0022-3727/4/8/320"
    ),
    "israelachvili_2011": "J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press, 2011.",
    "iso_4287": "ISO 4287:1997, Geometrical Product Specifications (GPS) - Surface texture: Profile method.",
    "iso_25178": "ISO 25178-2:2012, Geometrical product specifications (GPS) - Surface texture: Areal.",
    "fritsch_carlson_1980": (
        "F. N. Fritsch, R. E. Carlson, 'Monotone piecewise cubic interpolation', SIAM J. Numer. Anal. 17 "
        "(1980) 238-246. doi:10.1137/0717021"
    ),
    "jacobs_2017": (
        "T. D. B. Jacobs, T. Junge, L. Pastewka, 'Quantitative characterization of surface topography using "
        "spectral analysis', Surf. Topogr.: Metrol. Prop. 5 (2017) 013001. doi:10.1088/2051-672X/aa51f8"
    ),
    "teodorescu_2009": (
        "M. Teodorescu, S. Theodossiades, H. Rahnejat, 'Impact dynamics of rough and surface protected MEMS "
        "gears', Tribol. Int. 42 (2009) 197-205. doi:10.1016/j.triboint.2008.04.012"
    ),
    "goryacheva_torskaya_2003": (
        "I. G. Goryacheva, E. V. Torskaya, 'Stress and fracture analysis in periodic contact problem for "
        "coated bodies', Fatigue Fract. Eng. Mater. Struct. 26 (2003) 343-348. doi:10.1046/j.1460-2695.2003.00620.x"
    ),
    "rabotnov_1963": "Yu. N. Rabotnov, 'On the equations of state for creep', Progress in Applied Mechanics, 1963.",
    "srinivasan_1998": (
        "U. Srinivasan, M. R. Houston, R. T. Howe, R. Maboudian, 'Alkyltrichlorosilane-based self-assembled "
        "monolayer films for stiction reduction in silicon micromachines', J. Microelectromech. Syst. 7 (1998) "
        "252-260. doi:10.1109/84.679393"
    ),
    "vollebregt_2014": (
        "E. A. H. Vollebregt, 'A new solver for the elastic normal contact problem using conjugate gradients, "
        "deflation, and an FFT-based preconditioner', J. Comput. Phys. 257 (2014) 333-351. "
        "doi:10.1016/j.jcp.2013.10.005"
    ),
    "ashurst_2001": (
        "W. R. Ashurst, C. Yau, C. Carraro, R. Maboudian, M. T. Dugger, 'Dichlorodimethylsilane as an anti-stiction "
        "monolayer for MEMS: a comparison to the octadecyltrichlorosilane self-assembled monolayer', "
        "J. Microelectromech. Syst. 10 (2001) 41-49. doi:10.1109/84.911090"
    ),
    "maboudian_howe_1997": (
        "R. Maboudian, R. T. Howe, 'Critical review: adhesion in surface micromechanical structures', "
        "J. Vac. Sci. Technol. B 15 (1997) 1-20. doi:10.1116/1.589247"
    ),
    "krajcinovic_1996": "D. Krajcinovic, Damage Mechanics, North-Holland (Elsevier), 1996.",
    "hu_1986": (
        "J. Z. Hu, L. D. Merkle, C. S. Menoni, I. L. Spain, 'Crystal data for high-pressure phases of silicon', "
        "Phys. Rev. B 34 (1986) 4679-4684. doi:10.1103/PhysRevB.34.4679"
    ),
    "hamilton_goodman_1966": (
        "G. M. Hamilton, L. E. Goodman, 'The stress field created by a circular sliding contact', "
        "J. Appl. Mech. 33 (1966) 371-376. doi:10.1115/1.3625051"
    ),
    "wilson_1927": (
        "E. B. Wilson, 'Probable inference, the law of succession, and statistical inference', "
        "J. Am. Stat. Assoc. 22 (1927) 209-212. doi:10.1080/01621459.1927.10502953"
    ),
    "clopper_pearson_1934": (
        "C. J. Clopper, E. S. Pearson, 'The use of confidence or fiducial limits illustrated in the case of the "
        "binomial', Biometrika 26 (1934) 404-413. doi:10.1093/biomet/26.4.404"
    ),
    "sobol_2001": (
        "I. M. Sobol', 'Global sensitivity indices for nonlinear mathematical models and their Monte Carlo "
        "estimates', Math. Comput. Simul. 55 (2001) 271-280. doi:10.1016/S0378-4754(00)00270-6"
    ),
    "saltelli_2010": (
        "A. Saltelli, P. Annoni, I. Azzini, F. Campolongo, M. Ratto, S. Tarantola, 'Variance based sensitivity "
        "analysis of model output. Design and estimator for the total sensitivity index', Comput. Phys. Commun. "
        "181 (2010) 259-270. doi:10.1016/j.cpc.2009.09.018"
    ),
    "herman_usher_2017": (
        "J. Herman, W. Usher, 'SALib: an open-source Python library for sensitivity analysis', J. Open Source "
        "Softw. 2 (2017) 97. doi:10.21105/joss.00097"
    ),
    "owen_1998": (
        "A. B. Owen, 'Scrambling Sobol' and Niederreiter-Xing points', J. Complexity 14 (1998) 466-489. "
        "doi:10.1006/jcom.1998.0487"
    ),
    "sharpe_1997": (
        "W. N. Sharpe, B. Yuan, R. Vaidyanathan, R. L. Edwards, 'Measurements of Young's modulus, Poisson's ratio, "
        "and tensile strength of polysilicon', Proc. IEEE MEMS '97 (1997) 424-429. doi:10.1109/MEMSYS.1997.581881"
    ),
    "sharpe_2000": (
        "W. N. Sharpe, K. Jackson, G. Coles, D. A. LaVan, 'Mechanical properties of different polysilicons', "
        "Proc. ASME IMECE 2000, MEMS, 255-259. doi:10.1115/IMECE2000-1100"
    ),
    "kittel_2005": "C. Kittel, Introduction to Solid State Physics, 8th ed., Wiley, 2005 (Table 3.1, cohesive energies).",
}

_used: dict[str, None] = {}
_local = threading.local()  # .collectors: the dicts of the open collect_references() blocks of this thread


def cites(*keys: str):
    """Decorator: record ``keys`` in the run's reference list each time the function runs."""
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise KeyError(f"unknown reference key(s) {unknown}; add them to memstribo.references.REFERENCES")

    def decorate(function):
        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            for key in keys:
                _used[key] = None
            collectors = getattr(_local, "collectors", None)
            if collectors:
                for collected in collectors:
                    for key in keys:
                        collected[key] = None
            return function(*args, **kwargs)

        wrapper.references = keys
        return wrapper

    return decorate


def used_references() -> list[tuple[str, str]]:
    """The references used since the start (or the last :func:`reset_used_references`)."""
    return [(key, REFERENCES[key]) for key in _used]


def reset_used_references() -> None:
    """Forget the references recorded so far."""
    _used.clear()


def record_references(keys) -> None:
    """Add ``keys`` (reference keys used by work done in another process) to the run's record.

    Raises
    ------
    KeyError
        A key that is not in :data:`REFERENCES`.
    """
    keys = list(keys)
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise KeyError(f"unknown reference key(s) {unknown}; add them to memstribo.references.REFERENCES")
    for key in keys:
        _used[key] = None


@contextlib.contextmanager
def collect_references():
    """Collect the reference keys used inside the ``with`` block, in this thread, in order of first use.

    Yields a dict whose keys fill in as cited functions run (the process-wide record of
    :func:`used_references` fills as before). Blocks may nest; each collects what ran inside it::

        with collect_references() as used:
            simulate_mesh(params)
        list(used)   # ['thesis', 'model', ...]
    """
    collected: dict[str, None] = {}
    stack = getattr(_local, "collectors", None)
    if stack is None:
        stack = _local.collectors = []
    stack.append(collected)
    try:
        yield collected
    finally:
        for i in range(len(stack) - 1, -1, -1):  # by identity: nested blocks may hold equal dicts
            if stack[i] is collected:
                del stack[i]
                break
