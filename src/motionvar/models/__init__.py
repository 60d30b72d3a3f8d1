"""Generic learned models that more than one paper uses (shared part: imports no paper
package).

- :mod:`.bayesian_gplvm` — Bayesian GPLVM (Titsias & Lawrence 2010) in torch.
"""
