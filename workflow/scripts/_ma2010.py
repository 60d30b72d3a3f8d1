"""Shared by the Ma 2010 rule scripts: the dataset's joint map, the walking clips and
the published values the claims compare with."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

PAPER = "ma2010"
PUBLISHED_MAX_STRIDE_ERROR_CM = 1.2  # Sec. 7.1 / Fig. 6
PUBLISHED_SECONDS_PER_SECOND = 0.15  # Sec. 8
PROTOCOL = (
    "Paper: walks captured from 25 subjects at 120 fps, normalized to one skeleton. Ours: synthetic walks "
    "of generated subjects (motionvar.synth), cut into gait cycles at the key frames, rotations put on the "
    "mean skeleton; style = stride of the left and right support phases measured on that skeleton."
)


def joint_map(snakemake):
    from motionvar.core import cmu_joint_map
    from motionvar.io.joint_map_file import load_joint_map

    path = snakemake.params.joint_map
    return load_joint_map(path) if path else cmu_joint_map()


@dataclass
class WalkData:
    """The walking cycles of a dataset (rule ma2010_clips) and what the model needs."""

    clips: object  # motionvar.ma2010.ClipSet
    table: pd.DataFrame
    joint_map: object
    groups: dict
    solver: object
    options: dict

    @property
    def subjects(self) -> list[str]:
        return self.table["subject"].astype(str).tolist()


def load_walks(snakemake) -> WalkData:
    from motionvar.ma2010 import ClipSet, root_solver

    with np.load(snakemake.input.clips, allow_pickle=False) as z:
        clips = ClipSet.from_arrays({k: z[k] for k in z.files})
    table = pd.read_csv(snakemake.input.table, dtype={"clip_id": str, "subject": str, "source_clip": str})
    if len(table) != clips.n_clips or list(table["clip_id"]) != clips.clip_ids:
        raise ValueError(f"{snakemake.input.table} does not list the cycles of {snakemake.input.clips}; rerun ma2010_clips")
    jm = joint_map(snakemake)
    return WalkData(clips, table, jm, jm.group_indices(clips.skeleton), root_solver(clips.skeleton, jm), dict(snakemake.params.options))


def model(data: WalkData):
    """The model of Sec. 5-6 fitted to all walking cycles."""
    from motionvar.ma2010 import StyleVariationModel

    return StyleVariationModel(data.groups, structure(data.clips, data), data.options["variogram_model"]).fit(data.clips)


def structure(clips, data: WalkData) -> str:
    """config ma2010.structure, with "auto" resolved by D_l vs D_u of ``clips`` (Fig. 5)."""
    if data.options["structure"] != "auto":
        return data.options["structure"]
    d_l, d_u = structure_evidence(clips, data.joint_map)
    return "lower_first" if d_l >= d_u else "upper_first"


def structure_evidence(clips, joint_map) -> tuple[float, float]:
    """D_l and D_u (Eq. 3) over all the examples' frames, for the "auto" structure (Fig. 5)."""
    from motionvar.core.kinematics import fk
    from motionvar.ma2010.examples import lower_upper
    from motionvar.ma2010.keyframes import keyframe_signal

    sk = clips.skeleton
    lower, upper = lower_upper(joint_map, sk)
    d_l = d_u = 0.0
    for rot in clips.rotations:  # loop over clips
        sig = keyframe_signal(fk(rot, np.zeros((len(rot), 3)), sk.offsets, sk.parents), lower, upper)
        d_l, d_u = d_l + sig.d_lower**2, d_u + sig.d_upper**2
    return float(np.sqrt(d_l)), float(np.sqrt(d_u))
