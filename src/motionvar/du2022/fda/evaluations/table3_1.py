"""Du 2022 Table 3.1: per motion primitive the number of clips, of basis functions (the
Fig. 3.9 cut-off) and of latent dimensions: the smallest d whose observation-space
reconstruction error reaches a threshold, with SFPCA weights optimised at a reference
dimension (and, for comparison, with FPCA)."""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping

import numpy as np
import pandas as pd

from ....claims import EvaluationResult
from ..fpca import FPCA, WeightedFPCA
from ..functions import FunctionalMotions
from ..models import fit_reference_sfpca, reference_dims
from ..primitives import primitive_motions
from ..settings import FdaSettings
from ..sfpca import SFPCA
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
    dataset,
    chosen: pd.DataFrame,
    settings: FdaSettings,
    sfpca_models: Mapping[str, SFPCA] | None = None,
) -> EvaluationResult:
    """Table 3.1 for the canonical primitives of ``dataset`` (``motionvar.io.MotionDataset``)
    with the basis sizes of ``chosen`` (the table of :func:`motionvar.du2022.fda.choose_basis_sizes`).
    SFPCA (settings ``settings.sfpca``, :func:`sfpca_for`) is fitted once per primitive at
    ``settings.table.reference_components`` (:func:`fit_reference_sfpca`) and its weights
    kept for every d up to ``table.max_components`` (both capped at clips - 1); the latent
    dimension is the smallest d whose mean joint error is at most
    ``table.observation_error_cm``. ``sfpca_models``: such fits already made ({primitive:
    SFPCA}, e.g. read from the files of rule du2022_fda_sfpca; checked to be of the
    primitive's clips and dimension); the SFPCA of a primitive without one is fitted here.

    Table: one row per primitive with the published numbers. Figure: ``curves``
    {(primitive, "sfpca" | "fpca"): [(d, error)]}, ``primitives``, ``threshold``. No claim:
    the table documents the models."""
    observation_error_cm = settings.table.observation_error_cm
    rows, curves = [], {}
    for _, c in chosen.iterrows():
        motions, _ = primitive_motions(dataset, c["primitive"])
        fd = FunctionalMotions.from_motions(motions, int(c["n_basis"]))
        d_max, d_ref = reference_dims(fd.n_clips, settings.table)
        if sfpca_models and c["primitive"] in sfpca_models:
            weighted = _given_model(sfpca_models[c["primitive"]], c["primitive"], fd, d_ref)
        else:
            weighted = fit_reference_sfpca(fd, settings)
        log.info(
            "%s: SFPCA(%d) %.1f s, %s",
            c["primitive"],
            d_ref,
            getattr(weighted, "fit_time_s_", np.nan),
            weighted.fit_summary(),
        )
        reference = fd.positions()
        models = {"sfpca": WeightedFPCA(d_max, weighted.function_weights_).fit(fd), "fpca": FPCA(d_max).fit(fd)}
        row = {
            "primitive": c["primitive"],
            "behaviour": c["behaviour"],
            "clips": fd.n_clips,
            "basis_functions": int(c["n_basis"]),
            "canonical_frames": fd.n_frames,
            "sfpca_reference_dims": d_ref,
        }
        for name, model in models.items():

            def error(d, model=model):
                return observation_error(fd, model.reconstruct(fd, d), reference=reference)

            d, seen = smallest_dim(error, d_max, observation_error_cm)
            row[f"latent_dims_{name}"] = d if d is not None else np.nan
            row[f"error_at_dims_{name}_cm"] = seen[d] if d is not None else np.nan
            grid = sorted(set(np.unique(np.geomspace(1, d_max, 8).round().astype(int))) | set(seen))
            curves[(c["primitive"], name)] = [(g, seen[g] if g in seen else error(g)) for g in grid]
        pub = PUBLISHED.get(c["primitive"])
        row.update(
            {
                "published_clips": pub[0] if pub else np.nan,
                "published_basis": pub[1] if pub else np.nan,
                "published_dims": pub[2] if pub else np.nan,
            }
        )
        rows.append(row)
    table = pd.DataFrame(rows)
    figure = {"curves": curves, "primitives": list(table["primitive"]), "threshold": observation_error_cm}
    return EvaluationResult(table=table, claims=[], figure=figure)


def _given_model(model: SFPCA, primitive: str, fd: FunctionalMotions, d_ref: int) -> SFPCA:
    """A given SFPCA of ``primitive``, checked against its clips and the reference dimension."""
    model.check_fitted_on(fd, f"SFPCA model of {primitive}")
    if int(model.n_components) != d_ref:
        raise ValueError(
            f"SFPCA model of {primitive}: fitted at d = {model.n_components}, Table 3.1's reference "
            f"dimension is {d_ref} (config du2022_fda.table.reference_components): rerun rule du2022_fda_sfpca"
        )
    return model
