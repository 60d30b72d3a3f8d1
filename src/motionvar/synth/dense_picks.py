"""Dense-grid picking clips: the synthetic counterpart of the picking data of Du 2022
Fig. 4.11 / Sec. 4.6.2.

The thesis built that data "by sampling our statistical motion primitive model" with "a
dense and equally distributed grid" of picking targets, to test the search "in a large
and equally distributed dataset". Here the generator's own dense target grid
(:func:`motionvar.synth.reach.target_grid`, region ``dense``) plays that role: each
synthetic subject picks at random grid nodes, and the ``pick_reach`` segment of each pick
is cut at the generator's ground truth. The clips are returned as generated (world
placement); aligning them like the prep stage does is the caller's step.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..core.motion import Motion
from ..io.intervals import parse_named
from .reach import ReachParams, generate_pick
from .subjects import make_subjects

PRIMITIVE = "pick_reach"


def dense_pick_segments(
    n_subjects: int, seed: int, per_subject: int, grid_spacing_cm: float = 10.0, fps: float = 120.0
) -> tuple[list[Motion], pd.DataFrame]:
    """The ``pick_reach`` segments of ``per_subject`` dense-grid picks per synthetic
    subject (the subjects of the synthetic dataset with this ``seed``), unaligned, and
    their metadata (one row per clip: ids, subject, primitive, target, frames of the
    segment in its pick)."""
    if per_subject < 1 or n_subjects < 1:
        raise ValueError(f"dense picks: need subjects >= 1 and per_subject >= 1; got {n_subjects}, {per_subject}")
    pieces, rows = [], []
    for i, subject in enumerate(make_subjects(n_subjects, seed)):
        rng = np.random.default_rng([seed, i, 1000])
        for k in range(per_subject):
            params = ReachParams(region="dense", grid_spacing_cm=grid_spacing_cm, fps=fps)
            m, truth = generate_pick(subject, params, rng)
            seg = [s for s in parse_named(truth["segments"]) if s[0] == PRIMITIVE]
            if len(seg) != 1:
                raise ValueError(f"dense pick {i}/{k}: expected one {PRIMITIVE} segment in {truth['segments']!r}")
            _, start, stop = seg[0]
            pieces.append(m.slice(start, stop))
            rows.append(
                dict(
                    clip_id=f"s{subject.subject_id}_pick_dense_{k:02d}_00",
                    source_clip=f"s{subject.subject_id}_pick_dense_{k:02d}",
                    subject=subject.subject_id,
                    behaviour="pick",
                    style="neutral",
                    variant="dense",
                    primitive=PRIMITIVE,
                    target_x=truth["target_x"],
                    target_y=truth["target_y"],
                    target_z=truth["target_z"],
                    start_frame=start,
                    stop_frame=stop,
                )
            )
    return pieces, pd.DataFrame(rows)
