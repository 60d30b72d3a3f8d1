"""The foot contacts Ma 2010's measures and footskate cleanup see: the project's contact
detection (:func:`motionvar.prep.contacts.detect_foot_contacts`, default options: ankle or toe
slow and low) on a clip's ankle and toe joints, given by index (a
:class:`~.synthesis.RootSolver`'s ``feet``)."""

from __future__ import annotations

import numpy as np

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..prep.contacts import detect_foot_contacts


def foot_contacts(motion: Motion, feet: np.ndarray, positions: np.ndarray | None = None) -> np.ndarray:
    """(T, 2) contact masks of the left and the right foot of ``motion``, from the ankle and toe
    joints ``feet`` ((2, 2) joint indices: left/right x ankle/toe)."""
    feet = np.asarray(feet)
    if feet.shape != (2, 2):
        raise ValueError(f"foot_contacts: feet must be (2, 2) ankle and toe joints; got {feet.shape}")
    names = motion.skeleton.names
    jm = JointMap(
        joints={
            f"{side}_{part}": names[feet[f, j]]
            for f, side in enumerate(("left", "right"))
            for j, part in enumerate(("ankle", "toe"))
        }
    )
    c = detect_foot_contacts(motion, jm, positions=positions)
    return np.stack([c.left, c.right], axis=1)
