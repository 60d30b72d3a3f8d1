"""The measurements behind Ma et al. 2010's evaluations (Fig. 6, 7b, 8, Sec. 7.4, 8), as
library functions on a :class:`ClipSet`; the rule scripts only load data and write files.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping

import numpy as np
import pandas as pd
from scipy.spatial import cKDTree

from .baselines.mukai_kuriyama import StyleClipInterpolation, mk05_kriging, rose98_rbf
from ..core.kinematics import fk
from .correspondence import retime
from .examples import normalized_strides
from .representation import ClipSet
from .svi import ClipPrediction, StyleVariationModel
from .synthesis import RootSolver, sequence_motion
from .variation import joint_variation


def prediction_key_frames(key_times: np.ndarray, fps: float, n_frames: int) -> np.ndarray:
    """Key frames (K,) of a real-time clip whose key frames fall at ``key_times`` (s),
    made strictly increasing (as the inverse time warp makes the key times) and clipped
    to the clip's frames."""
    k = np.arange(len(key_times))
    kf = np.round((np.asarray(key_times) - key_times[0]) * fps).astype(np.int64)
    kf = np.maximum.accumulate(kf - k) + k
    return np.minimum(kf, n_frames - 1)


def predicted_strides(pred: ClipPrediction, reference_keys: np.ndarray, solver: RootSolver, fps: float) -> np.ndarray:
    """(M, 2) support-phase strides of predicted clips: each is retimed to real time, its
    root recovered by footskate cleanup, and the swing ankle's travel measured. NaN for a
    clip whose predicted key times leave no frames between its key frames (a failed
    synthesis, far outside the examples)."""
    out = np.full((len(pred), 2), np.nan)
    for m in range(len(pred)):  # loop over clips
        rot, _ = retime(pred.rotations[m], reference_keys, pred.key_times[m], fps)
        kf = prediction_key_frames(pred.key_times[m], fps, len(rot))
        if np.all(np.diff(kf) > 0):
            out[m] = normalized_strides(rot, kf, solver, fps)
    return out


def clip_pose_error(a: np.ndarray, b: np.ndarray, solver: RootSolver) -> np.ndarray:
    """Mean joint-position distance (cm) between clips a and b (M, T, J, 4) on the common
    timeline, root at the origin (the pose, not the path)."""
    sk = solver.skeleton
    pa = fk(a, np.zeros(a.shape[:-2] + (3,)), sk.offsets, sk.parents)
    pb = fk(b, np.zeros(b.shape[:-2] + (3,)), sk.offsets, sk.parents)
    return np.linalg.norm(pa - pb, axis=-1).mean(axis=(-1, -2))


def leave_one_out(
    clips: ClipSet,
    groups: Mapping[str, np.ndarray],
    solver: RootSolver,
    structure: str | dict = "lower_first",
    variogram_model: str = "linear",
    seed: int = 0,
    held_out: list[int] | None = None,
) -> pd.DataFrame:
    """Fig. 6 protocol: each clip in turn is held out, every model is fitted to the rest
    and asked for the held-out clip's style. One row per clip: the true strides, ours
    with the held-out clip's own latent variation (Eq. 7-9 with the training tau), with xi
    sampled from the network, and with xi at the network's conditional mean, Kriging on
    style only (MK05) and RBF (RBC98): predicted strides and pose error to the truth.
    ``held_out`` limits the folds to those clips (default: all)."""
    rng = np.random.default_rng(seed)
    rows = []
    for i in range(clips.n_clips) if held_out is None else held_out:  # loop over folds
        train = clips.subset(np.arange(clips.n_clips) != i)
        truth = clips.rotations[i : i + 1]
        c = clips.style[i : i + 1]
        model = StyleVariationModel(groups, structure, variogram_model).fit(train)
        delta = joint_variation(truth)
        own_xi = {g: delta[:, j] for g, j in model.tau_.items()}
        preds = {
            "ours": model.predict(c, own_xi),
            "ours_sampled_xi": model.synthesize_clips(c, rng=rng)[0],
            "ours_mean_xi": model.synthesize_clips(c, noise=False)[0],
            "kriging": mk05_kriging(variogram_model).fit(train).predict(c),
            "rbf": rose98_rbf().fit(train).predict(c),
        }
        row = {"clip_id": clips.clip_ids[i], "true_left_cm": c[0, 0], "true_right_cm": c[0, 1]}
        for name, pred in preds.items():
            s = predicted_strides(pred, clips.reference_keys, solver, clips.fps)[0]
            row[f"{name}_left_cm"], row[f"{name}_right_cm"] = s
            row[f"{name}_stride_error_cm"] = float(np.max(np.abs(s - c[0])))
            row[f"{name}_pose_error_cm"] = float(clip_pose_error(pred.rotations, truth, solver)[0])
        rows.append(row)
    return pd.DataFrame(rows)


def reliability_map(
    model: StyleVariationModel, clips: ClipSet, solver: RootSolver, n_grid: int = 15, margin: float = 0.5
) -> pd.DataFrame:
    """Fig. 7b: over a grid of the 2-D style space (the examples' range widened by
    ``margin`` times its extent on each side), the stride error of the synthesized clip
    (xi at the network's conditional mean; NaN where the synthesis fails) and the distance
    to the nearest example (cm)."""
    lo, hi = clips.style.min(axis=0), clips.style.max(axis=0)
    ext = np.maximum(hi - lo, 1.0)
    axes = [np.linspace(lo[k] - margin * ext[k], hi[k] + margin * ext[k], n_grid) for k in range(2)]
    gl, gr = np.meshgrid(*axes, indexing="ij")
    grid = np.stack([gl.ravel(), gr.ravel()], axis=1)
    pred, _ = model.synthesize_clips(grid, noise=False)
    measured = predicted_strides(pred, model.reference_keys_, solver, clips.fps)
    dist, _ = cKDTree(clips.style).query(grid)
    return pd.DataFrame({
        "left_cm": grid[:, 0], "right_cm": grid[:, 1],
        "measured_left_cm": measured[:, 0], "measured_right_cm": measured[:, 1],
        "stride_error_cm": np.max(np.abs(measured - grid), axis=1), "nearest_example_cm": dist,
    })


def group_spread(rotations: np.ndarray, groups: Mapping[str, np.ndarray], solver: RootSolver) -> dict[str, float]:
    """Spread of clips (M, T, J, 4) per joint group: the SD across clips of each joint's
    root-relative position (cm), as a vector norm, averaged over frames and the group's joints."""
    sk = solver.skeleton
    pos = fk(rotations, np.zeros(rotations.shape[:-2] + (3,)), sk.offsets, sk.parents)
    sd = np.sqrt(np.sum(pos.var(axis=0), axis=-1))  # (T, J)
    return {g: float(sd[:, j].mean()) for g, j in groups.items()}


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


def fixed_style_variants(
    model: StyleVariationModel, style: np.ndarray, n: int, solver: RootSolver, rng: np.random.Generator
) -> tuple[ClipPrediction, dict[str, np.ndarray], np.ndarray]:
    """Fig. 8(a): ``n`` clips at one style, xi sampled per clip; returns the clips, their
    xi and their measured strides (n, 2)."""
    pred, xi = model.synthesize_clips(np.tile(np.atleast_2d(style), (n, 1)), rng=rng)
    return pred, xi, predicted_strides(pred, model.reference_keys_, solver, model.fps_)


def interpolation_variants(interp: StyleClipInterpolation, style: np.ndarray, n: int) -> ClipPrediction:
    """n clips at one style from a style-only interpolation (RBF, Kriging)."""
    return interp.predict(np.tile(np.atleast_2d(style), (n, 1)))


def synthesis_seconds_per_second(
    model: StyleVariationModel, style: np.ndarray, solver: RootSolver, seconds: float, repeats: int = 3, seed: int = 0,
    clock: Callable[[], float] = time.perf_counter,
) -> tuple[float, float]:
    """Sec. 8: computation time per second of synthesized motion for a sequence of about
    ``seconds`` s (xi sampling, SVI, inverse time warp, transitions, footskate cleanup):
    the best of ``repeats`` runs. Returns (seconds per second, motion seconds)."""
    mean_cycle = float(np.mean(model.key_times_span_))
    n = max(int(np.ceil(seconds / mean_cycle)), 1)
    best, length = np.inf, 0.0
    for r in range(repeats):  # timing repeats
        rng = np.random.default_rng(seed + r)
        t0 = clock()
        pred, _ = model.synthesize_clips(np.tile(np.atleast_2d(style), (n, 1)), rng=rng)
        motion = sequence_motion(pred.rotations, pred.key_times, model.reference_keys_, solver, model.fps_, pred.root_height)
        elapsed = clock() - t0
        length = motion.duration
        best = min(best, elapsed / max(length, 1e-9))
    return best, length
