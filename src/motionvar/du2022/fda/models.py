"""The fits of chapter 3 that rules make once and evaluations read: SFPCA at Table 3.1's
reference dimension (rule du2022_fda_sfpca, read by Table 3.1 and Fig. 3.10's curves), the check
that a fit read from a file is the one wanted, and the Bayesian GPLVM baseline (Sec. 3.3.5)."""

from __future__ import annotations

import numpy as np

from .functions import FunctionalMotions
from .primitives import sfpca_for
from .settings import FdaSettings, GplvmSettings, SfpcaSettings, TableSettings
from .sfpca import SFPCA


def reference_dims(n_clips: int, table: TableSettings) -> tuple[int, int]:
    """(d_max, d_ref) of Table 3.1 for a primitive of ``n_clips`` clips: the largest
    dimension searched (``table.max_components``) and the one SFPCA's weights are optimised
    at (``table.reference_components``), both capped at clips - 1 (the rank of the centred
    data)."""
    d_max = min(table.max_components, n_clips - 1)
    return d_max, min(table.reference_components, d_max)


def fit_reference_sfpca(fd: FunctionalMotions, settings: FdaSettings) -> SFPCA:
    """The SFPCA of Table 3.1 for one primitive: fitted at the reference dimension
    (:func:`reference_dims` of ``settings.table``) with settings ``settings.sfpca``
    (:func:`~.primitives.sfpca_for`). For the Fig. 3.10 primitives it is fitted once (rule
    du2022_fda_sfpca) and read by Table 3.1 and by their curves, which fit SFPCA at the same
    dimension with the same settings."""
    _, d_ref = reference_dims(fd.n_clips, settings.table)
    return sfpca_for(fd, d_ref, settings.sfpca).fit(fd)


def fitted_sfpca(model: SFPCA, fd: FunctionalMotions, sfpca: SfpcaSettings, source: str = "SFPCA model") -> SFPCA:
    """``model`` (an SFPCA fitted elsewhere, e.g. read from a file) checked to be the fit
    that :func:`sfpca_for` with settings ``sfpca`` would make on ``fd`` at its dimension:
    same clips, same options. ValueError naming ``source`` otherwise."""
    model.check_fitted_on(fd, source)
    wanted = sfpca_for(fd, int(model.n_components), sfpca)
    differ = {
        n: (getattr(model, n), getattr(wanted, n))
        for n in SFPCA._SAVED_PARAMS
        if getattr(model, n) != getattr(wanted, n)
    }
    if differ:
        said = ", ".join(f"{n} {a!r} (wanted {b!r})" for n, (a, b) in differ.items())
        raise ValueError(f"{source}: fitted with other options: {said}; rerun the rule that wrote it")
    return model


def fit_gplvm(fd: FunctionalMotions, d: int, gplvm: GplvmSettings, seed: int, labels: np.ndarray | None):
    """The Bayesian GPLVM baseline of dimension ``d`` on ``fd`` (Sec. 3.3.5) with settings
    ``gplvm``, initialised with ``seed``; ``labels``: those of the discriminative prior
    (None: none)."""
    from .functional_gplvm import FunctionalGPLVM

    return FunctionalGPLVM(
        d,
        n_inducing=gplvm.n_inducing,
        max_iter=gplvm.max_iter,
        noise_init=gplvm.noise_init,
        discriminative_sigma2=gplvm.discriminative_sigma2,
        random_state=seed,
    ).fit(fd, labels)
