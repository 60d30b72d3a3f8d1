"""Preprocessing (motionvar.prep): contact intervals and their text format, the options, foot contacts and the segmentation into primitives."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from prep_toy import FPS, JM, WALK_STEPS, renamed_rig, standing, stepping, turned

from motionvar.core import JointMap
from motionvar.core import quaternions as Q
from motionvar.prep import (
    FootContacts,
    PrepOptions,
    Segment,
    clean_mask,
    detect_foot_contacts,
    format_intervals,
    format_segments,
    intervals_to_mask,
    mask_to_intervals,
    parse_intervals,
    parse_segments,
    segment_motion,
)
from motionvar.prep.segmentation import reach_boundary, sidestep_segments, step_segments, trailing_foot


def test_mask_interval_round_trip_and_cleaning():
    mask = np.zeros(40, bool)
    mask[[*range(0, 5), *range(8, 20), 25, *range(30, 40)]] = True
    iv = mask_to_intervals(mask)
    assert iv.tolist() == [[0, 5], [8, 20], [25, 26], [30, 40]]
    assert np.array_equal(intervals_to_mask(iv, 40), mask)
    # a 2-frame gap is filled, the isolated 1-frame run dropped, edge runs kept
    cleaned = clean_mask(mask, min_run=3, min_gap=4)
    assert mask_to_intervals(cleaned).tolist() == [[0, 20], [30, 40]]
    short_edge = np.zeros(10, bool)
    short_edge[-2:] = True
    assert clean_mask(short_edge, min_run=5, min_gap=0).tolist() == short_edge.tolist()
    assert mask_to_intervals(np.zeros(0, bool)).shape == (0, 2)


def test_interval_text_formats():
    assert parse_intervals("0:10;12:40").tolist() == [[0, 10], [12, 40]]
    assert parse_intervals("").shape == (0, 2) and parse_intervals(float("nan")).shape == (0, 2)
    segs = parse_segments("walk_start:0:50;walk_leftStance:50:110")
    assert segs == [Segment("walk_start", 0, 50), Segment("walk_leftStance", 50, 110)]
    assert format_segments(segs) == "walk_start:0:50;walk_leftStance:50:110"
    assert format_intervals(np.array([[0, 10], [12, 40]])) == "0:10;12:40"
    with pytest.raises(ValueError, match="left_contacts.*'3-9'"):
        parse_intervals("0:2;3-9", what="left_contacts")
    with pytest.raises(ValueError, match="start < stop"):
        parse_intervals("9:3")
    with pytest.raises(ValueError, match="segments of clip c7.*'walk:1'"):
        parse_segments("walk:1", what="segments of clip c7")


def test_options_validate_and_name_the_bad_option():
    assert PrepOptions.from_dict({"heading": "movement"}).heading == "movement"
    assert PrepOptions.from_dict(None) == PrepOptions()
    with pytest.raises(ValueError, match="unknown options \\['contact_speed'\\]"):
        PrepOptions.from_dict({"contact_speed": 3})
    with pytest.raises(ValueError, match="contact_velocity_cm_s"):
        PrepOptions(contact_velocity_cm_s=0)
    with pytest.raises(ValueError, match="heading"):
        PrepOptions(heading="north")
    with pytest.raises(ValueError, match="heading_frames"):
        PrepOptions(heading_frames=0)
    with pytest.raises(ValueError, match="floor_percentile"):
        PrepOptions(floor_percentile=80)
    with pytest.raises(ValueError, match="min_gap_s"):
        PrepOptions(min_gap_s=-1)
    with pytest.raises(ValueError, match="min_primitive_s"):
        PrepOptions(min_primitive_s=-0.1)


def test_config_schema_defaults_match_prep_options():
    import yaml

    schema = yaml.safe_load((Path(__file__).parents[2] / "config" / "schema.yaml").read_text())
    props = schema["properties"]["prep"]["properties"]
    defaults = PrepOptions().to_dict()
    assert set(props) == set(defaults)
    assert {k: v["default"] for k, v in props.items()} == defaults


def test_planted_and_lifted_feet():
    m = stepping([("left", 0.5, 1.0)], duration=1.5)
    c = detect_foot_contacts(m, JM)
    assert c.right.all(), "the right foot never moves"
    iv = c.left_intervals
    assert len(iv) == 2 and iv[0, 0] == 0 and iv[1, 1] == m.n_frames
    lift, land = iv[0, 1] / FPS, iv[1, 0] / FPS
    assert 0.5 < lift < 0.55 and 0.95 < land <= 1.0, (lift, land)  # the bump lands gently at 1.0 s
    assert c.onsets("left").tolist() == [iv[1, 0]] and c.onsets("right").size == 0


def test_rigid_translation_breaks_contact_above_the_speed_threshold():
    slow, fast = standing(121), standing(121)
    slow.root_pos[:, 0] += np.arange(121) * 10.0 / FPS  # 10 cm/s: still planted
    fast.root_pos[:, 0] += np.arange(121) * 100.0 / FPS  # 1 m/s: sliding, not planted
    assert detect_foot_contacts(slow, JM).left.all()
    c = detect_foot_contacts(fast, JM)
    assert not c.left.any() and not c.right.any()
    lifted = standing(121)
    lifted.root_pos[:, 1] += 20.0  # a still body 20 cm up in one half of the clip
    lifted.root_pos[60:, 1] -= 20.0
    iv = mask_to_intervals(detect_foot_contacts(lifted, JM).left)  # a drop: speed spikes at frames 59-60
    assert iv.tolist() in ([[60, 121]], [[61, 121]])


def test_contacts_scale_with_fps_and_units():
    steps = [("left", 0.5, 1.0), ("right", 1.1, 1.6)]
    hi, lo = stepping(steps, 2.0, fps=120.0), stepping(steps, 2.0, fps=30.0)
    c_hi, c_lo = detect_foot_contacts(hi, JM), detect_foot_contacts(lo, JM)
    for side in ("left", "right"):
        t_hi = c_hi.intervals(side) / 120.0
        t_lo = c_lo.intervals(side) / 30.0
        assert t_hi.shape == t_lo.shape and np.abs(t_hi - t_lo).max() < 2.5 / 30.0
    metres = replace(hi, skeleton=hi.skeleton.scaled(0.01), root_pos=hi.root_pos * 0.01)
    c_m = detect_foot_contacts(metres, JM, PrepOptions(units_cm=100.0))
    assert np.array_equal(c_m.left, c_hi.left) and np.array_equal(c_m.right, c_hi.right)
    # without the unit, metres look like a frozen body: every frame planted
    assert detect_foot_contacts(metres, JM).left.all()


def test_contacts_on_a_renamed_rig_and_bad_input():
    m = stepping(WALK_STEPS, 2.5)
    m2, jm2 = renamed_rig(m)
    a, b = detect_foot_contacts(m, JM), detect_foot_contacts(m2, jm2)
    assert np.array_equal(a.left, b.left) and np.array_equal(a.right, b.right)
    with pytest.raises(
        ValueError, match="foot contacts: the joint map has no toe joints and the ankles .* have no End Site"
    ):
        detect_foot_contacts(m, JointMap(joints={k: v for k, v in JM.joints.items() if k != "left_toe"}))
    with pytest.raises(ValueError, match="1 frame"):
        detect_foot_contacts(m.slice(0, 1), JM)
    with pytest.raises(ValueError, match="side"):
        a.mask("middle")


def test_walk_segments_at_heel_strikes():
    m = stepping(WALK_STEPS, 2.5)
    segs = segment_motion(m, "walk", JM)
    names = [s.name for s in segs]
    assert names == ["walk_start", "walk_rightStance", "walk_leftStance", "walk_rightStance", "walk_end"]
    strikes = np.array([s.start for s in segs[1:]]) / FPS
    assert np.all(np.abs(strikes - np.array([0.6, 1.1, 1.6, 2.1])) <= 0.05), strikes
    assert segs[0].start == 0 and segs[-1].stop == m.n_frames
    assert all(a.stop == b.start for a, b in zip(segs[:-1], segs[1:]))
    # same clip on a renamed rig, same cuts
    m2, jm2 = renamed_rig(m)
    assert segment_motion(m2, "walk", jm2) == segs


def test_run_drops_partial_steps_and_idle_is_one_segment():
    m = stepping(WALK_STEPS, 2.5)
    segs = segment_motion(m, "run", JM)
    assert [s.name for s in segs] == ["run_rightStance", "run_leftStance", "run_rightStance"]
    assert segment_motion(m, "idle", JM) == [Segment("idle", 0, m.n_frames)]


def test_step_segments_from_contact_masks():
    T = 100
    left = intervals_to_mask(np.array([[0, 10], [40, 70]]), T)
    right = intervals_to_mask(np.array([[0, 30], [60, 100]]), T)
    c = FootContacts(left, right, FPS)
    segs = step_segments(c, T, "walk", start=True, end=True)
    assert segs == [Segment("walk_start", 0, 40), Segment("walk_leftStance", 40, 60), Segment("walk_end", 60, 100)]
    assert step_segments(c, T, "walk") == [Segment("walk_leftStance", 40, 60)]
    # a shuffle (two left onsets in a row) is no stance; the second left onset starts one
    shuffle = FootContacts(intervals_to_mask(np.array([[0, 10], [20, 30], [40, 70]]), T), right, FPS)
    assert step_segments(shuffle, T, "walk") == [Segment("walk_leftStance", 40, 60)]


def test_walk_cut_mid_gait_has_no_start_or_end():
    m = stepping(WALK_STEPS, 2.5)
    m.root_pos[:, 0] += np.arange(m.n_frames) * 0.01  # 1.2 cm/s drift: still standing
    assert [s.name for s in segment_motion(m, "walk", JM)][::4] == ["walk_start", "walk_end"]
    mid = m.slice(100, 230)  # starts and ends with a foot in the air
    assert segment_motion(mid, "walk", JM) == [Segment("walk_leftStance", 32, 92)]
    moving = m.copy()  # planted feet but a root gliding at 1 m/s: not a standing start
    moving.root_pos[:30, 0] -= np.linspace(30.0, 0.0, 30) * 100.0 / FPS
    assert segment_motion(moving, "walk", JM)[0].name != "walk_start"


def test_sidestep_cycles_follow_the_trailing_foot():
    T = 200
    left = intervals_to_mask(np.array([[0, 20], [40, 110], [130, 200]]), T)
    right = intervals_to_mask(np.array([[0, 60], [80, 160], [180, 200]]), T)
    c = FootContacts(left, right, FPS)
    assert sidestep_segments(c, "right") == [Segment("sidestep", 80, 180)]
    assert sidestep_segments(c, "left") == [Segment("sidestep", 40, 130)]
    # a body facing +z has its left at +x: drifting to +x means the right foot trails
    m = standing(61)
    m.root_pos[:, 0] += np.linspace(0.0, 40.0, 61)
    assert trailing_foot(m, JM, m.positions()) == "right"
    m.root_pos[:, 0] -= np.linspace(0.0, 80.0, 61)
    assert trailing_foot(m, JM, m.positions()) == "left"
    # the same drift seen from a body turned by 90 degrees (its left is then -z)
    t = turned(m, np.pi / 2, (0.0, 0.0))
    assert trailing_foot(t, JM, t.positions()) == "left"


def test_reach_boundary_is_the_hand_stop():
    fps = FPS
    t = np.arange(int(2.4 * fps)) / fps
    m = standing(len(t))
    # raise both arms forward (shoulder rotation), hold at the target, lower them again
    up = np.clip((t - 0.3) / 0.8, 0, 1)
    down = np.clip((t - 1.4) / 0.8, 0, 1)
    mj = lambda u: 10 * u**3 - 15 * u**4 + 6 * u**5  # noqa: E731  minimum jerk
    angle = np.radians(70.0) * (mj(up) - mj(down))
    for side in ("left", "right"):
        j = JM.index(m.skeleton, f"{side}_shoulder")
        m.rotations[:, j] = Q.quat_about_axis([0.0, 1.0 if side == "left" else -1.0, 0.0], angle)
    segs = segment_motion(m, "pick", JM)
    assert [s.name for s in segs] == ["pick_reach", "pick_retrieve"]
    stop = segs[0].stop / fps
    assert 1.05 <= stop <= 1.15, stop  # the hands stop at 1.1 s and rest until 1.4 s
    assert segs[1] == Segment("pick_retrieve", segs[0].stop, m.n_frames)
    # a single speed valley between two peaks
    v = np.concatenate([np.sin(np.linspace(0, np.pi, 50)), np.sin(np.linspace(0, np.pi, 70))])
    o = PrepOptions()
    assert abs(reach_boundary(v, o.hand_stop_fraction, o.hand_rest_fraction) - 50) <= 1


def test_segmentation_errors():
    m = stepping(WALK_STEPS, 2.5)
    with pytest.raises(ValueError, match="unknown behaviour 'dance'"):
        segment_motion(m, "dance", JM)
    with pytest.raises(ValueError, match="1 frame"):
        segment_motion(m.slice(0, 1), "walk", JM)
