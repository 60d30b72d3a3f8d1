"""Du 2022 Fig. 3.11: the clips' latent coordinates (20-D in the thesis) of each method,
shown by t-SNE and coloured by label (walk: forward / left / right; pick: low / forward /
high), with the silhouette score and the leave-one-out k-NN label accuracy measured in
the latent space itself."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd
from sklearn.manifold import TSNE

from ....claims import EvaluationResult, judge_claims
from ...claims import CLAIMS
from ..settings import FdaSettings
from .curves import METHODS
from .measures import latent_separation


def evaluate_fig3_11(curves: Sequence[Mapping[str, np.ndarray]], settings: FdaSettings) -> EvaluationResult:
    """Fig. 3.11 from the latent coordinates in the measurements of
    :func:`.curves.reconstruction_curves` (one per primitive), for
    ``settings.reconstruction.primitives`` x the methods (:data:`.curves.METHODS`);
    ``settings.latent.knn``: k of the k-NN accuracy; t-SNE with ``latent.tsne_perplexity``
    (capped at (clips - 1) / 3) and random state ``settings.seed``.

    Table: per (primitive, method) the latent dimension, clips, silhouette and k-NN
    accuracy. Figure: ``panels`` (rows of dicts: primitive, method, dim, labels, xy (t-SNE
    map), silhouette, knn_accuracy), ``knn``. Measurements (:func:`fig3_11_measurements`): the
    separation of ``reconstruction.pick_primitive`` per method, judged in
    :mod:`motionvar.du2022.claims` (SFPCA separates the labels best)."""
    data = {}
    for z in curves:
        for method in z["methods"]:
            data[(str(z["primitive"]), str(method))] = (z[f"{method}/latent"], z["labels"], int(z["latent_dim"]))
    knn = settings.latent.knn
    rows, panels = [], []
    for primitive in settings.reconstruction.primitives:
        row = []
        for method in METHODS:
            latent, labels, dim = data[(primitive, method)]
            sep = latent_separation(latent, labels, knn)
            rows.append(
                {
                    "primitive": primitive,
                    "method": method,
                    "latent_dim": dim,
                    "n_clips": len(labels),
                    "silhouette": sep["silhouette"],
                    f"knn{knn}_accuracy": sep["knn_accuracy"],
                }
            )
            xy = tsne_map(latent, settings.latent.tsne_perplexity, settings.seed)
            row.append(
                {
                    "primitive": primitive,
                    "method": method,
                    "dim": dim,
                    "labels": labels,
                    "xy": xy,
                    "silhouette": sep["silhouette"],
                    "knn_accuracy": sep["knn_accuracy"],
                }
            )
        panels.append(row)
    table = pd.DataFrame(rows)
    measurements = fig3_11_measurements(table, settings.reconstruction.pick_primitive, knn)
    claims = judge_claims(CLAIMS, "du2022_fig3_11", measurements)
    return EvaluationResult(table, claims, {"panels": panels, "knn": knn}, measurements)


def fig3_11_measurements(table: pd.DataFrame, pick_primitive: str, knn: int) -> dict[str, Any]:
    """What the Fig. 3.11 claim is judged on: for ``pick_primitive`` its latent dimension and,
    per method in the table's order, the silhouette and the ``knn``-NN accuracy (``methods``
    empty when the table has no such primitive)."""
    sub = table[table["primitive"] == pick_primitive]
    return {
        "pick_primitive": str(pick_primitive),
        "knn": int(knn),
        "latent_dim": int(sub["latent_dim"].iloc[0]) if len(sub) else None,
        "methods": {
            str(r["method"]): {"silhouette": float(r["silhouette"]), "knn_accuracy": float(r[f"knn{knn}_accuracy"])}
            for r in sub.to_dict("records")
        },
    }


def tsne_map(latent: np.ndarray, tsne_perplexity: float, seed: int) -> np.ndarray:
    """(clips, 2) t-SNE map of latent coordinates (perplexity capped at (clips - 1) / 3)."""
    perplexity = min(tsne_perplexity, (len(latent) - 1) / 3.0)
    return TSNE(n_components=2, perplexity=perplexity, init="pca", random_state=seed).fit_transform(latent)
