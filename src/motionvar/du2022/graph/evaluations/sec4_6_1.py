"""Du 2022 Sec. 4.6.1 ("Compactness"): bytes of the motion primitive models against the
bytes of the clips they were fitted to (thesis: 41 MB of models for 4.2 GB of data), and
the thesis' point that "the size of the parametric statistical model is invariant to the
number of samples": each primitive refitted with its own settings to a seeded random half
of its clips (:func:`fit_half`), its size against the model of all clips."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from ....claims import EvaluationResult, judge_claims
from ....core.motion import Motion
from ...claims import CLAIMS
from ..primitive import MotionPrimitive

DENSE_SUFFIX = "_dense"  # a primitive fitted to the dense-grid picks (synthetic, Fig. 4.11)


def clips_by_primitive(
    names: Sequence[str], prep: Any, dense: Any = None, prep_source: str = "", dense_source: str = ""
):
    """The clips each primitive in ``names`` was fitted to, in the order of its metadata rows:
    ``prep``'s (a packed dataset of the prep stage), or ``dense``'s for a ``*_dense`` primitive;
    ValueError naming the primitive when its clips are missing."""
    from ..primitive import primitive_clips

    out = {}
    for name in names:
        data, source = (dense, dense_source) if name.endswith(DENSE_SUFFIX) else (prep, prep_source)
        if data is None:
            raise ValueError(f"sec4_6_1: primitive {name} needs the dense picks' clips")
        out[name] = primitive_clips(data, name.removesuffix(DENSE_SUFFIX), source=source)[0]
    return out


MIN_FIT_CLIPS = 3  # MotionPrimitive.fit needs at least 3 clips


def motion_bytes(n_frames: int, n_joints: int, itemsize: int = 8) -> int:
    """Bytes of a clip as raw arrays: root position (3) + one quaternion per joint per frame."""
    return int(n_frames) * (3 + 4 * int(n_joints)) * int(itemsize)


def half_clip_indices(n_clips: int, seed: int) -> np.ndarray:
    """Sorted indices of a seeded random half (``n_clips // 2``) of a primitive's clips."""
    rng = np.random.default_rng([int(seed), 461])
    return np.sort(rng.permutation(int(n_clips))[: int(n_clips) // 2])


def fit_half(
    models: Mapping[str, MotionPrimitive], clips: Mapping[str, Sequence[Motion]], seed: int
) -> dict[str, tuple[np.ndarray, MotionPrimitive]]:
    """Per primitive of ``models`` whose half of ``clips[name]`` (its clips, in the order of its
    metadata rows) has at least :data:`MIN_FIT_CLIPS` clips: the indices of that half
    (:func:`half_clip_indices`) and the primitive refitted to them with the model's own saved
    options (the same settings as the model of all clips)."""
    out = {}
    for name, model in models.items():
        idx = half_clip_indices(len(clips[name]), seed)
        if len(idx) >= MIN_FIT_CLIPS:
            out[name] = (idx, MotionPrimitive(name, model.options).fit([clips[name][i] for i in idx]))
    return out


def compactness_measurements(total: Mapping[str, Any], table: pd.DataFrame | None = None) -> dict[str, Any]:
    """What the Sec. 4.6.1 claims are judged on: the bytes of all models and of all their clips
    (``total``, the table's row ``all``), with the clip and frame counts; and, from the rows of
    ``table`` with a model fitted to half of the clips (column ``half_model_bytes``), the sums of
    model and data bytes of those primitives at all and at half of their clips, each one's growth,
    latent dimensions and Gaussians, and the primitives left out (``half`` None without such a
    column)."""
    out: dict[str, Any] = {k: int(total[k]) for k in ("model_bytes", "data_bytes", "clips", "frames")}
    out["half"] = None
    if table is not None and "half_model_bytes" in table.columns:
        rows = table[table["primitive"] != "all"]
        done = rows[rows["half_model_bytes"].notna()]
        out["half"] = {
            "primitives": [str(p) for p in done["primitive"]],
            "skipped": [str(p) for p in rows.loc[rows["half_model_bytes"].isna(), "primitive"]],
            **{k: int(done[k].sum()) for k in ("model_bytes", "data_bytes", "half_model_bytes", "half_data_bytes")},
            "per_primitive": [
                {
                    "primitive": str(r.primitive),
                    "growth": float(r.model_growth),
                    "latent": int(r.latent),
                    "half_latent": int(r.half_latent),
                    "gaussians": int(r.gaussians),
                    "half_gaussians": int(r.half_gaussians),
                }
                for r in done.itertuples()
            ],
        }
    return out


def _clip_rows(name: str, metadata: pd.DataFrame, dense_metadata: pd.DataFrame | None) -> pd.DataFrame:
    if name.endswith(DENSE_SUFFIX):
        if dense_metadata is None:
            raise ValueError(f"sec4_6_1: primitive {name} needs the dense picks' metadata")
        if "primitive" in dense_metadata.columns:  # the dense picks are modelled under the name <primitive>_dense
            return dense_metadata[dense_metadata["primitive"] == name.removesuffix(DENSE_SUFFIX)]
        return dense_metadata
    return metadata[metadata["primitive"] == name]


def evaluate_sec4_6_1(
    models: Mapping[str, MotionPrimitive],
    model_bytes: Mapping[str, int],
    metadata: pd.DataFrame,
    dense_metadata: pd.DataFrame | None = None,
    half: Mapping[str, tuple[Sequence[int], MotionPrimitive, int]] | None = None,
) -> EvaluationResult:
    """Sec. 4.6.1: per primitive of ``models`` (in their order), the bytes of its clips
    (frames from ``start_frame``/``stop_frame`` of the prep ``metadata``, or of
    ``dense_metadata`` for a ``*_dense`` primitive) against ``model_bytes`` (its files on
    disk); with ``half`` (name -> indices into the primitive's clip rows, the model fitted to
    them, its bytes on disk; :func:`fit_half`) the same at half of the clips and the growth
    from half to all; a last row ``all`` sums them."""
    rows = []
    for name, model in models.items():
        sub = _clip_rows(name, metadata, dense_metadata)
        frames = (sub["stop_frame"] - sub["start_frame"]).to_numpy()
        data = int(sum(motion_bytes(int(t), model.skeleton.n_joints) for t in frames))
        size = int(model_bytes[name])
        row = dict(primitive=name, clips=len(frames), frames=int(frames.sum()), data_bytes=data, model_bytes=size)
        row["ratio"] = data / size
        if half is not None:
            nan = float("nan")
            row.update(latent=model.n_latent, gaussians=model.gmm_.n_components, half_clips=nan)
            row.update(half_data_bytes=nan, half_model_bytes=nan, half_latent=nan, half_gaussians=nan)
            row.update(model_growth=nan, data_growth=nan)
            if name in half:
                idx, small, small_bytes = half[name]
                row.update(
                    half_clips=len(idx),
                    half_data_bytes=int(sum(motion_bytes(int(t), model.skeleton.n_joints) for t in frames[idx])),
                    half_model_bytes=int(small_bytes),
                    half_latent=small.n_latent,
                    half_gaussians=small.gmm_.n_components,
                )
                row["model_growth"] = size / row["half_model_bytes"]
                row["data_growth"] = data / row["half_data_bytes"]
        rows.append(row)
    table = pd.DataFrame(rows)
    total = dict(
        primitive="all",
        clips=int(table["clips"].sum()),
        frames=int(table["frames"].sum()),
        data_bytes=int(table["data_bytes"].sum()),
        model_bytes=int(table["model_bytes"].sum()),
    )
    total["ratio"] = total["data_bytes"] / total["model_bytes"]
    if half is not None:
        done = table[table["half_model_bytes"].notna()]
        for k in ("half_clips", "half_data_bytes", "half_model_bytes"):
            total[k] = int(done[k].sum())
        total["model_growth"] = done["model_bytes"].sum() / max(total["half_model_bytes"], 1)
        total["data_growth"] = done["data_bytes"].sum() / max(total["half_data_bytes"], 1)
    table = pd.concat([table, pd.DataFrame([total])], ignore_index=True)
    measurements = compactness_measurements(total, table if half is not None else None)
    claims = judge_claims(CLAIMS, "du2022_sec4_6_1", measurements)
    return EvaluationResult(table, claims, dict(total=total), measurements)
