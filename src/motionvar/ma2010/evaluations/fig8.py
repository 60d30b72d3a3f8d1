"""Ma et al. 2010 Fig. 8a, Sec. 7.3-7.4: cycles synthesized at one stride length, xi
sampled from the propagation network for each. The spread of each joint group across
them is compared with the spread of the example cycles nearest that style (from as many
subjects, as in Fig. 1), with the method's ceiling (cycles synthesized at the same style
from those examples' own xi), and with RBF and style-only Kriging, which return one clip
for one style."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...claims import EvaluationResult, judge_claims
from ..baselines.mukai_kuriyama import StyleClipInterpolation, mk05_kriging, rose98_rbf
from ..claims import CLAIMS
from ..correspondence import retime
from ..examples import WalkCycles
from ..settings import Ma2010Settings
from ..svi import ClipPrediction, StyleVariationModel
from ..synthesis import RootSolver
from ..variation import joint_variation
from .common import (
    PUBLISHED_MAX_STRIDE_ERROR_CM,
    group_spread,
    nearest_clips,
    position_spread,
    predicted_strides,
    prediction_key_frames,
    root_relative_positions,
)

GROUPS = ("legs", "left_arm", "right_arm", "upper_body")  # A, B, C, D (Fig. 4)


def fixed_style_variants(
    model: StyleVariationModel, style: np.ndarray, draws: int, shown: int, solver: RootSolver, rng: np.random.Generator
) -> tuple[ClipPrediction, ClipPrediction, dict[str, np.ndarray], np.ndarray]:
    """Fig. 8(a): ``draws`` clips at one style, xi sampled per clip; returns them, the first
    ``shown`` of them, their xi and their measured strides (shown, 2)."""
    every, xi = model.synthesize_clips(np.tile(np.atleast_2d(style), (draws, 1)), rng=rng)
    root_height = None if every.root_height is None else every.root_height[:shown]
    pred = ClipPrediction(rotations=every.rotations[:shown], key_times=every.key_times[:shown], root_height=root_height)
    xi = {g: v[:shown] for g, v in xi.items()}
    return every, pred, xi, predicted_strides(pred, model.reference_keys_, solver, model.fps_)


def ceiling_variants(
    model: StyleVariationModel, rotations: np.ndarray, style: np.ndarray, solver: RootSolver
) -> tuple[ClipPrediction, dict[str, np.ndarray], np.ndarray]:
    """The method's ceiling at one style: clips synthesized at ``style`` from the latent
    variation of example clips ``rotations`` (M, T, J, 4) (their own xi, Eq. 7-9 with the
    model's tau), instead of xi sampled from the network. Returns the clips, the xi and
    their measured strides (M, 2)."""
    delta = joint_variation(rotations)
    xi = {g: delta[:, j] for g, j in model.tau_.items()}
    pred = model.predict(np.tile(np.atleast_2d(style), (len(rotations), 1)), xi)
    return pred, xi, predicted_strides(pred, model.reference_keys_, solver, model.fps_)


def posture_free_spread(rotations: np.ndarray, groups: dict, solver: RootSolver) -> dict[str, float]:
    """:func:`.common.group_spread` of clips (M, T, J, 4) after each clip's mean posture (its
    root-relative joint positions averaged over the timeline) is subtracted: the spread
    left when constant posture offsets, which cancel out of Eq. 7's xi, are removed."""
    pos = root_relative_positions(rotations, solver)
    return position_spread(pos - pos.mean(axis=1, keepdims=True), groups)


def bootstrap_spread(
    rotations: np.ndarray, groups: dict, solver: RootSolver, resamples: int, rng: np.random.Generator
) -> dict[str, tuple[float, float]]:
    """95 % percentile interval of :func:`.common.group_spread` of clips (M, T, J, 4) over
    ``resamples`` draws of M clips with replacement (NaN without resamples)."""
    if not resamples:
        return {g: (float("nan"), float("nan")) for g in groups}
    pos = root_relative_positions(rotations, solver)
    picks = rng.integers(0, len(rotations), size=(resamples, len(rotations)))
    spreads = [position_spread(pos[k], groups) for k in picks]
    return {g: tuple(float(v) for v in np.percentile([s[g] for s in spreads], [2.5, 97.5])) for g in groups}


def interpolation_variants(interp: StyleClipInterpolation, style: np.ndarray, n: int) -> ClipPrediction:
    """n clips at one style from a style-only interpolation (RBF, Kriging)."""
    return interp.predict(np.tile(np.atleast_2d(style), (n, 1)))


def fixed_style_spreads(
    walks: WalkCycles,
    pred: ClipPrediction,
    ceil_pred: ClipPrediction,
    near: np.ndarray,
    style: np.ndarray,
    settings: Ma2010Settings,
) -> dict[str, dict[str, float]]:
    """Spread per joint group (:func:`.common.group_spread`) of ours (``pred``: every draw), the
    ceiling (``ceil_pred``), the nearest examples ``near`` (also with each clip's mean posture
    removed), RBF and style-only Kriging (``settings`` variogram_model, variogram_scale) at
    ``style``, as many clips as ours."""
    clips, groups, solver, n = walks.clips, walks.groups, walks.solver, len(pred)
    kriging = mk05_kriging(settings)
    return {
        "ours": group_spread(pred.rotations, groups, solver),
        "ceiling (their own xi)": group_spread(ceil_pred.rotations, groups, solver),
        f"data ({len(near)} nearest examples)": group_spread(clips.rotations[near], groups, solver),
        "data, mean posture removed": posture_free_spread(clips.rotations[near], groups, solver),
        "RBF": group_spread(
            interpolation_variants(rose98_rbf(settings).fit(clips), style, n).rotations,
            groups,
            solver,
        ),
        "Kriging": group_spread(interpolation_variants(kriging.fit(clips), style, n).rotations, groups, solver),
    }


def _stride_row(kind: str, name: str, xi: dict, k: int, strides: np.ndarray, errors: np.ndarray) -> dict:
    return {
        "kind": kind,
        "name": name,
        **{g: float(xi[g][k]) for g in GROUPS},
        "left_cm": strides[k, 0],
        "right_cm": strides[k, 1],
        "stride_error_cm": errors[k],
    }


def variant_motions(
    model: StyleVariationModel, pred: ClipPrediction, solver: RootSolver, fps: float
) -> tuple[list, list]:
    """The variants in real time (root by footskate cleanup) and their key frames, for the figure."""
    motions, keys = [], []
    for k in range(len(pred)):  # loop over variants
        rot, _ = retime(pred.rotations[k], model.reference_keys_, pred.key_times[k], fps)
        motions.append(solver.motion(rot, fps))
        keys.append(prediction_key_frames(pred.key_times[k], fps, len(rot)))
    return motions, keys


#: measurement key of each spread of :func:`fixed_style_spreads` but the data's (``motionvar.ma2010.claims``)
SPREAD_KEYS = {
    "ours": "ours",
    "ceiling (their own xi)": "ceiling",
    "data, mean posture removed": "data_posture_free",
    "RBF": "rbf",
    "Kriging": "kriging",
}


def fixed_style_measurements(
    spreads: dict,
    data_name: str,
    errors: np.ndarray,
    ceil_errors: np.ndarray,
    near_subjects: list[str],
    settings: Ma2010Settings,
    root_group: str,
    data_interval: dict[str, tuple[float, float]],
) -> dict:
    """What Fig. 8a's claims are judged on: the spread per joint group of every source
    (``spread_cm``: :data:`SPREAD_KEYS`, the nearest examples' ``data_name`` as ``data``), the
    data's 95 % bootstrap interval per group (``data_interval_cm``), the groups, the shown
    variants' largest stride error and how many exceed 1.2 cm, the ceiling's largest, the
    numbers of variants, of draws behind ours' spread, of nearest examples and of their subjects
    (``near_subjects``: each nearest example's), ``settings.fig8.spread_ratio_bounds`` and the root
    rotation's group."""
    spread = {SPREAD_KEYS.get(name, "data" if name == data_name else name): dict(s) for name, s in spreads.items()}
    return {
        "spread_cm": spread,
        "data_interval_cm": {g: list(v) for g, v in data_interval.items()},
        "draws": settings.fig8.draws,
        "groups": list(GROUPS),
        "max_stride_error_cm": float(errors.max()),
        "over_bound": int(np.sum(errors > PUBLISHED_MAX_STRIDE_ERROR_CM)),
        "variants": len(errors),
        "ceiling_max_stride_error_cm": float(ceil_errors.max()),
        "examples": len(near_subjects),
        "subjects": len(set(near_subjects)),
        "spread_ratio_bounds": list(settings.fig8.spread_ratio_bounds),
        "root_group": root_group,
    }


def fig8_fixed_style(walks: WalkCycles, model: StyleVariationModel, settings: Ma2010Settings) -> EvaluationResult:
    """Fig. 8a for ``model`` fitted to ``walks``: ``settings.fig8.draws`` cycles at the median
    stride (xi sampled, seeded by ``settings.seed``), the first ``settings.fig8.variants`` shown
    with their xi, strides and stride errors; the spread per joint group of ours (over every
    draw), of the ceiling (the same style from the
    nearest examples' own xi, :func:`ceiling_variants`), of the nearest examples (one per
    subject; also with each clip's mean posture removed, and their 95 % bootstrap interval over
    ``settings.fig8.bootstrap`` resamples), of RBF and of style-only Kriging
    (:func:`fixed_style_spreads`). Claims, judged on :func:`fixed_style_measurements`: the
    variants differ within ``settings.fig8.spread_ratio_bounds`` times the data's spread while
    keeping the stride (not testable with too few nearest examples or subjects); RBF and
    Kriging do not vary. Figure: ``motions`` and ``key_frames`` of the variants in real
    time, ``style``, ``errors``, ``spreads``, ``ceiling_errors``, ``data_name`` (the key of
    the data's spread), ``data_interval`` (group -> its 95 % bootstrap interval)."""
    clips, solver = walks.clips, walks.solver
    n = settings.fig8.variants
    style = np.median(clips.style, axis=0)
    rng = np.random.default_rng(settings.seed)
    draws, pred, xi, strides = fixed_style_variants(model, style, settings.fig8.draws, n, solver, rng)
    errors = np.max(np.abs(strides - style), axis=1)
    near = nearest_clips(clips, style, n, walks.subjects)
    data_name = f"data ({len(near)} nearest examples)"
    ceil_pred, ceil_xi, ceil_strides = ceiling_variants(model, clips.rotations[near], style, solver)
    ceil_errors = np.max(np.abs(ceil_strides - style), axis=1)
    spreads = fixed_style_spreads(walks, draws, ceil_pred, near, style, settings)
    interval = bootstrap_spread(clips.rotations[near], walks.groups, solver, settings.fig8.bootstrap, rng)
    rows = [_stride_row("variant", f"variant {k + 1}", xi, k, strides, errors) for k in range(n)]
    rows += [
        _stride_row("ceiling", f"own xi of {clips.clip_ids[i]}", ceil_xi, k, ceil_strides, ceil_errors)
        for k, i in enumerate(near)
    ]
    rows += [{"kind": "spread_cm", "name": name, **s} for name, s in spreads.items()]
    motions, keys = variant_motions(model, pred, solver, clips.fps)
    near_subjects = [walks.subjects[i] for i in near]
    measurements = fixed_style_measurements(
        spreads, data_name, errors, ceil_errors, near_subjects, settings, walks.root_group, interval
    )
    figure = {
        "motions": motions,
        "key_frames": keys,
        "style": style,
        "errors": errors,
        "spreads": spreads,
        "groups": GROUPS,
        "ceiling_errors": ceil_errors,
        "data_name": data_name,
        "data_interval": interval,
    }
    claims = judge_claims(CLAIMS, "ma2010_fig8", measurements)
    return EvaluationResult(pd.DataFrame(rows), claims, figure, measurements)
