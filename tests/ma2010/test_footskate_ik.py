"""Footskate cleanup "root+feet" ([KSG02] after Ma 2010 Sec. 6.3): the analytic leg IK
(motionvar.core.leg_ik) on random legs and on the CMU rig, the contact displacement, and
the cleanup on the generator's walks (ground truth: their feet never slide) and on walks
made to slide."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from motionvar.core import cmu_joint_map, cmu_skeleton, fk
from motionvar.core.leg_ik import bend_direction, knee_and_ankle, two_bone_ik
from motionvar.core.quaternions import qangle, qinv, qlog, qmul, qnormalize, qrot
from motionvar.ma2010.postprocess import CLEANUPS, contact_offsets, leg_chains, pin_feet, reconstruct_root
from motionvar.metrics.foot_skating import foot_skating

JM = cmu_joint_map()


def random_legs(n: int, seed: int = 0):
    """n posed legs: hip at random places, thigh 40-45 cm, shin 38-44 cm, knee bent 5-90
    degrees in a random plane; global rotations of the hip and knee joints that turn rest
    bones along -y onto them."""
    rng = np.random.default_rng(seed)
    hip_rot = qnormalize(rng.normal(size=(n, 4)))
    flex = np.radians(rng.uniform(5, 90, n))
    knee_local = np.stack([np.cos(flex / 2), np.sin(flex / 2), np.zeros(n), np.zeros(n)], axis=1)  # about x
    knee_rot = qmul(hip_rot, knee_local)
    l1, l2 = rng.uniform(40, 45, n), rng.uniform(38, 44, n)
    hip = rng.normal(scale=50, size=(n, 3))
    down = np.array([0.0, -1.0, 0.0])
    knee = hip + qrot(hip_rot, down * l1[:, None])
    ankle = knee + qrot(knee_rot, down * l2[:, None])
    return hip, knee, ankle, hip_rot, knee_rot, l1, l2, rng


def reached(ik, hip, l1, l2):
    """The ankle as the rotations place it (FK of the two bones from the hip)."""
    down = np.array([0.0, -1.0, 0.0])
    knee = hip + qrot(ik.hip_rotation, down * l1[:, None])
    return knee, knee + qrot(ik.knee_rotation, down * l2[:, None])


def test_leg_ik_reaches_a_reachable_target_and_keeps_the_bones():
    hip, knee, ankle, hr, kr, l1, l2, rng = random_legs(500)
    direction = rng.normal(size=(500, 3))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    target = hip + direction * rng.uniform(np.abs(l1 - l2) + 1, l1 + l2 - 0.01)[:, None]
    ik = two_bone_ik(hip, knee, ankle, hr, kr, target)
    k, a = reached(ik, hip, l1, l2)
    assert np.abs(a - target).max() < 1e-6  # cm
    assert np.abs(ik.ankle - target).max() < 1e-6 and np.abs(ik.knee - k).max() < 1e-6
    assert np.allclose(np.linalg.norm(k - hip, axis=1), l1, atol=1e-9)
    assert np.allclose(np.linalg.norm(a - k, axis=1), l2, atol=1e-9)


def test_leg_ik_leaves_a_leg_alone_when_the_target_is_its_ankle():
    hip, knee, ankle, hr, kr, l1, l2, _ = random_legs(200, seed=1)
    ik = two_bone_ik(hip, knee, ankle, hr, kr, ankle)
    assert qangle(ik.hip_rotation, hr).max() < 1e-6 and qangle(ik.knee_rotation, kr).max() < 1e-6
    assert np.abs(ik.knee - knee).max() < 1e-9


def test_leg_ik_points_a_straight_leg_at_an_unreachable_target():
    hip, knee, ankle, hr, kr, l1, l2, rng = random_legs(200, seed=2)
    direction = rng.normal(size=(200, 3))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    target = hip + direction * (l1 + l2 + rng.uniform(0.5, 30, 200))[:, None]
    ik = two_bone_ik(hip, knee, ankle, hr, kr, target)
    k, a = reached(ik, hip, l1, l2)
    assert np.allclose(a, hip + direction * (l1 + l2)[:, None], atol=1e-6)  # straight, towards the target
    assert np.allclose(k, hip + direction * l1[:, None], atol=1e-6)


def test_leg_ik_keeps_the_knee_plane_and_bends_only_the_knee():
    """A target in the leg's plane: the knee stays in that plane, on its side of the
    hip-ankle line; for any target the knee's local rotation changes by a rotation about
    the bend plane's normal only (flexion, no twist)."""
    hip, knee, ankle, hr, kr, l1, l2, rng = random_legs(300, seed=3)
    normal = np.cross(ankle - hip, knee - hip)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    in_plane = rng.normal(size=(300, 3))
    in_plane -= np.sum(in_plane * normal, axis=1, keepdims=True) * normal
    target = ankle + 5 * in_plane
    ik = two_bone_ik(hip, knee, ankle, hr, kr, target)
    assert np.abs(np.sum((ik.knee - hip) * normal, axis=1)).max() < 1e-9  # in the plane
    side_old = np.sum(np.cross(ankle - hip, knee - hip) * normal, axis=1)
    side_new = np.sum(np.cross(target - hip, ik.knee - hip) * normal, axis=1)
    bent = np.linalg.norm(target - hip, axis=1) < l1 + l2 - 0.01  # out of reach the leg is straight: no side
    assert bent.sum() > 200 and np.all(np.sign(side_old[bent]) == np.sign(side_new[bent]))  # same bending sense
    ik = two_bone_ik(hip, knee, ankle, hr, kr, ankle + rng.normal(scale=4, size=(300, 3)))
    change = qmul(qinv(qmul(qinv(hr), kr)), qmul(qinv(ik.hip_rotation), ik.knee_rotation))  # in the knee's local frame
    axis = qlog(change)
    hinge_local = qrot(qinv(kr), normal)  # the old plane's normal seen from the knee joint
    off_axis = np.linalg.norm(axis - np.sum(axis * hinge_local, axis=1, keepdims=True) * hinge_local, axis=1)
    assert off_axis.max() < 1e-9


def test_a_nearly_straight_leg_keeps_bending_forwards():
    """A knee bent by a hair towards +z, its ankle moved 1 cm forwards: measured from the
    new hip-target line the old knee lies behind it, but the leg keeps bending to the side it
    bent to (the current bend is the pole), never backwards; a straight leg bends towards
    the fallback pole."""
    hip, knee, ankle = np.zeros((1, 3)), np.array([[0.0, -40.0, 0.05]]), np.array([[0.0, -80.0, 0.0]])
    target = np.array([[0.0, -77.0, 1.0]])
    ik = two_bone_ik(hip, knee, ankle, np.array([[1.0, 0, 0, 0]]), np.array([[1.0, 0, 0, 0]]), target)
    line = target[0] / np.linalg.norm(target[0])
    across = ik.knee[0] - np.dot(ik.knee[0], line) * line
    assert across[2] > 1.0 and np.allclose(ik.ankle, target)  # in front of the hip-ankle line
    for pole, side in (([0.0, 0.0, 1.0], 1.0), ([0.0, 0.0, -1.0], -1.0)):
        k, a = knee_and_ankle(
            hip,
            np.array([[0.0, -70.0, 0.0]]),
            np.array([40.0]),
            np.array([40.0]),
            np.array([[0.0, -1.0, 0.0]]),
            fallback=np.array(pole),
        )
        assert np.sign(k[0, 2]) == side and np.allclose(a, [[0.0, -70.0, 0.0]])
    w = bend_direction(np.array([[0.0, -1.0, 0.0]]), np.array([[0.0, -2.0, 0.0]]))  # no pole, no fallback
    assert np.isclose(np.linalg.norm(w), 1.0) and abs(w[0, 1]) < 1e-12


def test_leg_ik_on_the_cmu_rig_moves_the_ankle_and_keeps_the_foot():
    """Through the rig's local rotations (as :func:`pin_feet` writes them): FK puts the
    ankle on the target to < 1e-6 cm and the foot keeps its global orientation."""
    sk = cmu_skeleton()
    rng = np.random.default_rng(4)
    T = 50
    rot = np.tile([1.0, 0, 0, 0], (T, sk.n_joints, 1))
    hip, knee, ankle = JM.indices(sk, ["left_hip", "left_knee", "left_ankle"])
    rot[:, hip] = qnormalize(np.array([1.0, 0, 0, 0]) + rng.normal(scale=0.15, size=(T, 4)))
    rot[:, knee] = qnormalize(np.stack([np.ones(T), rng.uniform(0.05, 0.5, T), np.zeros(T), np.zeros(T)], axis=1))
    pos, grot = fk(rot, np.zeros((T, 3)), sk.offsets, sk.parents, return_rotations=True)
    target = pos[:, ankle] + rng.normal(scale=2.0, size=(T, 3))
    target -= 3.0 * (target - pos[:, hip]) / np.linalg.norm(target - pos[:, hip], axis=1, keepdims=True)  # in reach
    ik = two_bone_ik(pos[:, hip], pos[:, knee], pos[:, ankle], grot[:, hip], grot[:, knee], target)
    new = rot.copy()
    new[:, hip] = qmul(qinv(grot[:, sk.parents[hip]]), ik.hip_rotation)
    new[:, knee] = qmul(qinv(ik.hip_rotation), ik.knee_rotation)
    new[:, ankle] = qmul(qinv(ik.knee_rotation), grot[:, ankle])
    pos2, grot2 = fk(new, np.zeros((T, 3)), sk.offsets, sk.parents, return_rotations=True)
    assert np.abs(pos2[:, ankle] - target).max() < 1e-6
    assert qangle(grot2[:, ankle], grot[:, ankle]).max() < 1e-9
    assert np.allclose(np.linalg.norm(pos2[:, knee] - pos2[:, hip], axis=1), np.linalg.norm(sk.offsets[knee]))
    others = [j for j in range(sk.n_joints) if j not in (hip, knee, ankle)]
    assert np.array_equal(new[:, others], rot[:, others])


# ---------------------------------------------------------------- the displacement of a contact


def sliding_foot(T=100, speed=0.2):
    """One foot of two joints (ankle 8 cm up, toe 2 cm up) planted on frames 20-59, sliding
    along x by ``speed`` cm per frame there; swinging (fast) otherwise."""
    p = np.zeros((T, 1, 2, 3))
    x = np.where(np.arange(T) < 20, 5.0 * (np.arange(T) - 20), 0.0)
    x = np.where((np.arange(T) >= 20) & (np.arange(T) < 60), speed * (np.arange(T) - 20), x)
    x = np.where(np.arange(T) >= 60, speed * 39 + 5.0 * (np.arange(T) - 59), x)
    p[:, 0, 0, 0], p[:, 0, 1, 0] = x, x + 15
    p[:, 0, 0, 1], p[:, 0, 1, 1] = 8.0, 2.0
    contacts = np.zeros((T, 1), dtype=bool)
    contacts[20:60] = True
    return p, contacts, np.array([[8.0, 2.0]])


@pytest.mark.parametrize("anchor", ["median", "start"])
def test_contact_offsets_hold_the_foot_and_blend_in_and_out(anchor):
    p, contacts, planted = sliding_foot()
    off = contact_offsets(p, contacts, planted, blend_frames=8, anchor=anchor)
    moved = p + off[:, :, None]
    assert foot_skating(moved, contacts, 100.0, planted) < 1e-9  # held
    assert foot_skating(p, contacts, 100.0, planted) == pytest.approx(20.0)
    assert np.all(off[..., 1] == 0)  # horizontal only: the height is kept
    expected = 0.2 * np.median(np.arange(40)) if anchor == "median" else 0.0
    assert off[20, 0, 0] == pytest.approx(expected)
    assert np.all(off[:12] == 0) and np.all(off[68:] == 0)  # nothing beyond the blends
    # no jump: per frame at most the slide's own step (0.2) or the blend's, whose steepest
    # step is 1.5 / (blend_frames + 1) of the displacement it blends (Eq. 15's cubic)
    blend_step = 1.5 / 9 * max(abs(off[20, 0, 0]), abs(off[59, 0, 0]))
    assert np.abs(np.diff(off[10:70, 0, 0])).max() <= max(0.2, blend_step) + 1e-9
    with pytest.raises(ValueError, match="anchor"):
        contact_offsets(p, contacts, planted, 8, anchor="mean")


def test_contact_offsets_follow_the_rolling_contact_point():
    """A foot that rolls over its toe (the ankle rises and moves on, the toe stays) needs no
    correction; the same roll with the toe sliding is held at the toe."""
    T = 40
    p = np.zeros((T, 1, 2, 3))
    p[:, 0, 1] = [15.0, 2.0, 0.0]  # toe planted
    t = np.arange(T)
    p[:, 0, 0, 0] = np.where(t < 20, 0.0, 0.3 * (t - 20))  # heel-off: the ankle moves and rises
    p[:, 0, 0, 1] = np.where(t < 20, 8.0, 8.0 + 0.4 * (t - 20))
    contacts = np.ones((T, 1), dtype=bool)
    planted = np.array([[8.0, 2.0]])
    assert np.abs(contact_offsets(p, contacts, planted, 5)).max() < 1e-12
    p[20:, 0, :, 2] += 0.1 * (t[20:, None] - 20)  # now the toe also slides sideways while rolling
    off = contact_offsets(p, contacts, planted, 5, anchor="start")
    assert foot_skating(p + off[:, :, None], contacts, 100.0, planted) < 1e-9


# ---------------------------------------------------------------- the cleanup on walks


@pytest.fixture(scope="module")
def generator_walk():
    from motionvar.synth import generate_walk, make_subjects, sample_walk_params

    s = make_subjects(1, seed=7)[0]
    m, truth = generate_walk(s, sample_walk_params(s, np.random.default_rng(1), "neutral", n_steps=6))
    return m, truth


def _solver(m):
    from motionvar.ma2010.examples import root_solver

    return root_solver(m.skeleton, JM)


def test_root_solver_defaults_to_the_papers_cleanup_and_checks_the_name(generator_walk):
    m, _ = generator_walk
    solver = _solver(m)
    assert solver.cleanup == "root" and CLEANUPS == ("root", "root+feet")
    with pytest.raises(ValueError, match="cleanup must be one of"):
        dataclasses.replace(solver, cleanup="feet")
    with pytest.raises(ValueError, match="foot_blend_s"):
        dataclasses.replace(solver, foot_blend_s=-1.0)
    paper = solver.motion(m.rotations, m.fps)
    assert np.array_equal(
        paper.root_pos,
        reconstruct_root(
            m.rotations,
            m.skeleton,
            solver.feet,
            solver.planted,
            min_support_frames=int(round(solver.min_support_s * m.fps)),
        ),
    )
    assert np.array_equal(paper.rotations, m.rotations)


def test_root_plus_feet_keeps_the_generators_walks_and_their_strides(generator_walk):
    """Ground truth: the generator's planted feet never slide; after "root+feet" the walk
    keeps its root, its strides (within 0.25 %) and its poses up to the IK's few tenths
    of a degree, and does not slide either."""
    from motionvar.ma2010.generate import walk_measures

    m, truth = generator_walk
    solver = _solver(m)
    paper = solver.motion(m.rotations, m.fps)
    feet = dataclasses.replace(solver, cleanup="root+feet").motion(m.rotations, m.fps)
    assert np.array_equal(feet.root_pos, paper.root_pos)
    a, b = walk_measures(paper, solver), walk_measures(feet, solver)
    assert b["foot_skating_cm_s"] < 0.05 and b["foot_skating_cm_s"] <= a["foot_skating_cm_s"] + 1e-9
    for side in ("left", "right"):
        assert b[f"{side}_support_stride_cm"] == pytest.approx(truth["stride_length_cm"], rel=2.5e-3)
    legs = leg_chains(m.skeleton, solver.feet)
    others = np.setdiff1d(np.arange(m.skeleton.n_joints), legs.reshape(-1))
    assert np.array_equal(feet.rotations[:, others], m.rotations[:, others])  # only the legs are touched
    assert np.degrees(qangle(feet.rotations, m.rotations)).max() < 5.0


def test_root_plus_feet_pins_the_other_foot_of_a_sliding_walk(generator_walk):
    """A walk whose right leg is swung back and forth about the hip by a few degrees (the
    kind of pose error that makes the paper's cleanup slide the foot the root does not
    hold): "root" leaves the right foot sliding during its contacts, "root+feet" holds it,
    without straightening any knee beyond what it was and without a jump in any joint."""
    from motionvar.ma2010.generate import walk_measures

    m, _ = generator_walk
    solver = _solver(m)
    rot = m.rotations.copy()
    hip = JM.indices(m.skeleton, ["right_hip"])[0]
    wobble = np.radians(3.0) * np.sin(2 * np.pi * 2.7 * np.arange(m.n_frames) / m.fps)
    rot[:, hip] = qmul(
        np.stack([np.cos(wobble / 2), np.zeros_like(wobble), np.zeros_like(wobble), np.sin(wobble / 2)], axis=1),
        rot[:, hip],
    )
    paper = solver.motion(rot, m.fps)
    fixed = dataclasses.replace(solver, cleanup="root+feet").motion(rot, m.fps)
    before, after = walk_measures(paper, solver), walk_measures(fixed, solver)
    assert before["foot_skating_cm_s"] > 1.0
    assert after["foot_skating_cm_s"] < 0.1
    legs = leg_chains(m.skeleton, solver.feet)
    pa, pb = paper.positions(), fixed.positions()
    for h, k, a in legs:

        def straightness(p):
            return np.linalg.norm(p[:, a] - p[:, h], axis=1) / (
                np.linalg.norm(p[:, k] - p[:, h], axis=1) + np.linalg.norm(p[:, a] - p[:, k], axis=1)
            )

        assert straightness(pb).max() <= max(straightness(pa).max(), 1.0 - 1e-9) + 1e-9
    step = np.linalg.norm(np.diff(pb, axis=0), axis=-1).max()
    assert step < 1.5 * np.linalg.norm(np.diff(pa, axis=0), axis=-1).max()  # no pop


def test_pin_feet_needs_a_leg_chain():
    sk = cmu_skeleton()
    feet = np.array([JM.indices(sk, ["left_ankle", "left_toe"]), JM.indices(sk, ["right_ankle", "right_toe"])])
    legs = leg_chains(sk, feet)
    assert [sk.names[j] for j in legs[0]] == ["LeftUpLeg", "LeftLeg", "LeftFoot"]
    with pytest.raises(ValueError, match="need a knee"):
        leg_chains(sk, np.array([[1, 2], [6, 7]]))  # LHipJoint's parent is the root: no hip above a knee
    T = 10
    rot = np.tile([1.0, 0, 0, 0], (T, sk.n_joints, 1))
    out = pin_feet(rot, np.zeros((T, 3)), sk, feet, np.zeros((2, 2)), np.zeros((T, 2), dtype=bool), 3)
    assert np.array_equal(out, rot)  # no contact, nothing to hold
