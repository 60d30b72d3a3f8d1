"""Du 2022 Fig. 4.10: constrained motion generation with the Morphable Graph: a walk
following a floor path (graph walk, Algorithm 1) and reaching targets with the picking
primitive; each step seeded by the k-means tree and optimised by Levenberg-Marquardt on
Eq. 4.9, with a look-ahead of T steps and Algorithm 1 line 9 (the walk's last N steps, or
all, optimised together) as configured. The table lists the constraint errors that
remain, per step after its own optimisation (the greedy walk) and at the end, and how far
the walk's hips are from the path.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from ....claims import EvaluationResult, judge_claims
from ....core.joint_map import JointMap
from ....io.dataset import MotionDataset
from ...claims import CLAIMS
from ..constraints import Constraint
from ..morphable_graph import MorphableGraph, Path2D, concatenate_steps, follow_path, synthesize_step
from ..primitive import MotionPrimitive, primitive_clips
from ..settings import GraphSettings, SynthesisSettings
from ..trees import SpacePartitioningTree
from .common import semantic_index

REACH_JOINT = "right_hand"
VARIANT_LABELS = {
    "greedy": "greedy (T = 1, no line 9)",
    "line9": "line 9 alone (T = 1, all steps optimised together)",
}


def _mode(look_ahead: int, joint_steps: int | str) -> str:
    line9 = (
        "all steps optimised together (Algorithm 1, line 9)"
        if joint_steps == "all"
        else f"the last {joint_steps} steps optimised together (Algorithm 1, line 9)"
        if joint_steps
        else "no joint optimisation (Algorithm 1, line 9 left out)"
    )
    ahead = f"look-ahead T = {look_ahead} (receding horizon)" if look_ahead > 1 else "look-ahead T = 1 (greedy)"
    return f"{ahead}, {line9}"


def fig4_10_measurements(
    table: pd.DataFrame,
    n_steps: int,
    end_gap_cm: float,
    reach_offset_cm: float,
    mode: str = "",
    max_deviation_cm: float = float("nan"),
    variants: Mapping[str, Mapping] | None = None,
) -> dict[str, Any]:
    """What the Fig. 4.10 claims are judged on, from the table of :func:`evaluate_fig4_10`: the
    walk's step count and mean hips position errors per step (final, after the tree search,
    after each step's own optimisation), mean heading error, end gap and largest distance from
    the path; ``mode`` (look-ahead and line 9); the summaries of the compared walks
    (``variants``, :data:`VARIANTS`); the reaching errors after LM and after the tree search,
    with the reach joint and the targets' offset."""
    path_rows = table[table["task"] == "path"]
    reach_rows = table[table["task"] == "reach"]
    own = path_rows["position_error_step_cm"].mean() if "position_error_step_cm" in path_rows.columns else None
    return {
        "path": {
            "n_steps": int(n_steps),
            "mean_step_cm": float(path_rows["position_error_cm"].mean()),
            "mean_tree_cm": float(path_rows["position_error_tree_cm"].mean()),
            "mean_step_own_cm": None if own is None else float(own),
            "heading_deg": float(path_rows["heading_error_deg"].mean()),
            "end_gap_cm": float(end_gap_cm),
            "max_deviation_cm": float(max_deviation_cm),
        },
        "mode": mode,
        "variants": {
            k: {
                "label": VARIANT_LABELS.get(k, k),
                **{f: v[f] for f in ("n_steps", "mean_step_cm", "max_deviation_cm", "end_gap_cm")},
            }
            for k, v in (variants or {}).items()
        },
        "reach": {
            "joint": REACH_JOINT,
            "offset_cm": reach_offset_cm,
            "errors_cm": [float(e) for e in reach_rows["position_error_cm"]],
            "tree_errors_cm": [float(e) for e in reach_rows["position_error_tree_cm"]],
        },
    }


VARIANTS = {"greedy": (1, 0), "line9": (1, "all")}  # compared walks: (look_ahead, joint_steps)


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
    the walks of :data:`VARIANTS` that differ from it. Returns (steps, table rows of every
    walk, the walk's figure data, its summary, the variants' summaries with their walks)."""
    floor_path = Path2D(np.asarray(st.path, dtype=float))
    steps = follow_path(graph, trees, floor_path, joint_map, st)
    hips = joint_map.index(steps[0].motion.skeleton, "hips")
    rows = _walk_rows(steps, floor_path, hips, "path")
    walk = concatenate_steps(steps)
    summary = _walk_summary(rows, walk, floor_path, hips)
    variants: dict[str, dict] = {}
    for name, (t, j) in VARIANTS.items():
        if not st.compare_variants or (t, j) == (int(st.look_ahead), st.joint_steps):
            continue
        v_steps = follow_path(graph, trees, floor_path, joint_map, st.replace(look_ahead=t, joint_steps=j))
        v_rows = _walk_rows(v_steps, floor_path, hips, f"path_{name}")
        v_walk = concatenate_steps(v_steps)
        rows += v_rows
        variants[name] = dict(_walk_summary(v_rows, v_walk, floor_path, hips), walk=v_walk)
    feet = {f: joint_map.index(walk.skeleton, f) for f in ("left_ankle", "right_ankle")}
    figure = dict(walk=walk, steps=steps, path=floor_path.points, hips=hips, feet=feet)
    return steps, rows, figure, summary, variants


def _reaches(
    reach: MotionPrimitive,
    tree: SpacePartitioningTree,
    dataset: MotionDataset,
    joint_map: JointMap,
    st: SynthesisSettings,
    rng: np.random.Generator,
    source: str,
) -> tuple[list[dict], list, list]:
    """Fig. 4.10 right: ``st.reach_targets`` targets, each a training clip's last
    :data:`REACH_JOINT` position moved ``st.reach_offset_cm`` in a random direction, reached
    at the last frame by :func:`~..morphable_graph.synthesize_step`. Returns (table rows,
    reaching motions, targets)."""
    hand = semantic_index(joint_map, reach.skeleton, REACH_JOINT, "graph.synthesis (reach joint)")
    clips, _ = primitive_clips(dataset, st.reach_primitive, source)
    picks = rng.choice(len(clips), size=min(st.reach_targets, len(clips)), replace=False)
    rows, reaches, targets = [], [], []
    for k, c in enumerate(picks):
        direction = rng.normal(size=3)
        target = clips[c].positions()[-1, hand] + st.reach_offset_cm * direction / np.linalg.norm(direction)
        cons = [Constraint("position", reach.n_frames - 1, (hand,), target[None])]
        fit, tree_err, evals = synthesize_step(reach, tree, cons, st)
        reaches.append(reach.to_motions(fit.latent[None])[0])
        targets.append(target)
        rows.append(
            dict(
                task="reach",
                item=k,
                primitive=st.reach_primitive,
                position_error_tree_cm=tree_err,
                position_error_cm=fit.errors_after[0],
                tree_evaluations=evals,
                log_prob=fit.log_prob_after,
            )
        )
    return rows, reaches, targets


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
    - right: ``st.reach_targets`` targets reached with ``st.reach_primitive`` (clips of it in
      ``dataset``; ``source`` names its file in errors; :func:`_reaches`).

    Each step: tree search (``st.beam``) then ``st.method`` on Eq. 4.9; path following with
    the look-ahead T and Algorithm 1 line 9 (``st.look_ahead``, ``st.joint_steps``).
    With ``st.compare_variants`` the walk is also made as :data:`VARIANTS` say (greedy:
    T = 1 without line 9; line9: T = 1 with all steps optimised together), where they
    differ from the configured one (table tasks ``path_<variant>``).
    Table: one row per path step and per target with the constraint errors after the tree
    search, after the step's own optimisation (path steps) and at the end, the distance of
    the step's end hips from the path and the largest distance of its hips from the path
    over its frames. The figure data hold the walk, its steps, the path, the variants'
    walks and the reaching motions with their targets."""
    st, seed = settings.synthesis, settings.seed
    rng = np.random.default_rng([seed, 410])
    trees = {n: SpacePartitioningTree(m.sample(st.tree_samples, rng), "kmeans", seed=seed) for n, m in models.items()}
    walk_names = [n for n in models if n.startswith("walk_")]
    graph = MorphableGraph.from_metadata(dataset.metadata, {n: models[n] for n in walk_names})
    steps, rows, walk_figure, summary, variants = _path_walks(graph, trees, joint_map, st)
    reach_rows, reaches, targets = _reaches(
        models[st.reach_primitive], trees[st.reach_primitive], dataset, joint_map, st, rng, source
    )
    table = pd.DataFrame(rows + reach_rows)
    figure = dict(walk_figure, reaches=reaches, targets=targets, reach_primitive=st.reach_primitive)
    mode = _mode(int(st.look_ahead), st.joint_steps)
    measurements = fig4_10_measurements(
        table, len(steps), summary["end_gap_cm"], st.reach_offset_cm, mode, summary["max_deviation_cm"], variants
    )
    claims = judge_claims(CLAIMS, "du2022_fig4_10", measurements)
    return EvaluationResult(table, claims, dict(figure, mode=mode, variants=variants), measurements)
