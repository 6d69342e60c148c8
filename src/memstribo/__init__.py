"""memstribo: friction, adhesion, stiction and coating wear of rough silicon MEMS gear teeth.

The model is organised by topic, one module each, in the order of the chain::

    roughness  -> nanoblock -> potentials/adhesion -> friction   (flat surfaces, thesis ch. 2-3)
    gear       -> contact   -> mesh                               (meshing cycle, ch. 4)
    coating    -> asperity/stresses -> damage                     (functionalised teeth, ch. 5)

Each public function implements one published relation in SI units; :mod:`memstribo.job.chain`
composes them into the main job (``memstribo run``). Heavy libraries (SurfaceTopography,
matplotlib, dask) are imported only where they are used, so ``import memstribo`` is quick.

The public API (:mod:`memstribo.api`, loaded on first use)
----------------------------------------------------------
read_surface(surface)            a measured surface as a Profile or SurfaceMap (heights in m)
parameter_set(name, **changes)   a validated parameter set (SI), with changes in any unit
mesh_cycle(params, surface)      one meshing cycle (or an ensemble): a MeshCycle
MeshCycle                        .dataset (xarray), .summary (dict), .ensemble, .plot(), .to_xarray()
sweep(params, parameter, values) meshing cycles over loads, torques or areas, as one dataset
run(config, out)                 the whole chain, roughness to damage, with report.html
design(spec, out)                the design search: the widest safe torque window (NSGA-II, resumable)
"""

#: the version: the top entry of CHANGELOG.md (pyproject.toml reads it; a test checks they agree)
__version__ = "3.0.0.dev0"

from memstribo.errors import ConvergenceError, DataFileError, InputError, MemstriboError  # noqa: E402
from memstribo.parameters import get_parameter_values  # noqa: E402

#: The public API (memstribo.api), imported on first use so that ``import memstribo`` stays quick.
_API = ("read_surface", "parameter_set", "mesh_cycle", "MeshCycle", "sweep", "run", "design")

__all__ = [
    "__version__",
    "ConvergenceError",
    "DataFileError",
    "InputError",
    "MemstriboError",
    "get_parameter_values",
    *_API,
]


def __dir__():
    """The module's names and the API's (loaded lazily), so that tab completion and ``dir`` offer them."""
    return sorted(set(globals()) | set(__all__))


def __getattr__(name):
    if name in _API:
        from memstribo import api

        return getattr(api, name)
    raise AttributeError(f"module 'memstribo' has no attribute {name!r}")
