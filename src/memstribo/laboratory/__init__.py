"""Against the laboratory: published MEMS measurements, their predictions with uncertainty, a calibration (MODEL 7e).

- :mod:`.data`: the measurements (``measurements.toml``) and their checks;
- :mod:`.predict`: each row's case at the paper's conditions, median and 90 % band;
- :mod:`.calibration`: importance sampling of prior samples on the declared calibration rows;
- :mod:`.fitted`: the fitted constants a run uses and the warnings when it runs far from their fit;
- :mod:`.report`: docs/experiments.md and its figure (``python -m memstribo.laboratory``).
"""
