"""The Morphable Graph (Du 2022 Sec. 4.4, 4.5; Herrmann et al. 2017): nodes are motion
primitives, edges the transitions seen in the data, and graph-walk generation
(Algorithm 1) for path following and reaching.

Edges come from the preprocessing metadata: consecutive primitives of the same source
clip (ordered by ``start_frame``) are a transition (Fig. 4.6); a primitive that opens
(closes) a clip is a start (end) node.

Synthesis of one step (Sec. 4.5.2-4.5.3): the step's constraints select the best of the
primitive's tree samples (beam search on Eq. 4.2), which seeds Levenberg-Marquardt on
the MAP objective (Eq. 4.9). Path following (Sec. 4.5.1): each step's constraint is the
floor position of the hips at the step's last frame, a median step length further along
the path, and the heading along the path there; among the transitions of the current
node the one whose mean motion fits the step constraint best is taken (look-ahead
T = 1), and the walk ends with ``walk_end`` when the end of the path is within a step.
Steps are concatenated by placing each primitive (aligned to start at the origin heading
+x) at the previous step's end position and heading; the transitions are not blended
and the final joint optimisation of all steps (Algorithm 1, line 9) is not done.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...core.quaternions import qmul, qrot, quat_about_axis
from .constraints import Constraint, Objective
from .primitive import MotionPrimitive
from .synthesis import MapResult, optimize_map
from .trees import SpacePartitioningTree

_UP = np.array([0.0, 1.0, 0.0])


@dataclass
class MorphableGraph:
    """Directed graph of primitives: ``edges[a]`` maps successor -> count of transitions
    seen; ``start_nodes`` / ``end_nodes`` count clips opened / closed by a primitive;
    ``primitives`` holds the fitted models (a node may have none)."""

    edges: dict[str, dict[str, int]]
    start_nodes: dict[str, int]
    end_nodes: dict[str, int]
    primitives: dict[str, MotionPrimitive] = field(default_factory=dict)

    @classmethod
    def from_metadata(cls, metadata: pd.DataFrame, primitives: Mapping[str, MotionPrimitive] | None = None
                      ) -> "MorphableGraph":
        """Transitions between consecutive primitives of each source clip (prep metadata:
        source_clip, primitive, start_frame)."""
        missing = [c for c in ("source_clip", "primitive", "start_frame") if c not in metadata.columns]
        if missing:
            raise ValueError(f"MorphableGraph: metadata lacks columns {missing}")
        edges: dict[str, dict[str, int]] = {}
        starts: dict[str, int] = {}
        ends: dict[str, int] = {}
        ordered = metadata.sort_values(["source_clip", "start_frame"], kind="stable")
        for _, rows in ordered.groupby("source_clip", sort=True):
            names = [str(p) for p in rows["primitive"]]
            starts[names[0]] = starts.get(names[0], 0) + 1
            ends[names[-1]] = ends.get(names[-1], 0) + 1
            for a, b in zip(names[:-1], names[1:]):
                edges.setdefault(a, {})
                edges[a][b] = edges[a].get(b, 0) + 1
        for n in set(starts) | set(ends):
            edges.setdefault(n, {})
        return cls(edges, starts, ends, dict(primitives or {}))

    @property
    def nodes(self) -> list[str]:
        return sorted(self.edges)

    def successors(self, node: str) -> list[str]:
        if node not in self.edges:
            raise KeyError(f"MorphableGraph: no node {node!r} (nodes: {', '.join(self.nodes)})")
        return sorted(self.edges[node])

    def edge_table(self) -> pd.DataFrame:
        rows = [(a, b, n) for a, succ in sorted(self.edges.items()) for b, n in sorted(succ.items())]
        return pd.DataFrame(rows, columns=["from", "to", "count"])


@dataclass
class StepResult:
    """One synthesised primitive of a graph walk, in world coordinates."""

    primitive: str
    motion: Motion
    constraints: list[Constraint]
    fit: MapResult
    tree_error: float
    tree_evals: int


def synthesize_step(primitive: MotionPrimitive, tree: SpacePartitioningTree, constraints: Sequence[Constraint],
                    beam: int = 2, likelihood_weight: float = 1.0, method: str = "lm",
                    max_nfev: int = 200) -> tuple[MapResult, float, int]:
    """Tree search (Eq. 4.2) then LM on Eq. 4.9 from the best candidate (Sec. 4.5.3)."""
    found = tree.search(Objective(primitive, constraints), beam)
    fit = optimize_map(primitive, constraints, found.latent, likelihood_weight, method, max_nfev)
    return fit, found.error, found.n_evals


def place_motion(motion: Motion, position_xz: np.ndarray, heading: np.ndarray) -> Motion:
    """An aligned clip (starts at the origin heading +x) turned to ``heading`` (a floor
    direction) and moved to ``position_xz`` on the floor."""
    theta = float(np.arctan2(-heading[2], heading[0]))
    q = quat_about_axis(_UP, theta)
    root = qrot(q, motion.root_pos) + np.array([position_xz[0], 0.0, position_xz[1]])
    rot = motion.rotations.copy()
    rot[:, 0] = qmul(q, rot[:, 0])
    return replace(motion, root_pos=root, rotations=rot)


def _to_local(point_xz: np.ndarray, position_xz: np.ndarray, heading: np.ndarray) -> np.ndarray:
    """A world floor point in a step's aligned frame (origin at the start, heading +x)."""
    d = np.asarray(point_xz, dtype=float) - position_xz
    h = heading[[0, 2]] / np.linalg.norm(heading[[0, 2]])
    # a turn by theta about +y maps +x to (cos, -sin) and +z to (sin, cos) in (x, z)
    return np.array([d @ h, d @ np.array([-h[1], h[0]])])


def _rotate_dir_to_local(direction: np.ndarray, heading: np.ndarray) -> np.ndarray:
    loc = _to_local(direction[[0, 2]], np.zeros(2), heading)
    return np.array([loc[0], 0.0, loc[1]])


class Path2D:
    """A polyline on the floor (P, 2) of (x, z) points with arc-length lookup."""

    def __init__(self, points: np.ndarray) -> None:
        p = np.asarray(points, dtype=float)
        if p.ndim != 2 or p.shape[1] != 2 or len(p) < 2 or not np.all(np.isfinite(p)):
            raise ValueError(f"path: points must be a finite (P >= 2, 2) array of floor (x, z); got {p.shape}")
        seg = np.linalg.norm(np.diff(p, axis=0), axis=1)
        if np.any(seg <= 0):
            raise ValueError("path: consecutive points must differ")
        self.points, self.arc = p, np.concatenate([[0.0], np.cumsum(seg)])

    @property
    def length(self) -> float:
        return float(self.arc[-1])

    def point(self, a: float) -> np.ndarray:
        a = float(np.clip(a, 0.0, self.length))
        return np.array([np.interp(a, self.arc, self.points[:, k]) for k in range(2)])

    def tangent(self, a: float) -> np.ndarray:
        i = int(np.clip(np.searchsorted(self.arc, a, side="right") - 1, 0, len(self.points) - 2))
        t = self.points[i + 1] - self.points[i]
        t = t / np.linalg.norm(t)
        return np.array([t[0], 0.0, t[1]])

    def project(self, xz: np.ndarray) -> float:
        """Arc length of the path point nearest to ``xz``."""
        a, b = self.points[:-1], self.points[1:]
        ab = b - a
        u = np.clip(np.einsum("ij,ij->i", np.asarray(xz) - a, ab) / np.einsum("ij,ij->i", ab, ab), 0.0, 1.0)
        d = np.linalg.norm(a + u[:, None] * ab - xz, axis=1)
        i = int(np.argmin(d))
        return float(self.arc[i] + u[i] * np.linalg.norm(ab[i]))


def _facing(positions: np.ndarray, left_hip: int, right_hip: int) -> np.ndarray:
    f = np.cross(_UP, positions[right_hip] - positions[left_hip])
    f[1] = 0.0
    return f / np.linalg.norm(f)


def step_length(primitive: MotionPrimitive, hips: int) -> float:
    """Floor distance travelled by the hips in the mean motion of the GMM (cm)."""
    mean = (primitive.gmm_.weights_[:, None] * primitive.gmm_.means_).sum(axis=0)
    pos, _ = primitive.key_frame_pose(mean[None], [0, primitive.n_frames - 1], [hips])
    return float(np.linalg.norm((pos[0, 1, 0] - pos[0, 0, 0])[[0, 2]]))


@dataclass
class WalkSettings:
    """Path following: start/end primitives, step constraints, search and LM settings."""

    start: str = "walk_start"
    end: str = "walk_end"
    cyclic: tuple[str, ...] = ("walk_leftStance", "walk_rightStance")
    max_steps: int = 30
    beam: int = 2
    likelihood_weight: float = 1.0
    method: str = "lm"
    max_nfev: int = 100


def follow_path(graph: MorphableGraph, trees: Mapping[str, SpacePartitioningTree], path: Path2D,
                joint_map: JointMap, settings: WalkSettings | None = None) -> list[StepResult]:
    """Graph-walk generation for a floor path (Algorithm 1, one "walk" action; module
    docstring). Returns the steps in world coordinates."""
    st = settings or WalkSettings()
    usable = [n for n in (st.start, *st.cyclic, st.end) if n in graph.primitives and n in trees]
    if not any(n in usable for n in st.cyclic):
        raise ValueError(f"follow_path: none of the stepping primitives {st.cyclic} is modelled")
    sk = next(iter(graph.primitives.values())).skeleton
    hips, lh, rh = (joint_map.index(sk, k) for k in ("hips", "left_hip", "right_hip"))
    lengths = {n: step_length(graph.primitives[n], hips) for n in usable}
    pos = path.points[0].copy()
    heading = path.tangent(0.0)
    progress = 0.0
    current: str | None = None
    steps: list[StepResult] = []
    cyclic_len = float(np.median([lengths[n] for n in st.cyclic if n in lengths]))
    while len(steps) < st.max_steps:
        if current is None:
            options = [st.start] if st.start in usable else [n for n in st.cyclic if n in usable]
        else:
            options = [n for n in graph.successors(current) if n in usable]
            remaining = path.length - progress
            if st.end in options and remaining < 0.75 * cyclic_len:
                options = [st.end]
            else:
                options = [n for n in options if n != st.end] or options
        if not options:
            break
        best = None
        for name in options:  # look-ahead T = 1: the mean motion against the step constraint
            prim = graph.primitives[name]
            target_a = path.length if name == st.end else progress + lengths[name]
            cons = _step_constraints(prim, path, target_a, pos, heading, hips, lh, rh, name == st.end)
            mean = (prim.gmm_.weights_[:, None] * prim.gmm_.means_).sum(axis=0)
            err = float(Objective(prim, cons)(mean[None])[0])
            if best is None or err < best[0]:
                best = (err, name, cons)
        _, name, cons = best
        prim = graph.primitives[name]
        fit, tree_err, tree_evals = synthesize_step(prim, trees[name], cons, st.beam, st.likelihood_weight,
                                                    st.method, st.max_nfev)
        local = prim.to_motions(fit.latent[None])[0]
        world = place_motion(local, pos, heading)
        steps.append(StepResult(name, world, cons, fit, tree_err, tree_evals))
        end_pos = world.positions()[-1]
        pos = end_pos[hips][[0, 2]]
        heading = _facing(end_pos, lh, rh)
        progress = max(progress, path.project(pos))
        current = name
        if name == st.end:
            break
    return steps


def _step_constraints(prim: MotionPrimitive, path: Path2D, arc: float, pos: np.ndarray, heading: np.ndarray,
                      hips: int, lh: int, rh: int, final: bool) -> list[Constraint]:
    """Hips floor position and heading at the step's last canonical frame, in the
    step's aligned frame (Sec. 4.5.1)."""
    last = prim.n_frames - 1
    target = _to_local(path.point(arc), pos, heading)
    tangent = _rotate_dir_to_local(path.tangent(min(arc, path.length - 1e-6)), heading)
    return [
        Constraint("position", last, (hips,), np.array([[target[0], 0.0, target[1]]]), mask=np.array([1.0, 0, 1.0])),
        Constraint("heading", last, (lh, rh), tangent),
    ]


def concatenate_steps(steps: Sequence[StepResult]) -> Motion:
    """The steps as one clip (the first frame of each later step, a repeat of the
    previous step's last pose, dropped)."""
    if not steps:
        raise ValueError("concatenate_steps: no steps")
    ms = [s.motion for s in steps]
    root = np.concatenate([ms[0].root_pos] + [m.root_pos[1:] for m in ms[1:]])
    rot = np.concatenate([ms[0].rotations] + [m.rotations[1:] for m in ms[1:]])
    return Motion(skeleton=ms[0].skeleton, root_pos=root, rotations=rot, fps=ms[0].fps)
