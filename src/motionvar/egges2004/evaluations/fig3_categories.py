"""Resting-posture categories (Egges et al. 2004, Sec. 5.1, 5.3) checked against the
ground truth of the data where it has one, and the category transition graphs (Fig. 3)
of the fitted databases.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...claims import EvaluationResult
from ...core.motion import Motion
from ..categories import frame_labels, parse_postures, segment_agreement
from ..pipeline import IdleModel
from ..settings import Egges2004Settings


def category_check(
    model: IdleModel, train: dict[str, list[tuple[pd.Series, Motion]]], settings: Egges2004Settings
) -> EvaluationResult:
    """Per subject: the categories found, resting segments, transitions, and (where the
    metadata has ``idle_postures``) the share of resting segments whose category is the
    true one and the adjusted Rand index. ``train``: the training clips (metadata row,
    Motion) per subject, as :func:`~motionvar.egges2004.pipeline.split_idle` gives them.
    No claim; the figure's data are ``graphs``, the category transition graphs (Fig. 3)
    of the first ``settings.figure_subjects`` subjects."""
    rows = []
    for subject, db in model.databases.items():
        found = []
        for row, motion in train[subject]:
            segs, cats = db.segments[str(row["clip_id"])]
            spec = row.get("idle_postures", "")
            if isinstance(spec, str) and spec:
                labels = frame_labels(parse_postures(spec, str(row["clip_id"])), motion.n_frames)
                found.append((segs, [db.categories.names[c] for c in cats], labels))
        acc = ari = float("nan")
        if found:
            names = [n for f in found for n in f[1]]
            labels = np.concatenate([f[2] for f in found])
            offsets = np.concatenate([[0], np.cumsum([len(f[2]) for f in found])[:-1]])
            segs = np.concatenate([f[0] + o for f, o in zip(found, offsets)])
            acc, ari = segment_agreement(segs, names, labels)
        rows.append(
            {
                "subject": subject,
                "categories": " ".join(db.categories.names),
                "resting_segments": int(sum(len(s) for s, _ in db.segments.values())),
                "balance_shifts": len(db.animations),
                "rest_speed_threshold": db.rest_speed,
                "category_accuracy": acc,
                "category_ari": ari,
            }
        )
    graphs = {s: model.databases[s].graph for s in list(model.databases)[: settings.figure_subjects]}
    return EvaluationResult(pd.DataFrame(rows), [], {"graphs": graphs})
