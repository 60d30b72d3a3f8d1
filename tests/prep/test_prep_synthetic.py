"""Preprocessing (motionvar.prep) on the synthetic generator's clips (its ground truth) and on a real CMU walk."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from bvh_files import real_bvh_dir
from prep_toy import JM, facing_heading

from motionvar.io import load_dataset, save_dataset
from motionvar.prep import (
    PrepOptions,
    detect_foot_contacts,
    intervals_to_mask,
    parse_intervals,
    parse_segments,
    preprocess_dataset,
    segment_motion,
)
from motionvar.prep.segmentation import hand_speed, reach_boundary
from motionvar.synth import locomotion, reach
from motionvar.synth.gait_params import RunParams, SidestepParams, WalkParams
from motionvar.synth.subjects import make_subjects

SUBJECTS = make_subjects(3, seed=7)


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
    return synthetic_clips()


def test_synthetic_contacts_agree_with_the_generator(synthetic):
    for behaviour, m, truth in synthetic:
        c = detect_foot_contacts(m, JM)
        for side in ("left", "right"):
            gt = intervals_to_mask(parse_intervals(truth[f"{side}_contacts"]), m.n_frames)
            agreement = np.mean(c.mask(side) == gt)
            assert agreement > 0.95, (behaviour, side, agreement)


def test_synthetic_segmentation_finds_every_step(synthetic):
    for behaviour, m, truth in synthetic:
        gt = parse_segments(truth["segments"])
        got = segment_motion(m, behaviour, JM)
        assert [s.name for s in got] == [s.name for s in gt], (behaviour, got, gt)
        err = np.abs(np.array([s[1:] for s in got]) - np.array([s[1:] for s in gt]))
        assert err.max() <= 3, (behaviour, got, gt)


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
            assert np.allclose(facing_heading(m), [1.0, 0.0, 0.0], atol=1e-6)
        walks = pmeta["primitive"].str.endswith("Stance") & pmeta["primitive"].str.startswith("walk")
        # a stance primitive of a straight walk travels forward, along +x
        fwd = [prims[i].root_pos[-1, 0] for i in np.flatnonzero(walks)]
        assert np.min(fwd) > 20.0


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


CMU = real_bvh_dir() / "cmu"


@pytest.mark.skipif(not (CMU / "02_01.bvh").is_file(), reason="CMU BVH files not present")
def test_real_cmu_walk_has_steps():
    from motionvar.core import CMU_UNIT_CM
    from motionvar.io import read_bvh

    m = read_bvh(CMU / "02_01.bvh", scale=CMU_UNIT_CM)
    m = m.slice(1, m.n_frames)  # frame 0 is the cgspeed T-pose
    segs = segment_motion(m, "walk", JM)
    stances = [s for s in segs if s.name.endswith("Stance")]
    assert len(stances) >= 2
