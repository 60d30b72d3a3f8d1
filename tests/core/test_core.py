"""Motion core: quaternions, forward kinematics (numpy vs torch), joint maps, datasets."""

import numpy as np
import pandas as pd
import pytest
import torch
from scipy.spatial.transform import Rotation

from motionvar.core import Motion, cmu_joint_map, cmu_skeleton, fk, fk_torch
from motionvar.core import quaternions as Q
from motionvar.io import DatasetError, load_dataset, save_dataset


def random_quats(rng, shape):
    return Q.qnormalize(rng.normal(size=(*shape, 4)))


def test_qmul_and_qrot_match_scipy():
    rng = np.random.default_rng(0)
    a, b = random_quats(rng, (50,)), random_quats(rng, (50,))
    ref = (Q.quat_to_scipy(a) * Q.quat_to_scipy(b)).as_quat(scalar_first=True)
    got = Q.qmul(a, b)
    assert np.allclose(np.abs(np.sum(ref * got, -1)), 1.0, atol=1e-12)
    v = rng.normal(size=(50, 3))
    assert np.allclose(Q.qrot(a, v), Q.quat_to_scipy(a).apply(v), atol=1e-12)


@pytest.mark.parametrize("order", ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "zxy"])
def test_euler_to_quat_is_scipys_from_euler_bit_for_bit(order):
    """The written-out composition gives scipy's quaternions exactly, signed zeros included,
    on random angles and on the multiples of 90 degrees where components vanish."""
    rng = np.random.default_rng(3)
    grid = np.stack(np.meshgrid(*[np.arange(-360, 361, 90.0)] * 3), axis=-1).reshape(-1, 3)
    angles = np.concatenate([rng.uniform(-400, 400, (5000, 3)), grid, -grid])
    ours = Q.euler_to_quat(angles.reshape(-1, 2, 3), order)
    ref = Rotation.from_euler(order.upper(), angles, degrees=True).as_quat(scalar_first=True)
    assert ours.shape == (len(angles) // 2, 2, 4)
    assert np.array_equal(ours.reshape(-1, 4), ref)
    assert np.array_equal(np.signbit(ours.reshape(-1, 4)), np.signbit(ref))


def test_euler_to_quat_rejects_an_order_that_is_not_a_permutation():
    with pytest.raises(ValueError, match="permutation of XYZ"):
        Q.euler_to_quat(np.zeros((2, 3)), "ZXZ")


@pytest.mark.parametrize("shape", [(4,), (7, 4), (60, 31, 4), (3, 20, 31, 4)])
def test_qnormalize_divides_by_numpys_norm_bit_for_bit(shape):
    q = np.random.default_rng(5).normal(size=shape) * 7.0
    assert np.array_equal(Q.qnormalize(q), q / np.linalg.norm(q, axis=-1, keepdims=True))
    assert Q.qnormalize(np.array([0, 3, 0, 4])).tolist() == [0.0, 0.6, 0.0, 0.8]  # integers too


def test_log_exp_round_trip():
    rng = np.random.default_rng(1)
    q = random_quats(rng, (200,))
    q[0] = [1, 0, 0, 0]
    back = Q.qexp(Q.qlog(q))
    assert np.allclose(np.abs(np.sum(back * q, -1)), 1.0, atol=1e-12)
    r = rng.normal(size=(200, 3))
    r *= rng.uniform(0, np.pi / 2 - 1e-3, size=(200, 1)) / np.linalg.norm(r, axis=-1, keepdims=True)
    assert np.allclose(Q.qlog(Q.qexp(r)), r, atol=1e-12)
    rv = Rotation.from_quat(q, scalar_first=True).as_rotvec()
    assert np.allclose(Q.quat_to_rotvec(q), rv, atol=1e-10)


def test_slerp_endpoints_and_midpoint():
    a = Q.quat_about_axis([0, 1, 0], 0.0)
    b = Q.quat_about_axis([0, 1, 0], 1.0)
    assert np.allclose(Q.qslerp(a, b, 0.0), a)
    assert np.allclose(Q.qslerp(a, b, 1.0), b)
    assert np.allclose(Q.qslerp(a, b, 0.5), Q.quat_about_axis([0, 1, 0], 0.5))


def test_sinusoidal_distance():
    a = Q.quat_about_axis([1, 0, 0], 0.0)
    b = Q.quat_about_axis([1, 0, 0], 0.6)
    # ||log(q1^-1 q2)|| is half the angle: sin(0.3)
    assert np.isclose(Q.qdistance_sinusoidal(a, b), np.sin(0.3))
    assert np.isclose(Q.qdistance_sinusoidal(a, -b), np.sin(0.3))
    assert np.isclose(Q.qdistance_sinusoidal(b, b), 0.0)


def test_qfix_removes_sign_flips():
    rng = np.random.default_rng(2)
    q = Q.quat_about_axis([0, 0, 1], np.linspace(0, 3, 40))
    flipped = q * rng.choice([-1.0, 1.0], size=(40, 1))
    fixed = Q.qfix(flipped)
    assert np.all(np.sum(fixed[1:] * fixed[:-1], -1) > 0)


def test_fk_numpy_matches_torch_to_1e5_cm():
    rng = np.random.default_rng(3)
    sk = cmu_skeleton()
    rot = random_quats(rng, (4, 30, sk.n_joints))
    root = rng.normal(scale=50, size=(4, 30, 3))
    ref = fk(rot, root, sk.offsets, sk.parents)
    got = fk_torch(torch.tensor(rot), torch.tensor(root), sk.offsets, sk.parents).numpy()
    assert np.max(np.abs(ref - got)) < 1e-5


def fk_per_joint(rotations, root, local, parents):
    """The textbook loop on (..., J, 4) arrays: R_j = R_parent * q_j, p_j = p_parent + R_parent o_j."""
    grot, gpos = [rotations[..., 0, :]], [root]
    for j in range(1, rotations.shape[-2]):
        grot.append(Q.qmul(grot[parents[j]], rotations[..., j, :]))
        gpos.append(gpos[parents[j]] + Q.qrot(grot[parents[j]], local[..., j, :]))
    return np.stack(gpos, axis=-2), np.stack(grot, axis=-2)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_fk_joint_major_equals_the_per_joint_loop_bit_for_bit(dtype):
    rng = np.random.default_rng(5)
    sk = cmu_skeleton()
    J = sk.n_joints
    rot = random_quats(rng, (3, 7, J)).astype(dtype)
    root = rng.normal(scale=50, size=(3, 7, 3)).astype(dtype)
    shared = np.broadcast_to(sk.offsets, (3, 7, J, 3))
    pos, grot = fk(rot, root, sk.offsets, sk.parents, return_rotations=True)
    ref_pos, ref_rot = fk_per_joint(rot, root, shared, sk.parents)
    assert pos.dtype == ref_pos.dtype and np.array_equal(pos, ref_pos) and np.array_equal(grot, ref_rot)
    per_clip = sk.offsets * rng.uniform(0.9, 1.1, size=(3, 1, 1, 1))  # one skeleton per clip
    translations = np.full((3, 7, J, 3), np.nan)
    translations[:, :, 1] = rng.normal(size=(3, 7, 3))  # a joint with position channels
    got = fk(rot, root, per_clip, sk.parents, translations=translations)
    local = np.where(np.isnan(translations), np.broadcast_to(per_clip, (3, 7, J, 3)), translations)
    assert np.array_equal(got, fk_per_joint(rot, root, local, sk.parents)[0])


def test_fk_torch_is_differentiable():
    sk = cmu_skeleton()
    rot = torch.tensor(Q.qidentity((2, sk.n_joints)), requires_grad=True)
    pos = fk_torch(rot, torch.zeros(2, 3, dtype=torch.float64), sk.offsets, sk.parents)
    pos[..., sk.index("LeftHand"), 1].sum().backward()
    assert torch.isfinite(rot.grad).all() and rot.grad.abs().sum() > 0


def test_fk_rest_pose_stands_upright():
    sk = cmu_skeleton()
    pos = fk(Q.qidentity((1, sk.n_joints)), np.zeros((1, 3)), sk.offsets, sk.parents)[0]
    jm = cmu_joint_map()
    head, toe = pos[jm.index(sk, "head"), 1], pos[jm.index(sk, "left_toe"), 1]
    assert 120 < head - toe < 160  # toe to the base of the skull of an adult, in cm


def test_joint_map_groups_partition_the_skeleton():
    sk = cmu_skeleton()
    jm = cmu_joint_map()
    jm.validate(sk)
    groups = jm.group_indices(sk)
    allj = np.sort(np.concatenate(list(groups.values())))
    assert np.array_equal(allj, np.arange(sk.n_joints))


def test_joint_map_names_missing_joints():
    from motionvar.core import JointMap

    jm = JointMap(joints={"hips": "Pelvis"})
    with pytest.raises(ValueError, match="missing semantic joints.*joints not in the skeleton"):
        jm.validate(cmu_skeleton(), source="config key datasets.x.joint_map")


def _motion(rng, T=12, scale=1.0):
    sk = cmu_skeleton().scaled(scale)
    return Motion(sk, rng.normal(size=(T, 3)), random_quats(rng, (T, sk.n_joints)), 120.0)


def test_dataset_round_trip(tmp_path):
    rng = np.random.default_rng(4)
    ms = [_motion(rng, 10, 1.0), _motion(rng, 7, 1.1)]
    meta = pd.DataFrame({"clip_id": ["a", "b"], "subject": ["01", "02"]})
    save_dataset(tmp_path, ms, meta)
    ds = load_dataset(tmp_path)
    assert len(ds) == 2 and list(ds.metadata["n_frames"]) == [10, 7]
    b = ds.by_id("b")
    assert np.allclose(b.positions(), ms[1].positions(), atol=1e-4)
    assert ds.metadata["subject"].iloc[0] == "01"


def test_dataset_rejects_bad_input_and_leaves_nothing(tmp_path):
    rng = np.random.default_rng(5)
    with pytest.raises(DatasetError, match="unique clip_id"):
        save_dataset(tmp_path, [_motion(rng), _motion(rng)], pd.DataFrame({"clip_id": ["a", "a"]}))
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(DatasetError, match="missing"):
        load_dataset(tmp_path)


def test_fixed_threads_sets_torch_and_blas_threads_and_restores_them():
    from threadpoolctl import threadpool_info

    from motionvar.core.threads import fixed_threads

    before_torch = torch.get_num_threads()
    before_blas = [i["num_threads"] for i in threadpool_info()]
    with fixed_threads(3):
        assert torch.get_num_threads() == 3
        assert all(i["num_threads"] == 3 for i in threadpool_info())
    assert torch.get_num_threads() == before_torch
    assert [i["num_threads"] for i in threadpool_info()] == before_blas


def test_end_site_positions_are_those_of_a_joint_at_the_end_site():
    """An End Site's position (the joint's, plus its offset turned by the joint's global
    rotation) equals the forward kinematics of the same skeleton with a joint added there; a
    map without toe joints takes the ankles' End Sites as its toes."""
    from motionvar.core import Skeleton
    from motionvar.core.extremities import end_site_positions, foot_points

    rng = np.random.default_rng(3)
    sk = cmu_skeleton()
    ankle = sk.index("LeftFoot")
    sk = Skeleton(sk.names, sk.parents, sk.offsets, {**sk.end_sites, ankle: np.array([0.0, -6.0, 14.0])})
    m = Motion(sk, rng.normal(size=(9, 3)), random_quats(rng, (9, sk.n_joints)), 60.0)
    grown = Skeleton((*sk.names, "tip"), np.append(sk.parents, ankle), np.vstack([sk.offsets, [[0.0, -6.0, 14.0]]]))
    tip = fk(np.concatenate([m.rotations, random_quats(rng, (9, 1))], axis=1), m.root_pos, grown.offsets, grown.parents)
    assert np.allclose(end_site_positions(m, [ankle])[:, 0], tip[:, -1], atol=1e-9)
    with pytest.raises(ValueError, match=r"joints \['Hips'\] have no End Site"):
        end_site_positions(m, [0])
    cmu = cmu_joint_map()
    toeless = type(cmu)({k: v for k, v in cmu.joints.items() if not k.endswith("_toe")}, cmu.groups)
    with pytest.raises(ValueError, match="no toe joints and the ankles .* have no End Site"):
        foot_points(m, toeless)  # the right ankle has no End Site here
    both = Skeleton(sk.names, sk.parents, sk.offsets, {**sk.end_sites, sk.index("RightFoot"): np.ones(3)})
    m2 = Motion(both, m.root_pos, m.rotations, 60.0)
    points = foot_points(m2, toeless)
    assert points.shape == (9, 2, 2, 3) and np.allclose(points[:, 0, 1], tip[:, -1], atol=1e-9)
    assert np.array_equal(foot_points(m, cmu)[:, 1, 1], m.positions()[:, sk.index("RightToeBase")])
