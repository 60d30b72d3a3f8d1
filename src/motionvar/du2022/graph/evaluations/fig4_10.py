"""Du 2022 Fig. 4.10: constrained motion generation with the Morphable Graph: a walk
following a floor path (graph walk, Algorithm 1) and reaching targets with the picking
primitive; each step seeded by the k-means tree and optimised by Levenberg-Marquardt on
Eq. 4.9. The walk of the verdict is the thesis' reading (Sec. 4.5.1): the next primitive is
the first of the T planned steps whose mean motions fit the path best, the step is then
optimised on its own constraints, and Algorithm 1 line 9 optimises the walk's steps together;
the greedy walk and our receding horizon are compared. The reaching targets
lie ``reach_offset_cm`` from training hand positions, inside the primitive's variation range
(Sec. 4.6.1: the random samples' hand positions), and a reach counts as natural when the GMM
log-likelihood of its solved parameters is no lower than most of the primitive's own random
samples'. The table lists the constraint errors that remain, per step after its own
optimisation and at the end, how far the walk's hips are from the path, and each reach's
log-likelihood.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd
from scipy.spatial import cKDTree

from ....claims import EvaluationResult, judge_claims
from ....core.joint_map import JointMap
from ....io.dataset import MotionDataset
from ...claims import CLAIMS, FIG4_10_NATURAL_PERCENTILE, FIG4_10_REACH_CLOSE_CM
from ..constraints import Constraint
from ..morphable_graph import MorphableGraph, Path2D, concatenate_steps, follow_path, synthesize_step
from ..primitive import MotionPrimitive, primitive_clips
from ..settings import REACH_JOINT, GraphSettings, SynthesisSettings
from ..trees import SpacePartitioningTree
from .common import semantic_index

#: the compared walks (table tasks ``path_<name>``): overrides of the configured ``du2022_graph.synthesis``; the greedy walk
#: (T = 1, no line 9) and our receding horizon with line 9 (T = 1 with line 9 alone is the thesis' walk on a graph
#: whose stepping nodes alternate, as ours: one successor per step after the first, so T changes little)
VARIANTS: dict[str, dict[str, Any]] = {
    "greedy": dict(look_ahead=1, receding_horizon=False, joint_steps=0),
    "receding": dict(receding_horizon=True, joint_steps="all"),
}
#: random (training clip, direction) draws per requested reaching target
DRAWS_PER_TARGET = 50


def _mode(st: SynthesisSettings) -> str:
    """The walk's synthesis in words: look-ahead, receding horizon and line 9."""
    js, t = st.joint_steps, int(st.look_ahead)
    line9 = (
        "all steps optimised together (Algorithm 1, line 9)"
        if js == "all"
        else f"the last {js} steps optimised together (Algorithm 1, line 9)"
        if js
        else "no joint optimisation (Algorithm 1, line 9 left out)"
    )
    if t == 1:
        ahead = "look-ahead T = 1 (greedy)"
    elif st.receding_horizon:
        ahead = f"look-ahead T = {t} with a receding horizon (our addition)"
    else:
        ahead = f"look-ahead T = {t} by the mean motions (Sec. 4.5.1)"
    return f"{ahead}, {line9}"


def _label(name: str, st: SynthesisSettings) -> str:
    """A compared walk's name with its T, receding horizon and line 9, in short."""
    js = st.joint_steps
    line9 = "line 9: all steps" if js == "all" else f"line 9: last {js} steps" if js else "no line 9"
    return f"{name} (T = {st.look_ahead}{', receding horizon' if _effective(st)[1] else ''}, {line9})"


def _effective(st: SynthesisSettings) -> tuple:
    """What makes two walks differ: T, the receding horizon (only with T > 1), line 9."""
    t = int(st.look_ahead)
    return t, bool(st.receding_horizon) and t > 1, st.joint_steps


def fig4_10_measurements(
    table: pd.DataFrame,
    n_steps: int,
    end_gap_cm: float,
    max_deviation_cm: float,
    reach: Mapping[str, Any],
    mode: str = "",
    variants: Mapping[str, Mapping] | None = None,
) -> dict[str, Any]:
    """What the Fig. 4.10 claims are judged on, from the table of :func:`evaluate_fig4_10`: the
    walk's step count and mean hips position error per step (the table gives it after the tree
    search and after each step's own optimisation too), mean heading error, end gap and largest distance of the
    hips from the path; ``mode`` (:func:`_mode`); the summaries of the compared walks
    (``variants``, :data:`VARIANTS`); per reach, the hand error after LM and after the tree
    search, the log-likelihood of the solved parameters and the target's distance from the
    nearest training hand position, with ``reach``'s reference numbers (``offset_cm``,
    ``range_samples``, ``draws``, ``natural_log_prob``: the samples' percentile, and
    ``train_log_prob_p5``: the training clips' own)."""
    path_rows = table[table["task"] == "path"]
    reach_rows = table[table["task"] == "reach"]

    def column(name: str) -> list[float]:
        return [float(v) for v in reach_rows[name]] if name in reach_rows.columns else []

    return {
        "path": {
            "n_steps": int(n_steps),
            "mean_step_cm": float(path_rows["position_error_cm"].mean()),
            "heading_deg": float(path_rows["heading_error_deg"].mean()),
            "end_gap_cm": float(end_gap_cm),
            "max_deviation_cm": float(max_deviation_cm),
        },
        "mode": mode,
        "variants": {
            k: {"label": v["label"], **{f: v[f] for f in ("n_steps", "mean_step_cm", "max_deviation_cm", "end_gap_cm")}}
            for k, v in (variants or {}).items()
        },
        "reach": {
            "joint": REACH_JOINT,
            **{k: reach[k] for k in ("offset_cm", "range_samples", "draws")},
            **{k: float(reach[k]) for k in ("natural_log_prob", "train_log_prob_p5")},
            "errors_cm": column("position_error_cm"),
            "tree_errors_cm": column("position_error_tree_cm"),
            "log_prob": column("log_prob"),
            "training_distance_cm": column("target_training_distance_cm"),
        },
    }


def _walk_rows(steps, floor_path: Path2D, hips: int, task: str) -> list[dict]:
    rows = []
    for i, st in enumerate(steps):
        dist = floor_path.distance(st.motion.positions()[:, hips][:, [0, 2]])
        rows.append(
            dict(
                task=task,
                item=i,
                primitive=st.primitive,
                position_error_tree_cm=st.fit.errors_before[0],
                position_error_step_cm=st.step_errors[0],
                position_error_cm=st.fit.errors_after[0],
                heading_error_tree_deg=st.fit.errors_before[1],
                heading_error_step_deg=st.step_errors[1],
                heading_error_deg=st.fit.errors_after[1],
                path_distance_cm=dist[-1],
                max_deviation_cm=dist.max(),
                tree_evaluations=st.tree_evals,
                log_prob=st.fit.log_prob_after,
            )
        )
    return rows


def _walk_summary(rows: list[dict], walk, floor_path: Path2D, hips: int) -> dict:
    hips_xz = walk.positions()[:, hips][:, [0, 2]]
    return dict(
        n_steps=len(rows),
        mean_step_cm=float(np.mean([r["position_error_cm"] for r in rows])),
        max_deviation_cm=float(floor_path.distance(hips_xz).max()),
        end_gap_cm=float(np.linalg.norm(hips_xz[-1] - floor_path.points[-1])),
    )


def _path_walks(
    graph: MorphableGraph, trees: Mapping[str, SpacePartitioningTree], joint_map: JointMap, st: SynthesisSettings
) -> tuple[list, list[dict], dict, dict, dict]:
    """Fig. 4.10 left: the walk along ``st.path`` with ``st``, and with ``st.compare_variants``
    the walks of :data:`VARIANTS` that differ from it and from each other. Returns (steps, table
    rows of every walk, the walk's figure data, its summary, the variants' summaries with their
    walks and labels)."""
    floor_path = Path2D(np.asarray(st.path, dtype=float))
    steps = follow_path(graph, trees, floor_path, joint_map, st)
    hips = joint_map.index(steps[0].motion.skeleton, "hips")
    rows = _walk_rows(steps, floor_path, hips, "path")
    walk = concatenate_steps(steps)
    summary = _walk_summary(rows, walk, floor_path, hips)
    variants: dict[str, dict] = {}
    seen = {_effective(st)}
    for name, overrides in VARIANTS.items() if st.compare_variants else ():
        v_st = st.replace(**overrides)
        if _effective(v_st) in seen:
            continue
        seen.add(_effective(v_st))
        v_steps = follow_path(graph, trees, floor_path, joint_map, v_st)
        v_rows = _walk_rows(v_steps, floor_path, hips, f"path_{name}")
        v_walk = concatenate_steps(v_steps)
        rows += v_rows
        variants[name] = dict(_walk_summary(v_rows, v_walk, floor_path, hips), walk=v_walk, label=_label(name, v_st))
    feet = {f: joint_map.index(walk.skeleton, f) for f in ("left_ankle", "right_ankle")}
    figure = dict(walk=walk, steps=steps, path=floor_path.points, hips=hips, feet=feet)
    return steps, rows, figure, summary, variants


def _reach_targets(
    hand_ends: np.ndarray, range_ends: np.ndarray, st: SynthesisSettings, rng: np.random.Generator
) -> tuple[np.ndarray, int]:
    """Up to ``st.reach_targets`` targets: a training clip's hand end position (``hand_ends``)
    moved ``st.reach_offset_cm`` in a random direction, kept when a natural sample's hand ends
    within :data:`FIG4_10_REACH_CLOSE_CM` of it (``range_ends``: inside the variation range), in
    the order drawn, of :data:`DRAWS_PER_TARGET` draws per target. Returns (targets, draws)."""
    draws = DRAWS_PER_TARGET * st.reach_targets
    clip = rng.integers(len(hand_ends), size=draws)
    direction = rng.normal(size=(draws, 3))
    cand = hand_ends[clip] + st.reach_offset_cm * direction / np.linalg.norm(direction, axis=1, keepdims=True)
    nearest = cKDTree(range_ends).query(cand)[0]
    return cand[nearest <= FIG4_10_REACH_CLOSE_CM][: st.reach_targets], draws


def _reaches(
    reach: MotionPrimitive,
    tree: SpacePartitioningTree,
    dataset: MotionDataset,
    joint_map: JointMap,
    st: SynthesisSettings,
    rng: np.random.Generator,
    source: str,
) -> tuple[list[dict], list, np.ndarray, dict]:
    """Fig. 4.10 right: targets of :func:`_reach_targets`, each reached at the last frame of
    ``st.reach_primitive`` (:data:`REACH_JOINT`) by :func:`~..morphable_graph.synthesize_step`.
    The variation range and the natural log-likelihood come from ``st.reach_range_samples`` GMM
    samples (their :data:`FIG4_10_NATURAL_PERCENTILE` th percentile; the samples at or above it
    make the range). Returns (table rows, reaching motions, targets, reference numbers)."""
    hand = semantic_index(joint_map, reach.skeleton, REACH_JOINT, "du2022_graph.synthesis (reach joint)")
    clips, _ = primitive_clips(dataset, st.reach_primitive, source)
    hand_ends = np.stack([c.positions()[-1, hand] for c in clips])
    train_lp = reach.log_prob(reach.training_latents(clips, source))
    samples = reach.sample(st.reach_range_samples, rng)
    sample_lp = reach.log_prob(samples)
    natural = float(np.percentile(sample_lp, FIG4_10_NATURAL_PERCENTILE))
    range_ends = reach.key_frame_pose(samples[sample_lp >= natural], [reach.n_frames - 1], [hand])[0][:, 0, 0]
    targets, draws = _reach_targets(hand_ends, range_ends, st, rng)
    rows, reaches = [], []
    for k, target in enumerate(targets):
        cons = [Constraint("position", reach.n_frames - 1, (hand,), target[None])]
        fit, tree_err, evals = synthesize_step(reach, tree, cons, st)
        reaches.append(reach.to_motions(fit.latent[None])[0])
        rows.append(
            dict(
                task="reach",
                item=k,
                primitive=st.reach_primitive,
                position_error_tree_cm=tree_err,
                position_error_cm=fit.errors_after[0],
                tree_evaluations=evals,
                log_prob=fit.log_prob_after,
                target_training_distance_cm=float(np.linalg.norm(hand_ends - target, axis=1).min()),
            )
        )
    reference = dict(
        offset_cm=float(st.reach_offset_cm),
        range_samples=int(st.reach_range_samples),
        draws=int(draws),
        natural_log_prob=natural,
        train_log_prob_p5=float(np.percentile(train_lp, FIG4_10_NATURAL_PERCENTILE)),
    )
    return rows, reaches, targets, reference


def evaluate_fig4_10(
    models: Mapping[str, MotionPrimitive],
    dataset: MotionDataset,
    joint_map: JointMap,
    settings: GraphSettings,
    source: str = "dataset",
) -> EvaluationResult:
    """Fig. 4.10 with ``settings.synthesis`` (``st``) and ``settings.seed``, with the fitted
    ``models`` (the walking primitives ``walk_*`` and ``st.reach_primitive``; one k-means
    tree of ``st.tree_samples`` GMM samples each):

    - left: a graph walk (edges from ``dataset``'s metadata) following the floor path
      ``st.path`` (points (x, z), cm), at most ``st.max_steps`` steps (:func:`_path_walks`);
    - right: up to ``st.reach_targets`` targets inside the variation range reached with
      ``st.reach_primitive`` (its clips in ``dataset``, the ones its model was fitted to;
      ``source`` names their file in errors; :func:`_reaches`).

    Each step: tree search (``st.beam``) then ``st.method`` on Eq. 4.9; path following with
    the look-ahead T, the receding horizon or not and Algorithm 1 line 9 (``st.look_ahead``,
    ``st.receding_horizon``, ``st.joint_steps``). With ``st.compare_variants`` the walk is also
    made as :data:`VARIANTS` say (greedy: T = 1 without line 9; receding: the configured T
    with the receding horizon and line 9), where they differ from the configured one (table
    tasks ``path_<variant>``).
    Table: one row per path step and per target with the constraint errors after the tree
    search, after the step's own optimisation (path steps) and at the end, the distance of
    the step's end hips from the path and the largest distance of its hips from the path
    over its frames, the log-likelihood of the solved parameters and (targets) the target's
    distance from the nearest training hand position. The figure data hold the walk, its
    steps, the path, the variants' walks and the reaching motions with their targets, table
    rows and the natural log-likelihood."""
    st, seed = settings.synthesis, settings.seed
    rng = np.random.default_rng([seed, 410])
    trees = {n: SpacePartitioningTree(m.sample(st.tree_samples, rng), "kmeans", seed=seed) for n, m in models.items()}
    walk_names = [n for n in models if n.startswith("walk_")]
    graph = MorphableGraph.from_metadata(dataset.metadata, {n: models[n] for n in walk_names})
    steps, rows, walk_figure, summary, variants = _path_walks(graph, trees, joint_map, st)
    reach_rows, reaches, targets, reference = _reaches(
        models[st.reach_primitive], trees[st.reach_primitive], dataset, joint_map, st, rng, source
    )
    table = pd.DataFrame(rows + reach_rows)
    figure = dict(
        walk_figure,
        reaches=reaches,
        targets=list(targets),
        reach_primitive=st.reach_primitive,
        reach_rows=reach_rows,
        natural_log_prob=reference["natural_log_prob"],
    )
    mode = _mode(st)
    measurements = fig4_10_measurements(
        table, len(steps), summary["end_gap_cm"], summary["max_deviation_cm"], reference, mode, variants
    )
    claims = judge_claims(CLAIMS, "du2022_fig4_10", measurements)
    return EvaluationResult(table, claims, dict(figure, mode=mode, variants=variants), measurements)
