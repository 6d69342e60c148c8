"""Layer 4, simulations: the physics composed over time and over parameters.

sliding (single / fixed-gap / fixed-load sliding of flat surfaces, thesis 2.6, 3.4), mesh (the
meshing cycle and its ensemble and sweeps, thesis 4.6, 4.9), study (parameter studies on
dask.distributed), design_map (grids of ensemble verdicts).
"""
