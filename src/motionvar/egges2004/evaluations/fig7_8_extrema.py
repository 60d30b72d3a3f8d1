"""The data of Fig. 7-8 (Egges et al. 2004, Sec. 6.1-6.2): one PC over a subject's
longest recorded resting segment, with the maxima and minima that the small-variation
model is built from.
"""

from __future__ import annotations

import numpy as np

from ..database import Recording
from ..pipeline import IdleModel
from ..settings import Egges2004Settings
from ..variations import find_extrema


def pc_extrema(model: IdleModel, recordings: dict[str, list[Recording]], settings: Egges2004Settings) -> dict:
    """For each of the first ``settings.figure_subjects`` subjects, PC
    ``settings.extrema_pc`` (1 = the first) over the longest resting segment of their
    training ``recordings`` and its extrema with error epsilon =
    ``settings.analysis.extrema_eps_sd`` times the RMS of that PC's mean-removed resting
    values (as in :func:`~motionvar.egges2004.variations.fit_variation_model`). Returns ``panels``
    (per subject: ``subject``, ``clip``, ``x``, ``fps``, ``extrema`` frame indices,
    ``is_max``), ``pc`` (0-based index) and ``eps_sd``."""
    k, eps_sd = settings.extrema_pc - 1, settings.analysis.extrema_eps_sd
    panels = []
    for s in list(model.databases)[: settings.figure_subjects]:
        db = model.databases[s]
        rests = [(r, a, b) for r in recordings[s] for a, b in db.segments[r.name][0]]
        r, a, b = max(rests, key=lambda x: x[2] - x[1])
        x = r.pcs[a:b, k]
        sd = np.sqrt(np.mean(np.concatenate([q.pcs[i:j, k] - q.pcs[i:j, k].mean() for q, i, j in rests]) ** 2))
        idx, is_max = find_extrema(x - x.mean(), eps_sd * sd)
        panels.append({"subject": s, "clip": r.name, "x": x, "fps": db.fps, "extrema": idx, "is_max": is_max})
    return {"panels": panels, "pc": k, "eps_sd": eps_sd}
