"""Idle standing generator: balance shifts, planted feet, sway, breathing, personal style."""

import time

import numpy as np
import pytest

from motionvar.io.intervals import parse_named, parse_ranges
from motionvar.synth.idle import (
    CATEGORIES,
    MOVEMENT_TRAITS,
    IdleParams,
    generate_idle,
    idle_style,
    movement_twin,
    sample_rests,
)
from motionvar.synth.signals import colored_noise, minimum_jerk
from motionvar.synth.stance import body_com, to_body_frame
from motionvar.synth.subjects import make_subjects

SUBJECTS = make_subjects(6, seed=3)


def _clip(subject, seed=0, **kw):
    kw.setdefault("duration_s", 60.0)
    return generate_idle(subject, IdleParams(**kw), np.random.default_rng(seed))


@pytest.fixture(scope="module")
def clip():
    return _clip(SUBJECTS[0], seed=1, start_xz=(120.0, -40.0), heading_deg=35.0)


def _rest_frames(truth, n):
    """Boolean mask of the frames inside a rest (not a shift)."""
    mask = np.zeros(n, dtype=bool)
    for name, a, b in parse_named(truth["idle_phases"]):
        if name == "rest":
            mask[a:b] = True
    return mask


def _body(motion, truth, joints):
    p = motion.positions()
    idx = [motion.skeleton.index(j) for j in joints]
    return to_body_frame(p[:, idx], truth["heading_deg"], (truth["start_x"], truth["start_z"])), p


def test_duration_and_speed():
    t0 = time.perf_counter()
    m, _ = _clip(SUBJECTS[1], seed=2, duration_s=60.0)
    elapsed = time.perf_counter() - t0
    assert m.fps == 120.0 and m.n_frames == 7201
    assert m.duration == pytest.approx(60.0)
    assert elapsed < 3.0  # ~0.2 s on an idle core; generous for a shared machine
    m2, _ = _clip(SUBJECTS[1], seed=2, duration_s=2.5, fps=60.0)
    assert m2.n_frames == 151


def test_deterministic(clip):
    m1, t1 = clip
    m2, t2 = _clip(SUBJECTS[0], seed=1, start_xz=(120.0, -40.0), heading_deg=35.0)
    assert np.array_equal(m1.rotations, m2.rotations) and np.array_equal(m1.root_pos, m2.root_pos)
    assert t1 == pytest.approx(t2, nan_ok=True)
    m3, t3 = _clip(SUBJECTS[0], seed=2, start_xz=(120.0, -40.0), heading_deg=35.0)
    assert not np.allclose(m1.rotations, m3.rotations)


def test_feet_planted_on_the_floor(clip):
    m, truth = clip
    p = m.positions()
    sk = m.skeleton
    for name in ("LeftFoot", "RightFoot", "LeftToeBase", "RightToeBase"):
        drift = np.linalg.norm(p[:, sk.index(name)] - p[0, sk.index(name)], axis=-1)
        assert drift.max() < 0.5, name
    assert np.allclose(p[:, [sk.index("LeftToeBase"), sk.index("RightToeBase")], 1], 0.0, atol=1e-6)
    # The feet stand where the truth says, facing the heading.
    ankles, _ = _body(m, truth, ["LeftFoot", "RightFoot"])
    mid = ankles[0].mean(axis=0)
    assert abs(mid[0]) < 1e-6 and abs(mid[2]) < 1e-6
    assert ankles[0, 0, 0] - ankles[0, 1, 0] == pytest.approx(truth["stance_width_cm"], abs=1e-6)
    assert parse_ranges(truth["left_contacts"]) == [(0, m.n_frames)] == parse_ranges(truth["right_contacts"])


def test_truth_intervals_cover_the_clip(clip):
    m, truth = clip
    post = parse_named(truth["idle_postures"])
    assert post[0][1] == 0 and post[-1][2] == m.n_frames
    assert all(a[2] == b[1] for a, b in zip(post, post[1:]))
    assert all(c in CATEGORIES for c, _, _ in post)
    assert all(a[0] != b[0] for a, b in zip(post, post[1:]))  # repeats are merged
    seg = parse_named(truth["idle_phases"])
    assert seg[0][1] == 0 and seg[-1][2] == m.n_frames
    assert all(a[2] == b[1] for a, b in zip(seg, seg[1:]))
    shifts = [(b - a) / m.fps for name, a, b in seg[:-1] if name == "shift"]
    assert shifts and all(0.49 <= d <= 1.51 for d in shifts)  # transitions of 0.5-1.5 s


def test_dwell_times_follow_the_subject():
    """Over an hour of rests the mean dwell is near the subject's weight_shift_s."""
    for subject in (SUBJECTS[0], SUBJECTS[2]):
        rests = sample_rests(subject, 3600.0, "both", np.random.default_rng(5))
        dwell = np.array([r.stop - r.start for r in rests[1:]])
        assert dwell.mean() == pytest.approx(subject.weight_shift_s, rel=0.15)
        shifts = np.array([r.shift_stop - r.stop for r in rests])
        assert shifts.min() >= 0.5 and shifts.max() <= 1.5


def test_posture_categories_are_visible(clip):
    """In a left rest the centre of mass is over the left foot, the right knee is the bent one
    and the pelvis drops to the right; mirrored for right; in between for both."""
    m, truth = clip
    sk = m.skeleton
    pts, p = _body(m, truth, ["LeftFoot", "RightFoot", "LeftUpLeg", "RightUpLeg"])
    com = to_body_frame(body_com(p, sk), truth["heading_deg"], (truth["start_x"], truth["start_z"]))
    rest = _rest_frames(truth, m.n_frames)
    knee = {}
    for side in ("Left", "Right"):
        u = p[:, sk.index(side + "Leg")] - p[:, sk.index(side + "UpLeg")]
        v = p[:, sk.index(side + "Foot")] - p[:, sk.index(side + "Leg")]
        knee[side] = np.degrees(np.arccos(np.sum(u * v, -1) / np.linalg.norm(u, axis=-1) / np.linalg.norm(v, axis=-1)))
    half = 0.5 * (pts[0, 0, 0] - pts[0, 1, 0])
    seen = set()
    for cat, a, b in parse_named(truth["idle_postures"]):
        f = np.arange(a, b)[rest[a:b]]
        if f.size < 60:
            continue
        seen.add(cat)
        x = com[f, 0].mean() / half  # +1: over the left ankle, -1: over the right ankle
        drop = (pts[f, 2, 1] - pts[f, 3, 1]).mean()  # left hip minus right hip height
        if cat == "left":
            assert x > 0.25 and drop > 0.3 and knee["Right"][f].mean() > knee["Left"][f].mean() + 3
        elif cat == "right":
            assert x < -0.25 and drop < -0.3 and knee["Left"][f].mean() > knee["Right"][f].mean() + 3
        else:
            assert abs(x) < 0.2
    assert len(seen) >= 2


def test_sway_rms_and_spectrum():
    """COM sway in rests (each rest's mean removed) has about the subject's sway_cm RMS,
    within the documented 0.3-1 cm, with its power below 1 Hz."""
    for subject in SUBJECTS[:4]:
        m, truth = _clip(subject, seed=7, duration_s=120.0)
        com = body_com(m.positions(), m.skeleton)
        dev = []
        for name, a, b in parse_named(truth["idle_phases"]):
            if name == "rest" and b - a > 2 * m.fps:
                c = com[a:b, [0, 2]]
                dev.append(c - c.mean(axis=0))
        dev = np.concatenate(dev)
        rms = np.sqrt(np.mean(np.sum(dev**2, axis=-1)))
        assert 0.6 * subject.sway_cm < rms < 1.2 * subject.sway_cm
        assert 0.2 < rms < 1.1
        spec = np.abs(np.fft.rfft(dev, axis=0)) ** 2
        f = np.fft.rfftfreq(len(dev), 1.0 / m.fps)
        assert spec[f < 1.0].sum() / spec.sum() > 0.85


def test_breathing_at_the_subject_rate():
    subject = SUBJECTS[3]
    m, _ = _clip(subject, seed=4, duration_s=120.0)
    q = m.rotations[:, m.skeleton.index("LeftShoulder")]
    elev = 2.0 * np.arctan2(q[:, 3], q[:, 0])  # rotation about +z raises the left shoulder
    spec = np.abs(np.fft.rfft(elev - elev.mean())) ** 2
    f = np.fft.rfftfreq(len(elev), 1.0 / m.fps)
    band = (f > 0.1) & (f < 1.0)
    peak = f[band][np.argmax(spec[band])]
    assert peak == pytest.approx(subject.breath_rate_hz, abs=0.03)
    assert np.degrees(elev).mean() == pytest.approx(subject.shoulder_lift_deg, abs=2.0)


def test_start_category_and_preferences():
    m, truth = _clip(SUBJECTS[0], seed=0, duration_s=5.0, start_category="both")
    assert parse_named(truth["idle_postures"])[0][0] == "both"
    # Over two hours the share of time per category is the subject's preference.
    for subject in SUBJECTS[:4]:
        rests = sample_rests(subject, 7200.0, "left", np.random.default_rng(1))
        total = sum(r.stop - r.start for r in rests)
        share = [sum(r.stop - r.start for r in rests if r.category == c) / total for c in CATEGORIES]
        assert np.allclose(share, subject.idle_foot_preference, atol=0.06)
    with pytest.raises(ValueError, match="category"):
        sample_rests(SUBJECTS[0], 10.0, "sitting", np.random.default_rng(0))


def test_subjects_can_be_told_apart():
    """Nearest-centroid identification from simple posture features (Egges 2004 Sec. 5.6)."""

    def features(motion, truth):
        p = motion.positions()
        sk = motion.skeleton
        i = sk.index
        u = p[:, i("LeftForeArm")] - p[:, i("LeftArm")]
        v = p[:, i("LeftHand")] - p[:, i("LeftForeArm")]
        elbow = np.degrees(np.arccos(np.sum(u * v, -1) / np.linalg.norm(u, axis=-1) / np.linalg.norm(v, axis=-1)))
        ankles = np.linalg.norm(p[0, i("LeftFoot")] - p[0, i("RightFoot")])
        head = p[:, i("Head")] - p[:, i("Neck1")]
        pitch = np.degrees(np.arctan2(np.linalg.norm(head[:, [0, 2]], axis=-1), head[:, 1]))
        return np.array([ankles, elbow.mean(), pitch.mean(), p[:, 0, 1].mean()])

    subjects = SUBJECTS[:4]
    feats = np.array([[features(*_clip(s, seed=k, duration_s=20.0)) for k in range(3)] for s in subjects])
    scale = feats.reshape(-1, feats.shape[-1]).std(axis=0)
    correct = 0
    for si in range(len(subjects)):
        for k in range(3):
            others = [
                np.delete(feats[sj], k, axis=0).mean(axis=0) if sj == si else feats[sj].mean(axis=0)
                for sj in range(len(subjects))
            ]
            d = [np.linalg.norm((feats[si, k] - c) / scale) for c in others]
            correct += int(np.argmin(d) == si)
    assert correct >= 11


def test_style_is_personal_and_stable():
    a, b = idle_style(SUBJECTS[0]), idle_style(SUBJECTS[0])
    assert a == b and idle_style(SUBJECTS[1]) != a


def test_movement_twins_stand_alike_and_move_differently():
    """movement_twin (the ground truth of movement-only identification, Egges 2004 Sec. 5.6): the
    same body, stance and posture traits, new movement traits; the default generator is unchanged."""
    from dataclasses import asdict

    base = SUBJECTS[0]
    (a, sa), (b, sb) = movement_twin(base, 0), movement_twin(base, 1)
    assert (a, sa) == movement_twin(base, 0)
    for twin, style in ((a, sa), (b, sb)):
        same = {k: v for k, v in asdict(twin).items() if k not in MOVEMENT_TRAITS and k != "skeleton"}
        assert same == {k: v for k, v in asdict(base).items() if k not in MOVEMENT_TRAITS and k != "skeleton"}
        assert twin.skeleton is base.skeleton
        assert {k: v for k, v in asdict(style).items() if k not in MOVEMENT_TRAITS} == {
            k: v for k, v in asdict(idle_style(base)).items() if k not in MOVEMENT_TRAITS
        }
    assert all(getattr(a, k, None) != getattr(b, k, None) or getattr(sa, k) != getattr(sb, k) for k in MOVEMENT_TRAITS)
    m0, _ = _clip(base, seed=2, duration_s=5.0)
    m1, _ = generate_idle(base, IdleParams(duration_s=5.0), np.random.default_rng(2), idle_style(base))
    assert np.array_equal(m0.rotations, m1.rotations)


@pytest.mark.parametrize(
    "kw, name",
    [
        ({"duration_s": 0.0}, "duration_s"),
        ({"duration_s": float("nan")}, "duration_s"),
        ({"fps": 0.0}, "fps"),
        ({"start_xz": (0.0, float("inf"))}, "start_xz"),
        ({"heading_deg": float("nan")}, "heading_deg"),
        ({"start_category": "sitting"}, "start_category"),
    ],
)
def test_bad_params_raise(kw, name):
    with pytest.raises(ValueError, match=name):
        _clip(SUBJECTS[0], **kw)


def test_signals():
    t = np.linspace(0, 1, 101)
    s = minimum_jerk(t)
    assert s[0] == 0 and s[-1] == 1 and np.all(np.diff(s) >= 0)
    assert minimum_jerk(-1.0) == 0 and minimum_jerk(2.0) == 1
    x = colored_noise(4000, 120.0, 0.3, np.random.default_rng(0), channels=3)
    assert x.shape == (4000, 3) and np.allclose(np.sqrt(np.mean(x**2, axis=0)), 1.0)
    with pytest.raises(ValueError, match="corner_hz"):
        colored_noise(100, 120.0, 0.0, np.random.default_rng(0))
