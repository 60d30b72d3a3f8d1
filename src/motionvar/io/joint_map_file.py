"""Joint maps stored as YAML (``config/joint_maps/*.yaml``).

Format::

    joints: {hips: Hips, spine: Spine, ...}        # the semantic joints (SEMANTIC_JOINTS); those of
                                                   # OPTIONAL_JOINTS (hands, toes) only if the rig has them
    groups: {legs: [...], left_arm: [...], right_arm: [...], upper_body: [...]}

``groups`` is optional; a joint may stand in one group only. Whether the rig joints
exist is checked against a skeleton by :meth:`JointMap.validate`.
"""

from __future__ import annotations

from pathlib import Path

import yaml

from ..core.joint_map import JOINT_GROUPS, REQUIRED_JOINTS, SEMANTIC_JOINTS, JointMap


class JointMapError(ValueError):
    """A joint-map file that cannot be used; the message names the file."""


def _names(value: object) -> bool:
    return isinstance(value, list) and all(isinstance(v, str) and v for v in value)


def load_joint_map(path: str | Path) -> JointMap:
    """Read a joint map from YAML; :class:`JointMapError` naming the file on any problem."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise JointMapError(f"{path}: cannot read joint map ({exc.strerror or exc})") from exc
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        raise JointMapError(f"{path}: not valid YAML{where} ({getattr(exc, 'problem', exc)})") from exc
    if not isinstance(data, dict) or not isinstance(data.get("joints"), dict):
        raise JointMapError(f"{path}: expected a mapping with 'joints' (and optionally 'groups')")
    unknown_keys = sorted(set(data) - {"joints", "groups"})
    if unknown_keys:
        raise JointMapError(f"{path}: unknown keys {unknown_keys} (expected 'joints', 'groups')")
    joints = data["joints"]
    missing = [s for s in REQUIRED_JOINTS if s not in joints]
    unknown = sorted(set(joints) - set(SEMANTIC_JOINTS))
    bad = [s for s, n in joints.items() if not isinstance(n, str) or not n]
    if missing or unknown or bad:
        parts = [f"missing semantic joints {missing}"] if missing else []
        parts += [f"unknown semantic joints {unknown} (known: {list(SEMANTIC_JOINTS)})"] if unknown else []
        parts += [f"joint names must be non-empty strings: {bad}"] if bad else []
        raise JointMapError(f"{path}: " + "; ".join(parts))
    groups = data.get("groups") or {}
    if not isinstance(groups, dict):
        raise JointMapError(f"{path}: 'groups' must map group names to lists of joint names")
    bad_groups = sorted(set(groups) - set(JOINT_GROUPS))
    if bad_groups:
        raise JointMapError(f"{path}: unknown groups {bad_groups} (expected {list(JOINT_GROUPS)})")
    not_lists = [g for g, ns in groups.items() if not _names(ns)]
    if not_lists:
        raise JointMapError(f"{path}: groups {not_lists} must be lists of joint names")
    listed = [n for ns in groups.values() for n in ns]
    twice = sorted({n for n in listed if listed.count(n) > 1})
    if twice:
        raise JointMapError(f"{path}: joints listed more than once in groups: {twice}")
    return JointMap.from_dict({"joints": joints, "groups": groups}, origin=str(path))


def rig_joint_map(path: str | Path | None) -> JointMap:
    """The joint map of a dataset's rig: the YAML at ``path`` (:func:`load_joint_map`), or the
    CMU 31-joint rig's (:func:`~motionvar.core.joint_map.cmu_joint_map`) when ``path`` is empty."""
    from ..core.joint_map import cmu_joint_map

    return load_joint_map(path) if path else cmu_joint_map()
