"""Du 2022 Table 3.1: per motion primitive the number of clips, of basis functions (the
Fig. 3.9 cut-off) and of latent dimensions: the smallest d whose observation-space
reconstruction error reaches a threshold, with SFPCA weights optimised at a reference
dimension (and, for comparison, with FPCA)."""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import pandas as pd

from ....claims import EvaluationResult
from ..fpca import FPCA, WeightedFPCA
from ..functions import FunctionalMotions
from ..primitives import primitive_motions, sfpca_for
from .measures import observation_error

log = logging.getLogger(__name__)

PUBLISHED = {  # Table 3.1: clips, basis functions, latent dimensions
    "walk_leftStance": (1366, 10, 42),
    "pick_reach": (374, 25, 45),
}


def smallest_dim(error_of: Callable[[int], float], d_max: int, threshold: float) -> tuple[int | None, dict[int, float]]:
    """Smallest d in [1, d_max] with error_of(d) <= threshold by bisection (the errors fall
    with d); None if even d_max misses it. Returns (d, {d: error} evaluated)."""
    seen: dict[int, float] = {}

    def err(d):
        if d not in seen:
            seen[d] = error_of(d)
        return seen[d]

    if err(d_max) > threshold:
        return None, seen
    lo, hi = 0, d_max  # err(hi) <= threshold; lo misses (or is 0)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if err(mid) <= threshold:
            hi = mid
        else:
            lo = mid
    return hi, seen


def evaluate_table3_1(
    dataset, chosen: pd.DataFrame, sfpca: Mapping[str, Any], reference_components: int, max_components: int,
    observation_error_cm: float,
) -> EvaluationResult:
    """Table 3.1 for the canonical primitives of ``dataset`` (``motionvar.io.MotionDataset``)
    with the basis sizes of ``chosen`` (the table of :func:`motionvar.du2022.fda.choose_basis_sizes`).
    SFPCA (options ``sfpca`` of :func:`sfpca_for`) is fitted once per primitive at
    ``reference_components`` and its weights kept for every d up to ``max_components``
    (both capped at clips - 1); the latent dimension is the smallest d whose mean joint
    error is at most ``observation_error_cm``.

    Table: one row per primitive with the published numbers. Figure: ``curves``
    {(primitive, "sfpca" | "fpca"): [(d, error)]}, ``primitives``, ``threshold``. No claim:
    the table documents the models."""
    rows, curves = [], {}
    for _, c in chosen.iterrows():
        motions, _ = primitive_motions(dataset, c["primitive"])
        fd = FunctionalMotions.from_motions(motions, int(c["n_basis"]))
        d_max = min(max_components, fd.n_clips - 1)
        d_ref = min(reference_components, d_max)
        weighted = sfpca_for(fd, d_ref, **sfpca).fit(fd)
        log.info("%s: SFPCA(%d) %.1f s, init %s", c["primitive"], d_ref, weighted.fit_time_s_, weighted.init_)
        reference = fd.positions()
        models = {"sfpca": WeightedFPCA(d_max, weighted.function_weights_).fit(fd), "fpca": FPCA(d_max).fit(fd)}
        row = {"primitive": c["primitive"], "behaviour": c["behaviour"], "clips": fd.n_clips,
               "basis_functions": int(c["n_basis"]), "canonical_frames": fd.n_frames, "sfpca_reference_dims": d_ref}
        for name, model in models.items():
            def error(d, model=model):
                return observation_error(fd, model.reconstruct(fd, d), reference=reference)

            d, seen = smallest_dim(error, d_max, observation_error_cm)
            row[f"latent_dims_{name}"] = d if d is not None else np.nan
            row[f"error_at_dims_{name}_cm"] = seen[d] if d is not None else np.nan
            grid = sorted(set(np.unique(np.geomspace(1, d_max, 8).round().astype(int))) | set(seen))
            curves[(c["primitive"], name)] = [(g, seen[g] if g in seen else error(g)) for g in grid]
        pub = PUBLISHED.get(c["primitive"])
        row.update({"published_clips": pub[0] if pub else np.nan, "published_basis": pub[1] if pub else np.nan,
                    "published_dims": pub[2] if pub else np.nan})
        rows.append(row)
    table = pd.DataFrame(rows)
    figure = {"curves": curves, "primitives": list(table["primitive"]), "threshold": observation_error_cm}
    return EvaluationResult(table=table, claims=[], figure=figure)
