"""Baselines of Ma et al. 2010, Sec. 7.4 (shared with the other papers' evaluations):

- :mod:`.perlin` — 1-D gradient (Perlin) noise over time for any number of channels, and
  noise added to joint rotations [Per95].
- :mod:`.rbf` — radial basis function interpolation with a linear term (Rose et al. 1998).
- :mod:`.kriging` — universal Kriging of whole clips over the style parameters only
  (Mukai & Kuriyama 2005), and the RBF counterpart on the same clips.
- :mod:`.gplvm` — a MAP Gaussian process latent variable model (Lawrence 2003) in torch,
  with a helix trajectory in its latent space.
- :mod:`.dbn` — linear-Gaussian dynamic Bayesian networks after Lau et al. 2009 (a prior
  network and a transition network unrolled over time).
"""
