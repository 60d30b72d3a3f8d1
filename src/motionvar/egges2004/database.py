"""A personalised idle-motion database (Egges et al. 2004, Sec. 5.1-5.3, 5.6, 6.1).

From one person's recordings of standing: the resting segments and their categories,
the balance-shift animations A between consecutive rests (translation offset removed,
Sec. 5.2), the posture sets Q_c (first / last frames of the animations plus stand-alone
resting postures, Sec. 5.3), the category transition graph with T_min / T_max, and the
small-variation model of Sec. 6 fitted on the resting segments.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from ..core.joint_map import JointMap
from ..core.motion import Motion
from .categories import (
    CategoryModel,
    find_categories,
    merge_close_rests,
    posture_speed,
    rest_spread,
    static_segments,
    support_ratio,
)
from .category_graph import CategoryGraph
from .pca import PosturePCA
from .settings import AnalysisSettings
from .variations import VariationModel, fit_variation_model

HORIZONTAL = np.array([1.0, 0.0, 1.0])  # x, z; the vertical (y) is kept (Sec. 3.1, 5.2)


@dataclass(frozen=True)
class Recording:
    """One recorded idle clip in PC space with the support ratio of every frame."""

    name: str
    pcs: np.ndarray
    support: np.ndarray
    fps: float


def analyse_recording(motion: Motion, pca: PosturePCA, joint_map: JointMap, name: str) -> Recording:
    """Project a recorded clip to PC space and measure its support ratio per frame."""
    return Recording(name, pca.project(motion), support_ratio(motion, joint_map), motion.fps)


def rest_speed_threshold(speeds: np.ndarray, seed: int) -> float:
    """Boundary between the rest and the shift components of a two-component Gaussian
    mixture of log posture speeds (the speed where both are equally likely)."""
    from sklearn.mixture import GaussianMixture  # only fitting needs scikit-learn (a slow import)

    x = np.log(np.maximum(np.asarray(speeds, dtype=float), 1e-12))[:, None]
    gmm = GaussianMixture(2, random_state=seed).fit(x)
    lo, hi = np.sort(gmm.means_.ravel())
    grid = np.linspace(lo, hi, 512)[:, None]
    post = gmm.predict_proba(grid)[:, np.argmin(gmm.means_.ravel())]
    return float(np.exp(grid[np.argmax(post < 0.5), 0]))


@dataclass
class IdleDatabase:
    """Everything the idle-motion engine needs for one person (Sec. 5.6).

    Attributes:
        subject: whose recordings these are.
        fps: frame rate of the recordings (and of generated motion).
        weights: Eq. 4 weights (footnote 1).
        categories: the category model (names, centroids).
        graph: transition probabilities and T_min / T_max (Fig. 3).
        animations: the database A, each (T_a, D) PC values, translation offset removed.
        anim_from, anim_to: category index of each animation's first / last frame.
        postures: Q_c per category, (n_c, D) PC values.
        variations: the small-variation model (Sec. 6).
        rest_speed: the posture-speed threshold used.
        segments: per recording, (n, 2) resting intervals and their category indices.
    """

    subject: str
    fps: float
    weights: np.ndarray
    categories: CategoryModel
    graph: CategoryGraph
    animations: list[np.ndarray]
    anim_from: np.ndarray
    anim_to: np.ndarray
    postures: list[np.ndarray]
    variations: VariationModel
    rest_speed: float
    segments: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)

    @property
    def anim_starts(self) -> np.ndarray:
        return np.stack([a[0] for a in self.animations])

    @property
    def anim_ends(self) -> np.ndarray:
        return np.stack([a[-1] for a in self.animations])

    def classify(self, posture: np.ndarray) -> int:
        """Category of a posture: the one holding the nearest posture (Eq. 4; Sec. 7.1)."""
        from .fitting import posture_distance

        best = [posture_distance(q, posture, self.weights).min() if len(q) else np.inf for q in self.postures]
        return int(np.argmin(best))


def remove_translation_offset(anim: np.ndarray, pca: PosturePCA) -> np.ndarray:
    """Sec. 5.2: subtract from every frame the mean horizontal root translation of the
    first and last frames, so the shift is centred on the origin."""
    root = pca.root_translation(anim[[0, -1]])
    return pca.shift_translation(anim, -root.mean(axis=0) * HORIZONTAL)


def build_database(
    recordings: Sequence[Recording],
    pca: PosturePCA,
    settings: AnalysisSettings,
    subject: str,
    seed: int,
) -> IdleDatabase:
    """Analyse one person's recordings into an :class:`IdleDatabase`: resting segments and
    their categories (Sec. 5.1), the balance shifts between them with the translation
    offset removed (Sec. 5.2), the category graph and posture sets Q_c (Sec. 5.3) and the
    small-variation model fitted on the rests (Sec. 6)."""
    if not recordings:
        raise ValueError(f"subject {subject}: no idle recordings")
    fps = recordings[0].fps
    if any(r.fps != fps for r in recordings):
        raise ValueError(f"subject {subject}: idle recordings have different frame rates")
    weights = pca.weights()
    segs, threshold = _resting_segments(recordings, weights, fps, settings, subject, seed)
    means = np.concatenate([[r.pcs[a:b].mean(axis=0) for a, b in s] for r, s in zip(recordings, segs) if len(s)])
    supp = np.concatenate([[r.support[a:b].mean() for a, b in s] for r, s in zip(recordings, segs) if len(s)])
    cat_model, seg_cat = find_categories(means, supp, weights, settings.max_categories, settings.support_margin, seed)
    k = len(cat_model.names)
    per_rec = np.split(seg_cat, np.cumsum([len(s) for s in segs])[:-1])
    graph, animations, a_from, a_to, rest_mid = _transitions(recordings, segs, per_rec, cat_model, pca, subject)
    postures = _posture_sets(animations, a_from, a_to, rest_mid, pca, k)
    rests = [r.pcs[a:b] for r, s in zip(recordings, segs) for a, b in s]
    n_var = min(settings.variation_pcs, pca.n_dims)
    variations = fit_variation_model(
        rests, np.arange(n_var), fps, settings.extrema_eps_sd, settings.variation_clusters, seed
    )
    return IdleDatabase(
        subject=subject,
        fps=fps,
        weights=weights,
        categories=cat_model,
        graph=graph,
        animations=animations,
        anim_from=a_from,
        anim_to=a_to,
        postures=postures,
        variations=variations,
        rest_speed=float(threshold),
        segments={r.name: (s, c) for r, s, c in zip(recordings, segs, per_rec)},
    )


def _resting_segments(
    recordings: Sequence[Recording],
    weights: np.ndarray,
    fps: float,
    settings: AnalysisSettings,
    subject: str,
    seed: int,
) -> tuple[list[np.ndarray], float]:
    """Per recording, the (n, 2) resting intervals (Sec. 5.1): frames below the posture-speed
    threshold for at least ``min_rest_s``, with rests joined across a gap that does not
    move the mean posture by ``min_shift_rms`` times the resting sway; and the threshold."""
    speeds = [posture_speed(r.pcs, weights, fps, settings.smooth_s) for r in recordings]
    threshold = settings.rest_speed
    if threshold is None:
        threshold = rest_speed_threshold(np.concatenate(speeds), seed)
    segs = [static_segments(s, fps, threshold, settings.min_rest_s) for s in speeds]
    if sum(len(s) for s in segs) == 0:
        raise ValueError(
            f"subject {subject}: no resting segment of at least {settings.min_rest_s} s below posture speed "
            f"{threshold:.4g} in {[r.name for r in recordings]}"
        )
    spread = np.sqrt(np.mean([rest_spread(s, r.pcs, weights) ** 2 for r, s in zip(recordings, segs) if len(s)]))
    segs = [merge_close_rests(s, r.pcs, weights, settings.min_shift_rms * spread) for r, s in zip(recordings, segs)]
    return segs, threshold


def _transitions(
    recordings: Sequence[Recording],
    segs: list[np.ndarray],
    per_rec: list[np.ndarray],
    cat_model: CategoryModel,
    pca: PosturePCA,
    subject: str,
) -> tuple[CategoryGraph, list[np.ndarray], np.ndarray, np.ndarray, list[list[np.ndarray]]]:
    """The category graph with T_min / T_max (Sec. 5.3, Fig. 3), the balance-shift
    animations A between consecutive rests with their translation offset removed (Sec. 5.2),
    their start and end categories, and the middle posture of every rest per category."""
    k = len(cat_model.names)
    fps = recordings[0].fps
    sequences, stays, censored = [], [], [[] for _ in range(k)]
    animations, a_from, a_to, rest_mid = [], [], [], [[] for _ in range(k)]
    for rec, s, cats in zip(recordings, segs, per_rec):
        dur = (s[:, 1] - s[:, 0]) / fps
        inner = (s[:, 0] > 0) & (s[:, 1] < len(rec.pcs))  # stays cut by the clip's ends are censored
        for c, d in zip(cats[~inner], dur[~inner]):
            censored[c].append(d)
        sequences.append(cats)
        stays.append(np.where(inner, dur, np.nan))
        for i in range(len(s) - 1):
            anim = rec.pcs[s[i, 1] - 1 : s[i + 1, 0] + 1]
            animations.append(remove_translation_offset(anim, pca))
            a_from.append(cats[i])
            a_to.append(cats[i + 1])
        for (a, b), c in zip(s, cats):
            rest_mid[c].append(rec.pcs[(a + b) // 2])
    if not animations:
        raise ValueError(f"subject {subject}: no balance shift between two resting segments in the recordings")
    graph = CategoryGraph.from_sequences(cat_model.names, sequences, stays)
    graph = _fill_censored_times(graph, censored)
    return graph, animations, np.array(a_from, dtype=np.int64), np.array(a_to, dtype=np.int64), rest_mid


def _posture_sets(
    animations: list[np.ndarray],
    a_from: np.ndarray,
    a_to: np.ndarray,
    rest_mid: list[list[np.ndarray]],
    pca: PosturePCA,
    k: int,
) -> list[np.ndarray]:
    """Q_c per category (Sec. 5.3): the first / last frames of the animations from / to it,
    then the stand-alone resting postures, moved to the mean translation of the others."""
    postures = []
    for c in range(k):
        ends = [a[0] for a, f in zip(animations, a_from) if f == c] + [
            a[-1] for a, t in zip(animations, a_to) if t == c
        ]
        alone = np.array(rest_mid[c]).reshape(-1, pca.n_dims)
        if ends and len(alone):  # stand-alone postures take the mean translation of the others (Sec. 5.3)
            target = pca.root_translation(np.array(ends)).mean(axis=0)
            alone = pca.shift_translation(alone, (target - pca.root_translation(alone)) * HORIZONTAL)
        postures.append(np.concatenate([np.array(ends).reshape(-1, pca.n_dims), alone]))
    return postures


def _fill_censored_times(graph: CategoryGraph, censored: list[list[float]]) -> CategoryGraph:
    """T_min / T_max of a category seen only in stays cut by a clip's ends: take those."""
    t_min, t_max = graph.t_min.copy(), graph.t_max.copy()
    for c, d in enumerate(censored):
        if np.isnan(t_min[c]) and d:
            t_min[c], t_max[c] = min(d), max(d)
    return CategoryGraph(graph.names, graph.counts, graph.probabilities, t_min, t_max)
