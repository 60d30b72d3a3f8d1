"""Posture PCA (Egges et al. 2004, Sec. 3.2, Fig. 1).

A frame is the vector of the log-maps (rotation vectors, Eq. 1-2) of its joint
rotations plus the root translation: v in R^(3m+3). A PCA of these vectors gives a PC
space of equal dimension; postures move between the spaces both ways (project /
reconstruct), the exponential map (Rodrigues, Eq. 3) bringing rotation vectors back to
rotations.

Units: the paper's H-Anim skeletons are in metres; our motions are in centimetres, so the
root translation is multiplied by ``translation_scale`` (config default 0.01: metres) before the
PCA, which keeps the translation on the same footing as rotations in radians.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..core.motion import Motion
from ..core.quaternions import qfix, qnormalize, quat_to_rotvec, rotvec_to_quat
from ..core.skeleton import Skeleton


def continuous_rotvecs(rotations: np.ndarray) -> np.ndarray:
    """Rotation vectors (T, J, 3) of quaternions (T, J, 4) that are continuous over frames.

    The quaternions are made sign-continuous over time (hemisphere of frame 0 with
    w >= 0), and the log is taken without folding back to w >= 0: a frame whose
    quaternion has w < 0 gets the equivalent rotation vector of angle 2*pi - |r| about the
    opposite axis, so a joint turning through pi does not jump in the log-map.
    """
    q = qfix(qnormalize(np.asarray(rotations, dtype=float)), axis=0)
    q = q * np.where(q[:1, :, :1] < 0, -1.0, 1.0)
    r = quat_to_rotvec(q)
    angle = np.linalg.norm(r, axis=-1, keepdims=True)
    unwrap = (q[..., :1] < 0) & (angle > 0)
    return np.where(unwrap, r - 2.0 * np.pi * r / np.maximum(angle, 1e-12), r)


def posture_vectors(motion: Motion, joints: np.ndarray, translation_scale: float) -> np.ndarray:
    """(T, 3m+3) posture vectors of a motion (Sec. 3.2): the rotation vectors of the
    ``joints`` (m indices) then the root translation times ``translation_scale``."""
    r = continuous_rotvecs(motion.rotations)[:, joints].reshape(motion.n_frames, -1)
    return np.concatenate([r, motion.root_pos * translation_scale], axis=1)


class PosturePCA:
    """PCA of posture vectors (Sec. 3.2), a scikit-learn-style estimator: ``PosturePCA(scale,
    joints).fit(motions)``, then ``project`` to and ``reconstruct`` from PC space.

    Parameters:
        translation_scale: factor on the root translation (0.01: cm -> m).
        joints: indices of the joints in the posture vector (the paper uses 25); None: every joint.

    Attributes learned by :meth:`fit`:
        joints_: the joint indices used.
        mean_: (D,) mean posture vector.
        components_: (D, D) principal axes as rows, by decreasing variance.
        explained_variance_: (D,) the eigenvalues.
        base_rotations_: (J, 4) rotations given to the joints left out of ``joints_``.
    """

    def __init__(self, translation_scale: float, joints: Sequence[int] | None = None) -> None:
        self.translation_scale = float(translation_scale)
        self.joints = joints

    def fit(self, motions: Sequence[Motion]) -> PosturePCA:
        """Fit on all frames of ``motions`` (one rig), the root translation times
        ``translation_scale``."""
        from sklearn.decomposition import PCA  # only fitting needs scikit-learn (a slow import)

        if len(motions) == 0:
            raise ValueError("PosturePCA.fit: no motions")
        n_joints = motions[0].skeleton.n_joints
        if any(m.skeleton.n_joints != n_joints for m in motions):
            raise ValueError("PosturePCA.fit: motions have different numbers of joints")
        joints = np.arange(n_joints) if self.joints is None else np.asarray(self.joints, dtype=np.int64)
        if joints.size == 0 or joints.min() < 0 or joints.max() >= n_joints:
            raise ValueError(f"PosturePCA.fit: joint indices must lie in [0, {n_joints}); got {joints.tolist()}")
        X = np.concatenate([posture_vectors(m, joints, self.translation_scale) for m in motions])
        if len(X) < 2:
            raise ValueError("PosturePCA.fit: need at least two frames")
        pca = PCA(svd_solver="full").fit(X)
        D = X.shape[1]
        components = np.zeros((D, D))
        variance = np.zeros(D)
        components[: pca.n_components_] = pca.components_
        variance[: pca.n_components_] = pca.explained_variance_
        if pca.n_components_ < D:  # fewer frames than dimensions: complete the basis
            q, _ = np.linalg.qr(np.concatenate([pca.components_.T, np.eye(D)], axis=1))
            components[pca.n_components_ :] = q[:, pca.n_components_ : D].T
        left_out = np.setdiff1d(np.arange(n_joints), joints)
        base = np.zeros((n_joints, 4))
        base[:, 0] = 1.0
        if left_out.size:
            base[left_out] = qnormalize(np.concatenate([m.rotations[:, left_out] for m in motions]).mean(axis=0))
        return self.set_fitted(joints, pca.mean_, components, variance, base)

    def set_fitted(
        self,
        joints: np.ndarray,
        mean: np.ndarray,
        components: np.ndarray,
        explained_variance: np.ndarray,
        base_rotations: np.ndarray,
    ) -> PosturePCA:
        """Set the learned attributes (:meth:`fit`, or a saved model's arrays); returns self."""
        self.joints_ = np.asarray(joints, dtype=np.int64)
        self.mean_, self.components_, self.explained_variance_ = mean, components, explained_variance
        self.base_rotations_ = base_rotations
        return self

    @property
    def n_dims(self) -> int:
        return self.mean_.shape[0]

    def weights(self) -> np.ndarray:
        """Weights w_i of the posture distance (Eq. 4, footnote 1): the eigenvalues
        normalised so that the first is 1 (non-negative and decreasing)."""
        ev = np.maximum(self.explained_variance_, 0.0)
        return ev / ev[0] if ev[0] > 0 else np.ones_like(ev)

    def vectors_to_pc(self, vectors: np.ndarray) -> np.ndarray:
        """Posture vectors (..., D) -> PC values (..., D)."""
        return (vectors - self.mean_) @ self.components_.T

    def pc_to_vectors(self, pcs: np.ndarray) -> np.ndarray:
        """PC values (..., D) -> posture vectors (..., D); missing trailing PCs count as 0."""
        pcs = np.asarray(pcs, dtype=float)
        k = pcs.shape[-1]
        return pcs @ self.components_[:k] + self.mean_

    def root_translation(self, pcs: np.ndarray) -> np.ndarray:
        """Root translation in cm (..., 3) of postures given as PC values (..., D)."""
        return self.pc_to_vectors(pcs)[..., -3:] / self.translation_scale

    def shift_translation(self, pcs: np.ndarray, delta_cm: np.ndarray) -> np.ndarray:
        """PC values of the postures ``pcs`` (..., D) with the root moved by ``delta_cm``
        (..., 3); the PCA is linear, so this is a constant offset in PC space."""
        return pcs + (np.asarray(delta_cm) * self.translation_scale) @ self.components_[:, -3:].T

    def components_for(self, share: float) -> int:
        """The fewest leading PCs that hold ``share`` of the posture variance (e.g. 0.9)."""
        ratio = np.cumsum(self.explained_variance_) / np.sum(self.explained_variance_)
        return int(min(np.searchsorted(ratio, share) + 1, len(ratio)))

    def project(self, motion: Motion) -> np.ndarray:
        """(T, D) PC values of every frame of ``motion`` (Fig. 1, left to right)."""
        if motion.skeleton.n_joints != self.base_rotations_.shape[0]:
            raise ValueError(
                f"PosturePCA.project: motion has {motion.skeleton.n_joints} joints, "
                f"the PCA was fitted on {self.base_rotations_.shape[0]}"
            )
        return self.vectors_to_pc(posture_vectors(motion, self.joints_, self.translation_scale))

    def to_rotations(self, pcs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """PC values (T, k) -> (local quaternions (T, J, 4), root positions (T, 3) in cm)
        (Fig. 1, right to left; Eq. 3 as the exponential map)."""
        v = self.pc_to_vectors(np.atleast_2d(pcs))
        T, m = v.shape[0], self.joints_.size
        rot = np.broadcast_to(self.base_rotations_, (T, *self.base_rotations_.shape)).copy()
        rot[:, self.joints_] = rotvec_to_quat(v[:, : 3 * m].reshape(T, m, 3))
        return rot, v[:, 3 * m :] / self.translation_scale

    def reconstruct(self, pcs: np.ndarray, skeleton: Skeleton, fps: float) -> Motion:
        """A Motion on ``skeleton`` from PC values (T, k)."""
        rot, root = self.to_rotations(pcs)
        return Motion(skeleton=skeleton, root_pos=root, rotations=rot, fps=fps)
