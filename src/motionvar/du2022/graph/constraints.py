"""Spatial constraints on a motion primitive and the objective of Du 2022 Eq. 4.2.

O(s, c) = sum_i || f_k(M(s)) - c_i ||: the distance of the back-projected motion's joints
to the constraints c_i at key frames of the canonical timeline. Constraint kinds
(Sec. 4.6.2):

- ``position``: one or more joints at one key frame; error = the Euclidean distance
  (cm), divided by the number of joints ("in the case of the pose constraints, the
  distance is divided by the number of constrained joints"). Optional axis mask (e.g.
  only the floor coordinates of the hips when following a path).
- ``orientation``: the global orientation of one joint (a quaternion); error = "the angle
  between reference vectors rotated by the global orientation of the joint": the mean
  angle (degrees) of the three rotated unit axes.
- ``heading``: the body's horizontal facing (up x (left hip -> right hip), as in the
  alignment) against a target direction on the floor; error = angle in degrees. Used for
  the step constraints of path following (Sec. 4.5.1).

:class:`Objective` evaluates Eq. 4.2 for a batch of latent vectors and counts how many
latent vectors it has evaluated (the "number of evaluations" of Fig. 4.12).
:class:`ConstraintStack` evaluates many queries of the same structure at once (each row
of a batch under its own query): :func:`kind_error` is elementwise over rows, so the
numbers are those of one query at a time.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from ...core.quaternions import qrot
from .primitive import MotionPrimitive

KINDS = ("position", "orientation", "heading")
_AXES = np.eye(3)
_UP = np.array([0.0, 1.0, 0.0])


@dataclass(frozen=True)
class Constraint:
    """One key-frame constraint (module docstring).

    Attributes:
        kind: position | orientation | heading.
        frame: canonical frame index of the primitive.
        joints: joint indices (position: any number; orientation: one; heading: the
            left and right hip).
        target: position: (len(joints), 3) cm; orientation: (4,) global quaternion;
            heading: (3,) direction on the floor.
        mask: position only: (3,) weights of the x, y, z differences (1 = constrained).
    """

    kind: str
    frame: int
    joints: tuple[int, ...]
    target: np.ndarray
    mask: np.ndarray = field(default_factory=lambda: np.ones(3))

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"constraint kind must be one of {KINDS}; got {self.kind!r}")
        object.__setattr__(self, "joints", tuple(int(j) for j in self.joints))
        target = np.asarray(self.target, dtype=float)
        want = {"position": (len(self.joints), 3), "orientation": (4,), "heading": (3,)}[self.kind]
        if target.shape != want or not np.all(np.isfinite(target)):
            raise ValueError(f"{self.kind} constraint: target must be finite with shape {want}; got {target.shape}")
        if self.kind == "orientation" and len(self.joints) != 1:
            raise ValueError("orientation constraint: exactly one joint")
        if self.kind == "heading" and len(self.joints) != 2:
            raise ValueError("heading constraint: joints must be (left hip, right hip)")
        if self.kind == "orientation":
            target = target / np.linalg.norm(target)
        object.__setattr__(self, "target", target)
        object.__setattr__(self, "mask", np.asarray(self.mask, dtype=float))

    @property
    def active_mask(self) -> np.ndarray | None:
        """The position mask, or None where it constrains all three axes (x * 1 is x: the
        product is left out)."""
        return None if self.kind != "position" or np.all(self.mask == 1.0) else self.mask

    def error(self, pos: np.ndarray | None, rot: np.ndarray | None) -> np.ndarray:
        """(B,) error from the constrained joints' positions (B, len(joints), 3) and
        global rotations (B, len(joints), 4) at the key frame (orientation reads only
        ``rot``, the other kinds only ``pos``: the other may be None)."""
        return kind_error(self.kind, pos, rot, self.target, self.active_mask)


def reference_axes(rot: np.ndarray) -> np.ndarray:
    """(B, 3, 3) the unit axes rotated by the global rotations (B, J', 4) of the constrained
    joint (the first): the reference vectors of the orientation error."""
    return qrot(rot[:, 0, None, :], _AXES)


def kind_error(
    kind: str,
    pos: np.ndarray | None,
    rot: np.ndarray | None,
    target: np.ndarray,
    mask: np.ndarray | None = None,
    axes: np.ndarray | None = None,
) -> np.ndarray:
    """(B,) errors of one constraint ``kind`` (module docstring) from the constrained joints'
    positions (B, J', 3) and rotations (B, J', 4) at the key frame (an orientation error
    reads only the rotations, or their :func:`reference_axes` ``axes`` where given; the
    others only the positions). ``target`` (and the position ``mask``, None: all axes) is
    one constraint's (the shapes of :class:`Constraint`) or one per row (a leading B axis;
    the mask then (B, 1, 3)): every operation is elementwise over rows, so many queries at
    once give the numbers of one query at a time (:class:`ConstraintStack`)."""
    if kind == "position":
        diff = pos - target
        return np.linalg.norm(diff if mask is None else diff * mask, axis=-1).mean(axis=-1)
    if kind == "orientation":
        a = reference_axes(rot) if axes is None else axes  # (B, 3, 3)
        b = qrot(target[..., None, :], _AXES)  # (3, 3), or (B, 3, 3) per row
        cos = np.einsum("bij,bij->bi" if b.ndim == 3 else "bij,ij->bi", a, b)
        sin = np.linalg.norm(np.cross(a, b), axis=-1)  # atan2: accurate near 0 (arccos is not)
        return np.degrees(np.arctan2(sin, cos)).mean(axis=-1)
    facing = np.cross(_UP, pos[:, 1] - pos[:, 0])
    return _angle_2d(facing, target)


def _angle_2d(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Angles (degrees) between the floor projections (x, z) of u (B, 3) and v (3,) or (B, 3)."""
    a = np.arctan2(u[:, 2], u[:, 0]) - np.arctan2(v[..., 2], v[..., 0])
    return np.degrees(np.abs((a + np.pi) % (2 * np.pi) - np.pi))


def _slot_errors(
    slots: Sequence[Constraint],
    targets: Sequence[np.ndarray],
    masks: Sequence[np.ndarray | None],
    pos: np.ndarray,
    rot: np.ndarray,
    frames: Sequence[int],
    joints: Sequence[int],
) -> np.ndarray:
    """(B, n_c) errors of the constraints ``slots`` (kind, frame, joints) with ``targets`` and
    ``masks`` (one constraint's or per row) from key-frame poses: positions (B, F, J', 3)
    and rotations (B, F, J', 4) of ``joints`` at ``frames``. ValueError naming the
    constraint when its frame or joints are not among ``frames`` and ``joints``."""
    fi = {int(f): i for i, f in enumerate(frames)}
    ji = {int(j): i for i, j in enumerate(joints)}
    out = np.empty((len(pos), len(slots)))
    for k, (c, target, mask) in enumerate(zip(slots, targets, masks)):  # the (few) constraints; rows batched
        try:
            f, idx = fi[c.frame], [ji[j] for j in c.joints]
        except KeyError:
            raise ValueError(
                f"constraint on frame {c.frame}, joints {c.joints} not precomputed (frames "
                f"{list(frames)}, joints {list(joints)})"
            ) from None
        if c.kind == "orientation":
            out[:, k] = kind_error(c.kind, None, rot[:, f, idx], target, mask)
        else:
            out[:, k] = kind_error(c.kind, pos[:, f, idx], None, target, mask)
    return out


def constraint_errors(
    constraints: Sequence[Constraint], pos: np.ndarray, rot: np.ndarray, frames: Sequence[int], joints: Sequence[int]
) -> np.ndarray:
    """(B, n_c) errors of ``constraints`` (the terms of Eq. 4.2) from key-frame poses: global
    positions (B, F, J', 3) and rotations (B, F, J', 4) of ``joints`` at ``frames`` (as
    :meth:`MotionPrimitive.key_frame_pose` gives them). ValueError naming the constraint when
    its frame or joints are not among ``frames`` and ``joints``."""
    return _slot_errors(
        constraints, [c.target for c in constraints], [c.active_mask for c in constraints], pos, rot, frames, joints
    )


class ConstraintStack:
    """Many queries of Eq. 4.2 at once: Q constraint lists of the same structure (constraint
    k of every query has the same kind, frame and joints, e.g. the random queries of one
    kind in Fig. 4.12), their targets and masks stacked.

    ``errors(pos, rot, frames, joints, query)`` gives the (B, n_c) errors of row b's pose
    under query ``query[b]``: the numbers :func:`constraint_errors` gives for that query
    alone (:func:`kind_error`), for the candidates of all queries in one vectorised call.
    """

    def __init__(self, queries: Sequence[Sequence[Constraint]]) -> None:
        queries = [list(q) for q in queries]
        if not queries or not queries[0]:
            raise ValueError("constraint stack: no queries, or a query without constraints")
        self.slots = queries[0]
        shape = [(c.kind, c.frame, c.joints) for c in self.slots]
        for i, q in enumerate(queries):
            got = [(c.kind, c.frame, c.joints) for c in q]
            if got != shape:
                raise ValueError(
                    f"constraint stack: query {i} has constraints {got}, query 0 {shape}: stacked queries "
                    "need the same kinds, frames and joints"
                )
        self.n_queries = len(queries)
        self.targets = [np.stack([q[k].target for q in queries]) for k in range(len(shape))]
        masks = [[q[k].active_mask for q in queries] for k in range(len(shape))]
        # (Q, 1, 3): broadcasts over the joints of a row; None where no query of a slot masks
        self.masks = [
            None if all(m is None for m in ms) else np.stack([np.ones(3) if m is None else m for m in ms])[:, None]
            for ms in masks
        ]

    def errors(
        self, pos: np.ndarray, rot: np.ndarray, frames: Sequence[int], joints: Sequence[int], query: np.ndarray
    ) -> np.ndarray:
        """(B, n_c) errors of the poses ``pos`` (B, F, J', 3), ``rot`` (B, F, J', 4) (of
        ``joints`` at ``frames``) under the queries ``query`` (B,) (indices into the stack)."""
        query = np.asarray(query, dtype=np.int64)
        return _slot_errors(
            self.slots,
            [t[query] for t in self.targets],
            [None if m is None else m[query] for m in self.masks],
            pos,
            rot,
            frames,
            joints,
        )


class Objective:
    """Eq. 4.2 for one primitive and a set of constraints, over batches of latent vectors.

    ``errors(S)`` gives (B, n_constraints) per-constraint errors, ``__call__(S)`` their sum
    O(s, c) (B,); both add B to ``n_evals``.
    """

    def __init__(self, primitive: MotionPrimitive, constraints: Sequence[Constraint]) -> None:
        if not constraints:
            raise ValueError("objective: no constraints given")
        self.primitive = primitive
        self.constraints = list(constraints)
        self.n_evals = 0
        frames = sorted({c.frame for c in self.constraints})
        joints = sorted({j for c in self.constraints for j in c.joints})
        self._frames, self._joints = frames, joints
        primitive.frame_map(frames)  # validates the frames

    def errors(self, S: np.ndarray) -> np.ndarray:
        S = np.atleast_2d(S)
        self.n_evals += len(S)
        pos, rot = self.primitive.key_frame_pose(S, self._frames, self._joints)
        return constraint_errors(self.constraints, pos, rot, self._frames, self._joints)

    def __call__(self, S: np.ndarray) -> np.ndarray:
        return self.errors(S).sum(axis=1)


def random_constraints(
    primitive: MotionPrimitive,
    kind: str,
    n: int,
    joints: Sequence[int],
    frame: int,
    rng: np.random.Generator | int | None = None,
) -> list[Constraint]:
    """``n`` constraints of ``kind`` met by fresh GMM samples (Sec. 4.6.2). ``position`` and
    ``orientation`` constrain ``joints[0]``; ``pose`` constrains all ``joints``."""
    S = primitive.sample(n, rng)
    pos, rot = primitive.key_frame_pose(S, [frame], list(joints))
    if kind == "position":
        return [Constraint("position", frame, (joints[0],), p[0, :1]) for p in pos]
    if kind == "orientation":
        return [Constraint("orientation", frame, (joints[0],), r[0, 0]) for r in rot]
    if kind == "pose":
        return [Constraint("position", frame, tuple(joints), p[0]) for p in pos]
    raise ValueError(f"random_constraints: kind must be position, orientation or pose; got {kind!r}")
