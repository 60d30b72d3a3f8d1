"""Baselines of Ma et al. 2010, Sec. 2 and 7.4 (used by :mod:`motionvar.ma2010.comparison`
and the evaluations):

- :mod:`.perlin` — noise added to joint rotations [Per95] (the noise itself:
  :func:`motionvar.core.noise.perlin_noise`).
- :mod:`.rbf` — radial basis function interpolation with a linear term (Rose et al. 1998).
- :mod:`.mukai_kuriyama` — universal Kriging of whole clips over the style parameters only
  (Mukai & Kuriyama 2005), and the RBF counterpart on the same clips.
- :mod:`.gplvm` — the helix trajectory along which Sec. 7.4's GPLVM baseline is driven.
  The GPLVM itself is the project's shared Bayesian GPLVM
  (:mod:`motionvar.models.bayesian_gplvm`, Titsias & Lawrence 2010), a stronger model than
  the MAP GPLVM of Lawrence 2003 [Law03] that the paper compares with.
- :mod:`.dbn` — linear-Gaussian dynamic Bayesian networks after Lau et al. 2009 (a prior
  network and a transition network unrolled over time).

This package imports nothing at init, so that :mod:`.mukai_kuriyama` may use the model's
modules (:mod:`motionvar.ma2010.svi`) without an import cycle.
"""
