"""Aligned example clips and their vector form for interpolation (Ma et al. 2010, Sec. 6.2:
"we treat motion clips as the basic units").

A :class:`ClipSet` holds N time-warped examples on one standard skeleton: rotations
(N, T, J, 4) on a common timeline, each clip's real key times, its root height and its
style parameters. A :class:`ClipCodec` turns the clips (or one joint group of them) into
feature vectors and back. Rotations are linearised in the tangent space of a reference:
v = log(q_ref(t, j)^-1 q), with q_ref the per-frame, per-joint mean rotation of the
examples, so that the linear operations of Kriging (Eq. 11) act on rotations without
leaving the unit sphere (the paper interpolates unit quaternions but does not say how).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.kinematics import fk
from ..core.quaternions import qexp, qinv, qlog, qmul, qnormalize
from ..core.skeleton import Skeleton
from .correspondence import decode_key_times, encode_key_times
from .settings import ModelSettings


def mean_rotation(q: np.ndarray, axis: int = 0) -> np.ndarray:
    """Normalized mean of unit quaternions along ``axis``, after putting them all in the
    hemisphere of the first one (a good approximation of the rotation mean when the
    rotations are close, as corresponding frames of example clips are)."""
    q = np.moveaxis(np.asarray(q, dtype=float), axis, 0)
    sign = np.where(np.sum(q * q[:1], axis=-1, keepdims=True) < 0, -1.0, 1.0)
    return qnormalize(np.sum(q * sign, axis=0))


def to_tangent(q: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """Tangent vectors (..., 3) of rotations about a broadcastable reference: log(ref^-1 q)."""
    return qlog(qmul(qinv(reference), q))


def from_tangent(v: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """Rotations (..., 4) from tangent vectors about a reference: ref * exp(v)."""
    return qmul(reference, qexp(v))


def rest_hip_height(skeleton: Skeleton, foot_joints: np.ndarray) -> float:
    """Height of the root above the lowest foot joint in the rest pose (cm)."""
    pos = fk(np.tile([1.0, 0, 0, 0], (skeleton.n_joints, 1)), np.zeros(3), skeleton.offsets, skeleton.parents)
    return float(pos[0, 1] - pos[np.asarray(foot_joints), 1].min())


@dataclass
class ClipSet:
    """N aligned example clips on a standard skeleton (Sec. 4.2).

    Attributes:
        rotations: (N, T, J, 4) local rotations on the common timeline.
        key_times: (N, K) real times (s) of each clip's key frames, from its first frame.
        root_height: (N, T) root height (cm) scaled to the standard skeleton's hip height.
        style: (N, d) user-defined style parameters c_i.
        reference_keys: (K,) key-frame positions on the common timeline (frames).
        skeleton: the standard skeleton.
        fps: frame rate of the real-time clips.
        clip_ids: one id per clip.
    """

    rotations: np.ndarray
    key_times: np.ndarray
    root_height: np.ndarray
    style: np.ndarray
    reference_keys: np.ndarray
    skeleton: Skeleton
    fps: float
    clip_ids: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        N, T, J = self.rotations.shape[:3]
        self.style = np.asarray(self.style, dtype=float)
        if self.style.ndim == 1:
            self.style = self.style[:, None]
        checks = {
            "key_times": (self.key_times.shape, (N, len(self.reference_keys))),
            "root_height": (self.root_height.shape, (N, T)),
            "style": (self.style.shape[:1], (N,)),
        }
        bad = [f"{k} {got} != {want}" for k, (got, want) in checks.items() if tuple(got) != tuple(want)]
        if J != self.skeleton.n_joints:
            bad.append(f"rotations have {J} joints, skeleton {self.skeleton.n_joints}")
        if bad:
            raise ValueError("ClipSet: " + "; ".join(bad))
        if not self.clip_ids:
            self.clip_ids = [str(i) for i in range(N)]

    @property
    def n_clips(self) -> int:
        return self.rotations.shape[0]

    @property
    def n_frames(self) -> int:
        return self.rotations.shape[1]

    def to_arrays(self) -> dict[str, np.ndarray]:
        """Plain arrays (for ``np.savez``); :meth:`from_arrays` restores the set."""
        sk = self.skeleton
        ends = np.array(sorted(sk.end_sites), dtype=np.int64)
        return {
            "rotations": self.rotations,
            "key_times": self.key_times,
            "root_height": self.root_height,
            "style": self.style,
            "reference_keys": self.reference_keys,
            "fps": np.array(self.fps),
            "clip_ids": np.array(self.clip_ids),
            "names": np.array(sk.names),
            "parents": sk.parents,
            "offsets": sk.offsets,
            "end_site_joints": ends,
            "end_site_offsets": np.array([sk.end_sites[j] for j in ends]).reshape(len(ends), 3),
        }

    @classmethod
    def from_arrays(cls, a: dict[str, np.ndarray]) -> "ClipSet":
        missing = [
            k
            for k in ("rotations", "key_times", "root_height", "style", "reference_keys", "fps", "names")
            if k not in a
        ]
        if missing:
            raise ValueError(f"ClipSet.from_arrays: missing arrays {missing}")
        sk = Skeleton(
            names=tuple(str(n) for n in a["names"]),
            parents=a["parents"],
            offsets=a["offsets"],
            end_sites={int(j): np.asarray(o) for j, o in zip(a["end_site_joints"], a["end_site_offsets"])},
        )
        return cls(
            rotations=np.asarray(a["rotations"], dtype=float),
            key_times=np.asarray(a["key_times"], dtype=float),
            root_height=np.asarray(a["root_height"], dtype=float),
            style=np.asarray(a["style"], dtype=float),
            reference_keys=np.asarray(a["reference_keys"], dtype=float),
            skeleton=sk,
            fps=float(a["fps"]),
            clip_ids=[str(c) for c in a["clip_ids"]],
        )

    def subset(self, index: np.ndarray) -> "ClipSet":
        """The clips at ``index`` (indices or a boolean mask)."""
        idx = np.arange(self.n_clips)[index]
        return ClipSet(
            rotations=self.rotations[idx],
            key_times=self.key_times[idx],
            root_height=self.root_height[idx],
            style=self.style[idx],
            reference_keys=self.reference_keys,
            skeleton=self.skeleton,
            fps=self.fps,
            clip_ids=[self.clip_ids[i] for i in idx],
        )


class ClipCodec:
    """Clip <-> feature vector for a subset of joints, optionally with the clip's key
    times (timing, for the inverse time warp; encoded by ``key_timing``,
    :func:`.correspondence.encode_key_times`) and root height curve (Sec. 6.3, behaviours
    with flight phases). Layout: [tangents (T*|I|*3), key times (K), root height (T)]. A scikit-learn-style estimator:
    ``ClipCodec(joints, ...).fit(clips)`` learns ``reference_``, the (T, J, 4) per-frame mean rotations of
    the examples."""

    def __init__(
        self,
        joints: np.ndarray,
        timing: bool = False,
        root_height: bool = False,
        key_timing: str = ModelSettings.key_timing,
    ) -> None:
        self.joints = np.asarray(joints, dtype=np.int64)
        self.timing, self.root_height, self.key_timing = timing, root_height, key_timing

    def fit(self, clips: ClipSet) -> ClipCodec:
        return self.set_fitted(mean_rotation(clips.rotations, axis=0))

    def set_fitted(self, reference: np.ndarray) -> ClipCodec:
        """Set the learned reference rotations (:meth:`fit`, or a saved model's); returns self."""
        self.reference_ = reference
        return self

    @property
    def n_frames(self) -> int:
        return self.reference_.shape[0]

    def encode(self, clips: ClipSet) -> np.ndarray:
        """(N, D) feature vectors."""
        v = to_tangent(clips.rotations[:, :, self.joints], self.reference_[None, :, self.joints])
        parts = [v.reshape(clips.n_clips, -1)]
        if self.timing:
            parts.append(encode_key_times(clips.key_times, self.key_timing))
        if self.root_height:
            parts.append(clips.root_height)
        return np.concatenate(parts, axis=1)

    def decode(self, features: np.ndarray, n_keys: int) -> tuple[np.ndarray, np.ndarray | None, np.ndarray | None]:
        """Rotations (M, T, |I|, 4), key times (M, K) or None, root height (M, T) or None."""
        features = np.atleast_2d(features)
        M, T, n_j = features.shape[0], self.n_frames, len(self.joints)
        n_rot = T * n_j * 3
        v = features[:, :n_rot].reshape(M, T, n_j, 3)
        rot = from_tangent(v, self.reference_[None, :, self.joints])
        pos = n_rot
        keys = height = None
        if self.timing:
            keys, pos = decode_key_times(features[:, pos : pos + n_keys], self.key_timing), pos + n_keys
        if self.root_height:
            height = features[:, pos : pos + T]
        return rot, keys, height


class PoseCodec:
    """Single poses <-> vectors: tangent vectors of every joint about its mean rotation over
    all frames of the examples (J * 3 values), for pose-based models (GPLVM, DBN). A
    scikit-learn-style estimator: ``PoseCodec().fit(rotations)`` learns ``reference_`` (J, 4)."""

    def fit(self, rotations: np.ndarray) -> PoseCodec:
        """From example rotations (..., J, 4) (all leading axes are frames)."""
        q = np.asarray(rotations, dtype=float)
        self.reference_ = mean_rotation(q.reshape(-1, *q.shape[-2:]), axis=0)
        return self

    def encode(self, rotations: np.ndarray) -> np.ndarray:
        """(T, J, 4) -> (T, J*3)."""
        return to_tangent(rotations, self.reference_).reshape(len(rotations), -1)

    def decode(self, vectors: np.ndarray) -> np.ndarray:
        """(T, J*3) -> (T, J, 4)."""
        v = np.asarray(vectors, dtype=float).reshape(len(vectors), -1, 3)
        return from_tangent(v, self.reference_)
