"""Nanoblocks: the hierarchical model of a rough silicon surface (thesis 2.6, 3.4, 4.2.3).

- :mod:`memstribo.physics.nanoblock.geometry`: block sizes, explicit or derived from a measured profile;
- :mod:`memstribo.physics.nanoblock.mechanics`: columns and hierarchical structures under a fixed gap
  or a fixed load, the bilinear law, elastic interlocking energy.
"""
