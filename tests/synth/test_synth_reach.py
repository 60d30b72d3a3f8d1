"""Pick / place generator and the two-bone IK behind it."""

import numpy as np
import pytest

from motionvar.core import cmu_joint_map
from motionvar.core.quaternions import qmul, qnormalize, qrot
from motionvar.io.intervals import format_named, parse_named, parse_ranges
from motionvar.metrics.realism import speed_peaks
from motionvar.prep.options import PrepOptions
from motionvar.prep.segmentation import hand_speed
from motionvar.synth import reach
from motionvar.synth.ik import two_bone_ik
from motionvar.synth.reach import REGIONS, ReachParams, generate_pick, generate_place, reach_style, target_grid
from motionvar.synth.signals import submovements
from motionvar.synth.stance import body_com, stance_habit, to_body_frame
from motionvar.synth.subjects import make_subjects

SUBJECTS = make_subjects(5, seed=11)
GEN = {"pick": generate_pick, "place": generate_place}


def _clip(kind, subject, seed=0, **kw):
    return GEN[kind](subject, ReachParams(**kw), np.random.default_rng(seed))


@pytest.fixture(scope="module")
def clips():
    """One clip per kind × region × subject (3 subjects), random start and heading."""
    out = []
    for kind in GEN:
        for region in ("low", "forward", "high"):
            for si, subject in enumerate(SUBJECTS[:3]):
                m, truth = _clip(kind, subject, seed=100 + si, region=region)
                out.append((kind, region, subject, m, truth))
    return out


def _grips(truth):
    t = np.array([truth["target_x"], truth["target_y"], truth["target_z"]])
    half = truth["object_width_cm"] / 2.0
    return t + np.array([[half, 0.0, 0.0], [-half, 0.0, 0.0]])


def _body_positions(m, truth):
    return to_body_frame(m.positions(), truth["heading_deg"], (truth["start_x"], truth["start_z"]))


def _hands(m, truth):
    """(T, 2, 3) wrist positions in the feet frame."""
    return _body_positions(m, truth)[:, [m.skeleton.index("LeftHand"), m.skeleton.index("RightHand")]]


def _angle(u, v):
    c = np.sum(u * v, -1) / np.linalg.norm(u, axis=-1) / np.linalg.norm(v, axis=-1)
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def test_hands_reach_the_target_and_stop(clips):
    for kind, region, subject, m, truth in clips:
        sk = m.skeleton
        p = _body_positions(m, truth)
        hands = p[:, [sk.index("LeftHand"), sk.index("RightHand")]]
        (name, a, end), (name2, b, _) = parse_named(truth["segments"])
        assert (name, name2) == (f"{kind}_reach", f"{kind}_retrieve") and end == b
        err = np.linalg.norm(hands[end - 1] - _grips(truth), axis=-1)
        assert err.max() < 1.0, (kind, region, err)
        speed = np.linalg.norm(hands[end - 1] - hands[end - 2], axis=-1) * m.fps
        assert speed.max() < 1.0  # cm/s: the hands have stopped
        early = end - 1 - int(round(0.1 * truth["reach_duration_s"] * m.fps))
        assert np.linalg.norm(hands[early] - _grips(truth), axis=-1).max() > 0.05  # ... and only just
        assert truth["variant"] == region
        lo, hi = np.array(REGIONS[region]).T * subject.height_scale
        target = np.array([truth["target_x"], truth["target_y"], truth["target_z"]])
        assert np.all(target >= lo - 1e-9) and np.all(target <= hi + 1e-9)


def test_feet_do_not_slide(clips):
    for kind, region, subject, m, truth in clips:
        p = m.positions()
        sk = m.skeleton
        for name in ("LeftFoot", "RightFoot", "LeftToeBase", "RightToeBase"):
            drift = np.linalg.norm(p[:, sk.index(name)] - p[0, sk.index(name)], axis=-1)
            assert drift.max() < 0.5, (kind, region, name)
        assert np.allclose(p[:, [sk.index("LeftToeBase"), sk.index("RightToeBase")], 1], 0.0, atol=1e-6)
        assert parse_ranges(truth["left_contacts"]) == [(0, m.n_frames)] == parse_ranges(truth["right_contacts"])


def test_segments_cover_the_clip(clips):
    for kind, region, subject, m, truth in clips:
        seg = parse_named(truth["segments"])
        assert seg[0][1] == 0 and seg[-1][2] == m.n_frames
        assert all(a[2] == b[1] and a[2] > a[1] for a, b in zip(seg, seg[1:]))
        assert truth["idle_postures"] == ""


def test_start_and_end_poses(clips):
    """A pick starts relaxed (hands low at the sides) and ends holding the object in front;
    a place does the opposite. Start and end are still."""
    for kind, region, subject, m, truth in clips:
        sk = m.skeleton
        p = _body_positions(m, truth)
        hands = p[:, [sk.index("LeftHand"), sk.index("RightHand")]]
        hips = p[:, 0]
        relaxed, carrying = (0, -1) if kind == "pick" else (-1, 0)
        assert np.all(hands[relaxed, :, 2] - hips[relaxed, 2] < 15.0)  # at the sides
        assert np.all(hands[carrying, :, 2] - hips[carrying, 2] > 15.0)  # held in front
        held = hands[carrying, 0] - hands[carrying, 1]
        assert np.linalg.norm(held) == pytest.approx(truth["object_width_cm"], abs=0.5)
        for f in (0, -1):
            g = 1 if f == 0 else -2
            assert np.abs(p[f] - p[g]).max() * m.fps < 1.0


def test_centre_of_mass_stays_over_the_feet(clips):
    """Hips move back as the trunk bends: the whole-body COM (arms included) stays between
    the ankles (minus a heel length of 5 cm) and the toes."""
    for kind, region, subject, m, truth in clips:
        sk = m.skeleton
        p = _body_positions(m, truth)
        com = body_com(p, sk)
        heel = p[0, [sk.index("LeftFoot"), sk.index("RightFoot")], 2].min() - 5.0
        toe = p[0, [sk.index("LeftToeBase"), sk.index("RightToeBase")], 2].max()
        assert heel < com[:, 2].min() and com[:, 2].max() < toe, (kind, region)


def test_low_targets_bend_more_than_high(clips):
    """Shoulders come down for low targets (stoop or squat), stay up for high ones."""
    drop = {}
    for kind, region, subject, m, truth in clips:
        y = m.positions()[:, m.skeleton.index("LeftArm"), 1]
        drop.setdefault(region, []).append(y[0] - y.min())
    assert min(drop["low"]) > 20.0 and max(drop["high"]) < 2.0
    assert np.mean(drop["low"]) > np.mean(drop["forward"]) > np.mean(drop["high"])


def test_joint_angles_in_human_ranges(clips):
    for kind, region, subject, m, truth in clips:
        sk = m.skeleton
        p = m.positions()
        rest = m.skeleton.offsets
        i = sk.index
        for s in ("Left", "Right"):
            hip, knee, ankle, toe = (p[:, i(s + n)] for n in ("UpLeg", "Leg", "Foot", "ToeBase"))
            k = _angle(knee - hip, ankle - knee)
            assert k.min() >= 0.0 and k.max() < 135.0, (kind, region, k.max())
            rest_ankle = _angle(-rest[i(s + "Foot")], rest[i(s + "ToeBase")])
            dorsi = rest_ankle - _angle(knee - ankle, toe - ankle)
            assert dorsi.max() < 40.0 and dorsi.min() > -25.0
            sh, el, wr = (p[:, i(s + n)] for n in ("Arm", "ForeArm", "Hand"))
            e = _angle(el - sh, wr - el)
            assert e.max() < 150.0
            hip_mid = 0.5 * (p[:, i("LeftUpLeg")] + p[:, i("RightUpLeg")])
            hip_flex = 180.0 - _angle(p[:, i("Spine1")] - hip_mid, knee - hip)
            assert hip_flex.max() < 130.0
        trunk = _angle(p[:, i("Spine1")] - p[:, 0], np.array([0.0, 1.0, 0.0]))
        assert trunk.max() < 110.0


def test_deterministic_and_varied():
    s = SUBJECTS[0]
    m1, t1 = _clip("pick", s, seed=3, region="forward")
    m2, t2 = _clip("pick", s, seed=3, region="forward")
    assert np.array_equal(m1.rotations, m2.rotations) and np.array_equal(m1.root_pos, m2.root_pos)
    assert t1 == t2
    m3, t3 = _clip("pick", s, seed=4, region="forward")
    assert t3["target_x"] != t1["target_x"] and t3["reach_duration_s"] != t1["reach_duration_s"]


def test_duration_scale_slows_the_movement():
    s = SUBJECTS[1]
    fixed = dict(target=(0.0, 90.0, 40.0), object_width_cm=30.0, hold_s=0.3, lead_in_s=0.2, settle_s=0.2)
    fast, _ = _clip("place", s, duration_scale=0.8, **fixed)
    slow, truth = _clip("place", s, duration_scale=1.25, **fixed)
    assert slow.n_frames > 1.2 * fast.n_frames * 0.9
    assert 0.5 <= truth["reach_duration_s"] <= 2.5 and truth["variant"] == "custom"


def test_habits_persist():
    """Head pitch and shoulder lift are the subject's at the still start; a larger elbow habit
    gives a more flexed relaxed elbow."""
    for s in SUBJECTS:
        m, _ = _clip("pick", s, seed=1, region="high")
        j = m.skeleton.index
        neck = m.rotations[0, [j("Neck1"), j("Head")]]
        pitch = np.degrees(2.0 * np.arctan2(neck[:, 1], neck[:, 0])).sum()
        assert pitch == pytest.approx(s.head_pitch_deg, abs=0.5)
        clav = m.rotations[0, j("LeftShoulder")]
        assert np.degrees(2.0 * np.arctan2(clav[3], clav[0])) == pytest.approx(s.shoulder_lift_deg, abs=0.5)
        p = m.positions()[0]
        elbow = _angle(p[j("LeftForeArm")] - p[j("LeftArm")], p[j("LeftHand")] - p[j("LeftForeArm")])
        assert elbow == pytest.approx(s.elbow_flex_deg, abs=1.0)
    assert reach_style(SUBJECTS[0]) == reach_style(SUBJECTS[0]) != reach_style(SUBJECTS[1])


def test_start_anywhere():
    s = SUBJECTS[2]
    m, truth = _clip("pick", s, seed=9, region="forward", start_xz=(250.0, -80.0), heading_deg=-120.0)
    p = m.positions()
    ankles = p[0, [m.skeleton.index("LeftFoot"), m.skeleton.index("RightFoot")]]
    assert np.allclose(ankles.mean(axis=0)[[0, 2]], [250.0, -80.0], atol=1e-6)
    left = (ankles[0] - ankles[1])[[0, 2]]  # the subject's left: +x turned by the heading
    h = np.radians(-120.0)
    assert np.allclose(left / np.linalg.norm(left), [np.cos(h), -np.sin(h)], atol=1e-6)


def test_target_grid():
    g = target_grid("dense", 10.0)
    (x0, x1), (y0, y1), (z0, z1) = REGIONS["dense"]
    assert np.all((g >= [x0, y0, z0]) & (g <= [x1, y1, z1]))
    for axis in range(3):
        u = np.unique(g[:, axis])
        assert np.allclose(np.diff(u), 10.0)
    assert len(g) == np.prod([len(np.unique(g[:, a])) for a in range(3)])
    assert len(target_grid("dense", 5.0)) > 4 * len(g)
    m, truth = _clip("pick", SUBJECTS[3], seed=2, region="dense", grid_spacing_cm=10.0)
    nodes = target_grid("dense", 10.0, SUBJECTS[3].height_scale)
    t = np.array([truth["target_x"], truth["target_y"], truth["target_z"]])
    assert np.min(np.linalg.norm(nodes - t, axis=-1)) < 1e-9
    with pytest.raises(ValueError, match="region"):
        target_grid("sideways")
    with pytest.raises(ValueError, match="spacing"):
        target_grid("dense", 0.0)


def test_dense_grid_is_reachable():
    """Every node of the dense grid (Du 2022 Fig. 4.11) is picked to within 1 cm."""
    s = SUBJECTS[4]
    nodes = target_grid("dense", 15.0, s.height_scale)
    for k, node in enumerate(nodes):
        m, truth = _clip("pick", s, seed=k, target=tuple(node), object_width_cm=40.0 if k % 2 else 20.0)
        end = parse_named(truth["segments"])[0][2]
        p = _body_positions(m, truth)[end - 1]
        hands = p[[m.skeleton.index("LeftHand"), m.skeleton.index("RightHand")]]
        assert np.linalg.norm(hands - _grips(truth), axis=-1).max() < 1.0


@pytest.mark.parametrize(
    "kw, name",
    [
        ({"region": "sideways"}, "region"),
        ({"target": (0.0, 90.0)}, "target"),
        ({"target": (0.0, -5.0, 30.0)}, "target"),
        ({"target": (0.0, 90.0, float("nan"))}, "target"),
        ({"target": (0.0, 5.0, 90.0)}, "target"),  # out of reach: names the target
        ({"object_width_cm": 100.0}, "object_width_cm"),
        ({"duration_scale": 0.0}, "duration_scale"),
        ({"hold_s": -1.0}, "hold_s"),
        ({"lead_in_s": 9.0}, "lead_in_s"),
        ({"settle_s": float("nan")}, "settle_s"),
        ({"grid_spacing_cm": 0.0}, "grid_spacing_cm"),
        ({"start_xz": (1.0, 2.0, 3.0)}, "start_xz"),
        ({"heading_deg": float("inf")}, "heading_deg"),
        ({"fps": 0.0}, "fps"),
        ({"correction": "yes"}, "correction"),
        ({"primary_amplitude": 1.1}, "primary_amplitude"),
        ({"correction_onset": 0.0}, "correction_onset"),
        ({"correction_duration": 2.0}, "correction_duration"),
    ],
)
def test_bad_params_raise(kw, name):
    for kind in GEN:
        with pytest.raises(ValueError, match=name):
            _clip(kind, SUBJECTS[0], **kw)


def test_two_bone_ik_reaches_and_bends_towards_the_pole():
    rng = np.random.default_rng(0)
    n = 500
    off_mid, off_end = np.array([0.0, -40.0, 0.0]), np.array([0.0, -38.0, 0.0])
    parent = qnormalize(rng.normal(size=(n, 4)))
    p0 = rng.normal(size=(n, 3)) * 10
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    target = p0 + d * rng.uniform(5.0, 77.0, size=(n, 1))
    pole = rng.normal(size=(n, 3))
    q_up, q_mid, reached = two_bone_ik(p0, target, parent, off_mid, off_end, np.array([1.0, 0, 0]), pole)
    g = qmul(parent, q_up)
    knee = p0 + qrot(g, np.broadcast_to(off_mid, (n, 3)))
    end = knee + qrot(qmul(g, q_mid), np.broadcast_to(off_end, (n, 3)))
    assert np.allclose(end, target, atol=1e-6) and np.allclose(reached, target, atol=1e-6)
    # the middle joint lies on the pole's side of the line from the upper joint to the target
    perp = (knee - p0) - np.sum((knee - p0) * d, -1, keepdims=True) * d
    assert np.all(np.sum(perp * pole, -1) > -1e-6)
    # the middle joint only hinges about its axis
    assert np.allclose(q_mid[:, 2:], 0.0)
    # out of reach: clamped to a straight chain pointing at the target
    far = p0 + d * 200.0
    _, _, got = two_bone_ik(p0, far, parent, off_mid, off_end, np.array([1.0, 0, 0]), pole)
    assert np.allclose(np.linalg.norm(got - p0, axis=-1), 78.0, atol=1e-3)


def test_intervals_round_trip():
    items = [("pick_reach", 0, 90), ("pick_retrieve", 90, 200)]
    assert parse_named(format_named(items)) == items
    with pytest.raises(ValueError, match="name:start:stop"):
        parse_named("a:1")


CORRECTED = dict(correction=True, primary_amplitude=0.85, correction_onset=0.85, correction_duration=0.3)


def _reach_peaks(m, truth):
    """Hand-speed peaks (prominence 10 % of the maximum, as the realism table counts them)
    from the start to the truth's end of the reach."""
    end = parse_named(truth["segments"])[0][2]
    speed = hand_speed(m, cmu_joint_map(), m.positions(), PrepOptions())
    return speed_peaks(speed[:end], 0.1)


@pytest.mark.parametrize("kind", sorted(GEN))
def test_corrective_submovement_gives_a_second_speed_peak(kind):
    """A reach whose primary falls 15 % short has a second hand-speed peak and still ends at
    the grips, stopped, at the same frame as the reach without one (Meyer et al. 1988;
    Novak, Miller & Houk 2002); feet stay planted."""
    for i, subject in enumerate(SUBJECTS[:3]):
        for region in ("low", "forward", "high"):
            one, t1 = _clip(kind, subject, seed=7 + i, region=region, correction=False)
            two, t2 = _clip(kind, subject, seed=7 + i, region=region, **CORRECTED)
            assert (t1["reach_submovements"], t2["reach_submovements"]) == (1, 2)
            assert (_reach_peaks(one, t1), _reach_peaks(two, t2)) == (1, 2), (kind, region, i)
            assert t1["segments"] == t2["segments"] and one.n_frames == two.n_frames
            end = parse_named(t2["segments"])[0][2]
            hands = [_hands(m, t) for m, t in ((one, t1), (two, t2))]
            grips = _grips(t2)
            assert np.linalg.norm(hands[1][end - 1] - grips, axis=-1).max() < 0.01
            assert np.linalg.norm(hands[1][end - 1] - hands[1][end - 2], axis=-1).max() * two.fps < 1.0
            feet = [two.skeleton.index(n) for n in ("LeftFoot", "RightFoot", "LeftToeBase", "RightToeBase")]
            assert np.abs(two.positions()[:, feet] - two.positions()[:1, feet]).max() < 0.5
            # at the primary's end (0.9 × reach time / 1.15 after the hands set off) the
            # corrected hands are still short by about half the 15 % shortfall
            primary_end = end - 1 - int(round(0.9 * t2["reach_duration_s"] * (1 - 1 / 1.15) * two.fps))
            way = np.linalg.norm(grips.mean(0) - hands[1][0].mean(0))
            short = [np.linalg.norm(h[primary_end].mean(0) - grips.mean(0)) / way for h in hands]
            assert short[0] < 0.03 and 0.04 < short[1] < 0.12, (kind, region, short)


def test_correction_share_and_draw_order():
    """Corrections are drawn on a share CORRECTION_SHARE of clips, their values in the stated
    ranges, and after every other value of the clip (giving them changes nothing else)."""
    subject = SUBJECTS[0]
    habit, style = stance_habit(subject), reach_style(subject)
    draws = [
        reach._draw_clip(subject, ReachParams(correction=None), habit, style, np.random.default_rng(k))
        for k in range(2000)
    ]
    corrections = [d.correction for d in draws if d.correction is not None]
    assert len(corrections) / len(draws) == pytest.approx(reach.CORRECTION_SHARE, abs=0.04)
    primary = np.array([c.primary for c in corrections])
    lo, hi = reach.PRIMARY_ERROR
    assert np.all((1.0 - primary >= lo) & (1.0 - primary <= hi))
    for name, (lo, hi) in (("onset", reach.CORRECTION_ONSET), ("duration", reach.CORRECTION_DURATION)):
        x = np.array([getattr(c, name) for c in corrections])
        assert np.all((x >= lo) & (x <= hi))
    forced = reach._draw_clip(subject, ReachParams(**CORRECTED), habit, style, np.random.default_rng(0))
    drawn = draws[0]
    for f in ("heading", "start_xz", "width", "dscale", "hold", "lead", "settle", "q", "elbow_pref"):
        assert getattr(forced, f) == getattr(drawn, f)
    assert np.array_equal(forced.target, drawn.target)
    assert forced.correction == reach._Correction(0.85, 0.85, 0.3)
    # correction=False (the default) draws nothing: the stream goes on as with every value given
    states = []
    for params in (ReachParams(), ReachParams(**CORRECTED), ReachParams(correction=None)):
        rng = np.random.default_rng(1)
        reach._draw_clip(subject, params, habit, style, rng)
        states.append(rng.random())
    assert states[0] == states[1] != states[2]


def test_submovement_profiles():
    """The secondary starts at onset × the primary's duration and the later of the two ends
    at τ = 1; both run 0 → 1."""
    tau = np.linspace(0.0, 1.0, 1001)
    first, second = submovements(tau, 0.8, 0.4)
    span = 1.2
    assert first[0] == second[0] == 0.0 and first[-1] == second[-1] == 1.0
    assert np.all(np.diff(first) >= 0) and np.all(np.diff(second) >= 0)
    assert np.all(first[tau >= 1.0 / span] == 1.0) and np.all(second[tau <= 0.8 / span] == 0.0)
    assert second[tau < 1.0].max() < 1.0
