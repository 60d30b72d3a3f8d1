"""The capture layer of the synthetic generator (motionvar.synth.capture, issue 32): captured-like
motion on the channels the generator holds constant, with the generator's ground truth intact."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from motionvar.core.quaternions import quat_to_rotvec
from motionvar.metrics import realism as rm
from motionvar.synth import BEHAVIOURS, SynthSpec, generate_dataset, make_subjects
from motionvar.synth.capture import (
    CAPTURE_CHANNELS,
    CORNER_HZ,
    GRIP_BEHAVIOURS,
    add_capture_motion,
    capture_offsets,
    capture_rng,
)
from motionvar.synth.dataset import _clips

SMALL = dict(
    subjects=1,
    walks_per_style=1,
    turning_walks=1,
    runs=1,
    sidesteps=1,
    picks=2,
    places=2,
    idle_clips=1,
    idle_duration_s=2.0,
    captured_variation=False,  # the clean clips; the capture layer is applied by _layered
)
LEGS = ("LHipJoint", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase")
LEGS += tuple(n.replace("Left", "Right").replace("LHip", "RHip") for n in LEGS)
HANDS = ("LeftHand", "RightHand")


@pytest.fixture(scope="module")
def both():
    """(clips with the capture layer, clips without it, metadata) of the same spec: the layer
    on the default clips, as generate_dataset applies it with captured_variation."""
    off, meta = generate_dataset(SynthSpec(**SMALL))
    return _layered(off, meta), off, meta


def _layered(clips, meta):
    seed, counts, out = SynthSpec(**SMALL).seed, {}, []
    for m, behaviour in zip(clips, meta["behaviour"]):
        n = counts[behaviour] = counts.get(behaviour, -1) + 1
        out.append(add_capture_motion(m, behaviour, capture_rng(seed, 0, BEHAVIOURS.index(behaviour), n)))
    return out


def _touched(skeleton) -> set[int]:
    """Joints whose local rotation the layer may change (its channels and the bone children)."""
    names = {n for g in CAPTURE_CHANNELS for n in g.joints}
    names |= {
        skeleton.names[skeleton.children(skeleton.index(n))[0]]
        for g in CAPTURE_CHANNELS
        if g.axes == "bone"
        for n in g.joints
    }
    return {skeleton.index(n) for n in names}


def test_constrained_joints_keep_their_positions(both):
    """Root, hips, knees, ankles and toes (and the gripping hands) are where the generator put
    them, to float precision; joints the layer does not touch keep their rotations bitwise."""
    on, off, meta = both
    for a, b, behaviour in zip(on, off, meta["behaviour"]):
        sk = a.skeleton
        names = ("Hips",) + LEGS + (HANDS if behaviour in GRIP_BEHAVIOURS else ())
        fixed = sk.indices(names)
        np.testing.assert_array_equal(a.root_pos, b.root_pos)
        np.testing.assert_allclose(a.positions()[:, fixed], b.positions()[:, fixed], rtol=0, atol=1e-6)
        feet = sk.indices(["LeftFoot", "RightFoot"])  # the foot's global orientation is kept too
        np.testing.assert_allclose(
            np.abs(np.sum(a.global_rotations()[:, feet] * b.global_rotations()[:, feet], axis=-1)), 1.0, atol=1e-12
        )
        untouched = [j for j in range(sk.n_joints) if j not in _touched(sk)]
        np.testing.assert_array_equal(a.rotations[:, untouched], b.rotations[:, untouched])
        if behaviour in GRIP_BEHAVIOURS:  # nothing on the path to the hands moves
            arms = sk.indices(["LeftForeArm", "RightForeArm"])
            np.testing.assert_array_equal(a.rotations[:, arms], b.rotations[:, arms])


def _sd(motions) -> dict[str, np.ndarray]:
    """Joint name -> (3,) channel SD in degrees over the clips (float32, as the pipeline packs them)."""
    sd = rm.rotation_channel_sd(np.concatenate([m.rotations.astype(np.float32) for m in motions]))
    return dict(zip(motions[0].skeleton.names, sd))


TARGETED = {
    "LeftLeg": "y",
    "RightLeg": "y",
    "LeftToeBase": "xy",
    "RightToeBase": "xy",
    "Neck": "xyz",
    "Neck1": "z",
    "LeftForeArm": "z",
    "RightForeArm": "z",
    "LeftHand": "x",
    "RightHand": "x",
    "LeftFingerBase": "xyz",
    "RightFingerBase": "xyz",
    "LThumb": "xyz",
    "RThumb": "xyz",
}
KEPT_STILL = ("LeftHandIndex1", "RightHandIndex1", "LHipJoint", "RHipJoint")


@pytest.mark.parametrize("behaviour", BEHAVIOURS)
def test_targeted_channels_move_and_still_ones_stay(both, behaviour):
    on, off, meta = both
    clips = [m for m, b in zip(on, meta["behaviour"]) if b == behaviour]
    before = _sd([m for m, b in zip(off, meta["behaviour"]) if b == behaviour])
    sd = _sd(clips)
    for name, axes in TARGETED.items():
        if behaviour in GRIP_BEHAVIOURS and "ForeArm" in name:
            np.testing.assert_array_equal(sd[name], before[name])
            continue
        for a in axes:
            assert sd[name]["xyz".index(a)] > 0.5, (name, a)
    for name in KEPT_STILL:
        assert np.all(sd[name] < 1e-3), name
    for name in ("LeftShoulder", "RightShoulder"):  # collars: no motion added
        np.testing.assert_array_equal(sd[name], before[name])


def test_capture_motion_is_smooth_and_zero_mean(both):
    """A slowly varying process: almost no power at or above the realism table's 8 Hz noise band."""
    on, off, meta = both
    walk = off[int(np.flatnonzero(meta["behaviour"] == "walk")[0])]
    for turn in capture_offsets(walk, "walk", capture_rng(0, 0, 0, 0)).values():
        rotvec = quat_to_rotvec(turn)
        power = np.abs(np.fft.rfft(rotvec - rotvec.mean(axis=0), axis=0)) ** 2
        f = np.fft.rfftfreq(len(rotvec), 1.0 / walk.fps)
        assert power[f >= 4 * CORNER_HZ].sum() < 1e-3 * power.sum()
        assert np.all(np.abs(rotvec.mean(axis=0)) < 1e-9)


# SynthSpec(**SMALL) as the generator made it before captured variation became the default
# (commit 569f754): per clip, its frames, a weighted sum of its rotations and the sum of its
# root positions (weights 1 -> 2 over the flattened rotations, so a moved or reordered value shows)
CLEAN_FINGERPRINT = {
    "s01_walk_neutral_00": (641, 28348.227766198463, -182705.49629552744),
    "s01_walk_proud_00": (597, 27148.419943872294, 195215.47241122252),
    "s01_walk_depressed_00": (744, 34889.321555667906, 305321.325192843),
    "s01_walk_angry_00": (587, 27099.116718460697, -21451.31119674161),
    "s01_walk_female_00": (738, 34016.856088712804, 357766.676618192),
    "s01_walk_childlike_00": (632, 29185.35101665302, 12280.238427290686),
    "s01_walk_old_00": (760, 32909.71939314071, -188007.5206092807),
    "s01_walk_left_00": (617, 28787.909345515483, 5838.677638517751),
    "s01_run_forward_00": (330, 14523.931961759565, 66458.51114703799),
    "s01_sidestep_left_00": (838, 39195.32359706186, 353421.47805560834),
    "s01_pick_low_00": (454, 20059.594299589728, -3075.4294537768965),
    "s01_pick_forward_00": (316, 14295.77884104949, 94452.8228584298),
    "s01_place_low_00": (453, 19732.882905022743, 117917.73586718927),
    "s01_place_forward_00": (320, 14294.751392078866, -68439.84765392105),
    "s01_idle_standing_00": (241, 11201.541532985566, 14467.698688642278),
}


def _fingerprint(m) -> tuple[int, float, float]:
    r = m.rotations.astype(float)
    return (
        m.n_frames,
        float((r * np.linspace(1, 2, r.size).reshape(r.shape)).sum()),
        float(m.root_pos.astype(float).sum()),
    )


def test_off_is_the_generator_unchanged(both):
    """captured_variation=False gives the clips the generator made before it had captured
    variation (a stored fingerprint, equal to 1e-12), and they are the clips of its own streams."""
    _, off, meta = both
    assert list(meta["clip_id"]) == list(CLEAN_FINGERPRINT)
    for m, clip in zip(off, meta["clip_id"]):
        n, rot, root = _fingerprint(m)
        assert n == CLEAN_FINGERPRINT[clip][0], clip
        assert rot == pytest.approx(CLEAN_FINGERPRINT[clip][1], rel=1e-12), clip
        assert root == pytest.approx(CLEAN_FINGERPRINT[clip][2], rel=1e-12, abs=1e-9), clip
    spec = SynthSpec(**SMALL)
    subject = make_subjects(spec.subjects, spec.seed)[0]
    direct = [
        m
        for b, behaviour in enumerate(BEHAVIOURS)
        for _, _, m, _ in _clips(subject, spec, behaviour, np.random.default_rng([spec.seed, 0, b]))
    ]
    assert len(direct) == len(off)
    for a, b in zip(off, direct):
        np.testing.assert_array_equal(a.rotations, b.rotations)
        np.testing.assert_array_equal(a.root_pos, b.root_pos)


def test_negative_control_the_fingerprint_sees_one_changed_value(both):
    _, off, _ = both
    m = off[0]
    moved = m.rotations.astype(float).copy()
    moved[len(moved) // 2, 3, 1] += 1e-6
    assert _fingerprint(dataclasses.replace(m, rotations=moved))[1] != pytest.approx(_fingerprint(m)[1], rel=1e-12)


def test_same_seed_same_arrays_other_seed_other_motion(both):
    on, off, meta = both
    again = _layered(*generate_dataset(SynthSpec(**SMALL)))
    for a, b in zip(on, again):
        np.testing.assert_array_equal(a.rotations, b.rotations)
    given = off[0].rotations.copy()
    one = add_capture_motion(off[0], "walk", capture_rng(1, 0, 0, 0))
    np.testing.assert_array_equal(off[0].rotations, given)  # the input is left as it was
    np.testing.assert_array_equal(one.rotations, add_capture_motion(off[0], "walk", capture_rng(1, 0, 0, 0)).rotations)
    assert not np.array_equal(one.rotations, on[0].rotations)


def test_captured_variation_must_be_a_bool():
    with pytest.raises(ValueError, match="captured_variation"):
        SynthSpec(subjects=1, captured_variation=1).validate()
