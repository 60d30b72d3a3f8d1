"""Motion: one clip as arrays over frames (root positions, local quaternions, fps)."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .kinematics import fk
from .quaternions import qfix, qnormalize
from .skeleton import Skeleton


@dataclass
class Motion:
    """A clip on a skeleton.

    Attributes:
        skeleton: the joint hierarchy (its offsets are this clip's bone lengths).
        root_pos: (T, 3) root position in cm, y up.
        rotations: (T, J, 4) local unit quaternions (w, x, y, z).
        fps: frames per second.
        translations: optional (T, J, 3) local translations of joints whose BVH channels
            include positions (NaN where a joint has none); None for rotation-only rigs.
    """

    skeleton: Skeleton
    root_pos: np.ndarray
    rotations: np.ndarray
    fps: float
    translations: np.ndarray | None = None

    def __post_init__(self) -> None:
        self.root_pos = np.asarray(self.root_pos, dtype=float)
        self.rotations = np.asarray(self.rotations, dtype=float)
        T, J = self.rotations.shape[:2] if self.rotations.ndim == 3 else (None, None)
        if self.rotations.ndim != 3 or self.rotations.shape[2] != 4 or J != self.skeleton.n_joints:
            raise ValueError(f"Motion: rotations must be (T, {self.skeleton.n_joints}, 4); got {self.rotations.shape}")
        if self.root_pos.shape != (T, 3):
            raise ValueError(f"Motion: root_pos must be ({T}, 3); got {self.root_pos.shape}")
        if self.translations is not None and np.shape(self.translations) != (T, J, 3):
            raise ValueError(f"Motion: translations must be ({T}, {J}, 3); got {np.shape(self.translations)}")
        if not self.fps > 0:
            raise ValueError(f"Motion: fps must be positive; got {self.fps}")

    @property
    def n_frames(self) -> int:
        return self.rotations.shape[0]

    @property
    def duration(self) -> float:
        """Length in seconds ((T - 1) / fps)."""
        return (self.n_frames - 1) / self.fps

    def positions(self) -> np.ndarray:
        """(T, J, 3) global joint positions in cm (forward kinematics)."""
        return fk(self.rotations, self.root_pos, self.skeleton.offsets, self.skeleton.parents, self.translations)

    def global_rotations(self) -> np.ndarray:
        """(T, J, 4) global joint rotations."""
        _, rot = fk(
            self.rotations,
            self.root_pos,
            self.skeleton.offsets,
            self.skeleton.parents,
            self.translations,
            return_rotations=True,
        )
        return rot

    def slice(self, start: int, stop: int) -> "Motion":
        """Frames [start, stop) as a new Motion."""
        tr = None if self.translations is None else self.translations[start:stop].copy()
        return replace(
            self,
            root_pos=self.root_pos[start:stop].copy(),
            rotations=self.rotations[start:stop].copy(),
            translations=tr,
        )

    def continuous(self) -> "Motion":
        """Copy with unit quaternions whose signs are continuous over frames."""
        return replace(self, rotations=qfix(qnormalize(self.rotations), axis=0))

    def copy(self) -> "Motion":
        tr = None if self.translations is None else self.translations.copy()
        return replace(self, root_pos=self.root_pos.copy(), rotations=self.rotations.copy(), translations=tr)
