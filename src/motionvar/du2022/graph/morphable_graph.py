"""The Morphable Graph (Du 2022 Sec. 4.4, 4.5; Herrmann et al. 2017): nodes are motion
primitives, edges the transitions seen in the data, and graph-walk generation
(Algorithm 1) for path following and reaching.

Edges come from the preprocessing metadata: consecutive primitives of the same source
clip (ordered by ``start_frame``) are a transition (Fig. 4.6); a primitive that opens
(closes) a clip is a start (end) node.

Synthesis of one step (Sec. 4.5.2-4.5.3, Algorithm 1 lines 3-7): the step's constraints
select the best of the primitive's tree samples (beam search on Eq. 4.2), which seeds
Levenberg-Marquardt on the MAP objective (Eq. 4.9). Path following (Sec. 4.5.1): each
step's constraint is the floor position of the hips at the step's last frame, a median
step length further along the path, and the heading along the path there. The next
primitive: the thesis "enumerate[s] all optional transitions from the current motion
primitive looking at a fixed number of steps T ahead" with the mean motions and Eq. 4.2,
and selects "the best next motion primitive with minimal error";
:class:`~.settings.SynthesisSettings` ``look_ahead`` is T (1: the best single transition), and
the chosen step's latent vector is then optimised on its own constraints (Algorithm 1,
lines 5-6). Our addition, ``receding_horizon``: with T > 1 the step's latent vector is
optimised together with the T - 1 planned steps after it (tree seeds,
:func:`~.synthesis.optimize_chain`) and only the step itself is kept (the walk starts
turning before a corner it cannot take in one step).
The walk ends with ``walk_end`` when the end of the path is within a step.

Algorithm 1, line 9 ("optimize all steps of current elementary action"): ``joint_steps``
optimises the last N steps of the walk together (``"all"``: every step, the thesis; 4:
DFKI's ``global_spatial_optimization_settings.max_steps``; 0: left out, the greedy walk),
each step's path constraint evaluated on the chained placement (:class:`~.synthesis.StepChain`).
Steps are concatenated by placing each primitive (aligned to start at the origin heading
+x) at the previous step's end (hips floor position and facing at its last canonical
frame, the frame its constraints are evaluated at); the transitions are not blended.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...core.progress import ProgressLog
from ...core.quaternions import qmul, qrot, quat_about_axis
from .constraints import Constraint, Objective
from .primitive import MotionPrimitive
from .settings import SynthesisSettings
from .synthesis import MapResult, StepChain, StepGoal, optimize_chain, optimize_map, step_end_local
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
    def from_metadata(
        cls, metadata: pd.DataFrame, primitives: Mapping[str, MotionPrimitive] | None = None
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
    """One synthesised primitive of a graph walk, in world coordinates: its motion, its
    constraints in its aligned frame, the optimisation (``fit``: errors of the tree seed
    before and the final errors after; with line 9 or the receding horizon, after them) and the
    tree search. Path steps also carry their world ``goal`` and ``step_errors``, the errors
    after the step's own optimisation alone (the greedy walk, before line 9)."""

    primitive: str
    motion: Motion
    constraints: list[Constraint]
    fit: MapResult
    tree_evals: int
    goal: StepGoal | None = None
    step_errors: np.ndarray | None = None


def synthesize_step(
    primitive: MotionPrimitive,
    tree: SpacePartitioningTree,
    constraints: Sequence[Constraint],
    settings: SynthesisSettings,
) -> tuple[MapResult, float, int]:
    """Tree search (Eq. 4.2, ``settings.beam``) then LM on Eq. 4.9 from the best candidate
    (Sec. 4.5.3; ``settings.likelihood_weight``, ``method``, ``max_nfev``)."""
    found = tree.search(Objective(primitive, constraints), settings.beam)
    fit = optimize_map(
        primitive, constraints, found.latent, settings.likelihood_weight, settings.method, settings.max_nfev
    )
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

    def distance(self, xz: np.ndarray) -> np.ndarray:
        """(N,) floor distance of points (N, 2) to the polyline."""
        q = np.atleast_2d(np.asarray(xz, dtype=float))
        a, ab = self.points[:-1], np.diff(self.points, axis=0)
        u = np.clip(np.einsum("nsk,sk->ns", q[:, None] - a, ab) / np.einsum("sk,sk->s", ab, ab), 0.0, 1.0)
        return np.linalg.norm(a + u[..., None] * ab - q[:, None], axis=-1).min(axis=1)

    def project(self, xz: np.ndarray) -> float:
        """Arc length of the path point nearest to ``xz``."""
        a, b = self.points[:-1], self.points[1:]
        ab = b - a
        u = np.clip(np.einsum("ij,ij->i", np.asarray(xz) - a, ab) / np.einsum("ij,ij->i", ab, ab), 0.0, 1.0)
        d = np.linalg.norm(a + u[:, None] * ab - xz, axis=1)
        i = int(np.argmin(d))
        return float(self.arc[i] + u[i] * np.linalg.norm(ab[i]))


def step_length(primitive: MotionPrimitive, hips: int) -> float:
    """Floor distance travelled by the hips in the mean motion of the GMM (cm)."""
    mean = (primitive.gmm_.weights_[:, None] * primitive.gmm_.means_).sum(axis=0)
    pos, _ = primitive.key_frame_pose(mean[None], [0, primitive.n_frames - 1], [hips])
    return float(np.linalg.norm((pos[0, 1, 0] - pos[0, 0, 0])[[0, 2]]))


class _Walker:
    """State and helpers of one :func:`follow_path` run."""

    def __init__(
        self,
        graph: MorphableGraph,
        trees: Mapping[str, SpacePartitioningTree],
        path: Path2D,
        joint_map: JointMap,
        st: SynthesisSettings,
    ) -> None:
        self.graph, self.trees, self.path, self.st = graph, trees, path, st
        self.usable = [n for n in (st.start, *st.cyclic, st.end) if n in graph.primitives and n in trees]
        if not any(n in self.usable for n in st.cyclic):
            raise ValueError(f"follow_path: none of the stepping primitives {st.cyclic} is modelled")
        sk = next(iter(graph.primitives.values())).skeleton
        self.joints = tuple(joint_map.index(sk, k) for k in ("hips", "left_hip", "right_hip"))
        self.lengths = {n: step_length(graph.primitives[n], self.joints[0]) for n in self.usable}
        self.cyclic_len = float(np.median([self.lengths[n] for n in st.cyclic if n in self.lengths]))
        self.means = {
            n: (graph.primitives[n].gmm_.weights_[:, None] * graph.primitives[n].gmm_.means_).sum(axis=0)
            for n in self.usable
        }

    def options(self, node: str | None, remaining: float) -> list[str]:
        st = self.st
        if node is None:
            return [st.start] if st.start in self.usable else [n for n in st.cyclic if n in self.usable]
        opts = [n for n in self.graph.successors(node) if n in self.usable]
        if st.end in opts and remaining < 0.75 * self.cyclic_len:
            return [st.end]
        return [n for n in opts if n != st.end] or opts

    def goals(self, names: Sequence[str], progress: float) -> list[StepGoal]:
        """World goals of consecutive planned steps from arc length ``progress``."""
        out, a = [], progress
        for n in names:
            a = self.path.length if n == self.st.end else a + self.lengths[n]
            out.append(StepGoal(self.path.point(a), self.path.tangent(min(a, self.path.length - 1e-6))))
        return out

    def sequences(self, node: str | None, progress: float, depth: int) -> list[list[str]]:
        """Every node sequence of up to ``depth`` steps from ``node`` (ending at the end node)."""
        if depth == 0:
            return [[]]
        out = []
        for n in self.options(node, self.path.length - progress):
            if n == self.st.end or depth == 1:
                out.append([n])
                continue
            rests = self.sequences(n, progress + self.lengths[n], depth - 1)
            out += [[n] + rest for rest in rests] if rests else [[n]]  # a dead end: the step alone
        return out

    def plan(self, node: str | None, progress: float, pos: np.ndarray, heading: np.ndarray) -> list[str]:
        """The best node sequence of up to T = ``look_ahead`` steps by the mean motions
        (Sec. 4.5.1, Eq. 4.2 summed over the steps)."""
        best = None
        for seq in self.sequences(node, progress, int(self.st.look_ahead)):
            chain = StepChain(
                [self.graph.primitives[n] for n in seq], self.goals(seq, progress), pos, heading, *self.joints
            )
            err = float(chain.errors(np.concatenate([self.means[n] for n in seq])[None]).sum())
            if best is None or err < best[0]:
                best = (err, seq)
        return best[1]

    def tree_seed(self, name: str, goal: StepGoal, pos: np.ndarray, heading: np.ndarray):
        prim = self.graph.primitives[name]
        cons = _goal_constraints(prim, goal, pos, heading, *self.joints)
        return cons, self.trees[name].search(Objective(prim, cons), self.st.beam)


def follow_path(
    graph: MorphableGraph,
    trees: Mapping[str, SpacePartitioningTree],
    path: Path2D,
    joint_map: JointMap,
    settings: SynthesisSettings,
) -> list[StepResult]:
    """Graph-walk generation for a floor path (Algorithm 1, one "walk" action; module
    docstring) with the step, look-ahead (receding horizon or not) and line-9 ``settings``.
    Returns the steps in world coordinates."""
    st = settings
    w = _Walker(graph, trees, path, joint_map, st)
    pos = path.points[0].copy()
    heading = path.tangent(0.0)
    progress, current = 0.0, None
    starts: list[tuple[np.ndarray, np.ndarray]] = []  # placement of each step's start
    steps: list[StepResult] = []
    step_log = ProgressLog(f"graph walk ({path.length:.0f} cm path) step", st.max_steps, at_most=True)
    while len(steps) < st.max_steps:
        if not w.options(current, path.length - progress):
            break
        plan = w.plan(current, progress, pos, heading)
        name, prim = plan[0], graph.primitives[plan[0]]
        goals = w.goals(plan, progress)
        cons, found = w.tree_seed(name, goals[0], pos, heading)
        fit = optimize_map(prim, cons, found.latent, st.likelihood_weight, st.method, st.max_nfev)
        step_errors = fit.errors_after.copy()
        if len(plan) > 1 and st.receding_horizon:  # our addition: optimise with the planned steps, keep the first
            seeds, p_k, h_k = [fit.latent], pos, heading
            for k in range(1, len(plan)):
                p_k, h_k = _step_end(graph.primitives[plan[k - 1]], seeds[-1], p_k, h_k, w.joints)
                seeds.append(w.tree_seed(plan[k], goals[k], p_k, h_k)[1].latent)
            chain = StepChain([graph.primitives[n] for n in plan], goals, pos, heading, *w.joints)
            joint = optimize_chain(chain, seeds, st.likelihood_weight, st.joint_method, st.joint_max_nfev)
            fit = _with_latent(prim, cons, fit, joint.latents[0])
        steps.append(
            StepResult(name, prim.to_motions(fit.latent[None])[0], cons, fit, found.n_evals, goals[0], step_errors)
        )
        starts.append((pos, heading))
        step_log(len(steps))
        pos, heading = _step_end(prim, fit.latent, pos, heading, w.joints)
        progress = max(progress, path.project(pos))
        current = name
        if name == st.end:
            break
    n_joint = len(steps) if st.joint_steps == "all" else min(int(st.joint_steps), len(steps))
    if n_joint > 0:  # Algorithm 1, line 9
        first = len(steps) - n_joint
        window = steps[first:]
        p0, h0 = starts[first]
        chain = StepChain([graph.primitives[s.primitive] for s in window], [s.goal for s in window], p0, h0, *w.joints)
        joint = optimize_chain(
            chain, [s.fit.latent for s in window], st.likelihood_weight, st.joint_method, st.joint_max_nfev
        )
        pos, heading = p0, h0
        for k, (s, z) in enumerate(zip(window, joint.latents)):
            prim = graph.primitives[s.primitive]
            cons = _goal_constraints(prim, s.goal, pos, heading, *w.joints)
            fit = _with_latent(prim, cons, s.fit, z)
            steps[first + k] = replace(s, motion=prim.to_motions(z[None])[0], constraints=cons, fit=fit)
            starts[first + k] = (pos, heading)
            pos, heading = _step_end(prim, z, pos, heading, w.joints)
    return [replace(s, motion=place_motion(s.motion, p, h)) for s, (p, h) in zip(steps, starts)]


def _with_latent(prim: MotionPrimitive, cons: Sequence[Constraint], fit: MapResult, latent: np.ndarray) -> MapResult:
    """``fit`` with a new final latent vector (errors_before kept: the tree seed's)."""
    after = Objective(prim, cons).errors(latent[None])[0]
    return replace(
        fit,
        latent=np.asarray(latent, dtype=float).copy(),
        errors_after=after,
        log_prob_after=float(prim.log_prob(latent[None])[0]),
    )


def _step_end(
    prim: MotionPrimitive, latent: np.ndarray, pos: np.ndarray, heading: np.ndarray, joints: tuple[int, int, int]
) -> tuple[np.ndarray, np.ndarray]:
    """World floor position and heading (x, 0, z) where a step placed at ``pos`` with
    ``heading`` ends (its last canonical frame): the next step's placement."""
    loc, face = step_end_local(prim, np.asarray(latent)[None], *joints)
    h = np.array([heading[0], heading[2]]) / np.hypot(heading[0], heading[2])
    side = np.array([-h[1], h[0]])
    end = pos + loc[0, 0] * h + loc[0, 1] * side
    f = face[0, 0] * h + face[0, 1] * side
    return end, np.array([f[0], 0.0, f[1]])


def _goal_constraints(
    prim: MotionPrimitive, goal: StepGoal, pos: np.ndarray, heading: np.ndarray, hips: int, lh: int, rh: int
) -> list[Constraint]:
    """A world step goal as the hips floor position and heading constraints at the step's
    last canonical frame, in the step's aligned frame (Sec. 4.5.1)."""
    last = prim.n_frames - 1
    target = _to_local(goal.target_xz, pos, heading)
    tangent = _rotate_dir_to_local(goal.direction, heading)
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
