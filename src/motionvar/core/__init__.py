"""Motion core: skeletons, motions, quaternions, forward kinematics, joint maps."""

from .lazy import lazy_exports

# imported on first use (PEP 562): the other packages' __init__ import core.lazy, and a job
# without motions (claims tables, GIF pages, the applicability table) need not load scipy
_EXPORTS = {
    ".joint_map": [
        "JOINT_GROUPS",
        "OPTIONAL_JOINTS",
        "REQUIRED_JOINTS",
        "SEMANTIC_JOINTS",
        "JointMap",
        "cmu_joint_map",
    ],
    ".kinematics": ["fk", "fk_torch"],
    ".motion": ["Motion"],
    ".skeleton": ["CMU_UNIT_CM", "Skeleton", "cmu_skeleton"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "CMU_UNIT_CM",
    "JOINT_GROUPS",
    "OPTIONAL_JOINTS",
    "REQUIRED_JOINTS",
    "SEMANTIC_JOINTS",
    "JointMap",
    "Motion",
    "Skeleton",
    "cmu_joint_map",
    "cmu_skeleton",
    "fk",
    "fk_torch",
]
