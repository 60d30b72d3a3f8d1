"""Preprocessing (motionvar.prep): alignment to the origin heading along x, resampling and dynamic time warping."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from prep_toy import FPS, JM, WALK_STEPS, facing_heading, renamed_rig, standing, stepping, turned

from motionvar.core import JointMap, Motion
from motionvar.core import quaternions as Q
from motionvar.prep import (
    PrepOptions,
    align_motion,
    align_motions,
    apply_warp,
    detect_foot_contacts,
    dtw_warp,
    median_length_index,
    resample_motion,
    sample_motion,
    warp_to_median,
)
from motionvar.prep.timewarp import check_warp


def test_alignment_starts_at_origin_heading_x():
    rng = np.random.default_rng(3)
    base = stepping(WALK_STEPS, 2.5)
    clips = [
        turned(base.slice(k * 10, 200 + k * 10), rng.uniform(-np.pi, np.pi), rng.uniform(-300, 300, 2))
        for k in range(5)
    ]
    assert not np.allclose(facing_heading(clips[0]), [1, 0, 0], atol=0.1)
    aligned = align_motions(clips, JM)
    for src, a in zip(clips, aligned):
        assert np.allclose(a.root_pos[0, [0, 2]], 0.0, atol=1e-9)
        assert np.isclose(a.root_pos[0, 1], src.root_pos[0, 1])
        assert np.allclose(facing_heading(a), [1.0, 0.0, 0.0], atol=1e-9)
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
    assert np.allclose(facing_heading(align_motion(still, JM, PrepOptions(heading="movement"))), [1, 0, 0], atol=1e-9)


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
