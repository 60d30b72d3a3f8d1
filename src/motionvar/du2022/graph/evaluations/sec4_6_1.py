"""Du 2022 Sec. 4.6.1 ("Compactness"): bytes of the motion primitive models against the
bytes of the clips they were fitted to (thesis: 41 MB of models for 4.2 GB of data)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import pandas as pd

from ....claims import EvaluationResult, judge_claims
from ...claims import CLAIMS
from ..primitive import MotionPrimitive

DENSE_SUFFIX = "_dense"  # a primitive fitted to the dense-grid picks (synthetic, Fig. 4.11)


def motion_bytes(n_frames: int, n_joints: int, itemsize: int = 8) -> int:
    """Bytes of a clip as raw arrays: root position (3) + one quaternion per joint per frame."""
    return int(n_frames) * (3 + 4 * int(n_joints)) * int(itemsize)


def compactness_measurements(total: Mapping[str, int]) -> dict[str, Any]:
    """What the Sec. 4.6.1 claim is judged on: the bytes of all models and of all their clips
    (``total``, the table's row ``all``), with the clip and frame counts."""
    return {k: int(total[k]) for k in ("model_bytes", "data_bytes", "clips", "frames")}


def evaluate_sec4_6_1(
    models: Mapping[str, MotionPrimitive],
    model_bytes: Mapping[str, int],
    metadata: pd.DataFrame,
    dense_metadata: pd.DataFrame | None = None,
) -> EvaluationResult:
    """Sec. 4.6.1: per primitive of ``models`` (in their order), the bytes of its clips
    (frames from ``start_frame``/``stop_frame`` of the prep ``metadata``, or of
    ``dense_metadata`` for a ``*_dense`` primitive) against ``model_bytes`` (its files on
    disk); a last row ``all`` sums them."""
    rows = []
    for name, model in models.items():
        if name.endswith(DENSE_SUFFIX):
            if dense_metadata is None:
                raise ValueError(f"sec4_6_1: primitive {name} needs the dense picks' metadata")
            sub = dense_metadata
        else:
            sub = metadata[metadata["primitive"] == name]
        frames = (sub["stop_frame"] - sub["start_frame"]).to_numpy()
        data = int(sum(motion_bytes(int(t), model.skeleton.n_joints) for t in frames))
        size = int(model_bytes[name])
        rows.append(
            dict(
                primitive=name,
                clips=len(frames),
                frames=int(frames.sum()),
                data_bytes=data,
                model_bytes=size,
                ratio=data / size,
            )
        )
    table = pd.DataFrame(rows)
    total = dict(
        primitive="all",
        clips=int(table["clips"].sum()),
        frames=int(table["frames"].sum()),
        data_bytes=int(table["data_bytes"].sum()),
        model_bytes=int(table["model_bytes"].sum()),
    )
    total["ratio"] = total["data_bytes"] / total["model_bytes"]
    table = pd.concat([table, pd.DataFrame([total])], ignore_index=True)
    measurements = compactness_measurements(total)
    claims = judge_claims(CLAIMS, "du2022_sec4_6_1", measurements)
    return EvaluationResult(table, claims, dict(total=total), measurements)
