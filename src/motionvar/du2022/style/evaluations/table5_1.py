"""Table 5.1 of Du 2022 (Sec. 5.4.3): the style distance D(m, s) (Eq. 5.12) between the
samples of each model m (the neutral VAE and one CVAE per style) and each style example
s; the thesis finds every row's minimum on the diagonal."""

from __future__ import annotations

import logging
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd
import torch

from ....claims import EvaluationResult, judge_claims
from ....io.dataset import MotionDataset
from ...claims import CLAIMS
from ..data import example_features, primitive_features
from ..features import FeatureLayout
from ..losses import style_distance
from ..model import FeatureSpace, SavedVAE, sample_maps
from ..networks import MotionVAE
from ..published import table5_1
from ..settings import StyleSettings
from ..training import last_epoch_drops

log = logging.getLogger(__name__)


def style_distance_matrix(
    models: Mapping[str, tuple[MotionVAE, tuple[int, int]]],
    examples: Mapping[str, np.ndarray],
    space: FeatureSpace,
    n_samples: int,
    seed: int,
) -> pd.DataFrame:
    """Table 5.1: D(m, s) (Eq. 5.12) for every model m (rows) and style example s
    (columns, features (T, C)). Each model's ``n_samples`` clips are decoded to motion
    and encoded again, Gram(encoder(x_i)); the examples are encoded once."""
    ex_maps = {s: space.encode(np.asarray(x)[None])[0] for s, x in examples.items()}
    table = pd.DataFrame(index=list(models), columns=list(examples), dtype=float)
    for k, (name, (vae, shape)) in enumerate(models.items()):
        enc = space.reencode(sample_maps(vae, shape, n_samples, seed + k))
        for s, m in ex_maps.items():
            table.loc[name, s] = float(style_distance(enc, m))
    table.index.name = "model"
    return table


@torch.no_grad()
def own_clips_distances(
    dataset: MotionDataset,
    layout: FeatureLayout,
    space: FeatureSpace,
    primitive: str,
    examples: Mapping[str, np.ndarray],
    example_ids: Mapping[str, str],
    n_frames: int,
) -> pd.DataFrame:
    """The ground truth beside Table 5.1: D(c, s) (Eq. 5.12) between each style's own clips of
    ``primitive`` (its style example left out), passed through the autoencoder as a perfect
    model's samples would be, and each style example s (features (T, C)). A row whose minimum
    lies off the diagonal says that D does not tell that style's own motion from another
    example on this data, whatever a model learns."""
    ex_maps = {s: space.encode(np.asarray(x)[None])[0] for s, x in examples.items()}
    table = pd.DataFrame(index=list(examples), columns=list(examples), dtype=float)
    for style in examples:
        rows, feats = primitive_features(dataset, layout, primitive, style, n_frames)
        keep = (rows["clip_id"].astype(str) != example_ids.get(style, "")).to_numpy()
        if not keep.any():
            continue
        enc = space.reencode(space.encode(feats[keep]))
        for s, m in ex_maps.items():
            table.loc[style, s] = float(style_distance(enc, m))
    table.index.name = "clips"
    return table


def diagonal_minima(table: pd.DataFrame) -> list[str]:
    """Rows whose smallest entry lies in the column of the same name."""
    return [r for r in table.index if r in table.columns and table.loc[r].idxmin() == r]


def evaluate_table5_1(
    dataset: MotionDataset,
    layout: FeatureLayout,
    space: FeatureSpace,
    neutral: SavedVAE,
    cvaes: Sequence[SavedVAE],
    settings: StyleSettings,
    histories: Sequence[pd.DataFrame] | None = None,
) -> EvaluationResult:
    """Table 5.1 for ``settings.distance_primitive``: rows the neutral VAE and the ``cvaes``
    (by their info's style), columns their style examples; for neutral "we use the mean
    motion as the style example" (the mean of the neutral clips on the
    ``settings.canonical_frames`` timeline). ``settings.distance_samples`` samples a model
    (seed ``settings.seed``). Table: model, style_example_clip, D per example,
    row_minimum_at, published_row_minimum_at, own_clips_row_minimum_at (where the row of the
    style's own clips has its minimum, :func:`own_clips_distances`; rounded to 6 decimals).
    Figure: the measured and published tables. Measurements (:func:`table5_1_measurements`):
    the distances, the own clips' row minima, the latent dimensions each model uses and, from
    the CVAEs' training ``histories`` (in the order of ``cvaes``), how far each one's style
    term still fell in its last epoch; judged in :mod:`motionvar.du2022.claims` (rows whose
    minimum is on the diagonal; not testable when a model's posterior collapsed)."""
    primitive, n_frames, n_samples = settings.distance_primitive, settings.canonical_frames, settings.distance_samples
    models = {"neutral": (neutral[0], neutral[1])}
    _, neutral_feats = primitive_features(dataset, layout, primitive, "neutral", n_frames)
    examples = {"neutral": neutral_feats.mean(axis=0)}
    example_ids = {"neutral": "mean of the neutral clips"}
    for cvae, shape, info in cvaes:
        models[info["style"]] = (cvae, shape)
        examples[info["style"]] = example_features(dataset, layout, info["example"], n_frames)
        example_ids[info["style"]] = info["example"]
    table = style_distance_matrix(models, examples, space, n_samples, settings.seed)
    own = own_clips_distances(dataset, layout, space, primitive, examples, example_ids, n_frames)
    published = table5_1()
    out = table.copy()
    out.insert(0, "style_example_clip", [example_ids[m] for m in table.index])
    out["row_minimum_at"] = table.idxmin(axis=1)
    out["published_row_minimum_at"] = published.loc[table.index, table.columns].idxmin(axis=1)
    out["own_clips_row_minimum_at"] = [_row_minimum(own, m) for m in table.index]
    log.info("style distances (%d samples a model):\n%s", n_samples, table.round(4).to_string())

    infos = [neutral[2], *(info for *_, info in cvaes)]
    measurements = table5_1_measurements(table, primitive, n_samples, infos, neutral[0].latent, own, histories)
    return EvaluationResult(
        table=out.round(6).reset_index(),
        claims=judge_claims(CLAIMS, "du2022_table5_1", measurements),
        figure={"measured": table, "published": published},
        measurements=measurements,
    )


def _row_minimum(table: pd.DataFrame, row: str) -> str | None:
    if row not in table.index or table.loc[row].isna().all():
        return None
    return str(table.loc[row].astype(float).idxmin())


def table5_1_measurements(
    table: pd.DataFrame,
    primitive: str,
    n_samples: int,
    infos: Sequence[Mapping[str, Any]],
    latent_dims: int,
    own_clips: pd.DataFrame | None = None,
    histories: Sequence[pd.DataFrame] | None = None,
) -> dict[str, Any]:
    """What the Table 5.1 claim is judged on: D(m, s) by model and style example (``table``
    of :func:`style_distance_matrix`), the primitive, the samples a model, the CVAEs' training
    regimes and, from every model's saved ``infos`` (the neutral VAE's and the CVAEs'), the latent
    dimensions each uses after training (:func:`~..model.active_units` on the neutral clips) of
    ``latent_dims``; the diagnostics of a row off the diagonal: where the row of each style's own
    clips has its minimum (``own_clips``, :func:`own_clips_distances`) and how far each CVAE's
    style term fell in its last epoch (``histories``, in the order of the CVAEs' ``infos``)."""
    cvaes = [info for info in infos if info.get("style") != "neutral"]
    return {
        "primitive": str(primitive),
        "samples": int(n_samples),
        "distances": {str(r): {str(c): float(table.loc[r, c]) for c in table.columns} for r in table.index},
        "cvae_regimes": list(dict.fromkeys(str(info["regime"]) for info in cvaes if "regime" in info)),
        "active_units": {
            str(info["style"]): int(info["active_units"]) for info in infos if {"style", "active_units"} <= set(info)
        },
        "latent_dims": int(latent_dims),
        "own_clips_minimum": {}
        if own_clips is None
        else {str(r): m for r in table.index if (m := _row_minimum(own_clips, r)) is not None},
        "style_last_drop": {}
        if histories is None
        else last_epoch_drops(cvaes, histories, lambda info: str(info["style"])),
    }
