"""What the verdict hangs on (MODEL 7d, issue 27): priors of the unmeasured constants, the stiction
probability with its confidence interval, global sensitivity and critical values.

Submodules (imported on use; ``import memstribo`` stays light):

- :mod:`memstribo.uncertainty.priors`: :class:`~memstribo.uncertainty.priors.Prior` and
  :func:`~memstribo.uncertainty.priors.priors_for` (the priors of a parameter set, as data in its TOML);
- :mod:`memstribo.uncertainty.sampling`: :func:`~memstribo.uncertainty.sampling.sample_constants`
  (scrambled, seeded Sobol / Latin-hypercube designs);
- :mod:`memstribo.uncertainty.intervals`: :func:`~memstribo.uncertainty.intervals.binomial_interval`,
  :func:`~memstribo.uncertainty.intervals.format_probability`,
  :func:`~memstribo.uncertainty.intervals.ensemble_interval`;
- :mod:`memstribo.uncertainty.rescale`: :func:`~memstribo.uncertainty.rescale.rescale_cycle` (a new bond
  energy without a new contact solve);
- :mod:`memstribo.uncertainty.study`: :func:`~memstribo.uncertainty.study.uncertainty_study`,
  :func:`~memstribo.uncertainty.study.critical_value`;
- :mod:`memstribo.uncertainty.decision`: the sensitivity of the decision (MODEL 7h):
  :func:`~memstribo.uncertainty.decision.regional_sensitivity` (stuck against free samples),
  :func:`~memstribo.uncertainty.decision.robust_bayes_band` (P(stiction) under priors moved by a factor 2);
- :mod:`memstribo.uncertainty.figures` and :mod:`memstribo.uncertainty.report`: the figures and the
  report section "What the verdict hangs on".
"""
