"""Motion metrics: jerk, foot skating, stride length, pose distance, discontinuities."""

import numpy as np
import pytest

from motionvar.metrics.discontinuities import count_discontinuities, peak_acceleration
from motionvar.metrics.foot_skating import foot_skating
from motionvar.metrics.jerk import mean_jerk
from motionvar.metrics.pose_distance import nearest_pose_distance, pose_features, pose_set_distance
from motionvar.metrics.stride import stride_lengths


def test_jerk_of_a_cubic_and_of_uniform_motion():
    t = np.arange(50) / 10.0
    pos = np.zeros((50, 2, 3))
    pos[:, 0, 0] = 2 * t**3  # jerk 12
    pos[:, 1, 1] = 5 * t  # jerk 0
    assert mean_jerk(pos, 10.0) == pytest.approx(6.0)
    with pytest.raises(ValueError, match="at least 4"):
        mean_jerk(pos[:3], 10.0)


def test_foot_skating_counts_only_contact_frames():
    feet = np.zeros((10, 2, 3))
    feet[:, 0, 0] = np.arange(10)  # sliding on the ground: 1 cm per frame
    feet[:, 1, 1] = 20.0
    feet[:, 1, 0] = 5 * np.arange(10)  # moving fast, but in the air
    assert foot_skating(feet, 100.0, contact_height=2.0) == pytest.approx(100.0)
    feet[:, 0, 1] = 20.0
    assert foot_skating(feet, 100.0, contact_height=2.0) == 0.0


def test_stride_lengths_take_the_swing_foot():
    feet = np.zeros((5, 2, 3))
    feet[:, 0, 0] = [0, 0, 0, 60, 120]  # left swings in the second phase
    feet[:, 1, 0] = [-60, 0, 60, 60, 60]  # right swings in the first
    assert np.allclose(stride_lengths(feet, np.array([0, 2, 4])), [120, 120])
    with pytest.raises(ValueError, match="boundaries"):
        stride_lengths(feet, np.array([0, 0, 4]))


def test_pose_distances():
    rng = np.random.default_rng(0)
    pos = rng.normal(size=(20, 4, 3))
    feats = pose_features(pos)
    assert np.allclose(nearest_pose_distance(feats, feats), 0)
    moved = pose_features(pos + [10, 0, 0])  # translation does not change a pose
    assert np.allclose(nearest_pose_distance(moved, feats), 0)
    assert pose_set_distance(feats, feats[::-1]) == 0.0 and pose_set_distance(feats, feats + 1) > 0
    with pytest.raises(ValueError):
        nearest_pose_distance(feats, feats[:, :6])


def test_discontinuities_flag_a_jump():
    pos = np.zeros((30, 1, 3))
    pos[:, 0, 0] = np.arange(30)
    pos[15:, 0, 0] += 10
    assert peak_acceleration(pos, 1.0).max() == pytest.approx(10)
    assert count_discontinuities(pos, 1.0, threshold=5.0) == 2


def test_stride_footprints_do_not_depend_on_the_exact_boundary():
    t = np.arange(60)
    feet = np.zeros((60, 2, 3))
    feet[:, 0, 0] = np.clip((t - 20) * 6.0, 0, 120)  # left still until 20, swings to 120 by 40
    feet[:, 1, 0] = 60.0
    for b0, b1 in ((0, 59), (18, 45), (22, 38)):  # boundaries inside the swing: footprints still found
        assert stride_lengths(feet, np.array([b0, b1]), footprint_window=5)[0] == pytest.approx(120.0)
    assert stride_lengths(feet, np.array([22, 38]))[0] < 120.0  # without footprints: the swing is cut short
