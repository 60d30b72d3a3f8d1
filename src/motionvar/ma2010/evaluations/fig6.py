"""Ma et al. 2010 Fig. 6, Sec. 7.1: leave-one-out cross validation over the walking
cycles. Each cycle is held out, the model is fitted to the others and asked for the
held-out cycle's style (its two support-phase strides); the stride of the synthesized
cycle is measured after footskate cleanup. The same folds compare universal Kriging on
the style alone (Mukai & Kuriyama 2005) with RBFs (Rose et al. 1998) by pose error."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from ...claims import Claim, EvaluationResult, verdict_from_bool, verdict_threshold
from ..baselines.mukai_kuriyama import mk05_kriging, rose98_rbf
from ..examples import WalkCycles
from ..representation import ClipSet
from ..svi import StyleVariationModel, resolve_structure
from ..synthesis import RootSolver
from ..variation import joint_variation
from .common import PAPER, PROTOCOL, PUBLISHED_MAX_STRIDE_ERROR_CM, clip_pose_error, predicted_strides


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
    ``held_out`` limits the folds to those clips (default: all). ``structure`` is used by
    every fold as given (resolve "auto" on all clips first: :func:`.svi.resolve_structure`)."""
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


def fig6_leave_one_out(
    walks: WalkCycles, structure: str = "auto", variogram_model: str = "linear", seed: int = 0, max_clips: int = 0
) -> EvaluationResult:
    """Fig. 6 over the walking cycles (at most ``max_clips`` folds, a seeded random subset;
    0: all), the structure resolved once on all cycles. Claims: every stride error within
    the published 1.2 cm; Kriging beats RBF by mean pose error (MK05). Figure:
    ``published_max_stride_error_cm`` (the table holds the rest)."""
    clips = walks.clips
    if max_clips and clips.n_clips > max_clips:
        keep = np.sort(np.random.default_rng(seed).choice(clips.n_clips, max_clips, replace=False))
        held_out = set(keep.tolist())
    else:
        held_out = set(range(clips.n_clips))
    table = leave_one_out(clips, walks.groups, walks.solver, resolve_structure(structure, clips, walks.groups),
                          variogram_model, seed, held_out=sorted(held_out))
    table.insert(1, "subject", [walks.subjects[clips.clip_ids.index(c)] for c in table["clip_id"]])

    err = table["ours_stride_error_cm"].to_numpy()
    err_sampled = table["ours_sampled_xi_stride_error_cm"].to_numpy()
    kr, rb = table["kriging_pose_error_cm"].mean(), table["rbf_pose_error_cm"].mean()
    n_better = int(np.sum(table["kriging_pose_error_cm"] < table["rbf_pose_error_cm"]))
    claims = [
        Claim(
            claim_id=f"{PAPER}.fig6.loo_max_stride_error_below_1_2cm", paper=PAPER, source="Fig. 6, Sec. 7.1",
            statement="In leave-one-out cross validation over walking clips the stride length of every synthesized "
                      "clip is within 1.2 cm of the held-out clip's.",
            published=f"max stride error < {PUBLISHED_MAX_STRIDE_ERROR_CM} cm",
            measured=f"max {err.max():.2f} cm, mean {err.mean():.2f} cm over {len(err)} cycles "
                     f"({int(np.sum(err < PUBLISHED_MAX_STRIDE_ERROR_CM))} below 1.2 cm)",
            verdict=verdict_threshold(float(err.max()), PUBLISHED_MAX_STRIDE_ERROR_CM, "<=", tolerance=1.0),
            note="partial: max error within twice the published bound. Each held-out cycle is synthesized from its own "
                 "style and latent variation parameters (Eq. 7-9, the training model's tau). With xi sampled from the "
                 f"propagation network instead: max {err_sampled.max():.2f} cm, mean {err_sampled.mean():.2f} cm. "
                 f"{PROTOCOL}",
        ),
        Claim(
            claim_id=f"{PAPER}.mk05.kriging_beats_rbf", paper=PAPER, source="Sec. 2 (citing Mukai & Kuriyama 2005)",
            statement="Universal Kriging predicts motions more accurately than RBFs.",
            published="Kriging error < RBF error (MK05)",
            measured=f"mean LOO pose error: Kriging {kr:.2f} cm, RBF {rb:.2f} cm; Kriging better on {n_better}/{len(table)} cycles",
            verdict=verdict_from_bool(kr < rb),
            note="Both interpolate whole cycles over the style alone (same clip vectors, same folds); pose error = mean "
                 "joint-position distance with the root at the origin on the common timeline. RBF: cubic B-splines "
                 f"with a linear term (Rose 1998); Kriging: {variogram_model} variogram.",
        ),
    ]
    return EvaluationResult(table=table, claims=claims,
                            figure={"published_max_stride_error_cm": PUBLISHED_MAX_STRIDE_ERROR_CM})
