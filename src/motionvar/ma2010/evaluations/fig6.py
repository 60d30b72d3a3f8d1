"""Ma et al. 2010 Fig. 6, Sec. 7.1: leave-one-out cross validation over the walking
cycles. Each fold leaves out a whole walk (every cycle cut from one capture; or, as an
option, a single cycle), fits the model to the rest and asks it for each held-out cycle's
style (its two support-phase strides); the synthesized cycle's strides are measured by the
measure that gave the held-out cycle its style (:func:`..examples.normalized_strides`) and
compared with the strides asked for. The held-out cycle's own latent variation xi and the
network's (conditional mean, and sampled) are reported side by side, steady cycles apart
from the closing cycle of each walk, and the model is refitted with the root rotation in the
other joint group (an ablation of the joint map's choice). The same folds compare universal
Kriging on the style alone (Mukai & Kuriyama 2005) with RBFs (Rose et al. 1998) by pose
error, paired over the folds."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd
from scipy.stats import wilcoxon

from ...claims import EvaluationResult, judge_claims
from ..baselines.mukai_kuriyama import mk05_kriging, rose98_rbf
from ..claims import CLAIMS
from ..examples import WalkCycles, joint_groups
from ..representation import ClipCodec, ClipSet
from ..settings import ROOT_GROUPS, Ma2010Settings, ModelSettings
from ..svi import GROUP_ORDER, ClipPrediction, resolve_structure, style_variation_model
from ..synthesis import RootSolver
from ..variation import joint_variation
from .common import (
    PUBLISHED_MAX_STRIDE_ERROR_CM,
    clip_pose_error,
    loo_folds,
    predicted_strides,
    walk_positions,
)

XI_KINDS = ("own", "mean", "sampled")  # the held-out cycle's xi, the network's conditional mean, a draw
#: the RBFs of the MK05 comparison (table prefix -> whether an example is a walk): one kernel per walk at its
#: cycles' mean style, each reaching the nearest other walk (judged), and one per cycle (Rose et al.'s rule applied
#: to the cycles, which are near-copies within a walk: its kernels seldom reach a held-out walk)
RBFS = {"rbf": True, "rbf_cycles": False}
#: a one-sided Wilcoxon signed-rank test over fewer folds cannot reach p < 0.05 (its smallest p is 1/2^n)
MIN_PAIRED_FOLDS = 5


def least_squares_clips(
    train: ClipSet, c: np.ndarray, rcond: float = 0.0, key_timing: str = ModelSettings.key_timing
) -> ClipPrediction:
    """Whole clips at styles c (M, d) from a linear least-squares fit on style alone (the
    trend of universal Kriging without its residual interpolation): the reference that
    tells whether Kriging or RBF interpolate anything beyond a hyperplane."""
    codec = ClipCodec(np.arange(train.skeleton.n_joints), timing=True, key_timing=key_timing).fit(train)
    sd = train.style.std(axis=0)
    mean, scale = train.style.mean(axis=0), np.where(sd > 1e-12, sd, 1.0)  # standardized, as the interpolators
    design = np.column_stack([np.ones(train.n_clips), (train.style - mean) / scale])
    beta = np.linalg.pinv(design, rcond=max(rcond, 1e-15)) @ codec.encode(train)
    query = np.column_stack([np.ones(len(c)), (np.atleast_2d(c) - mean) / scale])
    rot, keys, _ = codec.decode(query @ beta, len(train.reference_keys))
    return ClipPrediction(rotations=rot, key_times=keys)


def alternative_root_group(root_group: str) -> str:
    """The other placement of the root rotation (legs <-> upper_body)."""
    return next(g for g in ROOT_GROUPS if g != root_group)


def fold_predictions(
    train: ClipSet,
    truth: np.ndarray,
    c: np.ndarray,
    groups: Mapping[str, np.ndarray],
    structure: str | dict,
    settings: Ma2010Settings,
    rng: np.random.Generator,
    ablation_groups: Mapping[str, np.ndarray] | None,
    ablation_name: str,
    train_walks: Sequence[str] | None = None,
) -> tuple[dict[str, dict[str, np.ndarray]], dict[str, ClipPrediction], dict[str, np.ndarray]]:
    """One fold of :func:`leave_one_out`: every model fitted to ``train`` and asked for the
    held-out cycles ``truth`` (M, T, J, 4) at their styles ``c`` (M, d); ``train_walks`` names
    each training cycle's walk (:data:`RBFS`). Returns xi per kind (:data:`XI_KINDS`) and group,
    the predictions per method (table prefix), and per RBF whether a kernel reaches each held-out
    style (M,)."""
    model = style_variation_model(groups, structure, settings).fit(train)
    delta = joint_variation(truth)
    xi = {
        "own": {g: delta[:, j] for g, j in model.tau_.items()},
        "mean": model.sample_variation(c, noise=False),
        "sampled": model.sample_variation(c, rng=rng),
    }
    preds = {f"ours_{k}_xi": model.predict(c, xi[k]) for k in XI_KINDS}
    if ablation_groups is not None:
        alt = style_variation_model(ablation_groups, structure, settings).fit(train)
        preds[f"ours_own_xi_{ablation_name}"] = alt.predict(c, {g: delta[:, j] for g, j in alt.tau_.items()})
        preds[f"ours_mean_xi_{ablation_name}"] = alt.predict(c, alt.sample_variation(c, noise=False))
    preds["kriging"] = mk05_kriging(settings).fit(train).predict(c)
    reached = {}
    for name, per_walk in RBFS.items():
        rbf = rose98_rbf(settings).fit(train, train_walks if per_walk else None)
        preds[name] = rbf.predict(c)
        reached[name] = rbf.interpolator_.reaches(c)
    preds["least_squares"] = least_squares_clips(train, c, settings.model.trend_rcond, settings.model.key_timing)
    return xi, preds, reached


def fold_rows(
    clips: ClipSet,
    test: np.ndarray,
    context: dict,
    xi: dict[str, dict[str, np.ndarray]],
    measured: dict[str, tuple[np.ndarray, np.ndarray]],
    validation: np.ndarray,
) -> list[dict]:
    """The table rows of one fold's held-out cycles ``test`` (:func:`leave_one_out`):
    ``context`` holds each cycle's walk, place in it and whether it closes it, the fold's
    number, the training size and whether each RBF's kernels reach its style; ``measured`` method -> (strides (M, 2), pose errors (M,));
    ``validation`` (M, 2) the held-out cycles' strides re-measured from the model's
    representation of them."""
    walks, position, closing = context["walks"], context["position"], context["closing"]
    c = clips.style[test]
    rows = []
    for m, i in enumerate(test):  # loop over the fold's held-out cycles
        row = {
            "clip_id": clips.clip_ids[i],
            "source_clip": walks[i],
            "cycle_in_walk": int(position[i]),
            "closing": bool(closing[i]),
            "fold": context["fold"],
            "n_train": context["n_train"],
            "last_key_interval_s": float(clips.key_times[i, -1] - clips.key_times[i, -2]),
            "true_left_cm": c[m, 0],
            "true_right_cm": c[m, 1],
            # the held-out cycle as a "method": its own clip on the common timeline, retimed and measured
            # (diagnostic: what the time warp to the common timeline alone does to its strides)
            "validation_left_cm": validation[m, 0],
            "validation_right_cm": validation[m, 1],
            "validation_stride_error_cm": float(np.max(np.abs(validation[m] - c[m]))),
            "validation_pose_error_cm": 0.0,
        }
        row.update({f"{name}_reaches": bool(r[m]) for name, r in context["reached"].items()})
        for k in XI_KINDS:
            row.update({f"{k}_xi_{g}": float(xi[k][g][m]) for g in GROUP_ORDER})
        for name, (s, pose) in measured.items():
            row[f"{name}_left_cm"], row[f"{name}_right_cm"] = s[m]
            row[f"{name}_stride_error_cm"] = float(np.max(np.abs(s[m] - c[m])))
            row[f"{name}_pose_error_cm"] = float(pose[m])
        rows.append(row)
    return rows


def leave_one_out(
    clips: ClipSet,
    groups: Mapping[str, np.ndarray],
    solver: RootSolver,
    structure: str | dict,
    settings: Ma2010Settings,
    held_out: Sequence[int] | None = None,
    source_clips: Sequence[str] | None = None,
    ablation_groups: Mapping[str, np.ndarray] | None = None,
    ablation_name: str = "ablation",
) -> pd.DataFrame:
    """Fig. 6 protocol over the folds of :func:`.common.loo_folds` (``settings.fig6.unit``):
    every model is fitted to a fold's training cycles and asked for each held-out cycle's style.

    One row per held-out cycle: its walk (``source_clips``; without them each cycle is its
    own walk), place in the walk and whether it closes it, its fold, the training size, the
    strides asked for (the cycle's style); xi per group of the held-out cycle itself (Eq. 7-9
    with the training model's tau), at the network's conditional mean and sampled from it
    (Eq. 10; seeded by ``settings.seed``); for ours with each xi (``ours_own_xi``,
    ``ours_mean_xi``, ``ours_sampled_xi``), Kriging on style only (MK05), RBFs (RBC98, one kernel
    per walk or per cycle: :data:`RBFS`, with whether a kernel reaches the style) and a plain least-squares fit on style (``least_squares``,
    :func:`least_squares_clips`): the predicted strides (retimed to real time and measured by
    :func:`.common.predicted_strides`, the measure of the examples' styles), the larger error
    of the two phases against the strides asked for, and the pose error to the truth. The
    held-out cycle's own clip on the common timeline, measured alike (``validation_*``), tells
    what the time warp alone does to its strides (a diagnostic; Fig. 6 compares "the stride
    length of the validation walking clips", their style, with the predicted clips'). Kriging
    uses ``settings`` variogram_model and variogram_scale; every trend hyperplane (ours, Kriging,
    RBF, least squares) is the least-squares fit of Eq. 12-13 with ``settings.model.trend_rcond``. With
    ``ablation_groups`` the model is also fitted with those joint groups
    (``ours_own_xi_<ablation_name>``, ``ours_mean_xi_<ablation_name>``). ``held_out`` limits
    the predicted cycles (default: all). ``structure`` is used by every fold as given (resolve
    "auto" on all clips first: :func:`.svi.resolve_structure`)."""
    rng = np.random.default_rng(settings.seed)
    n = clips.n_clips
    held = np.arange(n) if held_out is None else np.asarray(held_out, dtype=np.int64)
    walks = [str(c) for c in clips.clip_ids] if source_clips is None else [str(s) for s in source_clips]
    if len(walks) != n:
        raise ValueError(f"leave_one_out: {len(walks)} source clips for {n} cycles")
    position, closing = walk_positions(walks)
    rows = []
    for k, (train_idx, test) in enumerate(loo_folds(walks, held, settings.fig6.unit)):  # loop over folds
        train = clips.subset(train_idx)
        truth, c = clips.rotations[test], clips.style[test]
        xi, preds, reached = fold_predictions(
            train,
            truth,
            c,
            groups,
            structure,
            settings,
            rng,
            ablation_groups,
            ablation_name,
            [walks[i] for i in train_idx],
        )
        measured = {
            name: (
                predicted_strides(p, clips.reference_keys, solver, clips.fps),
                clip_pose_error(p.rotations, truth, solver),
            )
            for name, p in preds.items()
        }
        validation = predicted_strides(
            ClipPrediction(rotations=truth, key_times=clips.key_times[test]), clips.reference_keys, solver, clips.fps
        )
        context = {"walks": walks, "position": position, "closing": closing, "fold": k, "n_train": len(train_idx)}
        context["reached"] = reached
        rows += fold_rows(clips, test, context, xi, measured, validation)
    return pd.DataFrame(rows)


def loo_summary(folds: pd.DataFrame, methods: Mapping[str, dict], bound: float) -> pd.DataFrame:
    """One row per method (``methods``: table prefix -> label columns) and set of held-out
    cycles (all, steady, closing): count, max and mean stride error against the strides asked
    for, cycles within ``bound`` and mean pose error."""
    rows = []
    subsets = {
        "all": np.ones(len(folds), bool),
        "steady": ~folds["closing"].to_numpy(bool),
        "closing": folds["closing"].to_numpy(bool),
    }
    for name, labels in methods.items():
        for subset, mask in subsets.items():
            err = folds.loc[mask, f"{name}_stride_error_cm"].to_numpy()
            if not len(err):
                continue
            rows.append(
                {
                    "kind": "summary",
                    "method": name,
                    **labels,
                    "cycles": subset,
                    "n": len(err),
                    "max_stride_error_cm": float(np.nanmax(err)) if np.isfinite(err).any() else np.nan,
                    "mean_stride_error_cm": float(np.nanmean(err)) if np.isfinite(err).any() else np.nan,
                    "n_within_bound": int(np.sum(err <= bound)),
                    "mean_pose_error_cm": float(folds.loc[mask, f"{name}_pose_error_cm"].mean()),
                }
            )
    return pd.DataFrame(rows)


def held_out_cycles(n_clips: int, max_clips: int, seed: int) -> np.ndarray:
    """The cycles Fig. 6 predicts: at most ``max_clips`` (a subset seeded by ``seed``; 0: all)."""
    if max_clips and n_clips > max_clips:
        return np.sort(np.random.default_rng(seed).choice(n_clips, max_clips, replace=False))
    return np.arange(n_clips)


def loo_methods(root: str, alt: str, alt_name: str, ablation: bool) -> dict[str, dict]:
    """Table prefix -> label columns (root group, xi) of every method of :func:`leave_one_out`."""
    methods = {f"ours_{k}_xi": {"root_group": root, "xi": k} for k in XI_KINDS}
    if ablation:
        methods |= {f"ours_{k}_xi_{alt_name}": {"root_group": alt, "xi": k} for k in ("own", "mean")}
    methods |= {
        "kriging": {"root_group": "", "xi": "none (style only)"},
        "rbf": {"root_group": "", "xi": "none (style only)"},
        "rbf_cycles": {"root_group": "", "xi": "none (style only)"},
        "least_squares": {"root_group": "", "xi": "none (style only)"},
        "validation": {"root_group": "", "xi": "the held-out cycle's own clip (diagnostic)"},
    }
    return methods


def summary_measurements(summary: pd.DataFrame) -> dict[str, dict[str, dict]]:
    """The summary rows of :func:`loo_summary` as method -> cycles ("all", "steady", "closing") ->
    the row's numbers (n, max and mean stride errors, cycles within the bound, mean pose error)."""
    keys = ("n", "max_stride_error_cm", "mean_stride_error_cm", "n_within_bound", "mean_pose_error_cm")
    out: dict[str, dict[str, dict]] = {}
    for row in summary.to_dict("records"):
        out.setdefault(row["method"], {})[row["cycles"]] = {k: row[k] for k in keys}
    return out


def paired_pose_errors(folds: pd.DataFrame) -> dict:
    """MK05 over the folds of :func:`leave_one_out`: each fold's mean pose error of Kriging and
    of the RBFs (:data:`RBFS`), Kriging minus the judged RBF (``rbf``) per fold, its median
    (the effect size) and a one-sided Wilcoxon signed-rank test that Kriging errs less (folds
    with no difference dropped, as scipy's default; p = 1 when fewer than
    :data:`MIN_PAIRED_FOLDS` folds differ: no such test can reach 0.05); and how far each
    interpolation lies from the plain least-squares fit (the largest per-cycle gap), and on how
    many held-out cycles a kernel of each RBF reaches the style (elsewhere it is the linear term alone)."""
    per_fold = folds.groupby("fold")[
        ["kriging_pose_error_cm", *(f"{r}_pose_error_cm" for r in RBFS), "least_squares_pose_error_cm"]
    ].mean()
    diff = (per_fold["kriging_pose_error_cm"] - per_fold["rbf_pose_error_cm"]).to_numpy()
    differing = int(np.sum(diff != 0))
    p = float(wilcoxon(diff, alternative="less").pvalue) if differing >= MIN_PAIRED_FOLDS else 1.0
    ls = folds["least_squares_pose_error_cm"]
    return {
        "folds": len(diff),
        "folds_differing": differing,
        "kriging_better_folds": int(np.sum(diff < 0)),
        "median_difference_cm": float(np.median(diff)),
        "p": p,
        "pose_error_cm": {
            name: float(folds[f"{name}_pose_error_cm"].mean()) for name in ("kriging", *RBFS, "least_squares")
        },
        "least_squares_gap_cm": {
            name: float(np.max(np.abs(folds[f"{name}_pose_error_cm"] - ls))) for name in ("kriging", *RBFS)
        },
        "reached": {name: int(folds[f"{name}_reaches"].sum()) for name in RBFS},
        "cycles": len(folds),
        "min_folds": MIN_PAIRED_FOLDS,
    }


def failure_causes(folds: pd.DataFrame, method: str, bound: float) -> dict[str, int]:
    """Why each held-out cycle whose stride error under ``method`` exceeds ``bound`` does, by a
    rule fixed before any run, first match: ``measure_floor`` when the cycle's own clip, retimed
    and re-measured, already errs above the bound (the measure cannot reach it on this cycle);
    ``no_interpolant`` when the style-only interpolants of the same examples (Kriging and least
    squares on the style parameters) both err above it too (the cycle departs from what the
    other examples' styles predict: the data's cycle-to-cycle variation); ``ours`` otherwise (an
    interpolant of the same examples gets within the bound, ours does not)."""
    over = folds[folds[f"{method}_stride_error_cm"] > bound]
    floor = over["validation_stride_error_cm"] > bound
    rivals = (over["kriging_stride_error_cm"] > bound) & (over["least_squares_stride_error_cm"] > bound)
    return {
        "measure_floor": int(floor.sum()),
        "no_interpolant": int((~floor & rivals).sum()),
        "ours": int((~floor & ~rivals).sum()),
    }


def loo_measurements(
    folds: pd.DataFrame, summary: pd.DataFrame, settings: Ma2010Settings, root: str, alt: str | None
) -> dict:
    """What Fig. 6's claims are judged on (``motionvar.ma2010.claims``): the stride error of ours
    with the xi of ``settings.fig6.xi`` against the strides asked for, over every held-out cycle
    (max, mean, count, count within 1.2 cm), the summary rows (:func:`summary_measurements`), the
    folds' setup (root group ``root``, the ablation's ``alt`` or None, fold unit, xi, number of
    walks, variogram), MK05's paired pose errors (``mk05``: :func:`paired_pose_errors`) and why
    the cycles above 1.2 cm are (``failure_causes``: :func:`failure_causes`)."""
    method = f"ours_{settings.fig6.xi}_xi"
    err = folds[f"{method}_stride_error_cm"].to_numpy()
    return {
        "stride_error_cm": {
            "max": float(err.max()),
            "mean": float(err.mean()),
            "n": len(err),
            "n_within": int(np.sum(err <= PUBLISHED_MAX_STRIDE_ERROR_CM)),
        },
        "failure_causes": failure_causes(folds, method, PUBLISHED_MAX_STRIDE_ERROR_CM),
        "summary": summary_measurements(summary),
        "root_group": root,
        "ablation_root_group": alt,
        "loo_unit": settings.fig6.unit,
        "loo_xi": settings.fig6.xi,
        "walks": int(folds["source_clip"].nunique()),
        "variogram_model": settings.model.variogram_model,
        "mk05": paired_pose_errors(folds),
    }


def fig6_leave_one_out(walks: WalkCycles, settings: Ma2010Settings, ablation: bool = True) -> EvaluationResult:
    """Fig. 6 over the walking cycles (at most ``settings.fig6.max_clips`` held-out cycles, a
    subset seeded by ``settings.seed``; 0: all), folds by ``settings.fig6.unit`` ("walk": the
    whole walk of the held-out cycle leaves training; "cycle": only the cycle), the
    structure (``settings.model.structure``) resolved once on all cycles; :func:`leave_one_out`.
    With ``ablation`` the model is refitted with the root rotation in the other joint group
    than ``walks.root_group``. Claims (on ``walks.root_group``, xi by ``settings.fig6.xi``):
    every stride error against the strides asked for within the published 1.2 cm; Kriging errs
    less than RBF over the folds (MK05, a paired test), judged on :func:`loo_measurements`.
    Table: summary rows (``kind`` "summary": method x all / steady / closing cycles) then one
    row per held-out cycle (``kind`` "fold"). Figure: ``published_max_stride_error_cm``,
    ``root_group``, ``ablation`` (the ablation's table prefix or None), ``loo_unit``, ``loo_xi``."""
    clips = walks.clips
    held_out = held_out_cycles(clips.n_clips, settings.fig6.max_clips, settings.seed)
    root, alt = walks.root_group, alternative_root_group(walks.root_group)
    alt_name = f"root_{alt}"
    alt_groups = joint_groups(walks.joint_map, clips.skeleton, alt) if ablation else None
    folds = leave_one_out(
        clips,
        walks.groups,
        walks.solver,
        resolve_structure(settings.model.structure, clips, walks.groups),
        settings,
        held_out=held_out,
        source_clips=walks.source_clips,
        ablation_groups=alt_groups,
        ablation_name=alt_name,
    )
    folds.insert(0, "kind", "fold")
    folds.insert(2, "subject", [walks.subjects[clips.clip_ids.index(c)] for c in folds["clip_id"]])
    summary = loo_summary(folds, loo_methods(root, alt, alt_name, ablation), PUBLISHED_MAX_STRIDE_ERROR_CM)
    summary.insert(3, "loo_unit", settings.fig6.unit)
    table = pd.concat([summary, folds], ignore_index=True)
    measurements = loo_measurements(folds, summary, settings, root, alt if ablation else None)
    figure = {
        "published_max_stride_error_cm": PUBLISHED_MAX_STRIDE_ERROR_CM,
        "root_group": root,
        "ablation": alt_name if ablation else None,
        "alt_root_group": alt,
        "loo_unit": settings.fig6.unit,
        "loo_xi": settings.fig6.xi,
    }
    return EvaluationResult(table, judge_claims(CLAIMS, "ma2010_fig6", measurements), figure, measurements)
