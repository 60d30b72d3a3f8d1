"""motionvar.prep: foot contacts, segmentation, alignment, resampling, DTW, pipeline.

Unit tests run on small procedural clips built from core (a standing CMU body whose legs
lift by hip flexion bumps, rigid translations and turns); end-to-end tests run on the
synthetic generator when it is importable, and on real CMU BVH files when present.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from motionvar.core import JointMap, Motion, Skeleton, cmu_joint_map, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.io import load_dataset, save_dataset
from motionvar.prep import (
    DROPPED_COLUMNS,
    FootContacts,
    PrepOptions,
    Segment,
    align_motion,
    align_motions,
    apply_warp,
    clean_mask,
    detect_foot_contacts,
    drop_summary,
    dtw_warp,
    facing_directions,
    format_intervals,
    format_segments,
    intervals_to_mask,
    mask_to_intervals,
    median_length_index,
    parse_intervals,
    parse_segments,
    preprocess_dataset,
    resample_motion,
    sample_motion,
    segment_motion,
    warp_to_median,
)
from motionvar.prep.pipeline import too_short
from motionvar.prep.segmentation import hand_speed, reach_boundary, sidestep_segments, step_segments, trailing_foot
from motionvar.prep.timewarp import check_warp

FPS = 120.0
JM = cmu_joint_map()


# ----------------------------------------------------------------------------- fixtures


def standing(n_frames: int, fps: float = FPS, skeleton: Skeleton | None = None) -> Motion:
    """A CMU body standing still with zero rotations, its lowest foot joint on the floor."""
    sk = skeleton or cmu_skeleton()
    m = Motion(sk, np.zeros((n_frames, 3)), Q.qidentity((n_frames, sk.n_joints)), fps)
    pos = m.positions()[:1]
    feet = JM.indices(cmu_skeleton(), ["left_ankle", "left_toe", "right_ankle", "right_toe"])
    m.root_pos[:, 1] = -pos[0, feet, 1].min()
    return m


def bump(t: np.ndarray, a: float, b: float) -> np.ndarray:
    """sin^2 bump rising from 0 at time a to 1 and back to 0 at time b (seconds)."""
    u = np.clip((t - a) / (b - a), 0.0, 1.0)
    return np.sin(np.pi * u) ** 2


def stepping(steps: list[tuple[str, float, float]], duration: float, fps: float = FPS, deg: float = 35.0) -> Motion:
    """Stepping in place: each (side, a, b) lifts that leg by hip flexion from a to b seconds
    (the foot leaves the floor after a and lands again at b), the root stays put."""
    n = int(round(duration * fps)) + 1
    m = standing(n, fps)
    t = np.arange(n) / fps
    for side, a, b in steps:
        j = JM.index(m.skeleton, f"{side}_hip")
        angle = np.radians(deg) * bump(t, a, b)
        m.rotations[:, j] = Q.qmul(m.rotations[:, j], Q.quat_about_axis([1.0, 0.0, 0.0], -angle))
    return m


def turned(m: Motion, yaw: float, shift: tuple[float, float]) -> Motion:
    """``m`` rotated by ``yaw`` about +y and moved by ``shift`` (x, z) on the floor."""
    q = Q.quat_about_axis([0.0, 1.0, 0.0], yaw)
    rot = m.rotations.copy()
    rot[:, 0] = Q.qmul(q, rot[:, 0])
    root = Q.qrot(q, m.root_pos) + np.array([shift[0], 0.0, shift[1]])
    return replace(m, root_pos=root, rotations=rot)


def renamed_rig(m: Motion) -> tuple[Motion, JointMap]:
    """The same clip on a rig whose joints have other names, and that rig's joint map."""
    names = tuple(f"j{k}_{n.lower()}" for k, n in enumerate(m.skeleton.names))
    rename = dict(zip(m.skeleton.names, names))
    sk = replace(m.skeleton, names=names)
    jm = JointMap(
        joints={s: rename[n] for s, n in JM.joints.items()},
        groups={g: tuple(rename[n] for n in ns) for g, ns in JM.groups.items()},
    )
    return replace(m, skeleton=sk), jm


WALK_STEPS = [("right", 0.2, 0.6), ("left", 0.7, 1.1), ("right", 1.2, 1.6), ("left", 1.7, 2.1)]


# ----------------------------------------------------------------------------- intervals


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


# ----------------------------------------------------------------------------- options


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


# ----------------------------------------------------------------------------- contacts


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


# ----------------------------------------------------------------------------- segmentation


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


# ----------------------------------------------------------------------------- alignment


def _heading(m: Motion) -> np.ndarray:
    lh, rh = JM.indices(m.skeleton, ["left_hip", "right_hip"])
    f = facing_directions(m.positions()[0], lh, rh)
    return f / np.linalg.norm(f)


def test_alignment_starts_at_origin_heading_x():
    rng = np.random.default_rng(3)
    base = stepping(WALK_STEPS, 2.5)
    clips = [
        turned(base.slice(k * 10, 200 + k * 10), rng.uniform(-np.pi, np.pi), rng.uniform(-300, 300, 2))
        for k in range(5)
    ]
    assert not np.allclose(_heading(clips[0]), [1, 0, 0], atol=0.1)
    aligned = align_motions(clips, JM)
    for src, a in zip(clips, aligned):
        assert np.allclose(a.root_pos[0, [0, 2]], 0.0, atol=1e-9)
        assert np.isclose(a.root_pos[0, 1], src.root_pos[0, 1])
        assert np.allclose(_heading(a), [1.0, 0.0, 0.0], atol=1e-9)
        # a rigid motion on the floor: the shape of every pose is kept
        p, q = src.positions(), a.positions()
        assert np.allclose(np.linalg.norm(p - p[:, :1], axis=-1), np.linalg.norm(q - q[:, :1], axis=-1), atol=1e-9)
        assert np.allclose(p[..., 1], q[..., 1], atol=1e-9)
        assert np.array_equal(a.rotations[:, 1:], src.rotations[:, 1:])
    # batch and one-by-one agree, inputs untouched
    one = align_motion(clips[2], JM)
    assert np.allclose(one.root_pos, aligned[2].root_pos) and np.allclose(one.rotations, aligned[2].rotations)
    assert not np.allclose(clips[0].root_pos[0, [0, 2]], 0.0)


def test_alignment_movement_heading():
    m = standing(61)
    d = np.array([3.0, 0.0, -4.0]) / 5.0
    m.root_pos += np.linspace(0, 100, 61)[:, None] * d  # slides along d while facing +z
    m = turned(m, 0.4, (50.0, -20.0))
    a = align_motion(m, JM, PrepOptions(heading="movement"))
    travel = a.root_pos[-1] - a.root_pos[0]
    assert np.allclose(travel / np.linalg.norm(travel), [1.0, 0.0, 0.0], atol=1e-9)
    # a clip that does not travel falls back to the hips
    still = turned(standing(30), 1.0, (10.0, 10.0))
    assert np.allclose(_heading(align_motion(still, JM, PrepOptions(heading="movement"))), [1, 0, 0], atol=1e-9)


def test_alignment_and_resampling_keep_translation_channels():
    m = turned(stepping([("left", 0.2, 0.5)], 1.0), 0.7, (10.0, 20.0))
    tr = np.full(m.rotations.shape[:2] + (3,), np.nan)
    knee = JM.index(m.skeleton, "left_knee")
    tr[:, knee] = m.skeleton.offsets[knee] * 1.1  # a BVH joint with position channels
    mt = replace(m, translations=tr)
    a, at = align_motions([m, mt], JM, PrepOptions(heading_frames=3))
    assert np.allclose(a.root_pos, at.root_pos) and np.array_equal(at.translations, tr, equal_nan=True)
    r = resample_motion(mt, 50)
    assert r.translations.shape == (50, m.skeleton.n_joints, 3) and np.allclose(r.translations[:, knee], tr[0, knee])


def test_alignment_errors():
    m = standing(10)
    with pytest.raises(ValueError, match="no motions"):
        align_motions([], JM)
    with pytest.raises(ValueError, match="motion 1 has another skeleton topology"):
        align_motions([m, renamed_rig(m)[0]], JM)
    with pytest.raises(ValueError, match="lacks semantic joints \\['left_hip'\\]"):
        align_motions([m], JointMap(joints={k: v for k, v in JM.joints.items() if k != "left_hip"}))


# ----------------------------------------------------------------------------- resampling


def spinning(n: int, fps: float = FPS) -> Motion:
    """Root moving linearly, every joint turning at a constant rate about its own axis."""
    m = standing(n, fps)
    rng = np.random.default_rng(0)
    axes = rng.normal(size=(m.skeleton.n_joints, 3))
    rates = rng.uniform(-2.0, 2.0, m.skeleton.n_joints)
    t = np.arange(n) / fps
    for j in range(m.skeleton.n_joints):
        m.rotations[:, j] = Q.quat_about_axis(axes[j], rates[j] * t)
    m.root_pos += np.outer(t, [30.0, 5.0, -20.0])
    return m


def test_resample_is_exact_on_linear_root_and_uniform_rotation():
    m = spinning(101)
    r = resample_motion(m, 37)
    assert r.n_frames == 37 and np.isclose(r.duration, m.duration)
    ref = spinning(37, fps=36 / m.duration)
    assert np.allclose(r.root_pos, ref.root_pos, atol=1e-9)
    assert np.allclose(Q.qangle(r.rotations, ref.rotations), 0.0, atol=1e-6)
    kept = resample_motion(m, 37, keep_duration=False)
    assert kept.fps == m.fps and np.allclose(kept.root_pos, r.root_pos)
    same = resample_motion(m, m.n_frames)
    assert np.allclose(same.root_pos, m.root_pos) and np.allclose(Q.qangle(same.rotations, m.rotations), 0, atol=1e-6)


def test_resample_errors():
    m = spinning(20)
    for bad in (1, 2.5, 0):
        with pytest.raises(ValueError, match="n_frames"):
            resample_motion(m, bad)
    with pytest.raises(ValueError, match="1 frame"):
        resample_motion(m.slice(0, 1), 5)
    with pytest.raises(ValueError, match="within|lie in"):
        sample_motion(m, np.array([0.0, 19.5]))


# ----------------------------------------------------------------------------- DTW


def test_dtw_recovers_a_time_stretch():
    ref = stepping(WALK_STEPS, 2.5)
    stretch = 1.5
    src = sample_motion(ref, np.linspace(0, ref.n_frames - 1, int(round((ref.n_frames - 1) * stretch)) + 1))
    warp = dtw_warp(src, ref)
    assert warp.shape == (ref.n_frames,)
    assert np.all(np.diff(warp) >= 0) and warp[0] == 0 and warp[-1] == src.n_frames - 1
    truth = np.arange(ref.n_frames) * (src.n_frames - 1) / (ref.n_frames - 1)
    err = np.abs(warp - truth)
    moving = ~(detect_foot_contacts(ref, JM).left & detect_foot_contacts(ref, JM).right)
    assert np.median(err) < 1.0 and err[moving].max() < 3.0, (np.median(err), err[moving].max())
    back = apply_warp(src, warp)
    assert back.n_frames == ref.n_frames
    assert np.abs(back.positions() - ref.positions())[moving].max() < 1.0


def test_dtw_recovers_a_nonlinear_warp_on_features():
    t = np.linspace(0, 1, 150)
    ref = np.stack([np.sin(6 * t), np.cos(9 * t) * t], axis=1)
    g = lambda s: s**1.6  # noqa: E731  source time -> reference time
    s = np.linspace(0, 1, 200)
    src = np.stack([np.sin(6 * g(s)), np.cos(9 * g(s)) * g(s)], axis=1)
    warp = dtw_warp(src, ref)  # canonical frame -> source frame
    truth = (t ** (1 / 1.6)) * 199
    assert np.all(np.diff(warp) >= 0) and np.median(np.abs(warp - truth)) < 2.0
    # one-dimensional features work too, and a wide enough window gives the same path
    assert np.allclose(dtw_warp(src[:, 0], ref[:, 0], window=200), dtw_warp(src[:, 0], ref[:, 0]))


def test_warp_to_median_and_errors():
    base = stepping(WALK_STEPS, 2.5)
    clips = [resample_motion(base, n, keep_duration=False) for n in (240, 301, 280)]
    ref, warps = warp_to_median(clips)
    assert ref == 2 and median_length_index(clips) == 2
    assert all(len(w) == 280 and np.all(np.diff(w) >= 0) for w in warps)
    assert np.allclose(warps[2], np.arange(280))
    with pytest.raises(ValueError, match="120 features per frame, reference 2"):
        dtw_warp(np.zeros((10, 120)), np.zeros((12, 2)))
    with pytest.raises(ValueError, match="window must be an integer >= 4"):
        dtw_warp(np.zeros((10, 2)), np.zeros((13, 2)), window=2)
    with pytest.raises(ValueError, match="NaN"):
        dtw_warp(np.full((10, 2), np.nan), np.zeros((13, 2)))
    with pytest.raises(ValueError, match="T >= 2"):
        dtw_warp(np.zeros((1, 2)), np.zeros((13, 2)))
    with pytest.raises(ValueError, match="non-decreasing.*frame 2"):
        apply_warp(base, np.array([0.0, 3.0, 2.0]))
    with pytest.raises(ValueError, match="within the source frames"):
        check_warp(np.array([0.0, 1e6]), base.n_frames)
    with pytest.raises(ValueError, match="no motions"):
        median_length_index([])


# ----------------------------------------------------------------------------- pipeline


def small_dataset(tmp_path: Path, with_truth: bool = True) -> Path:
    walk = turned(stepping(WALK_STEPS, 2.5), 1.2, (100.0, -40.0))
    idle = turned(standing(90), -2.0, (-30.0, 60.0))
    motions = [walk, idle]
    meta = pd.DataFrame(
        {
            "clip_id": ["w1", "i1"],
            "subject": ["s1", "s1"],
            "behaviour": ["walk", "idle"],
            "style": ["neutral", "neutral"],
            "primitive": ["", ""],
        }
    )
    if with_truth:
        meta["segments"] = ["walk_start:0:70;walk_rightStance:70:130;walk_leftStance:130:301", "idle:0:90"]
    d = tmp_path / "data"
    save_dataset(d, motions, meta)
    return d


def test_preprocess_dataset_detected_and_ground_truth(tmp_path):
    ds = load_dataset(small_dataset(tmp_path))
    motions, meta, dropped = preprocess_dataset(ds, JM, PrepOptions())
    assert dropped.empty and list(dropped.columns) == list(DROPPED_COLUMNS)
    assert meta["clip_id"].tolist() == ["w1_00", "w1_01", "w1_02", "w1_03", "w1_04", "i1_00"]
    assert meta["primitive"].tolist()[:2] == ["walk_start", "walk_rightStance"]
    assert meta["source_clip"].tolist() == ["w1"] * 5 + ["i1"]
    assert (meta["n_frames"] == meta["stop_frame"] - meta["start_frame"]).all()
    assert [m.n_frames for m in motions] == meta["n_frames"].tolist()
    assert meta["subject"].eq("s1").all() and meta["style"].eq("neutral").all()
    for m in motions:
        assert np.allclose(m.root_pos[0, [0, 2]], 0.0, atol=1e-9)
        assert np.allclose(_heading(m), [1.0, 0.0, 0.0], atol=1e-6)
    gt_motions, gt, _ = preprocess_dataset(ds, JM, PrepOptions(use_ground_truth_segments=True))
    assert gt[["primitive", "start_frame", "stop_frame"]].values.tolist() == [
        ["walk_start", 0, 70],
        ["walk_rightStance", 70, 130],
        ["walk_leftStance", 130, 301],
        ["idle", 0, 90],
    ]
    assert gt_motions[1].n_frames == 60
    # round trip through a packed dataset
    save_dataset(tmp_path / "prep", gt_motions, gt)
    assert load_dataset(tmp_path / "prep").metadata["clip_id"].tolist() == gt["clip_id"].tolist()


def test_preprocess_dataset_errors(tmp_path):
    ds = load_dataset(small_dataset(tmp_path, with_truth=False))
    with pytest.raises(ValueError, match="lacks columns \\['segments'\\].*use_ground_truth_segments"):
        preprocess_dataset(ds, JM, PrepOptions(use_ground_truth_segments=True))
    bad = replace(ds, metadata=ds.metadata.assign(behaviour=["walk", "dance"]))
    with pytest.raises(ValueError, match="clip i1: .*unknown behaviour 'dance'"):
        preprocess_dataset(bad, JM)
    nobeh = replace(ds, metadata=ds.metadata.drop(columns=["behaviour"]))
    with pytest.raises(ValueError, match="lacks columns \\['behaviour'\\]"):
        preprocess_dataset(nobeh, JM)
    beyond = replace(ds, metadata=ds.metadata.assign(segments=["walk_start:0:999", "idle:0:90"]))
    with pytest.raises(ValueError, match="clip w1: segments .* beyond the clip's 301 frames"):
        preprocess_dataset(beyond, JM, PrepOptions(use_ground_truth_segments=True))
    garbled = replace(ds, metadata=ds.metadata.assign(segments=["walk_start:0", "idle:0:90"]))
    with pytest.raises(ValueError, match="segments of clip w1"):
        preprocess_dataset(garbled, JM, PrepOptions(use_ground_truth_segments=True))
    with pytest.raises(ValueError, match="joint map.*missing semantic joints \\['head'\\]"):
        preprocess_dataset(ds, JointMap(joints={k: v for k, v in JM.joints.items() if k != "head"}))
    # a "run" standing still has no step: dropped and listed (default), or an error naming it
    one_step = replace(ds, metadata=ds.metadata.assign(behaviour=["idle", "run"]))
    with pytest.raises(
        ValueError, match="1 of 2 clips of dataset d1 .*clip i1: no run primitive found.*skip_unsegmentable: true"
    ):
        preprocess_dataset(one_step, JM, PrepOptions(skip_unsegmentable=False), name="d1")
    _, meta, dropped = preprocess_dataset(one_step, JM)
    assert meta["clip_id"].tolist() == ["w1_00"]
    assert dropped[["clip_id", "behaviour", "primitive", "n_frames", "reason"]].values.tolist() == [
        ["i1", "run", "", 90, "no primitive found"]
    ]


def test_too_short_primitives_are_dropped_and_counted(tmp_path):
    ds = load_dataset(small_dataset(tmp_path))
    assert too_short([Segment("a", 0, 1), Segment("b", 0, 23), Segment("c", 0, 24)], FPS, 0.2).tolist() == [
        True,
        True,
        False,
    ]  # 24 frames at 120 fps are 0.2 s: kept
    assert too_short([Segment("a", 5, 6)], FPS, 0.0).tolist() == [True]  # one frame is never a primitive
    segs = ["walk_start:0:70;walk_rightStance:70:71;walk_leftStance:71:93;walk_end:93:301", "idle:0:20"]
    short = replace(ds, metadata=ds.metadata.assign(segments=segs))
    opt = PrepOptions(use_ground_truth_segments=True)
    result = preprocess_dataset(short, JM, opt, name="d1")
    assert result.metadata["clip_id"].tolist() == ["w1_00", "w1_01"]
    assert result.metadata["primitive"].tolist() == ["walk_start", "walk_end"]
    assert [m.n_frames for m in result.motions] == [70, 208]
    assert result.dropped[["clip_id", "primitive", "start_frame", "n_frames", "reason"]].values.tolist() == [
        ["w1", "walk_rightStance", 70, 1, "too short"],
        ["w1", "walk_leftStance", 71, 22, "too short"],
        ["i1", "idle", 0, 20, "too short"],
    ]
    assert np.allclose(result.dropped["duration_s"], [1 / 120, 22 / 120, 20 / 120])
    summary = drop_summary(result, len(short), "d1", 0.2)
    assert "dataset d1: 2 clips -> 2 primitives from 1 clips (walk_end 1, walk_start 1)" in summary
    assert "dropped 3 primitives shorter than 0.2 s (idle 1, walk_leftStance 1, walk_rightStance 1)" in summary
    assert "dropped 1 clips with no primitive left (0 with none found, 1 with all too short; idle 1)" in summary
    # the threshold is a config value: at 0 only the one-frame sliver goes
    kept = preprocess_dataset(short, JM, replace(opt, min_primitive_s=0.0))
    assert kept.metadata["primitive"].tolist() == ["walk_start", "walk_leftStance", "walk_end", "idle"]
    # a clip left empty stops the run when skip_unsegmentable is off, naming it
    with pytest.raises(
        ValueError, match="1 of 2 clips of dataset d1.*clip i1: all 1 idle primitives shorter than 0.2 s"
    ):
        preprocess_dataset(short, JM, replace(opt, skip_unsegmentable=False), name="d1")


def test_preprocess_script_lists_and_logs_what_it_dropped(tmp_path, capsys):
    from rule_scripts import FakeSnakemake, Named, run, script

    ds = load_dataset(small_dataset(tmp_path))
    segs = ["walk_start:0:70;walk_rightStance:70:71;walk_end:71:301", "idle:0:20"]
    save_dataset(tmp_path / "short", [ds.motion(0), ds.motion(1)], ds.metadata.assign(segments=segs))
    out = tmp_path / "results" / "prep"

    def fake(options):
        return FakeSnakemake(
            tmp_path,
            "preprocess",
            input=Named(clips=str(tmp_path / "short" / "clips.npz")),
            output=Named(clips=str(out / "clips.npz"), metadata=str(out / "metadata.csv")),
            params=Named(settings=options, joint_map=None),
            wildcards=Named(dataset="mine"),
        )

    run(fake({"use_ground_truth_segments": True}), script("preprocess").main)
    dropped = pd.read_csv(out / "dropped.csv")
    assert dropped[["clip_id", "primitive", "n_frames", "reason"]].values.tolist() == [
        ["w1", "walk_rightStance", 1, "too short"],
        ["i1", "idle", 20, "too short"],
    ]
    assert pd.read_csv(out / "metadata.csv")["clip_id"].tolist() == ["w1_00", "w1_01"]
    log = (tmp_path / "preprocess.log").read_text()
    assert "WARNING dataset mine: 2 clips -> 2 primitives from 1 clips" in log and "shorter than 0.2 s" in log
    # nothing left: one error line naming the dataset, no output
    for f in out.iterdir():
        f.unlink()
    with pytest.raises(SystemExit):
        run(fake({"use_ground_truth_segments": True, "min_primitive_s": 5.0}), script("preprocess").main)
    err = capsys.readouterr().err
    assert "ERROR rule preprocess: preprocess_dataset: no primitive left in dataset mine (2 clips)" in err
    assert not any(out.iterdir())


def test_nothing_left_names_the_dataset_and_the_commonest_reason(tmp_path):
    ds = load_dataset(small_dataset(tmp_path))
    slivers = replace(ds, metadata=ds.metadata.assign(segments=["walk_start:0:3;walk_end:3:5", "idle:0:2"]))
    with pytest.raises(
        ValueError,
        match="no primitive left in dataset d1 \\(2 clips\\); most common reason: in 2 "
        "clips every primitive was shorter than prep.min_primitive_s = 0.2 s",
    ):
        preprocess_dataset(slivers, JM, PrepOptions(use_ground_truth_segments=True), name="d1")
    still = [turned(standing(90), 0.3 * k, (10.0 * k, 0.0)) for k in range(3)]
    meta = pd.DataFrame({"clip_id": ["a", "b", "c"], "subject": "s", "style": "neutral", "behaviour": "run"})
    save_dataset(tmp_path / "still", still, meta)
    with pytest.raises(
        ValueError,
        match="no primitive left in dataset d2 \\(3 clips\\); most common reason: no "
        "primitive found in 3 clips \\(run: 3\\)",
    ):
        preprocess_dataset(load_dataset(tmp_path / "still"), JM, name="d2")


def test_errors_name_the_clip():
    m = stepping(WALK_STEPS, 2.5)
    one = m.slice(0, 1)
    with pytest.raises(ValueError, match="resample_motion: clip w7_03 has 1 frame\\(s\\); need at least 2"):
        resample_motion(one, 30, clip_id="w7_03")
    with pytest.raises(ValueError, match="dtw_warp: source clip w7_03 has 1 frame\\(s\\)"):
        dtw_warp(one, m, clip_id="w7_03")
    with pytest.raises(ValueError, match="dtw_warp: reference clip r1 has 1 frame"):
        dtw_warp(m, one, reference_id="r1")
    with pytest.raises(ValueError, match="source clip w7_03 features contain NaN"):
        dtw_warp(np.full((10, 2), np.nan), np.zeros((13, 2)), clip_id="w7_03")
    with pytest.raises(ValueError, match="warp_to_median: clips w7_03 \\(1 frame\\(s\\)\\) have fewer than 2"):
        warp_to_median([m, one, m], clip_ids=["a", "w7_03", "b"])
    with pytest.raises(ValueError, match="apply_warp: clip w7_03: warp must be non-decreasing"):
        apply_warp(m, np.array([0.0, 3.0, 2.0]), clip_id="w7_03")
    bad = replace(m, root_pos=np.where(np.arange(m.n_frames)[:, None] == 5, np.nan, m.root_pos))
    with pytest.raises(ValueError, match="sample_motion: clip w7_03 has NaN or inf"):
        resample_motion(bad, 30, clip_id="w7_03")
    with pytest.raises(ValueError, match="alignment: clip w7_03 has NaN or inf"):
        align_motions([m, bad], JM, clip_ids=["a", "w7_03"])
    with pytest.raises(ValueError, match="alignment: clip w7_03 has no frames"):
        align_motions([m, m.slice(0, 0)], JM, clip_ids=["a", "w7_03"])


# ----------------------------------------------------------------------------- synthetic data (end to end)

# The generators are written by others at the same time; these tests run once they import.
try:
    from motionvar.synth import locomotion, reach
    from motionvar.synth.gait_params import RunParams, SidestepParams, WalkParams
    from motionvar.synth.subjects import make_subjects
except ImportError:  # pragma: no cover - only while the generator is missing
    locomotion = None

needs_synth = pytest.mark.skipif(locomotion is None, reason="synthetic generator (motionvar.synth) not available")
SUBJECTS = make_subjects(3, seed=7) if locomotion is not None else []


def synthetic_clips():
    """(behaviour, Motion, truth) of walks (styles, turns, first feet, slow and fast), runs
    and side-steps of three subjects, from anywhere on the floor with any heading."""
    rng = np.random.default_rng(11)
    out = []
    for k, subject in enumerate(SUBJECTS):
        where = dict(start_xz=tuple(rng.uniform(-300, 300, 2)), heading_deg=float(rng.uniform(-180, 180)))
        walks = [
            WalkParams(style=("neutral", "old", "angry")[k], first_foot=("left", "right")[k % 2], **where),
            WalkParams(
                style="depressed",
                turn_deg=(-50.0, 40.0, 70.0)[k],
                speed_cm_s=90.0,
                stride_length_cm=110.0,
                stand_start_s=0.1,
                stand_end_s=0.1,
                **where,
            ),
        ]
        out += [("walk", *locomotion.generate_walk(subject, p)) for p in walks]
        out.append(("run", *locomotion.generate_run(subject, RunParams(first_foot=("right", "left")[k % 2], **where))))
        side = SidestepParams(direction=("left", "right")[k % 2], n_cycles=3 + k, **where)
        out.append(("sidestep", *locomotion.generate_sidestep(subject, side)))
    return out


@pytest.fixture(scope="module")
def synthetic():
    if locomotion is None:
        pytest.skip("synthetic generator (motionvar.synth) not available")
    return synthetic_clips()


@needs_synth
def test_synthetic_contacts_agree_with_the_generator(synthetic):
    for behaviour, m, truth in synthetic:
        c = detect_foot_contacts(m, JM)
        for side in ("left", "right"):
            gt = intervals_to_mask(parse_intervals(truth[f"{side}_contacts"]), m.n_frames)
            agreement = np.mean(c.mask(side) == gt)
            assert agreement > 0.95, (behaviour, side, agreement)


@needs_synth
def test_synthetic_segmentation_finds_every_step(synthetic):
    for behaviour, m, truth in synthetic:
        gt = parse_segments(truth["segments"])
        got = segment_motion(m, behaviour, JM)
        assert [s.name for s in got] == [s.name for s in gt], (behaviour, got, gt)
        err = np.abs(np.array([s[1:] for s in got]) - np.array([s[1:] for s in gt]))
        assert err.max() <= 3, (behaviour, got, gt)


@needs_synth
def test_synthetic_aligned_primitives_start_at_origin_heading_x(synthetic, tmp_path):
    motions = [m for _, m, _ in synthetic]
    meta = pd.DataFrame(
        {
            "clip_id": [f"c{k}" for k in range(len(motions))],
            "subject": "s",
            "style": "neutral",
            "behaviour": [b for b, _, _ in synthetic],
            "segments": [t["segments"] for _, _, t in synthetic],
        }
    )
    save_dataset(tmp_path, motions, meta)
    ds = load_dataset(tmp_path)
    for truth in (False, True):
        prims, pmeta, dropped = preprocess_dataset(ds, JM, PrepOptions(use_ground_truth_segments=truth))
        assert dropped.empty, dropped  # every synthetic primitive is longer than min_primitive_s
        assert len(prims) == sum(len(parse_segments(t["segments"])) for _, _, t in synthetic)
        for m in prims:
            assert np.allclose(m.root_pos[0, [0, 2]], 0.0, atol=1e-6)
            assert np.allclose(_heading(m), [1.0, 0.0, 0.0], atol=1e-6)
        walks = pmeta["primitive"].str.endswith("Stance") & pmeta["primitive"].str.startswith("walk")
        # a stance primitive of a straight walk travels forward, along +x
        fwd = [prims[i].root_pos[-1, 0] for i in np.flatnonzero(walks)]
        assert np.min(fwd) > 20.0


@needs_synth
def test_synthetic_reach_boundary_within_a_tenth_of_a_second():
    rng = np.random.default_rng(2)
    errors, any_rise = [], []
    for k in range(24):
        subject = SUBJECTS[k % 3]
        kind = ("pick", "place")[k % 2]
        gen = reach.generate_pick if kind == "pick" else reach.generate_place
        # half the reaches with a corrective sub-movement: its rise is part of the reach
        params = reach.ReachParams(region=("forward", "high")[k // 2 % 2], correction=k >= 12)
        m, truth = gen(subject, params, rng)
        gt = parse_segments(truth["segments"])
        got = segment_motion(m, kind, JM)
        assert [s.name for s in got] == [s.name for s in gt]
        errors.append(got[0].stop - gt[0].stop)
        o = PrepOptions()
        speed = hand_speed(m, JM, m.positions(), o)
        any_rise.append(reach_boundary(speed, o.hand_stop_fraction, rest_fraction=1.0) - gt[0].stop)
    errors = np.abs(errors)
    # the hands approach the target with a minimum-jerk profile: "stopped" (2 % of the
    # peak speed) comes a few frames before the generator's first frame at the target
    assert errors.max() <= 12 and errors.mean() <= 6, errors
    # negative control: ending the reach at any rise of the speed stops corrected reaches
    # at the dip before their secondary sub-movement
    assert np.min(any_rise[12:]) < -12, any_rise


# ----------------------------------------------------------------------------- real CMU data

CMU = Path("/work/shared/data/bvh/cmu")


@pytest.mark.skipif(not (CMU / "02_01.bvh").is_file(), reason="CMU BVH files not present")
def test_real_cmu_walk_has_steps():
    from motionvar.core import CMU_UNIT_CM
    from motionvar.io import read_bvh

    m = read_bvh(CMU / "02_01.bvh", scale=CMU_UNIT_CM)
    m = m.slice(1, m.n_frames)  # frame 0 is the cgspeed T-pose
    segs = segment_motion(m, "walk", JM)
    stances = [s for s in segs if s.name.endswith("Stance")]
    assert len(stances) >= 2
