"""The motion primitives of a dataset as functional data (Du 2022, Sec. 3.3.3, 4.4.1): the
clips of each primitive on a canonical timeline, the number of B-spline basis functions
chosen per primitive by the Fig. 3.9 cut-off rule, and one primitive's clips as
:class:`FunctionalMotions` with that basis size.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ...core.motion import Motion
from ...prep import apply_warp, median_length_index, resample_motion, warp_to_median
from .bspline import choose_n_basis
from .functions import FunctionalMotions, bspline_fit_rmse

if TYPE_CHECKING:
    from .settings import BasisSettings, SfpcaSettings
    from .sfpca import SFPCA

log = logging.getLogger(__name__)


def primitive_motions(dataset, primitive: str) -> tuple[list[Motion], pd.DataFrame]:
    """(motions, metadata rows) of one primitive of a dataset (``motionvar.io.MotionDataset``);
    ValueError naming it when absent."""
    meta = dataset.metadata
    idx = np.flatnonzero(meta["primitive"].to_numpy() == primitive)
    if len(idx) == 0:
        known = ", ".join(sorted(meta["primitive"].unique()))
        raise ValueError(f"primitive {primitive!r} has no canonical clips (known: {known})")
    return [dataset.motion(int(i)) for i in idx], meta.iloc[idx].reset_index(drop=True)


def canonical_primitives(
    dataset, behaviours: Sequence[str], min_clips: int, time_warping: str
) -> tuple[list[Motion], pd.DataFrame]:
    """The primitives of ``behaviours`` on a canonical timeline (Sec. 3.3.3 / 4.4.1): by DTW
    to the median-length clip of each primitive (``time_warping="dtw"``) or by linear
    resampling to the median length. A primitive with fewer than ``min_clips`` clips is
    left out (warning). Returns the warped motions and their metadata (``source_frames``,
    the clip's own length, and ``canonical_reference``, the clip warped to)."""
    meta = dataset.metadata
    known = set(meta["behaviour"].unique())
    absent = [b for b in behaviours if b not in known]
    behaviours = [b for b in behaviours if b in known]
    if not behaviours:
        raise ValueError(
            f"config du2022_fda.behaviours: none of {absent} in the prep data (behaviours: {sorted(known)})"
        )
    if absent:
        log.warning(
            "config du2022_fda.behaviours %s: not in the data, left out (the data has %s)", absent, sorted(known)
        )
    out_motions, out_rows = [], []
    for primitive in sorted(meta.loc[meta["behaviour"].isin(behaviours), "primitive"].unique()):
        idx = np.flatnonzero(meta["primitive"].to_numpy() == primitive)
        if len(idx) < min_clips:
            log.warning("primitive %s: %d clips < du2022_fda.min_clips=%d, left out", primitive, len(idx), min_clips)
            continue
        motions = [dataset.motion(int(i)) for i in idx]
        ids = meta["clip_id"].iloc[idx].astype(str).tolist()
        if time_warping == "dtw":
            ref, warps = warp_to_median(motions, clip_ids=ids)
            warped = [apply_warp(m, w, clip_id=c) for m, w, c in zip(motions, warps, ids)]
        else:
            ref = median_length_index(motions)
            warped = [
                resample_motion(m, motions[ref].n_frames, keep_duration=False, clip_id=c) for m, c in zip(motions, ids)
            ]
        rows = meta.iloc[idx].copy()
        rows["source_frames"] = rows["n_frames"]
        rows["canonical_reference"] = meta["clip_id"].iloc[idx[ref]]
        out_motions += warped
        out_rows.append(rows.drop(columns=["n_frames", "fps"]))
        log.info("%s: %d clips -> %d canonical frames (%s)", primitive, len(idx), warped[0].n_frames, time_warping)
    if not out_motions:
        raise ValueError("config du2022_fda.behaviours: no primitive has du2022_fda.min_clips clips")
    return out_motions, pd.concat(out_rows, ignore_index=True)


def choose_basis_sizes(dataset, basis: BasisSettings) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Sec. 3.3.3, Fig. 3.9: for every primitive of the canonical ``dataset`` the joint-space
    RMSE (cm) of its B-spline functions for each candidate K in ``basis.n_basis`` (those not
    above the canonical frames), and the K chosen by the cut-off rule (:func:`choose_n_basis`
    with ``basis.min_relative_drop``). Returns (RMSE table: one row per primitive and K,
    chosen table: one row per primitive)."""
    n_basis, min_relative_drop = basis.n_basis, basis.min_relative_drop
    rows, chosen = [], []
    for primitive in sorted(dataset.metadata["primitive"].unique()):
        motions, meta = primitive_motions(dataset, primitive)
        T = motions[0].n_frames
        ks = [k for k in sorted(n_basis) if k <= T]
        if not ks:
            raise ValueError(
                f"config du2022_fda.basis.n_basis: every K exceeds the {T} canonical frames of {primitive}"
            )
        rmse = bspline_fit_rmse(motions, ks)
        K = choose_n_basis(np.array(ks), np.array(rmse), min_relative_drop)
        behaviour = meta["behaviour"].iloc[0]
        chosen.append(
            {
                "primitive": primitive,
                "behaviour": behaviour,
                "n_basis": K,
                "n_clips": len(motions),
                "canonical_frames": T,
            }
        )
        rows += [
            {
                "primitive": primitive,
                "behaviour": behaviour,
                "n_clips": len(motions),
                "canonical_frames": T,
                "n_basis": k,
                "rmse_cm": r,
                "chosen": k == K,
            }
            for k, r in zip(ks, rmse)
        ]
    return pd.DataFrame(rows), pd.DataFrame(chosen)


def n_basis_of(chosen: pd.DataFrame, primitive: str, source: str = "n_basis table") -> int:
    """The basis size chosen for ``primitive`` in the table of :func:`choose_basis_sizes`
    (``source`` names the table in the error)."""
    row = chosen[chosen["primitive"] == primitive]
    if len(row) != 1:
        raise ValueError(f"{source}: no basis size for primitive {primitive!r} (config du2022_fda.behaviours)")
    return int(row["n_basis"].iloc[0])


def functional_primitive(dataset, primitive: str, n_basis: int) -> tuple[FunctionalMotions, pd.DataFrame]:
    """(FunctionalMotions, metadata) of one primitive of the canonical ``dataset``."""
    motions, meta = primitive_motions(dataset, primitive)
    return FunctionalMotions.from_motions(motions, n_basis), meta


def sfpca_for(fd: FunctionalMotions, n_components: int, settings: SfpcaSettings) -> SFPCA:
    """An unfitted :class:`SFPCA` of ``n_components`` for the clips ``fd`` with the options of
    ``settings`` (config ``du2022_fda.sfpca``): its objective runs forward kinematics at
    ``settings.eval_frames_per_basis`` frames per basis function (0: every canonical frame)."""
    from .sfpca import SFPCA  # here: rules that fit no SFPCA skip scipy.optimize and scikit-learn

    per_basis = settings.eval_frames_per_basis
    n_eval = min(fd.n_frames, per_basis * fd.basis.n_basis) if per_basis else None
    return SFPCA(
        n_components,
        weight_groups=settings.weight_groups,
        gradient=settings.gradient,
        max_iter=settings.max_iter,
        tol=settings.tol,
        n_eval_frames=n_eval,
        stop_window=settings.stop_window,
        stop_rtol=settings.stop_rtol,
        eigensolver=settings.eigensolver,
    )
