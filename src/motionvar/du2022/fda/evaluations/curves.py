"""The measurements behind Du 2022 Fig. 3.10-3.11 for one primitive: for each method (FPCA,
normalized FPCA, SFPCA, Bayesian GPLVM) the average reconstruction error in feature and
observation space per number of latent dimensions, and the clips' latent coordinates at
the Fig. 3.11 dimension. They are measured once per primitive (the SFPCA and GPLVM fits
take minutes) and read by :func:`.fig3_10.evaluate_fig3_10` and
:func:`.fig3_11.evaluate_fig3_11`.

The measurements of one primitive are a flat dict of arrays (saved as one ``.npz``; they
are results, not a fitted model): ``primitive``, ``dims``, ``latent_dim``, ``labels``,
``n_basis``, ``n_clips``, ``canonical_frames``, ``methods`` and per method, keys prefixed
by its name, ``<method>/feature_error``, ``/observation_error``, ``/fit_seconds``,
``/info`` (one entry per dimension) and ``<method>/latent`` (clips x latent_dim).
"""

from __future__ import annotations

import logging
import time
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

if TYPE_CHECKING:
    from ..functions import FunctionalMotions
    from ..settings import FdaSettings
    from ..sfpca import SFPCA

log = logging.getLogger(__name__)

METHODS = ("fpca", "normalized_fpca", "sfpca", "gplvm")
#: the normalized FPCA of each du2022_fda.reconstruction.normalized_variant (Fig. 3.10 only)
NORMALIZED_METHODS = {
    "zscore": "normalized_fpca",
    "zscore_floored": "normalized_fpca_floored",
    "root_scaled": "root_scaled_fpca",
}


def kmeans_labels(fd: FunctionalMotions, positions: np.ndarray, n_clusters: int, seed: int) -> np.ndarray:
    """Thesis Sec. 3.3.5: labels of the discriminative prior from k-means++ on the clips'
    joint-position trajectories."""
    from sklearn.cluster import KMeans

    x = positions.reshape(fd.n_clips, -1)
    return KMeans(n_clusters=n_clusters, init="k-means++", n_init=10, random_state=seed).fit_predict(x)


def method_curves(
    method: str,
    fd: FunctionalMotions,
    reference: np.ndarray,
    dims: Sequence[int],
    latent_dim: int,
    settings: FdaSettings,
    fitted: Mapping[int, SFPCA] | None = None,
) -> tuple[list[tuple[float, float, float, str]], np.ndarray]:
    """([(feature error, observation error, fit seconds, note) per d in ``dims``], latent
    coordinates at ``latent_dim``) of one method. ``reference``: the clips' joint positions
    (``fd.positions()``); ``settings``: ``seed``, ``sfpca`` (:func:`sfpca_for`) and ``gplvm``
    (:func:`fit_gplvm`; ``discriminative_sigma2`` None: no prior). ``fitted``: SFPCA fits
    already made with these settings, by dimension (e.g. Table 3.1's reference fit,
    :func:`..models.fit_reference_sfpca`), used instead of fitting again; their fit seconds
    are those of the original fit."""
    # the fitting classes (scikit-learn, scipy.optimize) are imported here: Fig. 3.10's
    # rule needs only curves_table
    from ..fpca import FPCA, NormalizedFPCA, RootScaledFPCA
    from ..models import fit_gplvm, fitted_sfpca  # scipy.optimize and the GPLVM load with the fits
    from ..primitives import sfpca_for
    from .measures import feature_error, observation_error

    fitted = fitted or {}
    seed, sfpca, gplvm = settings.seed, settings.sfpca, settings.gplvm

    def errors(coefs):
        return feature_error(fd, coefs), observation_error(fd, coefs, reference=reference)

    rows = []
    linear = {
        "fpca": FPCA,
        "normalized_fpca": NormalizedFPCA,
        "normalized_fpca_floored": lambda n: NormalizedFPCA(n, settings.reconstruction.normalized_sd_floor),
        "root_scaled_fpca": RootScaledFPCA,
    }
    if method in linear:
        start = time.perf_counter()
        model = linear[method](max(max(dims), latent_dim)).fit(fd)  # nested eigenfunctions: one fit serves every d
        fit_s = time.perf_counter() - start
        for d in dims:
            rows.append((*errors(model.reconstruct(fd, d)), fit_s, ""))
        return rows, model.transform(fd)[:, :latent_dim]

    labels_dp = None
    if method == "gplvm" and gplvm.discriminative_sigma2 is not None:
        labels_dp = kmeans_labels(fd, reference, min(gplvm.n_clusters, fd.n_clips - 1), seed)
    latent = None
    for d in sorted(set(dims) | {latent_dim}):
        start = time.perf_counter()
        if method == "sfpca" and d in fitted:
            model = fitted_sfpca(fitted[d], fd, sfpca, f"SFPCA model at d = {d}")
            note = model.fit_summary()
        elif method == "sfpca":
            model = sfpca_for(fd, d, sfpca).fit(fd)
            note = model.fit_summary()
        else:
            model = fit_gplvm(fd, d, gplvm, seed, labels_dp)
            note = f"{model.gplvm_.n_iter_} it, {model.gplvm_.message_[:40]}"
        fit_s = time.perf_counter() - start
        if method == "sfpca" and d in fitted:  # the time of the fit itself, made elsewhere
            fit_s = float(getattr(model, "fit_time_s_", np.nan))
        log.info("%s d=%d: %.1f s, %s", method, d, fit_s, note)
        if d == latent_dim:
            latent = model.transform(fd)
        if d in dims:
            rows.append((*errors(model.reconstruct(fd)), fit_s, note))
    return rows, latent


def reconstruction_curves(
    fd: FunctionalMotions,
    labels: Sequence[str],
    primitive: str,
    methods: Sequence[str],
    settings: FdaSettings,
    sfpca_models: Sequence[SFPCA] = (),
) -> dict[str, np.ndarray]:
    """The Fig. 3.10-3.11 measurements of one primitive (module docstring) for ``methods``,
    at the dimensions ``settings.reconstruction.dims`` (those above clips - 1, the rank of
    the centred data, dropped) and latent coordinates at ``settings.latent.n_components``
    (capped there); ``labels``: one per clip (Fig. 3.11 colours). ``sfpca_models``: SFPCA
    fits of these clips with settings ``settings.sfpca`` made elsewhere (Table 3.1's
    reference fit), used at their dimension instead of fitting again (:func:`method_curves`)."""
    fitted = {int(m.n_components): m for m in sfpca_models}
    n_max = fd.n_clips - 1  # rank of the centred data
    dims = sorted({d for d in settings.reconstruction.dims if d <= n_max})
    if not dims:
        raise ValueError(f"config du2022_fda.reconstruction.dims: none <= {n_max} (clips - 1 of {primitive})")
    latent_dim = min(settings.latent.n_components, n_max)
    reference = fd.positions()
    out = {
        "primitive": np.array(primitive),
        "dims": np.array(dims),
        "latent_dim": np.array(latent_dim),
        "labels": np.array([str(v) for v in labels], dtype=str),
        "n_basis": np.array(fd.basis.n_basis),
        "n_clips": np.array(fd.n_clips),
        "canonical_frames": np.array(fd.n_frames),
        "methods": np.array(methods, dtype=str),
    }
    for method in methods:
        rows, latent = method_curves(method, fd, reference, dims, latent_dim, settings, fitted)
        feat, obs, seconds, notes = zip(*rows)
        out.update(
            {
                f"{method}/feature_error": np.array(feat),
                f"{method}/observation_error": np.array(obs),
                f"{method}/fit_seconds": np.array(seconds),
                f"{method}/info": np.array(notes, dtype=str),
                f"{method}/latent": latent,
            }
        )
    return out


def curves_table(curves: Sequence[Mapping[str, np.ndarray]]) -> pd.DataFrame:
    """One row per (primitive, method, dimension) of the measurements of several primitives
    (the Fig. 3.10 table)."""
    rows = []
    for z in curves:
        for method in z["methods"]:
            for i, d in enumerate(z["dims"]):
                rows.append(
                    {
                        "primitive": str(z["primitive"]),
                        "method": str(method),
                        "dims": int(d),
                        "feature_error": float(z[f"{method}/feature_error"][i]),
                        "observation_error_cm": float(z[f"{method}/observation_error"][i]),
                        "fit_seconds": float(z[f"{method}/fit_seconds"][i]),
                        "n_clips": int(z["n_clips"]),
                        "n_basis": int(z["n_basis"]),
                        "info": str(z[f"{method}/info"][i]),
                    }
                )
    return pd.DataFrame(rows)
