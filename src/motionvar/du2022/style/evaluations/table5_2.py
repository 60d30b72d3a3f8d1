"""Tables 5.2-5.3 of Du 2022 (Sec. 5.4.5): pose_SD, V_SD and step_SD (Eq. 5.13-5.15) of
the neutral training clips, the neutral VAE and the stylistic CVAEs, per primitive (walk
left and right stance), with the thesis' three claims about them."""

from __future__ import annotations

import logging
from collections.abc import Sequence

import pandas as pd

from ....claims import Claim, EvaluationResult, verdict_from_fraction
from ....io.dataset import MotionDataset
from ..data import primitive_features
from ..diversity import diversity
from ..features import FeatureLayout
from ..model import FeatureSpace, SavedVAE, active_units, sample_features
from ..published import diversity_tables

log = logging.getLogger(__name__)


def evaluate_table5_2(
    dataset: MotionDataset,
    layout: FeatureLayout,
    space: FeatureSpace,
    models: Sequence[SavedVAE],
    primitives: Sequence[str],
    n_frames: int = 60,
    n_samples: int = 10000,
    seed: int = 0,
    pose_sd_tolerance: float = 0.05,
) -> EvaluationResult:
    """Diversity of each primitive's neutral clips (on the ``n_frames`` timeline) and of
    ``n_samples`` samples of each of its ``models`` (neutral VAE first, then the CVAEs, by
    their info's primitive and style), with the latent dimensions each model uses on the
    training clips (:func:`~..model.active_units`). Table (rounded to 5 decimals):
    primitive, model, n, pose_sd, v_sd, step_sd, active_latents and the published
    values. Figure: the unrounded table. Claims: the neutral VAE's pose_SD within
    ``pose_sd_tolerance`` of the training data's; its step_SD below the training data's;
    every style's pose_SD below the neutral VAE's."""
    J = layout.n_joints
    n = n_samples
    rows = []
    for k, primitive in enumerate(primitives):
        _, train = primitive_features(dataset, layout, primitive, "neutral", n_frames)
        rows.append({"primitive": primitive, "model": "training data", "n": len(train), **diversity(train, J)})
        train_maps = space.encode(train)
        for j, (vae, shape, info) in enumerate(m for m in models if m[2]["primitive"] == primitive):
            feats = sample_features(vae, shape, space, n, seed + 1000 * k + j)
            rows.append({"primitive": primitive, "model": info["style"], "n": n, **diversity(feats, J),
                         "active_latents": active_units(vae, train_maps)})
    table = pd.DataFrame(rows)
    pub = diversity_tables().rename(columns={c: f"published_{c}" for c in ("pose_sd", "v_sd", "step_sd")})
    table = table.merge(pub, on=["primitive", "model"], how="left")
    log.info("diversity:\n%s", table.round(4).to_string())

    t = table.set_index(["primitive", "model"])
    prims = list(primitives)
    tol = pose_sd_tolerance
    rel = {p: abs(t.loc[(p, "neutral"), "pose_sd"] / t.loc[(p, "training data"), "pose_sd"] - 1) for p in prims}
    step = {p: (t.loc[(p, "neutral"), "step_sd"], t.loc[(p, "training data"), "step_sd"]) for p in prims}
    styles = [m for m in t.index.get_level_values("model").unique() if m not in ("training data", "neutral")]
    lower = [(p, s) for p in prims for s in styles if t.loc[(p, s), "pose_sd"] < t.loc[(p, "neutral"), "pose_sd"]]
    neutral_active = ", ".join(f"{p}: {int(t.loc[(p, 'neutral'), 'active_latents'])}" for p in prims)
    note = (f"{n} samples a model; synthetic data, CMU 21-joint subset, reduced training budgets (see the caption); "
            f"latent dimensions in use by the neutral VAE (of {models[0][0].latent}): {neutral_active}.")
    claims = [
        Claim(
            claim_id="du2022.table5_2.neutral_pose_sd_close_to_training", paper="du2022", source="Tables 5.2-5.3",
            statement=f"The neutral VAE's pose_SD is close to the training data's (within {tol:.0%}).",
            published="52.68 vs 52.86 (left), 52.88 vs 53.04 (right): within 0.4%",
            measured="; ".join(f"{p}: {t.loc[(p, 'neutral'), 'pose_sd']:.2f} vs "
                               f"{t.loc[(p, 'training data'), 'pose_sd']:.2f} ({rel[p]:.1%})" for p in prims),
            verdict=verdict_from_fraction(sum(r <= tol for r in rel.values()), len(prims)), note=note,
        ),
        Claim(
            claim_id="du2022.table5_2.neutral_step_sd_lower_than_training", paper="du2022", source="Tables 5.2-5.3",
            statement="The neutral VAE's step-length SD is lower than the training data's.",
            published="7.66 < 10.12 (left), 7.51 < 9.98 (right)",
            measured="; ".join(f"{p}: {a:.2f} vs {b:.2f}" for p, (a, b) in step.items()),
            verdict=verdict_from_fraction(sum(a < b for a, b in step.values()), len(prims)), note=note,
        ),
        Claim(
            claim_id="du2022.table5_2.style_pose_sd_lower_than_neutral", paper="du2022", source="Tables 5.2-5.3",
            statement="Every stylistic model's pose_SD is lower than the neutral VAE's.",
            published="12 of 12 (6 styles x 2 primitives)",
            measured=f"{len(lower)} of {len(prims) * len(styles)}",
            verdict=verdict_from_fraction(len(lower), len(prims) * len(styles)), note=note,
        ),
    ]
    return EvaluationResult(table=table.round(5), claims=claims, figure={"table": table})
