"""Re-rooting a clip at the pelvis (rigs whose BVH ROOT is a floor point): the kept
joints' forward kinematics is unchanged; joints that would be lost are refused."""

from __future__ import annotations

import numpy as np
import pytest
from bvh_files import floor_rooted

from motionvar.core.reroot import RerootError, reroot
from motionvar.io import read_bvh, write_bvh


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
