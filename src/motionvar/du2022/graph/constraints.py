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

    def error(self, pos: np.ndarray, rot: np.ndarray) -> np.ndarray:
        """(B,) error from the constrained joints' positions (B, len(joints), 3) and
        global rotations (B, len(joints), 4) at the key frame."""
        if self.kind == "position":
            return np.linalg.norm((pos - self.target) * self.mask, axis=-1).mean(axis=-1)
        if self.kind == "orientation":
            a = qrot(rot[:, 0, None, :], _AXES)  # (B, 3, 3) rotated reference axes
            b = qrot(self.target[None, :], _AXES)  # (3, 3)
            cos = np.einsum("bij,ij->bi", a, b)
            sin = np.linalg.norm(np.cross(a, b), axis=-1)  # atan2: accurate near 0 (arccos is not)
            return np.degrees(np.arctan2(sin, cos)).mean(axis=-1)
        facing = np.cross(_UP, pos[:, 1] - pos[:, 0])
        return _angle_2d(facing, self.target)


def _angle_2d(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Angles (degrees) between the floor projections (x, z) of u (B, 3) and v (3,)."""
    a = np.arctan2(u[:, 2], u[:, 0]) - np.arctan2(v[2], v[0])
    return np.degrees(np.abs((a + np.pi) % (2 * np.pi) - np.pi))


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
        self._fi = {f: i for i, f in enumerate(frames)}
        self._ji = {j: i for i, j in enumerate(joints)}
        primitive.frame_map(frames)  # validates the frames

    def errors(self, S: np.ndarray) -> np.ndarray:
        S = np.atleast_2d(S)
        self.n_evals += len(S)
        pos, rot = self.primitive.key_frame_pose(S, self._frames, self._joints)
        out = np.empty((len(S), len(self.constraints)))
        for k, c in enumerate(self.constraints):
            f = self._fi[c.frame]
            idx = [self._ji[j] for j in c.joints]
            out[:, k] = c.error(pos[:, f, idx], rot[:, f, idx])
        return out

    def __call__(self, S: np.ndarray) -> np.ndarray:
        return self.errors(S).sum(axis=1)


def constraint_from_sample(primitive: MotionPrimitive, s: np.ndarray, kind: str, frame: int,
                           joints: Sequence[int]) -> Constraint:
    """The constraint that latent vector ``s`` meets exactly (Sec. 4.6.2: "random
    constraints ... by sampling from the motion models")."""
    pos, rot = primitive.key_frame_pose(np.asarray(s)[None], [frame], list(joints))
    if kind == "position":
        return Constraint("position", frame, tuple(joints), pos[0, 0])
    if kind == "orientation":
        return Constraint("orientation", frame, tuple(joints[:1]), rot[0, 0, 0])
    raise ValueError(f"constraint_from_sample: kind must be position or orientation; got {kind!r}")


def random_constraints(primitive: MotionPrimitive, kind: str, n: int, joints: Sequence[int], frame: int,
                       rng: np.random.Generator | int | None = None) -> list[Constraint]:
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
