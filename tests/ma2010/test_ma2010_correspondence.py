"""Ma 2010 key frames (Eq. 1-4), correspondence (Eq. 5-6, time warping), the latent variation (Eq. 7-9) and the parameter propagation network (Eq. 10)."""

import numpy as np
import pytest
from ma2010_toy import JM, KEYFRAMES
from ma2010_toywalk import toy_walk

from motionvar.core import Motion
from motionvar.core.quaternions import qmul, quat_about_axis
from motionvar.ma2010 import PropagationNetwork, choose_structure, extract_cycles, root_solver
from motionvar.ma2010.correspondence import (
    decode_key_times,
    encode_key_times,
    key_times_increase,
    reference_key_positions,
    retime,
    space_warp,
    standard_skeleton,
    time_warp,
)
from motionvar.ma2010.evaluations.common import predicted_strides
from motionvar.ma2010.keyframes import find_extrema, keyframe_signal
from motionvar.ma2010.network import LOWER_FIRST, UPPER_FIRST
from motionvar.ma2010.settings import KEY_TIMINGS
from motionvar.ma2010.svi import ClipPrediction
from motionvar.ma2010.variation import determinative_joints, joint_importance, joint_variation


def test_keyframes_of_a_walk_are_the_double_supports_and_passings():
    m = toy_walk(n_cycles=4)
    ex = extract_cycles(m, JM, *KEYFRAMES)
    assert ex.signal.part == "lower" and ex.signal.d_lower > ex.signal.d_upper  # walking: legs move most
    assert np.all(np.diff(ex.kinds) != 0)  # alternating maxima and minima
    period = 1.1 * m.fps
    maxima = ex.frames[ex.kinds == 1]
    assert np.allclose(np.diff(maxima), period / 2, atol=2)  # two double supports per cycle
    la, ra = JM.index(m.skeleton, "left_ankle"), JM.index(m.skeleton, "right_ankle")
    pos = m.positions()
    spread = np.abs(pos[:, la, 2] - pos[:, ra, 2])
    assert np.all(spread[maxima] > 0.9 * spread.max())  # maxima: feet farthest apart
    assert len(ex.cycles) >= 2
    for c in ex.cycles:
        assert pos[c.start, la, 2] > pos[c.start, ra, 2]  # starts with the left foot ahead
        assert len(c.key_frames) == 5 and c.key_frames[0] == 0


def test_keyframe_signal_picks_the_upper_body_when_it_moves_more():
    rng = np.random.default_rng(1)
    pos = np.zeros((100, 4, 3))
    pos[:, 1] = [0, -1, 0]
    pos[:, 2] = [0, -1, 0] + 0.01 * rng.normal(size=(100, 3))  # lower body nearly still
    pos[:, 3] = np.stack([np.sin(np.arange(100) / 5), np.ones(100), np.zeros(100)], 1)  # waving arm
    sig = keyframe_signal(pos, np.array([1, 2]), np.array([3]))
    assert sig.part == "upper"
    frames, kinds = find_extrema(sig.signal, 0.2)
    assert len(frames) >= 4 and np.all(np.diff(kinds) != 0)


def test_keyframe_signal_rejects_bad_shapes():
    with pytest.raises(ValueError, match="positions must be"):
        keyframe_signal(np.zeros((2, 3, 3)), np.array([0]), np.array([1]))


def test_space_warp_turns_the_walk_onto_x_and_starts_at_origin():
    m = toy_walk(n_cycles=2)
    rot = quat_about_axis([0, 1, 0], 0.7)
    turned = Motion(
        m.skeleton,
        m.root_pos @ np.array([[np.cos(0.7), 0, -np.sin(0.7)], [0, 1, 0], [np.sin(0.7), 0, np.cos(0.7)]])
        + [50, 0, -20],
        m.rotations.copy(),
        m.fps,
    )
    turned.rotations[:, 0] = qmul(rot, turned.rotations[:, 0])
    w = space_warp(turned, JM)
    d = w.root_pos[-1] - w.root_pos[0]
    assert abs(d[2]) < 1e-6 * abs(d[0]) + 1e-9 and d[0] > 0
    assert np.allclose(w.root_pos[0, [0, 2]], 0)
    # body geometry is preserved: joint distances to the root are unchanged
    a, b = turned.positions(), w.positions()
    assert np.allclose(np.linalg.norm(a - a[:, :1], axis=-1), np.linalg.norm(b - b[:, :1], axis=-1))


def test_time_warp_maps_key_frames_to_reference_and_is_monotonic():
    m = toy_walk(n_cycles=1.2)
    m.root_pos[:, 0] = np.arange(m.n_frames)  # the warp's source frame, to check monotonicity
    keys = np.array([0, 30, 70, 100, 140])
    ref = reference_key_positions([keys], [m.n_frames], 60)
    w = time_warp(m.slice(0, 141), keys, ref)
    assert w.n_frames == 60
    src_root = m.root_pos[keys]
    assert np.allclose(w.root_pos[np.round(ref).astype(int)][[0, -1]], src_root[[0, -1]])
    assert np.all(np.diff(w.root_pos[:, 0]) > 0)  # monotonic warp
    assert np.allclose(w.root_pos[np.round(ref).astype(int), 0], keys, atol=3)
    rot, extra = retime(w.rotations, ref, keys / m.fps, m.fps, w.root_pos)
    assert len(rot) == 141 and np.allclose(extra[[0, -1]], src_root[[0, -1]], atol=1e-6)


def test_key_times_as_log_intervals_always_move_forward():
    """Sec. 4.2: the progression through a synthesized clip increases. Key times interpolated as
    log intervals decode to increasing times whatever the features; absolute ones need not."""
    kt = np.array([[0.0, 0.2, 0.45, 0.7, 1.0], [0.0, 0.3, 0.5, 0.8, 1.1]])
    for how in KEY_TIMINGS:
        assert np.allclose(decode_key_times(encode_key_times(kt, how), how), kt)
    far = 3.0 * encode_key_times(kt[:1], "log_intervals") - 5.0 * encode_key_times(kt[1:], "log_intervals")
    assert key_times_increase(decode_key_times(far, "log_intervals")).all()  # an extrapolation
    far = 3.0 * kt[:1] - 5.0 * kt[1:]
    assert not key_times_increase(decode_key_times(far, "absolute")).any()
    with pytest.raises(ValueError, match="key times must increase"):
        encode_key_times(kt[:, ::-1], "log_intervals")
    with pytest.raises(ValueError, match="key_timing must be one of"):
        encode_key_times(kt, "relative")


def test_a_synthesis_that_would_run_backwards_is_failed(toy_clips):
    """A prediction whose key times do not increase has no strides (a failed synthesis in Fig. 6
    and 7b), where the inverse warp alone would clamp it into a zero-length segment."""
    solver = root_solver(toy_clips.skeleton, JM)
    good = ClipPrediction(rotations=toy_clips.rotations[:2], key_times=toy_clips.key_times[:2].copy())
    backward = good.key_times.copy()
    backward[1, 2] = backward[1, 1] - 0.01
    pred = ClipPrediction(rotations=good.rotations, key_times=backward)
    strides = predicted_strides(pred, toy_clips.reference_keys, solver, toy_clips.fps)
    assert np.isfinite(strides[0]).all() and np.isnan(strides[1]).all()


def test_standard_skeleton_is_the_mean_and_checks_topology():
    a, b = toy_walk(height=0.9, n_cycles=0.2).skeleton, toy_walk(height=1.1, n_cycles=0.2).skeleton
    assert np.allclose(standard_skeleton([a, b]).offsets, (a.offsets + b.offsets) / 2)
    with pytest.raises(ValueError, match="no skeletons"):
        standard_skeleton([])


def test_joint_variation_sums_sinusoidal_distances():
    T, step = 11, 0.1
    rot = np.zeros((1, T, 3, 4))
    rot[..., 0] = 1
    rot[0, :, 1] = quat_about_axis([0, 0, 1], step * np.arange(T))
    delta = joint_variation(rot)
    assert delta[0, 0] == pytest.approx(0)
    assert delta[0, 1] == pytest.approx((T - 1) * np.sin(step / 2))  # ||.||_s = sin(||log||), log = half angle
    eta = joint_importance(np.array([[0.0, 1.0, 5.0], [0.0, 3.0, 5.0]]))
    assert determinative_joints(eta, {"a": np.array([0, 1]), "b": np.array([2])}) == {"a": 1, "b": 2}


def test_network_recovers_linear_gaussian_weights_and_samples():
    rng = np.random.default_rng(2)
    n = 4000
    c = rng.uniform(100, 150, size=(n, 2))
    legs = 0.02 * c[:, 0] - 0.01 * c[:, 1] + rng.normal(0.5, 0.1, n)
    upper = 0.5 * legs + rng.normal(0.1, 0.05, n)
    arms = -1.0 * upper + rng.normal(0.3, 0.2, n)
    xi = {"legs": legs, "upper_body": upper, "left_arm": arms, "right_arm": arms + rng.normal(0, 0.01, n)}
    net = PropagationNetwork(LOWER_FIRST).fit(c, xi)
    assert np.allclose(net.nodes_["legs"].weights, [0.02, -0.01], atol=2e-3)
    assert net.nodes_["legs"].mu == pytest.approx(0.5, abs=0.1)
    assert net.nodes_["upper_body"].sigma2 == pytest.approx(0.05**2, rel=0.1)
    s = net.sample(np.tile([120.0, 120.0], (3000, 1)), rng=rng)
    assert s["legs"].mean() == pytest.approx(0.02 * 120 - 0.01 * 120 + 0.5, abs=0.01)
    assert s["legs"].std() == pytest.approx(0.1, rel=0.1)
    fixed = net.sample([120.0, 120.0], rng=rng, fixed={"upper_body": 2.0})
    assert fixed["upper_body"][0] == 2.0
    mean = net.sample([120.0, 120.0], noise=False)
    assert mean["left_arm"][0] == pytest.approx(
        net.nodes_["left_arm"].weights[0] * mean["upper_body"][0] + net.nodes_["left_arm"].mu
    )
    with pytest.raises(ValueError, match="unknown groups"):
        net.sample([120.0, 120.0], rng=rng, fixed={"tail": 1.0})


def test_network_structures_follow_fig5():
    assert choose_structure(2.0, 1.0) == LOWER_FIRST and choose_structure(1.0, 2.0) == UPPER_FIRST
    with pytest.raises(ValueError, match="not defined before"):
        PropagationNetwork({"upper_body": ("legs",), "legs": ("c",)})
