"""A walk along a floor path from the fitted Morphable Graph (Du 2022 Sec. 4.5.1,
Algorithm 1; Fig. 4.10 left), for the ``motionvar du2022 walk`` command: one k-means tree
of GMM samples per walking primitive (Sec. 4.4.2), then graph-walk generation
(:func:`~.morphable_graph.follow_path`: each step seeded by the tree and optimised by
Levenberg-Marquardt on Eq. 4.9, looking ahead, line 9's joint optimisation), the steps
concatenated into one clip (:func:`~.morphable_graph.concatenate_steps`) — the path of
the Fig. 4.10 evaluation with the user's path.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, fields

import numpy as np

from ...core.joint_map import JointMap
from ...core.motion import Motion
from .morphable_graph import (
    MorphableGraph,
    Path2D,
    StepResult,
    concatenate_steps,
    follow_path,
    step_length,
)
from .primitive import MotionPrimitive
from .settings import SynthesisSettings
from .trees import SpacePartitioningTree

WALK_SETTING_KEYS = tuple(f.name for f in fields(SynthesisSettings))


def check_path(points: Sequence[Sequence[float]]) -> Path2D:
    """The floor path (x, z) in cm as a :class:`Path2D`; ValueError saying what is wrong
    (fewer than 2 points, repeated consecutive points, non-finite values)."""
    p = np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError(f"path: expected points (x, z); got an array of shape {p.shape}")
    if len(p) < 2:
        raise ValueError(f"path: needs at least 2 points (x,z cm); got {len(p)}")
    if not np.all(np.isfinite(p)):
        raise ValueError("path: points must be finite numbers")
    if np.any(np.linalg.norm(np.diff(p, axis=0), axis=1) <= 0):
        raise ValueError("path: consecutive points must differ")
    return Path2D(p)


def walk_settings(settings: Mapping[str, object], max_steps: int | None = None) -> SynthesisSettings:
    """The graph walk's :class:`~.settings.SynthesisSettings` from the settings saved with the
    graph (config ``du2022_graph.synthesis`` and ``du2022_graph.seed``; other keys ignored), with
    ``max_steps`` when given."""
    st = SynthesisSettings.from_dict({k: v for k, v in settings.items() if k in WALK_SETTING_KEYS})
    return st if max_steps is None else st.replace(max_steps=int(max_steps))


def steps_for_path(
    primitives: Mapping[str, MotionPrimitive], path: Path2D, joint_map: JointMap, settings: SynthesisSettings
) -> int:
    """How many steps ``path`` takes. With the end primitive modelled the walk ends itself
    when the path's end is within a step (:func:`~.morphable_graph.follow_path`): a bound
    of twice the path over the shortest step, plus the start and end steps. Without it the
    walk would step on the spot at the path's end until ``max_steps``: the path's length
    over the median step (:func:`~.morphable_graph.step_length` of the mean motions), plus
    the start step when modelled."""
    sk = next(iter(primitives.values())).skeleton
    hips = joint_map.index(sk, "hips")
    lengths = [step_length(primitives[n], hips) for n in settings.cyclic if n in primitives]
    if not lengths:
        raise ValueError(
            f"walk: none of the stepping primitives {list(settings.cyclic)} is modelled "
            f"(have {', '.join(sorted(primitives))})"
        )
    if settings.end in primitives:
        return int(np.ceil(2.0 * path.length / max(min(lengths), 1.0))) + 2
    start = step_length(primitives[settings.start], hips) if settings.start in primitives else 0.0
    return max(
        1,
        int(round(max(path.length - start, 0.0) / max(float(np.median(lengths)), 1.0)))
        + (settings.start in primitives),
    )


@dataclass
class GeneratedPathWalk:
    """The walk (steps concatenated, world coordinates), its steps and the floor path."""

    motion: Motion
    steps: list[StepResult]
    path: Path2D

    def end_gap_cm(self, hips: int) -> float:
        """Floor distance of the walk's last hips position from the path's end."""
        return float(np.linalg.norm(self.motion.positions()[-1, hips, [0, 2]] - self.path.points[-1]))


def walk_along_path(
    primitives: Mapping[str, MotionPrimitive],
    graph: MorphableGraph,
    path: Path2D,
    joint_map: JointMap,
    settings: SynthesisSettings,
    seed: int,
    progress: Callable[[int, int], None] | None = None,
) -> GeneratedPathWalk:
    """A walk following ``path`` (module docstring) with the walking primitives among
    ``primitives`` (``settings``' start, stepping and end primitives) on the transitions of
    ``graph``. The trees hold ``settings.tree_samples`` GMM samples each, drawn from
    ``numpy.random.default_rng([seed, 410])`` (as Fig. 4.10). ``progress(done, total)`` is
    called after each tree and after the walk."""
    names = [n for n in (settings.start, *settings.cyclic, settings.end) if n in primitives]
    if not any(n in names for n in settings.cyclic):
        raise ValueError(
            f"walk: none of the stepping primitives {list(settings.cyclic)} is modelled "
            f"(have {', '.join(sorted(primitives))})"
        )
    rng = np.random.default_rng([seed, 410])
    total = len(names) + 1
    trees = {}
    for k, n in enumerate(names):  # one tree per primitive
        trees[n] = SpacePartitioningTree(primitives[n].sample(settings.tree_samples, rng), "kmeans", seed=seed)
        if progress is not None:
            progress(k + 1, total)
    walk_graph = MorphableGraph(graph.edges, graph.start_nodes, graph.end_nodes, {n: primitives[n] for n in names})
    steps = follow_path(walk_graph, trees, path, joint_map, settings)
    if progress is not None:
        progress(total, total)
    return GeneratedPathWalk(concatenate_steps(steps), steps, path)
