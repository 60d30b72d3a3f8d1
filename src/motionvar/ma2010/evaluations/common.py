"""What the Ma et al. 2010 evaluations share: the paper key, the published stride bound of
Fig. 6 (declared with the claims, :mod:`motionvar.ma2010.claims`), the measures used by
several of them (strides of predicted clips, pose error, spread per joint group, nearest
examples), and the leave-one-out folds (whole walks or single cycles) with each cycle's place in its walk.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from ...core.kinematics import fk
from ..claims import PUBLISHED_MAX_STRIDE_ERROR_CM  # noqa: F401  (re-exported: Fig. 6's bound)
from ..correspondence import key_times_increase, retime
from ..examples import normalized_strides
from ..representation import ClipSet
from ..settings import LOO_UNITS
from ..svi import ClipPrediction
from ..synthesis import RootSolver

PAPER = "ma2010"


def prediction_key_frames(key_times: np.ndarray, fps: float, n_frames: int) -> np.ndarray:
    """Key frames (K,) of a real-time clip whose key frames fall at ``key_times`` (s),
    made strictly increasing (as the inverse time warp makes the key times) and clipped
    to the clip's frames."""
    k = np.arange(len(key_times))
    kf = np.round((np.asarray(key_times) - key_times[0]) * fps).astype(np.int64)
    kf = np.maximum.accumulate(kf - k) + k
    return np.minimum(kf, n_frames - 1)


def predicted_strides(pred: ClipPrediction, reference_keys: np.ndarray, solver: RootSolver, fps: float) -> np.ndarray:
    """(M, 2) support-phase strides of predicted clips: each is retimed to real time and
    measured as every example cycle's style is (:func:`..examples.normalized_strides`). NaN for
    a failed synthesis (far outside the examples): predicted key times that do not increase
    (it would run backwards, :func:`..correspondence.key_times_increase`) or that leave no
    frame between key frames."""
    out = np.full((len(pred), 2), np.nan)
    forward = key_times_increase(pred.key_times)
    for m in np.flatnonzero(forward):  # loop over clips
        rot, _ = retime(pred.rotations[m], reference_keys, pred.key_times[m], fps)
        kf = prediction_key_frames(pred.key_times[m], fps, len(rot))
        if np.all(np.diff(kf) > 0):
            out[m] = normalized_strides(rot, kf, solver, fps)
    return out


def root_relative_positions(rotations: np.ndarray, solver: RootSolver) -> np.ndarray:
    """(M, T, J, 3) joint positions (cm) of clips (M, T, J, 4) with the root at the origin."""
    sk = solver.skeleton
    return fk(rotations, np.zeros(rotations.shape[:-2] + (3,)), sk.offsets, sk.parents)


def clip_pose_error(a: np.ndarray, b: np.ndarray, solver: RootSolver) -> np.ndarray:
    """Mean joint-position distance (cm) between clips a and b (M, T, J, 4) on the common
    timeline, root at the origin (the pose, not the path)."""
    pa, pb = root_relative_positions(a, solver), root_relative_positions(b, solver)
    return np.linalg.norm(pa - pb, axis=-1).mean(axis=(-1, -2))


def position_spread(positions: np.ndarray, groups: Mapping[str, np.ndarray]) -> dict[str, float]:
    """Spread of clips' joint positions (M, T, J, 3) per joint group: the SD across clips of each
    joint's position, as a vector norm, averaged over frames and the group's joints."""
    sd = np.sqrt(np.sum(positions.var(axis=0), axis=-1))  # (T, J)
    return {g: float(sd[:, j].mean()) for g, j in groups.items()}


def group_spread(rotations: np.ndarray, groups: Mapping[str, np.ndarray], solver: RootSolver) -> dict[str, float]:
    """Spread of clips (M, T, J, 4) per joint group (:func:`position_spread` of their
    root-relative positions, cm)."""
    return position_spread(root_relative_positions(rotations, solver), groups)


def nearest_clips(clips: ClipSet, style: np.ndarray, n: int, distinct_subjects: list[str] | None = None) -> np.ndarray:
    """Indices of the ``n`` clips nearest in style to ``style`` (one per subject when
    ``distinct_subjects`` names each clip's subject, as the five clips of Fig. 1)."""
    order = np.argsort(np.linalg.norm(clips.style - style, axis=1), kind="stable")
    if distinct_subjects is None:
        return order[:n]
    picked, seen = [], set()
    for i in order:
        if distinct_subjects[i] not in seen:
            picked.append(int(i))
            seen.add(distinct_subjects[i])
        if len(picked) == n:
            break
    return np.array(picked)


def walk_positions(source_clips: Sequence[str]) -> tuple[np.ndarray, np.ndarray]:
    """Each cycle's place in its walk: (N,) position (0 = the walk's first cycle, in the
    order the cycles are listed, which is their order in the walk) and (N,) ``closing``,
    True for the last cycle of each walk (the slow-down into the closing step), False for
    the steady cycles before it."""
    s = pd.Series([str(x) for x in source_clips])
    position = s.groupby(s, sort=False).cumcount().to_numpy()
    closing = (s.groupby(s, sort=False).cumcount(ascending=False) == 0).to_numpy()
    return position, closing


def loo_folds(
    source_clips: Sequence[str] | None, held_out: Sequence[int], unit: str, n_clips: int | None = None
) -> list[tuple[np.ndarray, np.ndarray]]:
    """Leave-one-out folds: a list of (training cycle indices, held-out cycle indices).

    ``unit`` (config ma2010.fig6.unit, one of :data:`..settings.LOO_UNITS`) "walk": a fold
    leaves out every cycle of one walk (``source_clips`` names each cycle's walk) and
    predicts the cycles of ``held_out`` among them, so no model is trained on a sibling
    cycle of the cycle it predicts (the paper predicts a new clip from the others, Sec. 7.1;
    cycles cut from one capture are near-copies of each other). "cycle": one cycle per fold,
    its sibling cycles stay in training (the literal "single example motion clip as the test
    data", with a clip = a cycle). ``n_clips`` (default ``len(source_clips)``) is the number
    of cycles."""
    if unit not in LOO_UNITS:
        raise ValueError(f"loo_folds: unit must be one of {list(LOO_UNITS)}; got {unit!r}")
    if source_clips is None:
        if unit == "walk":
            raise ValueError("loo_folds: whole-walk folds need each cycle's source clip")
        if n_clips is None:
            raise ValueError("loo_folds: give n_clips or source_clips")
        walks = np.arange(n_clips).astype(str)
    else:
        walks = np.asarray([str(x) for x in source_clips])
    n = len(walks)
    held_out = np.asarray(held_out, dtype=np.int64)
    if held_out.size and (held_out.min() < 0 or held_out.max() >= n):
        raise ValueError(f"loo_folds: held-out cycles must lie in 0..{n - 1}")
    idx = np.arange(n)
    if unit == "cycle":
        return [(idx[idx != i], np.array([i])) for i in held_out]
    folds = []
    for w in dict.fromkeys(walks[held_out]):  # loop over walks, in order of first appearance
        out = walks == w
        folds.append((idx[~out], np.intersect1d(held_out, idx[out])))
    return folds
