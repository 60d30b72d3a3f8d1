"""The realism statistics (motionvar.metrics.realism, motionvar.realism): each measure on
inputs whose answer is known, the generator's ground truth, and the bands' bookkeeping."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from motionvar.core import cmu_joint_map
from motionvar.core.quaternions import quat_about_axis
from motionvar.metrics import realism as rm
from motionvar.realism import BANDS, Band, judge
from motionvar.realism.bands import CMU_CAPTURED_CHANNELS

FPS = 100.0


def _events(sides, footprints, starts, stance=50):
    starts = np.asarray(starts)
    return rm.WalkEvents(
        side=np.asarray(sides), start=starts, stop=starts + stance, footprint=np.asarray(footprints, float), fps=FPS
    )


def test_walk_cycles_steps_strides_and_asymmetry():
    # left steps 72 cm, right steps 68 cm along +x; steps every 0.55 s
    x = np.cumsum([0, 72, 68, 72, 68, 72, 68, 72])
    sides = [0, 1, 0, 1, 0, 1, 0, 1]  # footfall i+1 ends step i: steps end on 1, 0, 1, ...
    ev = _events(sides, np.stack([x, np.zeros_like(x)], axis=1), 55 * np.arange(8))
    cyc = rm.walk_cycles(ev)
    np.testing.assert_allclose(cyc.step_length, np.diff(x))
    np.testing.assert_allclose(cyc.stride_length, 140.0)
    np.testing.assert_allclose(cyc.step_time, 0.55)
    np.testing.assert_allclose(cyc.stride_time, 1.1)
    np.testing.assert_allclose(cyc.stance_fraction, 0.5 / 1.1)
    assert rm.step_asymmetry(cyc) == pytest.approx(4.0)
    assert rm.coefficient_of_variation(cyc.stride_length) == pytest.approx(0.0)


def test_walk_cycles_skip_a_missed_contact():
    # two left footfalls in a row (a right contact missed): no step and no stride across it
    ev = _events([0, 1, 0, 0, 1, 0], [[0, 0], [70, 0], [140, 0], [280, 0], [350, 0], [420, 0]], 55 * np.arange(6))
    cyc = rm.walk_cycles(ev)
    assert len(cyc.step_length) == 4
    np.testing.assert_allclose(cyc.stride_length, [140.0, 140.0])


def test_coefficient_of_variation():
    assert rm.coefficient_of_variation([100.0, 110.0, 90.0]) == pytest.approx(0.1)
    assert np.isnan(rm.coefficient_of_variation([100.0, 110.0]))


def test_toe_clearance_at_mid_swing():
    t = np.arange(100)
    contact = (t < 30) | (t >= 70)
    height = np.where(contact, 2.0, 2.0 + 1.5 + 5.0 * np.sin(np.pi * (t - 30) / 40) ** 2)
    height[50] = 2.0 + 1.2  # the minimum, at mid-swing
    np.testing.assert_allclose(rm.toe_clearance(height, contact), [1.2])


def test_high_frequency_rms_sees_noise_not_motion():
    t = np.arange(0, 10, 1 / FPS)
    slow = np.zeros((len(t), 2, 3))
    slow[:, 1, 0] = 20.0 * np.sin(2 * np.pi * 1.0 * t)  # a 1 Hz swing of 20 cm
    noisy = slow.copy()
    noisy[:, 1, 1] = 0.1 * np.sin(2 * np.pi * 11.0 * t)  # 1 mm at 11 Hz
    assert rm.high_frequency_rms(slow, FPS, (8.0, 14.0)) < 1e-3
    # one of six coordinates carries amplitude 0.1: RMS 0.1 / sqrt(2) / sqrt(6)
    assert rm.high_frequency_rms(noisy, FPS, (8.0, 14.0)) == pytest.approx(0.1 / np.sqrt(12), rel=0.05)


def test_rotation_channel_sd():
    T = 2000
    angle = np.radians(np.random.default_rng(0).normal(0.0, 3.0, T))
    q = np.zeros((T, 2, 4))
    q[:, 0] = quat_about_axis([1.0, 0.0, 0.0], angle)
    q[:, 1] = [1.0, 0.0, 0.0, 0.0]
    sd = rm.rotation_channel_sd(q)
    assert sd[0, 0] == pytest.approx(3.0, rel=0.05)
    assert sd[0, 1:].max() < 1e-6 and sd[1].max() < 1e-6
    np.testing.assert_array_equal(rm.channel_classes(sd[0], 1e-3, 0.5), ["moving", "static", "static"])


def test_rotation_channel_sd_agrees_with_scipy():
    """The channels are the rotation vectors of each frame relative to the joint's mean rotation:
    scipy's Rotation composition and ``as_rotvec`` give the same SDs (small angles and a joint
    that never moves included)."""
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(1)
    q = rng.normal(size=(500, 5, 4)) * [4.0, 1.0, 1.0, 1.0]  # spreads past 90 degrees
    q[:, 3] = [10.0, 1e-7, 0.0, 0.0] + rng.normal(scale=1e-9, size=(500, 4))  # tiny angles
    q[:, 4] = [0.5, 0.5, 0.5, 0.5]  # still: relative rotations of exactly zero
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    aligned = q * np.where(np.sum(q * q[:1], axis=-1, keepdims=True) < 0, -1.0, 1.0)
    mean = aligned.mean(axis=0) / np.linalg.norm(aligned.mean(axis=0), axis=-1, keepdims=True)
    inverse = Rotation.from_quat(np.broadcast_to(mean, q.shape).reshape(-1, 4), scalar_first=True).inv()
    relative = inverse * Rotation.from_quat(aligned.reshape(-1, 4), scalar_first=True)
    expected = np.degrees(relative.as_rotvec().reshape(q.shape[:2] + (3,)).std(axis=0))
    np.testing.assert_allclose(rm.rotation_channel_sd(q), expected, rtol=1e-9, atol=1e-12)


def test_speed_peaks_and_path_ratio():
    t = np.linspace(0, 1, 200)
    bell = np.exp(-(((t - 0.4) / 0.1) ** 2))
    corrected = bell + 0.3 * np.exp(-(((t - 0.8) / 0.05) ** 2))
    assert rm.speed_peaks(bell, 0.1) == 1
    assert rm.speed_peaks(corrected, 0.1) == 2
    line = np.stack([t, 0 * t, 0 * t], axis=1)
    arc = np.stack([np.sin(np.pi * t / 2), 1 - np.cos(np.pi * t / 2), 0 * t], axis=1)
    assert rm.path_ratio(line) == pytest.approx(1.0)
    assert rm.path_ratio(arc) == pytest.approx((np.pi / 2) / np.sqrt(2), rel=1e-3)


def test_within_between_ratio():
    rng = np.random.default_rng(1)
    groups = np.repeat(np.arange(400), 5)
    subject = rng.normal(0.0, 10.0, 400)[groups]
    values = subject + rng.normal(0.0, 2.0, len(groups))
    assert rm.within_between_ratio(values, groups) == pytest.approx(0.2, abs=0.03)
    assert np.isnan(rm.within_between_ratio(values, np.zeros(len(values))))  # one group


def test_band_rules_and_judge():
    assert Band("factor2", "x", {"a": 2.0, "b": 4.0}).limits == (1.0, 8.0)
    assert Band("share", "x", {"a": 0.05, "b": 0.5}).limits == pytest.approx((0.0, 0.6))
    assert Band("literature", "x", lo=0.1, hi=0.9).limits == (0.1, 0.9)
    with pytest.raises(ValueError):
        Band("factor2", "x")
    table = pd.DataFrame(
        {
            "statistic": ["stride_cv_pct", "stride_cv_pct", "strides"],
            "behaviour": ["walk"] * 3,
            "value": [0.0, 2.0, 9.0],
        }
    )
    judged = judge(table)
    assert judged["in_band"].tolist()[:2] == [False, True]
    assert pd.isna(judged["in_band"].iloc[2])  # no band


def test_every_band_has_a_source_and_a_statistic_of_the_table():
    from motionvar.realism.table import _walk_rows, _WalkStats

    walk_stats = {row[0] for row in _walk_rows(_WalkStats())}
    channels = {f"channels_{c}_share" for c in ("static", "near_static", "moving")}
    cmu = {"cmu_captured_moving_kept_share", "cmu_captured_static_kept_share"}
    spread = {"stride_within_between", "posture_within_between"}
    reach = {"reach_multi_peak_share", "reach_path_ratio"}
    idle = {
        f"idle_{s}"
        for s in ("sway_sd_cm", "sway_fast_rms_mm", "sway_median_hz", "weight_shifts_per_min", "posture_within_between")
    }
    known = walk_stats | channels | cmu | spread | reach | idle
    for (stat, _), band in BANDS.items():
        assert stat in known and band.source
    assert set(CMU_CAPTURED_CHANNELS) == set(cmu_joint_map_names())


def test_idle_sway_measures_on_known_signals():
    """The sway measures on signals whose answers are known: a 0.2 Hz sway of 3 cm amplitude
    along x has an SD of 3 / sqrt(2) cm and its median frequency at 0.2 Hz; above 0.5 Hz it
    leaves what the 2nd-order high-pass run both ways passes, (f/fc)^4 / (1 + (f/fc)^4) of it
    (2.5 %); a 1 Hz tremor of 1 mm beside it adds 16/17 of its own RMS."""
    from motionvar.metrics import standing as rm

    def passed(f):
        return (f / 0.5) ** 4 / (1 + (f / 0.5) ** 4)

    fps, t = 24.0, np.arange(0, 120, 1 / 24.0)
    slow = np.stack([3.0 * np.sin(2 * np.pi * 0.2 * t), np.zeros_like(t)], axis=1)
    assert rm.sway_sd(slow) == pytest.approx(3 / np.sqrt(2), rel=1e-3)
    assert rm.sway_median_frequency(slow, fps, (0.05, 3.0), 20.0) == pytest.approx(0.2, abs=0.026)
    leak = 3 / np.sqrt(2) * passed(0.2)
    assert rm.sway_band_rms(slow, fps, 0.5) == pytest.approx(leak, rel=0.02)
    tremor = slow + np.stack([np.zeros_like(t), 0.1 * np.sin(2 * np.pi * 1.0 * t)], axis=1)
    both = np.hypot(leak, 0.1 / np.sqrt(2) * passed(1.0))
    assert rm.sway_band_rms(tremor, fps, 0.5) == pytest.approx(both, rel=0.02)
    assert np.isnan(rm.sway_median_frequency(slow[:100], fps, (0.05, 3.0), 20.0))


def test_weight_shifts_count_held_sides_only():
    """A pelvis over the left foot, both, the right foot, each held 3 s, is two shifts; a 0.5 s
    passage to the right and back is none; flicker across the margin is none."""
    from motionvar.metrics import standing as rm

    fps = 24.0
    held = np.repeat([0.9, 0.5, 0.1], 72)
    assert rm.weight_shifts(held, fps, 0.1, 1.0) == 2
    passage = np.concatenate([np.full(72, 0.9), np.full(12, 0.1), np.full(72, 0.9)])
    assert rm.weight_shifts(passage, fps, 0.1, 1.0) == 0
    flicker = 0.6 + 0.02 * np.sign(np.sin(np.arange(240)))
    assert rm.weight_shifts(flicker, fps, 0.1, 1.0) == 0
    hips, left, right = np.array([[2.0, 0.0]]), np.array([[10.0, 0.0]]), np.array([[-10.0, 0.0]])
    assert rm.support_ratio(hips, left, right)[0] == pytest.approx(0.6)


def cmu_joint_map_names():
    from motionvar.core.skeleton import cmu_skeleton

    return cmu_skeleton().names[1:]


def test_measures_on_generator_ground_truth():
    """A generated walk: the footfalls found from detected contacts are the generator's heel
    strikes, their strides its footprints' (stride_length_cm, the plan's truth)."""
    from motionvar.prep.contacts import detect_foot_contacts
    from motionvar.synth import SynthSpec, generate_dataset

    spec = SynthSpec(
        subjects=1, walks_per_style=1, turning_walks=0, runs=0, sidesteps=0, picks=0, places=0, idle_clips=0
    )
    motions, meta = generate_dataset(spec)
    jm = cmu_joint_map()
    for motion, (_, row) in zip(motions, meta.iterrows()):
        pos = motion.positions()
        contacts = detect_foot_contacts(motion, jm, None, pos)
        ankles = tuple(int(i) for i in jm.indices(motion.skeleton, ["left_ankle", "right_ankle"]))
        cyc = rm.walk_cycles(rm.walk_events(pos, (contacts.left, contacts.right), ankles, motion.fps))
        truth = [float(x) for x in row["footfall_strides_cm"].split(";")]
        assert len(cyc.stride_length) >= 2, row["clip_id"]
        # the measured strides join heel strikes 1-3, 2-4, ...: the first of the truth's
        np.testing.assert_allclose(cyc.stride_length, truth[: len(cyc.stride_length)], atol=0.5)
        toes = jm.indices(motion.skeleton, ["left_toe", "right_toe"])
        clear = rm.toe_clearance(pos[:, toes[0], 1], contacts.left)
        assert clear.min() > 0.5, row["clip_id"]  # the generator's toe clears the floor in every swing


ROOT = Path(__file__).resolve().parents[2]
REAL = ROOT.parent / "shared" / "data" / "real"


def _real_table(name: str) -> pd.DataFrame:
    """The realism table of a shared real set, loaded by rule data's own loader from its
    config/real entry and packed as that rule packs it (float32 rotations)."""
    from rule_scripts import script

    from motionvar.io import load_dataset, save_dataset
    from motionvar.realism import dataset_realism

    entry = yaml.safe_load((ROOT / "config" / "real" / f"{name}.yaml").read_text())["datasets"][name]
    entry = {**entry, "path": str(REAL / name)}  # the config's paths are relative to the repository root
    if entry.get("joint_map"):
        entry["joint_map"] = str(ROOT / entry["joint_map"])
    motions, meta, jm = script("data").load(entry)
    with tempfile.TemporaryDirectory() as tmp:
        save_dataset(tmp, motions, meta)
        table, _ = dataset_realism(load_dataset(tmp), jm)
    return table.set_index(["statistic", "behaviour"])


WITHIN_WALK = ("stride_cv_pct", "stride_time_cv_pct", "step_time_cv_pct", "stance_fraction_sd_pct", "step_asymmetry_cm")


@pytest.mark.skipif(not REAL.is_dir(), reason=f"{REAL} absent")
@pytest.mark.parametrize("name", ["xia", "bandai_ds1", "dfki_markerless", "reactidle_idle"])
def test_bands_record_what_the_captured_sets_give(name):
    """Every captured value a band is derived from is what the measure gives on that set."""
    values = _real_table(name)["value"]
    recorded = {key: band.captured[name] for key, band in BANDS.items() if name in band.captured}
    assert recorded
    for key, value in recorded.items():
        assert values[key] == pytest.approx(value, abs=1e-3), key


@pytest.mark.skipif(not REAL.is_dir(), reason=f"{REAL} absent")
def test_single_steps_give_no_within_walk_statistic_and_say_why():
    """DFKI's markerless files hold one step each, some with spurious contacts: no walk of
    three plausible strides, so no within-walk value (it read 12.6 % stride CV and 107 %
    step-time CV before the events were checked), and the note says why."""
    table = _real_table("dfki_markerless")
    for stat in WITHIN_WALK:
        row = table.loc[(stat, "walk")]
        assert np.isnan(row["value"]) and row["n"] == 0, stat
        assert row["note"].startswith("no walk of") and "left out as implausible" in row["note"], row["note"]


CMU_WALK = ROOT.parent / "shared" / "data" / "bvh" / "cmu" / "02_01.bvh"
CMU_STYLISED = CMU_WALK.with_name("131_01.bvh")


@pytest.mark.skipif(not CMU_STYLISED.is_file(), reason=f"{CMU_STYLISED} absent")
def test_a_stylised_start_walk_stop_is_left_out_and_a_plain_walk_kept(tmp_path):
    """CMU 131_01 (start, walk, stop in Michael Jackson's style) detects footfalls no walk has
    (a step asymmetry of 74 cm, step-time CV 65 %, a toe 1.4 cm under its contact height before
    the check); CMU 02_01, a plain walk of two strides, passes."""
    from motionvar.io import load_dataset, save_dataset
    from motionvar.io.bvh_dataset import import_bvh_folder
    from motionvar.io.joint_map_file import load_joint_map
    from motionvar.realism import dataset_realism

    for name, joint_map, kept in (("131_01.bvh", "cmu_3dsmax.yaml", False), ("02_01.bvh", "cmu.yaml", True)):
        folder = tmp_path / name
        folder.mkdir()
        (folder / name).symlink_to(CMU_WALK.with_name(name))
        (folder / "labels.csv").write_text(f"file,subject,behaviour,style\n{name},s,walk,neutral\n")
        jm = load_joint_map(ROOT / "config" / "joint_maps" / joint_map)
        motions, meta = import_bvh_folder(folder, "labels.csv", 5.644444, drop_first_frame=True, joint_map=jm)
        save_dataset(tmp_path / f"{name}.ds", motions, meta)
        table = dataset_realism(load_dataset(tmp_path / f"{name}.ds"), jm)[0].set_index(["statistic", "behaviour"])
        note = table.loc[("strides", "walk"), "note"]
        assert (note == "") if kept else ("1 of 1 walks' gait events left out" in note), (name, note)
        assert np.isnan(table.loc[("step_asymmetry_cm", "walk"), "value"]) or kept


def test_implausible_events_name_each_check():
    """A steady walk (stance 0.6, strides as long as the root's travel) passes; a stance of 0.95,
    a spurious footfall and a toe 2 cm under its contact height each fail, named."""
    x = 70.0 * np.arange(8)
    sides, starts = [0, 1] * 4, 55 * np.arange(8)
    root = np.stack([np.arange(500) * 70.0 / 55.0, np.zeros(500)], axis=1)
    fp = np.stack([x, np.zeros(8)], axis=1)

    def check(events, clearance=np.array([1.0, 1.5])):
        return rm.implausible_events(rm.walk_cycles(events), root, clearance, (0.35, 0.9), 0.25, -1.0)

    assert check(_events(sides, fp, starts, stance=66)) == ""
    assert check(_events(sides, fp, starts, stance=105)).startswith("stance fraction: 0.95")
    assert check(_events(sides, fp, starts, stance=66), np.array([1.0, -2.0])).startswith(
        "toe below its contact height"
    )
    # the right foot's contact broken in two (a spurious footfall at t = 82, where it stands):
    # the stride from it spans 140 cm in the time the root travels 106
    spurious = _events(
        [0, 1, 1, 0, 1, 0, 1, 0], np.insert(fp[:7], 2, [[70.0, 0.0]], axis=0), np.insert(starts[:7], 2, 82), 66
    )
    assert check(spurious).startswith("stride against the root's travel")


@pytest.mark.skipif(not (REAL.is_dir() and CMU_WALK.is_file()), reason="the shared captured walks are absent")
def test_cmu_captured_channels_are_where_xia_and_cmu_agree():
    from motionvar.io import import_bvh_folder
    from motionvar.io.bvh import read_bvh
    from motionvar.realism import RealismSettings

    s = RealismSettings()

    def classes(rotations):
        return rm.channel_classes(rm.rotation_channel_sd(rotations[:, 1:]), s.static_deg, s.near_static_deg)

    xia, meta = import_bvh_folder(REAL / "xia", "labels.csv", 5.644444, style_aliases={"sexy": "female"})
    walks = [m for m, b in zip(xia, meta["behaviour"]) if b == "walk"]
    xia_classes = classes(np.concatenate([m.rotations.astype(np.float32) for m in walks]))
    cmu = read_bvh(CMU_WALK, scale=5.644444)
    cmu_classes = classes(cmu.rotations[1:].astype(np.float32))  # frame 0 of a cgspeed CMU file: a T-pose
    still = lambda c: "moving" if c == "moving" else "still"  # noqa: E731
    for j, name in enumerate(cmu.skeleton.names[1:]):
        expected = tuple(still(a) if still(a) == still(b) else "either" for a, b in zip(xia_classes[j], cmu_classes[j]))
        assert CMU_CAPTURED_CHANNELS[name] == expected, name


def test_reach_boundary_and_peaks_on_the_generators_truth():
    """On generated picks with and without a corrective sub-movement: the reach ends as the
    hands stop on the grips, a corrective sub-movement included (in the last 0.25 s of the truth's pick_reach segment, the
    slow tail of a minimum-jerk approach, or at most 0.05 s after it), and the reaches with
    two speed peaks are corrected ones (reach_submovements): never an uncorrected reach, and at
    least a third of the corrected (the others' secondary merges into the primary's slowing:
    4 of the 9 here)."""
    from motionvar.prep import PrepOptions
    from motionvar.prep.segmentation import hand_speed, reach_boundary
    from motionvar.realism import RealismSettings
    from motionvar.synth import ReachParams, generate_pick, make_subjects

    s, jm = RealismSettings(), cmu_joint_map()
    found = {1: [], 2: []}
    for k, subject in enumerate(make_subjects(3, seed=5)):
        for j, region in enumerate(("low", "forward", "high")):
            for correction in (False, True):
                params = ReachParams(region=region, correction=correction)
                m, truth = generate_pick(subject, params, np.random.default_rng([k, j]))
                p = PrepOptions()
                speed = hand_speed(m, jm, m.positions(), p)
                end = reach_boundary(speed, p.hand_stop_fraction, p.hand_rest_fraction)
                b = next(int(x.split(":")[2]) for x in truth["segments"].split(";") if x.startswith("pick_reach"))
                assert b - 0.25 * m.fps <= end <= b + 0.05 * m.fps, (end, b)
                found[truth["reach_submovements"]].append(rm.speed_peaks(speed[:end], s.peak_prominence))
    assert all(p == 1 for p in found[1])
    assert np.mean(np.array(found[2]) >= 2) >= 1 / 3
