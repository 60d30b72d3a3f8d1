"""The synthetic dense-grid picking primitive of Du 2022 Fig. 4.11 / Sec. 4.6.2.

The thesis built it "by sampling our statistical motion primitive model" with "a dense
and equally distributed grid" of picking targets, to test the search "in a large and
equally distributed dataset". Here the synthetic generator's own dense target grid
(:func:`motionvar.synth.reach.target_grid`, region ``dense``) plays that role: each
synthetic subject picks at random grid nodes; the ``pick_reach`` segments are cut at the
generator's ground truth and aligned like the prep stage does (start at the origin, +x).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...prep import PrepOptions, align_motions, parse_segments
from ...synth.reach import ReachParams, generate_pick
from ...synth.subjects import make_subjects

PRIMITIVE = "pick_reach"


def dense_pick_clips(n_subjects: int, seed: int, per_subject: int, joint_map: JointMap,
                     grid_spacing_cm: float = 10.0, fps: float = 120.0,
                     prep: PrepOptions | None = None) -> tuple[list[Motion], pd.DataFrame]:
    """Aligned ``pick_reach`` clips of ``per_subject`` dense-grid picks per synthetic subject
    (the subjects of the synthetic dataset with this ``seed``) and their metadata."""
    if per_subject < 1 or n_subjects < 1:
        raise ValueError(f"dense picks: need subjects >= 1 and per_subject >= 1; got {n_subjects}, {per_subject}")
    pieces, rows = [], []
    for i, subject in enumerate(make_subjects(n_subjects, seed)):
        rng = np.random.default_rng([seed, i, 1000])
        for k in range(per_subject):
            m, truth = generate_pick(subject, ReachParams(region="dense", grid_spacing_cm=grid_spacing_cm, fps=fps), rng)
            seg = [s for s in parse_segments(truth["segments"], what="dense pick segments") if s.name == PRIMITIVE]
            if len(seg) != 1:
                raise ValueError(f"dense pick {i}/{k}: expected one {PRIMITIVE} segment in {truth['segments']!r}")
            pieces.append(m.slice(seg[0].start, seg[0].stop))
            rows.append(dict(clip_id=f"s{subject.subject_id}_pick_dense_{k:02d}_00",
                             source_clip=f"s{subject.subject_id}_pick_dense_{k:02d}", subject=subject.subject_id,
                             behaviour="pick", style="neutral", variant="dense", primitive=PRIMITIVE,
                             target_x=truth["target_x"], target_y=truth["target_y"], target_z=truth["target_z"],
                             start_frame=seg[0].start, stop_frame=seg[0].stop))
    return align_motions(pieces, joint_map, prep), pd.DataFrame(rows)
