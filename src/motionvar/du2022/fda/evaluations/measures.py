"""Measures shared by the Du 2022 ch. 3 evaluations (Sec. 3.3.5): reconstruction errors
in feature and observation space (Fig. 3.10, Table 3.1) and how well labelled clips stay
apart in a latent space (Fig. 3.11).
"""

from __future__ import annotations

import numpy as np

from ..functions import FunctionalMotions


def feature_error(X: FunctionalMotions, coefs_hat: np.ndarray) -> float:
    """Average Euclidean reconstruction error in feature space: the mean over clips of
    the functional norm ||y_i - y^_i|| = sqrt(sum_d int (y_id - y^_id)^2 dt) (Eq. 3.5),
    in the functions' own units (cm for the root translation, unitless quaternions)."""
    diff = X.coefs - coefs_hat
    sq = np.einsum("nkd,kl,nld->n", diff, X.basis.gram(), diff)
    return float(np.mean(np.sqrt(np.maximum(sq, 0.0))))


def observation_error(
    X: FunctionalMotions, coefs_hat: np.ndarray, n_frames: int | None = None, reference: np.ndarray | None = None
) -> float:
    """Average Euclidean reconstruction error in observation space (cm): the mean
    distance between the joint positions f_k(Y) and f_k(Y^) (Eq. 3.7) over clips,
    canonical frames and joints. ``reference`` may pass f_k(Y) (``X.positions(n_frames=...)``)
    computed once for many reconstructions."""
    a = X.positions(n_frames=n_frames) if reference is None else reference
    b = X.positions(coefs_hat, n_frames=n_frames)
    if a.shape != b.shape:
        raise ValueError(f"observation_error: reference positions {a.shape} do not match {b.shape}")
    dx, dy, dz = np.moveaxis(a - b, -1, 0)
    return float(np.mean(np.sqrt(dx * dx + dy * dy + dz * dz)))  # the norm, summed as np.linalg.norm does


def knn_accuracy(latent: np.ndarray, labels: np.ndarray, k: int = 5) -> float:
    """Leave-one-out k-nearest-neighbour label accuracy in the latent space (Euclidean;
    majority vote, ties to the nearest neighbour's label)."""
    latent = np.asarray(latent, dtype=float)
    labels = np.asarray(labels)
    n = len(latent)
    if n != len(labels) or n <= k:
        raise ValueError(f"knn_accuracy: need more than k={k} points with one label each; got {n} and {len(labels)}")
    sq = np.sum(latent**2, axis=1)
    dist = sq[:, None] + sq[None, :] - 2.0 * latent @ latent.T
    np.fill_diagonal(dist, np.inf)
    nearest = np.argsort(dist, axis=1, kind="stable")[:, :k]
    _, codes = np.unique(labels, return_inverse=True)
    votes = codes[nearest]  # (n, k)
    counts = np.stack([np.sum(votes == c, axis=1) for c in range(codes.max() + 1)], axis=1)
    best = counts.max(axis=1, keepdims=True)
    tied = counts == best
    # ties: the label among the tied ones that appears first in the neighbour order
    first_pos = np.where(tied[np.arange(n)[:, None], votes], np.arange(k)[None, :], k).argmin(axis=1)
    pred = votes[np.arange(n), first_pos]
    return float(np.mean(pred == codes))


def latent_separation(latent: np.ndarray, labels: np.ndarray, k: int = 5) -> dict[str, float]:
    """Silhouette score and leave-one-out k-NN accuracy of the labels in a latent space."""
    from sklearn.metrics import silhouette_score  # here: the error curves need no scikit-learn

    labels = np.asarray(labels)
    if len(np.unique(labels)) < 2:
        raise ValueError("latent_separation: need at least two distinct labels")
    return {"silhouette": float(silhouette_score(latent, labels)), "knn_accuracy": knn_accuracy(latent, labels, k)}
