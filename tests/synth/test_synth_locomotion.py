"""Synthetic locomotion: determinism, ground truth measured back from the motion (stride,
contacts, segments), planted feet, joint ranges, styles, subject habits, bad input.

Every measurement is taken from forward kinematics of the generated clips, never from the
generator's parameters, except where the test compares the two.
"""

import numpy as np
import pandas as pd
import pytest

from motionvar.core import cmu_joint_map
from motionvar.core.quaternions import qinv, qrot
from motionvar.io.intervals import parse_named, parse_ranges
from motionvar.prep.segmentation import segment_motion
from motionvar.synth import (
    CONTRACT_COLUMNS,
    Manner,
    RunParams,
    SidestepParams,
    SynthSpec,
    WalkParams,
    generate_dataset,
    generate_run,
    generate_sidestep,
    generate_walk,
    make_subjects,
    sample_run_params,
    sample_sidestep_params,
    sample_walk_params,
)

SIDES = ("left", "right")


@pytest.fixture(scope="module")
def subjects():
    return make_subjects(3, seed=7)


@pytest.fixture(scope="module")
def clips(subjects):
    """(kind, Motion, truth) for a straight and a turning walk, an old-style walk, a run with
    a turn and a side-step, of two subjects."""
    rng = np.random.default_rng(1)
    out = []
    for s in subjects[:2]:
        out.append(("walk", *generate_walk(s, sample_walk_params(s, rng, "neutral", n_steps=5))))
        out.append(("walk", *generate_walk(s, sample_walk_params(s, rng, "old", turn_deg=-70.0, n_steps=6))))
        out.append(("run", *generate_run(s, sample_run_params(s, rng, turn_deg=45.0, n_steps=4))))
        out.append(("sidestep", *generate_sidestep(s, sample_sidestep_params(s, rng, "right", n_cycles=3))))
    return out


def joint(m, positions, name):
    return positions[:, m.skeleton.index(name)]


def knee_flexion_deg(m, side):
    q = m.rotations[:, m.skeleton.index(side.capitalize() + "Leg")]
    return np.degrees(2.0 * np.arctan2(q[:, 1] * np.sign(q[:, 0]), np.abs(q[:, 0])))


def sagittal_deg(m, joint_name, bone):
    """Angle (deg) of a child bone, in its parent joint's frame, in the y-z plane from
    straight down (forward positive)."""
    v = qrot(m.rotations[:, m.skeleton.index(joint_name)], np.asarray(bone, dtype=float))
    return np.degrees(np.arctan2(v[:, 2], -v[:, 1]))


def stance_segments(truth):
    return [s for s in parse_named(truth["segments"]) if "Stance" in s[0]]


# ---------------------------------------------------------------- determinism, contract


def test_generators_are_deterministic(subjects):
    s = subjects[0]
    for gen, p in (
        (generate_walk, sample_walk_params(s, np.random.default_rng(3), "female", turn_deg=40.0)),
        (generate_run, sample_run_params(s, np.random.default_rng(3))),
        (generate_sidestep, sample_sidestep_params(s, np.random.default_rng(3))),
    ):
        (m1, t1), (m2, t2) = gen(s, p), gen(s, p)
        assert np.array_equal(m1.root_pos, m2.root_pos) and np.array_equal(m1.rotations, m2.rotations)
        assert t1 == t2 or pd.Series(t1).equals(pd.Series(t2))
    # same seed, same draws
    a = sample_walk_params(s, np.random.default_rng(5), "angry")
    b = sample_walk_params(s, np.random.default_rng(5), "angry")
    assert a == b


SMALL = dict(
    subjects=2,
    walks_per_style=1,
    turning_walks=1,
    runs=1,
    sidesteps=1,
    picks=1,
    places=1,
    idle_clips=1,
    idle_duration_s=2.0,
)


def test_dataset_is_deterministic_and_follows_the_contract():
    m1, meta1 = generate_dataset(SynthSpec(**SMALL))
    m2, meta2 = generate_dataset(SynthSpec(**SMALL), workers=2)  # parallel: the same data
    pd.testing.assert_frame_equal(meta1, meta2)
    assert all(
        np.array_equal(a.rotations, b.rotations) and np.array_equal(a.root_pos, b.root_pos) for a, b in zip(m1, m2)
    )

    assert list(meta1.columns[: len(CONTRACT_COLUMNS)]) == list(CONTRACT_COLUMNS)
    assert any(c.startswith("subj_") for c in meta1.columns)
    assert meta1["clip_id"].is_unique and len(meta1) == len(m1) == 2 * (7 + 1 + 1 + 1 + 1 + 1 + 1)
    assert set(meta1["behaviour"]) == {"walk", "run", "sidestep", "pick", "place", "idle"}
    walks = meta1[meta1.behaviour == "walk"]
    assert set(walks["style"]) == {"neutral", "proud", "depressed", "angry", "female", "childlike", "old"}
    assert set(walks["variant"]) <= {"forward", "left", "right"} and (meta1.primitive == "").all()
    loco = meta1.behaviour.isin(["walk", "run", "sidestep"])
    assert meta1.loc[loco, ["stride_length_cm", "speed_cm_s", "step_width_cm", "turn_deg"]].notna().all().all()
    assert meta1.loc[~loco, "stride_length_cm"].isna().all()
    assert meta1.loc[loco, ["target_x", "target_y", "target_z"]].isna().all().all()
    assert meta1.loc[meta1.behaviour != "idle", "idle_postures"].isna().all()
    assert meta1[["segments", "left_contacts", "right_contacts"]].notna().all().all()
    for m, (_, row) in zip(m1, meta1.iterrows()):  # every interval lies inside its clip
        for col in ("left_contacts", "right_contacts"):
            assert all(0 <= a < b <= m.n_frames for a, b in parse_ranges(row[col]))
        assert all(0 <= a < b <= m.n_frames for _, a, b in parse_named(row["segments"]))
    # a changed count of one behaviour leaves the other behaviours' clips as they were
    m3, meta3 = generate_dataset(SynthSpec(**{**SMALL, "subjects": 1, "runs": 2}))
    same = meta3[meta3.behaviour != "run"].reset_index(drop=True)
    first = meta1[(meta1.behaviour != "run") & (meta1.subject == meta3.subject[0])].reset_index(drop=True)
    pd.testing.assert_frame_equal(same, first)


# ---------------------------------------------------------------- ground truth from FK


def footprints(m, truth, side):
    """Ankle positions (K, 2) on the floor at each contact's first frame, and the starts."""
    p = joint(m, m.positions(), side.capitalize() + "Foot")
    starts = np.array([a for a, _ in parse_ranges(truth[side + "_contacts"])])
    return p[starts][:, [0, 2]], starts


def test_stride_length_measured_from_fk_matches_metadata(clips):
    """Stride = distance between successive same-foot contact positions (the ankle at the
    contact's first frame). Walks count the strides between heel strikes that open a
    stance primitive (the half steps of gait initiation and the closing step are not
    strides); runs and side-steps count every pair of successive contacts inside the clip."""
    for kind, m, truth in clips:
        strides = []
        opens = {s[1] for s in stance_segments(truth)}
        for side in SIDES:
            xz, starts = footprints(m, truth, side)
            keep = np.isin(starts, list(opens)) if kind == "walk" else starts > 0
            if kind == "sidestep":
                keep = np.ones(len(starts), dtype=bool)
            pts = xz[keep]
            strides += list(np.linalg.norm(np.diff(pts, axis=0), axis=1))
        measured = float(np.mean(strides))
        assert abs(measured - truth["stride_length_cm"]) <= 0.02 * truth["stride_length_cm"], (kind, measured, truth)


def test_speed_measured_from_the_root_matches_metadata(clips):
    for kind, m, truth in clips:
        segs = stance_segments(truth) or parse_named(truth["segments"])
        a, b = segs[0][1], segs[-1][1]
        path = np.linalg.norm(np.diff(m.root_pos[a:b, [0, 2]], axis=0), axis=1).sum()
        measured = path / ((b - a) / m.fps)
        assert abs(measured - truth["speed_cm_s"]) <= 0.05 * truth["speed_cm_s"], (kind, measured, truth["speed_cm_s"])


def test_planted_feet_do_not_slide(clips):
    """Contact point: the ankle while it is at its lowest in the contact (heel down), the toe
    base while it is at its lowest (forefoot down). Each moves < 0.5 cm horizontally while
    down, and in every contact frame one of them is down."""
    for kind, m, truth in clips:
        pos = m.positions()
        for side in SIDES:
            ankle, toe = joint(m, pos, side.capitalize() + "Foot"), joint(m, pos, side.capitalize() + "ToeBase")
            for a, b in parse_ranges(truth[side + "_contacts"]):
                covered = np.zeros(b - a, dtype=bool)
                for p in (ankle[a:b], toe[a:b]):
                    down = p[:, 1] <= p[:, 1].min() + 0.05
                    xz = p[down][:, [0, 2]]
                    assert np.linalg.norm(xz - xz[0], axis=1).max() < 0.5, (kind, side, a, b)
                    covered |= down
                assert covered.all(), (kind, side, a, b)


def test_swing_feet_clear_the_floor_and_land_on_their_footprints(clips):
    for kind, m, truth in clips:
        pos = m.positions()
        for side in SIDES:
            toe = joint(m, pos, side.capitalize() + "ToeBase")
            assert toe[:, 1].min() > -1e-6, (kind, side)
            contacts = parse_ranges(truth[side + "_contacts"])
            for (_, stop), (start, _) in zip(contacts[:-1], contacts[1:]):
                mid = slice(stop + (start - stop) // 5, start - (start - stop) // 5)
                assert toe[mid, 1].min() > 1.0, (kind, side, stop, start)  # minimum toe clearance
        assert truth["stance_ik_error_cm"] < 1e-6


def test_joint_angles_stay_in_human_ranges(clips):
    """Knee a hinge flexing 0-140° (never hyperextended), hip -35..+125° (extension..flexion,
    relative to the pelvis), ankle -40..+55° (dorsi..plantarflexion)."""
    for kind, m, _ in clips:
        for side in SIDES:
            cap = side.capitalize()
            q = m.rotations[:, m.skeleton.index(cap + "Leg")]
            assert np.abs(q[:, 2:]).max() < 1e-9  # pure hinge about x
            knee = knee_flexion_deg(m, side)
            assert knee.min() >= 0.0 and knee.max() <= 140.0, (kind, side, knee.min(), knee.max())
            hip = sagittal_deg(m, cap + "UpLeg", [0, -1, 0])
            assert -35.0 <= hip.min() and hip.max() <= 125.0, (kind, side, hip.min(), hip.max())
            toes = qrot(m.rotations[:, m.skeleton.index(cap + "Foot")], np.array([0.0, 0.0, 1.0]))
            ankle = np.degrees(np.arctan2(-toes[:, 1], toes[:, 2]))  # toes down = plantarflexion > 0
            assert -40.0 <= ankle.min() and ankle.max() <= 55.0, (kind, side, ankle.min(), ankle.max())
        if kind == "walk":  # docs/gait.md: swing knee peak 60-65° (× habit), stance ≈ 5° at heel strike
            assert 45.0 < max(knee_flexion_deg(m, s).max() for s in SIDES) < 90.0
        if kind == "run":  # docs/gait.md: 90-130° in swing
            assert max(knee_flexion_deg(m, s).max() for s in SIDES) > 85.0


def test_segments_and_contacts_are_consistent(clips):
    for kind, m, truth in clips:
        segs = parse_named(truth["segments"])
        starts = {s: {a for a, _ in parse_ranges(truth[s + "_contacts"])} for s in SIDES}
        if kind == "walk":
            assert (
                segs[0][0] == "walk_start"
                and segs[0][1] == 0
                and segs[-1][0] == "walk_end"
                and segs[-1][2] == m.n_frames
            )
            assert all(a[2] == b[1] for a, b in zip(segs[:-1], segs[1:]))  # contiguous
            for side in SIDES:  # both feet down while standing at either end
                r = parse_ranges(truth[side + "_contacts"])
                assert r[0][0] == 0 and r[-1][1] == m.n_frames
        for name, a, b in segs:
            if "Stance" in name:
                side = "left" if "left" in name else "right"
                other = "right" if side == "left" else "left"
                assert a in starts[side] and b in starts[other], (kind, name, a, b)
        if kind == "run":  # flight: frames in which neither foot touches the floor
            mask = np.zeros((2, m.n_frames), dtype=bool)
            for i, side in enumerate(SIDES):
                for a, b in parse_ranges(truth[side + "_contacts"]):
                    mask[i, a:b] = True
            assert (~mask.any(axis=0)).sum() > 0.1 * m.n_frames and not mask.all(axis=0).any()
        if kind == "sidestep":
            trail = "left" if truth["variant"] == "right" else "right"
            assert all(a in starts[trail] and b in starts[trail] for _, a, b in segs)


def test_prep_recovers_the_ground_truth_primitives(clips):
    """motionvar.prep segments from foot contacts alone; it must find the generator's
    primitives (same names, boundaries within 3 frames = 25 ms)."""
    jm = cmu_joint_map()
    for kind, m, truth in clips:
        found = segment_motion(m, kind, jm)
        want = parse_named(truth["segments"])
        assert [s.name for s in found] == [s[0] for s in want], kind
        assert max(max(abs(f.start - w[1]), abs(f.stop - w[2])) for f, w in zip(found, want)) <= 3, kind


# ---------------------------------------------------------------- styles and habits


def gait_measures(m, truth):
    """Speed, cadence, step width, arm swing, elbow flexion and head pitch measured from the
    clip's steady gait (from the first to the last stance primitive)."""
    pos = m.positions()
    segs = stance_segments(truth)
    a, b = segs[0][1], segs[-1][1]
    root = m.root_pos[a:b, [0, 2]]
    fwd = root[-1] - root[0]
    fwd /= np.linalg.norm(fwd)
    lateral = np.array([fwd[1], -fwd[0]])
    speed = np.linalg.norm(root[-1] - root[0]) / ((b - a) / m.fps)
    cadence = 60.0 * (len(segs) - 1) / ((segs[-1][1] - segs[0][1]) / m.fps)
    lat = {s: np.array([p @ lateral for p, st in zip(*footprints(m, truth, s)) if a <= st <= b]) for s in SIDES}
    width = abs(lat["left"].mean() - lat["right"].mean())
    # upper arm in the chest frame: sagittal angle of shoulder -> elbow
    g = m.global_rotations()
    chest = g[a:b, m.skeleton.index("Spine1")]
    arm = []
    for side in ("Left", "Right"):
        v = joint(m, pos, side + "ForeArm")[a:b] - joint(m, pos, side + "Arm")[a:b]
        v = qrot(qinv(chest), v)
        ang = np.degrees(np.arctan2(v[:, 2], -v[:, 1]))
        arm.append(0.5 * (ang.max() - ang.min()))
    elbow = []
    for side in ("Left", "Right"):
        q = m.rotations[a:b, m.skeleton.index(side + "ForeArm")]
        elbow.append(np.degrees(2 * np.arccos(np.clip(np.abs(q[:, 0]), 0, 1))).mean())
    head_up = qrot(g[a:b, m.skeleton.index("Head")], np.array([0.0, 1.0, 0.0]))
    head_pitch = np.degrees(np.arctan2(head_up[:, [0, 2]] @ fwd, head_up[:, 1])).mean()
    chest_up = qrot(chest, np.array([0.0, 1.0, 0.0]))
    lean = np.degrees(np.arctan2(chest_up[:, [0, 2]] @ fwd, chest_up[:, 1])).mean()
    return dict(
        speed=speed, cadence=cadence, width=width, arm=np.mean(arm), elbow=np.mean(elbow), head=head_pitch, lean=lean
    )


def test_styles_differ_in_the_documented_directions(subjects):
    rng = np.random.default_rng(2)
    meas = {}
    for style in ("neutral", "proud", "depressed", "angry", "female", "childlike", "old"):
        rows = [
            gait_measures(*generate_walk(s, sample_walk_params(s, rng, style, n_steps=6)))
            for s in subjects
            for _ in range(2)
        ]
        meas[style] = pd.DataFrame(rows).mean().to_dict()
    n, p, d, a, o = (meas[k] for k in ("neutral", "proud", "depressed", "angry", "old"))
    assert d["speed"] < 0.8 * p["speed"] and d["arm"] < 0.6 * p["arm"]
    assert d["head"] > p["head"] + 15 and d["lean"] > p["lean"] + 8
    assert d["speed"] < n["speed"] < p["speed"] and d["arm"] < n["arm"] < p["arm"]
    assert a["speed"] > n["speed"] and a["elbow"] > n["elbow"] + 15 and a["arm"] > n["arm"]
    assert o["speed"] < n["speed"] and o["width"] > n["width"] + 2 and o["lean"] > n["lean"] + 4
    assert meas["childlike"]["cadence"] > 1.1 * n["cadence"]
    assert meas["female"]["width"] < 0.5 * n["width"]


def test_subject_habits_persist_across_clips():
    """Arm swing and trunk lean measured from neutral walks: the spread between subjects'
    means is larger than the spread of a subject's own clips."""
    subs = make_subjects(4, seed=11)
    rng = np.random.default_rng(4)
    table = pd.DataFrame(
        [
            {
                "subject": s.subject_id,
                **gait_measures(*generate_walk(s, sample_walk_params(s, rng, "neutral", n_steps=5))),
            }
            for s in subs
            for _ in range(3)
        ]
    )
    for habit in ("arm", "lean"):
        between = table.groupby("subject")[habit].mean().var()
        within = table.groupby("subject")[habit].var().mean()
        assert between > 4.0 * within, (habit, between, within)


# ---------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    "make, name",
    [
        (lambda s: WalkParams(stride_length_cm=-5.0), "stride_length_cm"),
        (lambda s: WalkParams(n_steps=1), "n_steps"),
        (lambda s: WalkParams(style="happy"), "style"),
        (lambda s: WalkParams(first_foot="middle"), "first_foot"),
        (lambda s: WalkParams(turn_deg=float("nan")), "turn_deg"),
        (lambda s: WalkParams(speed_cm_s=300.0, stride_length_cm=60.0), "speed_cm_s"),
        (lambda s: WalkParams(manner=Manner(knee_peak_deg=170.0)), "knee_peak_deg"),
        (lambda s: RunParams(manner=Manner(stance_fraction=0.7)), "stance_fraction"),
        (lambda s: SidestepParams(direction="up"), "direction"),
        (lambda s: SidestepParams(n_cycles=1), "n_cycles"),
        (lambda s: sample_walk_params(s, np.random.default_rng(0), "happy"), "style"),
    ],
)
def test_bad_params_raise_value_error_naming_the_parameter(subjects, make, name):
    gens = {WalkParams: generate_walk, RunParams: generate_run, SidestepParams: generate_sidestep}
    with pytest.raises(ValueError, match=name):
        p = make(subjects[0])
        gens[type(p)](subjects[0], p)


def test_unwalkable_strides_and_bad_specs_are_rejected(subjects):
    with pytest.raises(ValueError, match="stride_length_cm"):
        generate_walk(subjects[0], WalkParams(stride_length_cm=240.0, speed_cm_s=230.0))
    for bad in ({"subjects": 0}, {"seed": -1}, {"runs": 1.5}, {"idle_duration_s": -1.0}, {"fps": 0}):
        with pytest.raises(ValueError, match=next(iter(bad))):
            generate_dataset(SynthSpec(**bad))
    with pytest.raises(ValueError, match="workers"):
        generate_dataset(SynthSpec(subjects=1), workers=0)
