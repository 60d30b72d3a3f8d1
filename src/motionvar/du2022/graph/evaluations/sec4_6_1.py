"""Du 2022 Sec. 4.6.1 ("Compactness"): bytes of the motion primitive models against the
bytes of the clips they were fitted to (thesis: 41 MB of models for 4.2 GB of data)."""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from ....claims import Claim, EvaluationResult, verdict_threshold
from ..primitive import MotionPrimitive

PAPER = "du2022"
DENSE_SUFFIX = "_dense"  # a primitive fitted to the dense-grid picks (synthetic, Fig. 4.11)


def motion_bytes(n_frames: int, n_joints: int, itemsize: int = 8) -> int:
    """Bytes of a clip as raw arrays: root position (3) + one quaternion per joint per frame."""
    return int(n_frames) * (3 + 4 * int(n_joints)) * int(itemsize)


def compactness_claim(model_bytes: int, data_bytes: int, published_ratio: float = 100.0) -> Claim:
    """Sec. 4.6.1: the models are ~100 times smaller than the data (41 MB vs 4.2 GB)."""
    ratio = data_bytes / max(model_bytes, 1)
    return Claim(
        f"{PAPER}.sec4_6_1.model_much_smaller_than_data",
        PAPER,
        "Sec. 4.6.1, 4.8",
        "The motion primitive models are a compact representation, about 100 times smaller than the motion data.",
        "41 MB of models for 4.2 GB of motion data (about 100x)",
        f"{model_bytes / 1e6:.2f} MB of models for {data_bytes / 1e6:.1f} MB of data ({ratio:.0f}x)",
        verdict_threshold(ratio, published_ratio, ">=", tolerance=0.9),
        note="data bytes: the modelled primitives' clips as float64 arrays (root position + one quaternion per "
        "joint per frame), not BVH text as in the thesis; partial from 10x.",
        value=ratio,
        bound=published_ratio,
        unit="ratio",
        direction=">=",
    )


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
    return EvaluationResult(
        table=table, claims=[compactness_claim(total["model_bytes"], total["data_bytes"])], figure=dict(total=total)
    )
