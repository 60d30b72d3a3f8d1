"""Re-rooting a clip at the pelvis (rigs whose BVH ROOT is a floor point): the kept
joints' forward kinematics is unchanged; joints that would be lost are refused."""

from __future__ import annotations

import numpy as np
import pytest

from motionvar.core import Motion, Skeleton, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.core.reroot import RerootError, reroot
from motionvar.io import read_bvh, write_bvh


def floor_rooted(translations: bool, frames: int = 20, seed: int = 0) -> Motion:
    """The CMU rig under an extra ROOT ``Ground`` (a floor point, like Bandai's joint_Root),
    random rotations everywhere; with ``translations``, every joint has position channels
    that move (as Bandai's 6-channel joints)."""
    rng = np.random.default_rng(seed)
    cmu = cmu_skeleton()
    names = ("Ground",) + cmu.names
    parents = np.concatenate([[-1], cmu.parents + 1])
    parents[1] = 0
    offsets = np.vstack([[0.0, 0.0, 0.0], cmu.offsets])
    offsets[1] = [0.0, 93.0, -3.0]
    end_sites = {j + 1: o for j, o in cmu.end_sites.items()}
    J = len(names)
    sk = Skeleton(names, parents, offsets, end_sites, ("ZXY",) * J, (True,) * J if translations else None)
    rot = Q.qnormalize(np.array([1.0, 0, 0, 0]) + 0.3 * rng.normal(size=(frames, J, 4)))
    root = np.column_stack([np.linspace(0, 100, frames), np.zeros(frames), rng.normal(size=frames)])
    tr = None
    if translations:
        tr = offsets + rng.normal(size=(frames, J, 3))
        tr[:, 0] = np.nan
    return Motion(sk, root, rot, fps=30.0, translations=tr)


@pytest.mark.parametrize("translations", [False, True])
def test_reroot_keeps_every_kept_joint_in_place(translations):
    m = floor_rooted(translations)
    r = reroot(m, "Hips")
    assert r.skeleton.names == m.skeleton.names[1:] and r.skeleton.parents[0] == -1
    assert np.array_equal(r.skeleton.parents[1:], m.skeleton.parents[2:] - 1)
    assert r.skeleton.position_channels[0]
    assert np.abs(r.positions() - m.positions()[:, 1:]).max() < 1e-6  # cm
    assert np.abs(r.root_pos - m.positions()[:, 1]).max() < 1e-9
    assert np.allclose(np.abs(np.sum(r.global_rotations() * m.global_rotations()[:, 1:], axis=-1)), 1.0)
    assert (r.translations is not None) == translations
    if translations:
        assert np.isnan(r.translations[:, 0]).all()
    assert sorted(r.skeleton.end_sites) == sorted(j - 1 for j in m.skeleton.end_sites)


def test_rerooted_clip_writes_and_reads_back(tmp_path):
    r = reroot(floor_rooted(True), "Hips")
    write_bvh(tmp_path / "r.bvh", r)
    back = read_bvh(tmp_path / "r.bvh")
    assert back.skeleton.names[0] == "Hips"
    assert np.abs(back.positions() - r.positions()).max() < 1e-3


def test_reroot_at_the_root_is_a_no_op():
    m = floor_rooted(False)
    assert reroot(m, 0) is m


def test_reroot_refuses_to_lose_joints():
    """Joints above the new root with other children: those children would vanish."""
    m = floor_rooted(False)
    with pytest.raises(RerootError, match=r"cannot make LeftUpLeg the root: .*lost: \['RHipJoint'"):
        reroot(m, "LeftUpLeg")
