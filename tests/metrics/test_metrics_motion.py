"""Motion metrics: jerk, foot skating, stride length, pose distance, discontinuities; the
motion measures checked on the generator's ground truth first (its walks cannot slide and
know their contacts)."""

import numpy as np
import pytest

from motionvar.metrics.discontinuities import count_discontinuities, peak_acceleration
from motionvar.metrics.foot_skating import contact_point_speeds, foot_skating, low_joint_speed
from motionvar.metrics.jerk import mean_jerk, root_free_jerk
from motionvar.metrics.pose_distance import nearest_pose_distance, pose_features, pose_set_distance
from motionvar.metrics.stride import footfall_strides, stride_lengths


def test_jerk_of_a_cubic_and_of_uniform_motion():
    t = np.arange(50) / 10.0
    pos = np.zeros((50, 2, 3))
    pos[:, 0, 0] = 2 * t**3  # jerk 12
    pos[:, 1, 1] = 5 * t  # jerk 0
    assert mean_jerk(pos, 10.0) == pytest.approx(6.0)
    with pytest.raises(ValueError, match="at least 4"):
        mean_jerk(pos[:3], 10.0)


def test_low_joint_speed_counts_only_low_frames():
    feet = np.zeros((10, 2, 3))
    feet[:, 0, 0] = np.arange(10)  # sliding on the ground: 1 cm per frame
    feet[:, 1, 1] = 20.0
    feet[:, 1, 0] = 5 * np.arange(10)  # moving fast, but in the air
    assert low_joint_speed(feet, 100.0, contact_height=2.0) == pytest.approx(100.0)
    feet[:, 0, 1] = 20.0
    assert low_joint_speed(feet, 100.0, contact_height=2.0) == 0.0


def test_foot_skating_takes_the_contact_point_during_contacts():
    """A planted foot that rolls over its toe (ankle rising and moving, toe still) does not
    skate; a foot sliding on its sole does; a foot out of contact does not count."""
    T = 20
    feet = np.zeros((T, 2, 2, 3))  # (T, feet, [ankle, toe], 3)
    feet[:, :, 1, 0] = 15.0  # toes 15 cm ahead of the ankles
    feet[:, :, 0, 1], feet[:, :, 1, 1] = 8.0, 2.0  # planted heights
    roll = np.clip(np.arange(T) - 10, 0, None).astype(float)
    feet[:, 0, 0, 1] += roll  # heel-off from frame 10: the ankle rises ...
    feet[:, 0, 0, 0] += roll  # ... and moves forward; the toe stays put
    contacts = np.ones((T, 2), dtype=bool)
    assert foot_skating(feet, contacts, 100.0) == pytest.approx(0.0, abs=1e-12)
    assert low_joint_speed(feet.reshape(T, 4, 3) - [0, 2.0, 0], 100.0, contact_height=8.0) > 0  # the old measure: > 0
    feet[:, 1, :, 2] += 0.5 * np.arange(T)[:, None]  # the right foot slides sideways at 50 cm/s
    speeds = contact_point_speeds(feet, contacts, 100.0)
    assert np.allclose(speeds[:, 0], 0) and np.allclose(speeds[:, 1], 50.0)
    assert foot_skating(feet, contacts, 100.0) == pytest.approx(25.0)
    contacts[:, 1] = False  # the sliding foot in the air: not skating
    assert foot_skating(feet, contacts, 100.0) == pytest.approx(0.0, abs=1e-12)
    assert foot_skating(feet, np.zeros((T, 2), dtype=bool), 100.0) == 0.0
    with pytest.raises(ValueError, match="contacts"):
        foot_skating(feet, contacts[:, :1], 100.0)


@pytest.fixture(scope="module")
def generator_walks():
    """Walks of the project's generator (neutral and childlike, two subjects) with their
    ground-truth contact masks (T, 2): its planted feet never slide."""
    from motionvar.io.intervals import parse_ranges
    from motionvar.synth import generate_walk, make_subjects, sample_walk_params

    rng = np.random.default_rng(1)
    out = []
    for s in make_subjects(2, seed=7):
        for style in ("neutral", "childlike"):
            m, truth = generate_walk(s, sample_walk_params(s, rng, style, n_steps=6))
            contacts = np.zeros((m.n_frames, 2), dtype=bool)
            for f, side in enumerate(("left", "right")):
                for a, b in parse_ranges(truth[f"{side}_contacts"]):
                    contacts[a:b, f] = True
            out.append((m, truth, contacts))
    return out


def _feet(m, positions):
    from motionvar.core import cmu_joint_map

    jm = cmu_joint_map()
    idx = np.array([jm.indices(m.skeleton, [f"{side}_ankle", f"{side}_toe"]) for side in ("left", "right")])
    return positions[:, idx], idx  # (T, 2, 2, 3)


def test_foot_skating_of_the_generators_walks_is_zero(generator_walks):
    """Ground truth first: the generator's walks cannot slide, so they score ~0, with the
    generator's contacts and with the project's contact detection; the earlier
    height-threshold measure flags them (heel and toe roll)."""
    from motionvar.core import cmu_joint_map
    from motionvar.prep.contacts import detect_foot_contacts

    for m, _, truth_contacts in generator_walks:
        pos = m.positions()
        feet, idx = _feet(m, pos)
        assert foot_skating(feet, truth_contacts, m.fps) < 0.05  # cm/s
        c = detect_foot_contacts(m, cmu_joint_map(), positions=pos)
        detected = np.stack([c.left, c.right], axis=1)
        assert (detected == truth_contacts).mean() > 0.98
        assert foot_skating(feet, detected, m.fps) < 1.0  # cm/s
        low = pos[:, idx.reshape(-1)].copy()
        low[..., 1] -= np.percentile(low[..., 1], 5, axis=0)
        assert low_joint_speed(low, m.fps, contact_height=2.0) > 5.0  # the earlier measure: not ground truth


def test_foot_skating_reads_a_deliberate_slide(generator_walks):
    """The same walks with the whole body drifting sideways at 20 cm/s (a treadmill): every
    planted foot slides at 20 cm/s, and that is what the measure reads."""
    from motionvar.core import Motion, cmu_joint_map
    from motionvar.prep.contacts import detect_foot_contacts

    for m, _, truth_contacts in generator_walks:
        root = m.root_pos.copy()
        root[:, 2] += 20.0 * np.arange(m.n_frames) / m.fps
        slid = Motion(skeleton=m.skeleton, root_pos=root, rotations=m.rotations, fps=m.fps)
        pos = slid.positions()
        feet, _ = _feet(slid, pos)
        assert foot_skating(feet, truth_contacts, m.fps) == pytest.approx(20.0, abs=0.05)
        c = detect_foot_contacts(slid, cmu_joint_map(), positions=pos)
        assert foot_skating(feet, np.stack([c.left, c.right], axis=1), m.fps) == pytest.approx(20.0, abs=1.0)


def test_whole_body_and_root_free_jerk_of_the_generators_walks(generator_walks):
    """Both jerks are finite and of the order of a smooth walk's (1e3-1e5 cm/s^3 at 120
    fps); root-free jerk leaves out the root's path, so it is the same wherever the root
    goes, and below the whole body's."""
    from motionvar.core import Motion

    for m, _, _ in generator_walks:
        pos = m.positions()
        whole, free = mean_jerk(pos, m.fps), root_free_jerk(pos, m.fps)
        assert np.isfinite(whole) and np.isfinite(free)
        assert 1e3 < free < whole < 1e5
        jolted = m.root_pos.copy()
        jolted[m.n_frames // 2 :, 0] += 0.7  # a 0.7 cm root jump
        pj = Motion(skeleton=m.skeleton, root_pos=jolted, rotations=m.rotations, fps=m.fps).positions()
        assert root_free_jerk(pj, m.fps) == pytest.approx(free) and mean_jerk(pj, m.fps) > whole
    with pytest.raises(ValueError, match="root"):
        root_free_jerk(pos, m.fps, root=99)


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


def test_footfall_strides_run_between_the_swing_foots_footfalls():
    """Two strides of 120 cm: the left foot lands at 0 then 120, the right at 60 then 180;
    boundaries between footfalls take each foot's nearest contact."""
    T = 100
    feet = np.zeros((T, 2, 3))
    contacts = np.zeros((T, 2), dtype=bool)
    t = np.arange(T)
    # left: contact 0-39 at x=0, swing 40-59, contact 60-99 at x=120; right: contact 0-19 at
    # -60, swing, contact 30-69 at 60, swing, contact 80-99 at 180
    feet[:, 0, 0] = np.interp(t, [39, 60], [0, 120])
    feet[:, 1, 0] = np.interp(t, [19, 30, 69, 80], [-60, 60, 60, 180])
    feet[:, :, 1] = 10.0  # in the air ...
    contacts[:40, 0] = contacts[60:, 0] = True
    contacts[:20, 1] = contacts[30:70, 1] = contacts[80:, 1] = True
    feet[contacts, 1] = 0.0  # ... except on the ground
    assert np.allclose(footfall_strides(feet, contacts, np.array([19, 45, 75])), [120, 120])
    assert np.allclose(footfall_strides(feet, contacts, np.array([25, 50])), [120])  # boundary between footfalls
    nothing = contacts.copy()
    nothing[:, 1] = False
    assert np.isnan(footfall_strides(feet, nothing, np.array([19, 45]))).all()
    with pytest.raises(ValueError, match="boundaries"):
        footfall_strides(feet, contacts, np.array([45, 19]))


def test_footfall_strides_read_a_footfall_off_the_joint_that_is_down():
    """A cycle cut at a key frame starts with the trailing (right) foot rolling off its toe: its
    heel is already 8 cm up and its ankle 5 cm past its footprint, the toe still on it. With the
    ankle and the toe of each foot the stride runs toe to toe there (120 cm); the ankle alone
    comes out short (115 cm); where both are down at both ends the ankle is used."""
    T = 60
    feet = np.zeros((T, 2, 2, 3))  # (frames, left/right, ankle/toe, xyz)
    feet[:, 0, 0] = [0.0, 3.0, 0.0]  # left ankle: planted 3 cm up
    feet[:, 0, 1] = [12.0, 0.0, 0.0]  # left toe
    t = np.arange(T)
    feet[:, 1, 0, 0] = np.interp(t, [0, 40], [-55.0, 60.0])  # right ankle: heel up, then lands at 40
    feet[:, 1, 0, 1] = np.interp(t, [0, 20, 40], [8.0, 20.0, 3.0])
    feet[:, 1, 1, 0] = np.interp(t, [0, 3, 40, 45], [-48.0, -48.0, 71.0, 72.0])  # right toe: leaves at 3
    feet[:, 1, 1, 1] = np.interp(t, [0, 3, 20, 40, 45], [0.0, 0.0, 20.0, 2.0, 0.0])
    contacts = np.zeros((T, 2), dtype=bool)
    contacts[:, 0] = True
    contacts[:3, 1] = contacts[40:, 1] = True
    planted = np.array([[3.0, 0.0], [3.0, 0.0]])
    both = footfall_strides(feet, contacts, np.array([0, 50]), planted=planted, joint_tolerance=1.0)
    assert both == pytest.approx([120.0])
    assert footfall_strides(feet[:, :, 0], contacts, np.array([0, 50]))[0] == pytest.approx(115.0)
    flat = feet.copy()
    flat[:, 1, 0, 0] = np.interp(t, [0, 3, 40], [-60.0, -60.0, 60.0])
    flat[:3, 1, 0, 1] = 3.0  # the right heel down at the start too: ankle to ankle
    assert footfall_strides(flat, contacts, np.array([0, 50]), planted=planted, joint_tolerance=1.0)[0] == (
        pytest.approx(120.0)
    )
    with pytest.raises(ValueError, match="contacts must be"):
        footfall_strides(feet, contacts[:, :1], np.array([0, 50]))
