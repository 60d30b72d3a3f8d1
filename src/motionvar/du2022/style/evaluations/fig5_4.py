"""Fig. 5.4-5.5 of Du 2022 (Sec. 5.4.2-5.4.3): random samples of the neutral VAEs and of
the stylistic CVAEs, as joint positions to draw (the last frame of each sample, characters
started side by side) and to animate, with each model's sample statistics. The thesis
makes no quantitative claim here ("the samples show good variation")."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from ....claims import EvaluationResult
from ....io.dataset import MotionDataset
from ..data import example_features, primitive_mask
from ..diversity import diversity
from ..features import FeatureLayout, features_to_positions
from ..model import FeatureSpace, SavedVAE, sample_features
from ..settings import StyleSettings

EXAMPLE_OFFSET_CM = np.array([0.0, 0.0, -75.0])
"""Where a CVAE's style example stands: one character spacing left of the first sample."""


def primitive_clip_fps(metadata: pd.DataFrame, primitive: str, n_frames: int) -> float:
    """Frame rate that gives a clip of ``n_frames`` canonical frames the mean duration of
    the primitive's clips (metadata columns n_frames, fps)."""
    rows = metadata[primitive_mask(metadata, primitive)]
    return (n_frames - 1) / float(((rows["n_frames"] - 1) / rows["fps"]).mean())


def evaluate_fig5_4(
    dataset: MotionDataset,
    layout: FeatureLayout,
    space: FeatureSpace,
    models: Sequence[SavedVAE],
    settings: StyleSettings,
) -> EvaluationResult:
    """``settings.figure_samples`` samples of each of ``models`` (neutral VAEs and CVAEs, by
    their info's primitive and style; model k drawn with seed ``settings.seed + k``; clips
    on ``settings.canonical_frames`` frames). Table (rounded to
    4 decimals): primitive, model, samples, step length mean and SD (cm) and the
    diversity measures of the samples. Figure: ``rows`` (label, samples' positions
    (n, T, J, 3), the style example's positions or None), the feature joints'
    ``parents`` and ``names``, and ``animations``: per group ("neutral", "styles") one
    (positions (T, J, 3), frame rate, label) per model. No claims."""
    J, n_frames, n_samples, seed = layout.n_joints, settings.canonical_frames, settings.figure_samples, settings.seed
    fig_rows, table, animations = [], [], {"neutral": [], "styles": []}
    for k, (vae, shape, info) in enumerate(models):
        feats = sample_features(vae, shape, space, n_samples, seed + k)
        pos = features_to_positions(feats, layout)
        example = None
        label = f"{info['primitive']}: neutral VAE"
        if info["style"] != "neutral":
            example = features_to_positions(example_features(dataset, layout, info["example"], n_frames), layout)
            example = example + EXAMPLE_OFFSET_CM
            label = f"{info['primitive']}: {info['style']} CVAE (grey: example {info['example']})"
        fig_rows.append((label, pos, example))
        steps = np.linalg.norm(feats[:, :-1, 3 * J : 3 * J + 2], axis=-1).sum(axis=1)
        table.append(
            {
                "primitive": info["primitive"],
                "model": info["style"],
                "samples": n_samples,
                "step_length_mean_cm": steps.mean(),
                "step_length_sd_cm": steps.std(ddof=1),
                **diversity(feats, J),
            }
        )
        neutral = info["style"] == "neutral"
        animations["neutral" if neutral else "styles"].append(
            (
                pos[0],
                primitive_clip_fps(dataset.metadata, info["primitive"], n_frames),
                info["primitive"] if neutral else info["style"],
            )
        )
    figure = {"rows": fig_rows, "parents": layout.parents, "names": layout.names, "animations": animations}
    return EvaluationResult(table=pd.DataFrame(table).round(4), claims=[], figure=figure)
