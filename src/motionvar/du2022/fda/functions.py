"""Motion clips as multivariate functional data (Du 2022, Sec. 3.2.1 and 3.3.3, Eq. 3.1-3.2).

Parameterisation (Eq. 3.2): y_i(t) = {p_i(t), q_i1(t), ..., q_im(t)}, i.e. per clip
D = 3 + 4 J functions:

- functions 0..2: root translation p(t) (x, y, z in cm, in the aligned frame: each clip
  starts at the origin heading +x);
- functions 3 + 4 j .. 6 + 4 j: the unit quaternion (w, x, y, z) of joint j; joint 0's
  quaternion is the root orientation, the others are local to the parent joint.

Quaternions are made sign-continuous (Sec. 3.2.1; q and -q are the same rotation): first
over frames within a clip (no hemisphere flips), then across clips (each clip's
trajectory of joint j is negated where its time average points away from the clips'
average rotation of joint j), so that PCA over clips sees no artificial sign jumps.

Every clip's frames are mapped to normalised time [0, 1] and fitted by the same
B-spline basis; evaluating the functions at n canonical frames is linear time
normalisation to a canonical timeline of n frames. Clips that were already warped to
a canonical timeline (e.g. by DTW) simply share one length.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from ...core.kinematics import fk
from ...core.motion import Motion
from ...core.quaternions import qfix, qnormalize
from ...core.skeleton import Skeleton
from .bspline import BSplineBasis

ROOT_FUNCTIONS = 3


@dataclass(frozen=True)
class FunctionLayout:
    """Which function is which: root translation (3) then one quaternion (4) per joint."""

    n_joints: int

    @property
    def n_functions(self) -> int:
        return ROOT_FUNCTIONS + 4 * self.n_joints

    def split(self, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(..., D) -> root translation (..., 3) and quaternions (..., J, 4) (not normalised)."""
        if values.shape[-1] != self.n_functions:
            raise ValueError(f"expected {self.n_functions} functions (3 + 4 x {self.n_joints}); got {values.shape[-1]}")
        return values[..., :ROOT_FUNCTIONS], values[..., ROOT_FUNCTIONS:].reshape(*values.shape[:-1], self.n_joints, 4)

    def pack(self, root_pos: np.ndarray, rotations: np.ndarray) -> np.ndarray:
        """Root translation (..., 3) and quaternions (..., J, 4) -> (..., D)."""
        return np.concatenate([root_pos, rotations.reshape(*rotations.shape[:-2], 4 * self.n_joints)], axis=-1)

    def function_groups(self) -> np.ndarray:
        """(D,) group index per function: 0 for the root translation, 1 + j for joint j's
        quaternion (the coarser one-weight-per-joint scaling, as in DFKI's implementation)."""
        return np.concatenate([np.zeros(ROOT_FUNCTIONS, dtype=np.int64), 1 + np.repeat(np.arange(self.n_joints), 4)])


def align_quaternion_signs(rotations: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Sign-continuous quaternions (Sec. 3.2.1): continuous over frames (axis 0) in each
    clip, then each clip's joint trajectory flipped into the hemisphere of the average
    rotation of that joint over all clips (the principal eigenvector of sum q q^T)."""
    fixed = [qfix(qnormalize(np.asarray(r, dtype=float)), axis=0) for r in rotations]
    means = np.stack([r.mean(axis=0) for r in fixed])  # (N, J, 4)
    scatter = np.einsum("nja,njb->jab", means, means)
    _, vecs = np.linalg.eigh(scatter)
    ref = vecs[..., -1]  # (J, 4)
    ref = np.where(ref[..., :1] < 0, -ref, ref)
    signs = np.where(np.einsum("nja,ja->nj", means, ref) < 0, -1.0, 1.0)  # (N, J)
    return [r * s[None, :, None] for r, s in zip(fixed, signs)]


def _function_values(motions: Sequence[Motion]) -> tuple[FunctionLayout, list[np.ndarray]]:
    """The layout and each clip's (T, D) function values: root translation and
    sign-continuous quaternions (:func:`align_quaternion_signs`), independent of the basis."""
    layout = FunctionLayout(motions[0].skeleton.n_joints)
    rots = align_quaternion_signs([m.rotations for m in motions])
    return layout, [layout.pack(m.root_pos, r) for m, r in zip(motions, rots)]


def _positions_by_length(motions: Sequence[Motion], groups: list[np.ndarray]) -> list[np.ndarray]:
    """(n, T, J, 3) joint positions of the clips of each group of equal length, by one
    forward-kinematics call per group (element for element the same arithmetic as
    ``Motion.positions`` per clip); clips with per-frame joint translations per clip."""
    out = []
    for idx in groups:
        clips = [motions[i] for i in idx]
        if any(m.translations is not None for m in clips):
            out.append(np.stack([m.positions() for m in clips]))
            continue
        out.append(
            fk(
                np.stack([m.rotations for m in clips]),
                np.stack([m.root_pos for m in clips]),
                np.stack([m.skeleton.offsets for m in clips])[:, None],
                clips[0].skeleton.parents,
            )
        )
    return out


def _check_clips(motions: Sequence[Motion], basis: BSplineBasis) -> None:
    if len(motions) == 0:
        raise ValueError("functional data: no clips given")
    sk0 = motions[0].skeleton
    for i, m in enumerate(motions):
        if not m.skeleton.same_topology(sk0):
            raise ValueError(f"functional data: clip {i} has another skeleton topology than clip 0")
        if m.n_frames < basis.n_basis:
            raise ValueError(
                f"functional data: clip {i} has {m.n_frames} frames, fewer than the {basis.n_basis} basis functions"
            )
        if not (np.all(np.isfinite(m.rotations)) and np.all(np.isfinite(m.root_pos))):
            raise ValueError(f"functional data: clip {i} has non-finite root positions or rotations")


def _fit_by_length(basis: BSplineBasis, values: list[np.ndarray]) -> np.ndarray:
    """Coefficients (N, K, D) of clips of any lengths; one vectorised fit per distinct length."""
    lengths = np.array([v.shape[0] for v in values])
    coefs = np.empty((len(values), basis.n_basis, values[0].shape[-1]))
    for T in np.unique(lengths):
        idx = np.flatnonzero(lengths == T)
        coefs[idx] = basis.fit(np.stack([values[i] for i in idx]))
    return coefs


@dataclass
class FunctionalMotions:
    """N clips of one motion primitive as B-spline functional data (Eq. 3.1-3.2).

    Attributes:
        coefs: (N, K, D) B-spline coefficients of the D functions of each clip.
        basis: the shared B-spline basis.
        layout: which function is which (see module docstring).
        offsets: (N, J, 3) bone offsets of each clip's skeleton (for forward kinematics).
        parents: (J,) parent indices.
        n_frames: length of the canonical timeline the functions are evaluated on.
    """

    coefs: np.ndarray
    basis: BSplineBasis
    layout: FunctionLayout
    offsets: np.ndarray
    parents: np.ndarray
    n_frames: int

    def __post_init__(self) -> None:
        N, K, D = self.coefs.shape
        if K != self.basis.n_basis or D != self.layout.n_functions:
            raise ValueError(f"coefs {self.coefs.shape} do not match {K=} basis functions x {D=} functions")
        if self.offsets.shape != (N, self.layout.n_joints, 3):
            raise ValueError(f"offsets must be ({N}, {self.layout.n_joints}, 3); got {self.offsets.shape}")

    @classmethod
    def from_motions(
        cls, motions: Sequence[Motion], n_basis: int, n_frames: int | None = None, degree: int = 3
    ) -> "FunctionalMotions":
        """Fit every clip with ``n_basis`` B-splines; ``n_frames`` (the canonical timeline)
        defaults to the median clip length."""
        basis = BSplineBasis(n_basis, degree)
        _check_clips(motions, basis)
        return cls._from_values(motions, *_function_values(motions), basis, n_frames)

    @classmethod
    def _from_values(
        cls,
        motions: Sequence[Motion],
        layout: FunctionLayout,
        values: list[np.ndarray],
        basis: BSplineBasis,
        n_frames: int | None,
    ) -> "FunctionalMotions":
        """:meth:`from_motions` with the clips' function values (:func:`_function_values`)
        already computed: one sign alignment serves every basis size."""
        if n_frames is None:
            n_frames = int(round(float(np.median([m.n_frames for m in motions]))))
        return cls(
            coefs=_fit_by_length(basis, values),
            basis=basis,
            layout=layout,
            offsets=np.stack([m.skeleton.offsets for m in motions]),
            parents=np.asarray(motions[0].skeleton.parents),
            n_frames=int(n_frames),
        )

    @property
    def n_clips(self) -> int:
        return self.coefs.shape[0]

    def with_coefs(self, coefs: np.ndarray) -> "FunctionalMotions":
        """Same clips (skeletons, basis, timeline) with other coefficients (a reconstruction)."""
        return replace(self, coefs=np.asarray(coefs, dtype=float))

    def subset(self, idx: np.ndarray) -> "FunctionalMotions":
        return replace(self, coefs=self.coefs[idx], offsets=self.offsets[idx])

    def values(self, coefs: np.ndarray | None = None, n_frames: int | None = None) -> np.ndarray:
        """(N, T, D) function values at the canonical frames."""
        return self.basis.evaluate(self.coefs if coefs is None else coefs, n_frames or self.n_frames)

    def motion_arrays(self, coefs: np.ndarray | None = None, n_frames: int | None = None):
        """Root positions (N, T, 3) and unit quaternions (N, T, J, 4) at the canonical frames."""
        root, quats = self.layout.split(self.values(coefs, n_frames))
        return root, qnormalize(quats)

    def positions(self, coefs: np.ndarray | None = None, n_frames: int | None = None) -> np.ndarray:
        """(N, T, J, 3) global joint positions (cm) by forward kinematics f_k (Eq. 3.6)."""
        root, quats = self.motion_arrays(coefs, n_frames)
        return fk(quats, root, self.offsets[:, None], self.parents)

    def to_motions(self, skeleton: Skeleton, fps: float, coefs: np.ndarray | None = None) -> list[Motion]:
        """The functional clips (or a reconstruction ``coefs``) as Motions on ``skeleton``."""
        root, quats = self.motion_arrays(coefs)
        return [Motion(skeleton=skeleton, root_pos=r, rotations=q, fps=fps) for r, q in zip(root, quats)]


def bspline_fit_rmse(motions: Sequence[Motion], n_basis: int | Sequence[int], degree: int = 3) -> float | np.ndarray:
    """Joint-space RMSE (cm) between each clip's frames and its B-spline representation
    evaluated at the same frames (Fig. 3.9): sqrt of the mean squared joint distance over
    clips, frames and joints; one value per entry of ``n_basis`` (a float for an int)."""
    ks = np.atleast_1d(n_basis)
    lengths = np.array([m.n_frames for m in motions])
    groups = [np.flatnonzero(lengths == T) for T in np.unique(lengths)]
    original = _positions_by_length(motions, groups)  # once for every K
    prepared = _function_values(motions)  # likewise (the sign alignment does not depend on K)
    rmse = np.empty(len(ks))
    for j, k in enumerate(ks):
        basis = BSplineBasis(int(k), degree)
        _check_clips(motions, basis)
        fd = FunctionalMotions._from_values(motions, *prepared, basis, None)
        sq_sum, count = 0.0, 0
        for idx, orig in zip(groups, original):
            fitted = fd.subset(idx).positions(n_frames=orig.shape[1])
            sq_sum += float(np.sum((fitted - orig) ** 2))
            count += orig.shape[0] * orig.shape[1] * orig.shape[2]
        rmse[j] = np.sqrt(sq_sum / count)
    return rmse if np.ndim(n_basis) else float(rmse[0])
