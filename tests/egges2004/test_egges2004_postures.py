"""Egges 2004 posture PCA (Sec. 3.2), the distance and fitting of Eq. 4 and Fig. 5, and the rests, categories and graph (Sec. 5.1-5.3)."""

import numpy as np
import pytest
from egges2004_toy import toy_recording

from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import qangle, qidentity, quat_about_axis
from motionvar.egges2004 import (
    AnalysisSettings,
    CategoryGraph,
    PosturePCA,
    build_database,
    fit_anim,
    fit_anim_part,
    posture_distance,
    static_segments,
)
from motionvar.egges2004.categories import frame_labels, parse_postures, segment_agreement
from motionvar.egges2004.fitting import best_fitting_animation
from motionvar.egges2004.pca import continuous_rotvecs


def test_pca_round_trip_reproduces_rotations_and_root(toy):
    recs, pca, _, _ = toy
    m = recs[0][0]
    back = pca.reconstruct(pca.project(m), m.skeleton, m.fps)
    assert np.max(qangle(back.rotations, m.rotations)) < 1e-9
    assert np.allclose(back.root_pos, m.root_pos, atol=1e-9)
    assert pca.project(m).shape == (m.n_frames, 3 * m.skeleton.n_joints + 3)


def test_pca_weights_follow_footnote_1(toy):
    w = toy[1].weights()
    assert w[0] == 1.0 and np.all(w >= 0) and np.all(np.diff(w) <= 1e-15)


def test_continuous_rotvecs_do_not_jump_through_pi():
    angle = np.linspace(2.8, 3.5, 50)  # crosses pi: the folded log would flip the axis
    q = quat_about_axis([0, 1, 0], angle)[:, None]
    r = continuous_rotvecs(q)
    assert np.allclose(r[:, 0, 1], angle)


def test_pca_with_a_joint_subset_keeps_the_others_at_their_mean():
    m, _ = toy_recording(["left", "right"], [2, 2])
    pca = PosturePCA(0.01, joints=[0, 1, 2]).fit([m])
    rot, root = pca.to_rotations(pca.project(m))
    assert rot.shape == m.rotations.shape and np.allclose(root, m.root_pos)
    assert np.allclose(rot[:, 5:, 0], 1.0)  # identity rotations in the toy data


def test_pca_rejects_bad_input():
    m, _ = toy_recording(["left", "right"], [2, 2])
    with pytest.raises(ValueError, match="no motions"):
        PosturePCA(0.01).fit([])
    with pytest.raises(ValueError, match="joint indices"):
        PosturePCA(0.01, joints=[40]).fit([m])
    pca = PosturePCA(0.01, joints=[0, 1]).fit([m])
    small = Motion(
        cmu_skeleton().__class__(("a",), np.array([-1]), np.zeros((1, 3))), np.zeros((3, 3)), qidentity((3, 1)), 30.0
    )
    with pytest.raises(ValueError, match="joints"):
        pca.project(small)


def test_posture_distance_is_eq_4():
    p, q, w = np.array([1.0, 2.0, 3.0]), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.5, 0.25])
    assert posture_distance(p, q, w) == pytest.approx(1 + 0.5 * 4 + 0.25 * 4)


def test_best_fitting_animation_minimises_the_larger_distance():
    starts = np.array([[0.0], [1.0], [5.0]])
    ends = np.array([[9.0], [2.0], [5.0]])
    i, m = best_fitting_animation(starts, ends, np.array([0.0]), np.array([2.0]), np.ones(1))
    assert i == 1 and m.tolist() == [49.0, 1.0, 25.0]
    with pytest.raises(ValueError, match="empty"):
        best_fitting_animation(np.zeros((0, 1)), np.zeros((0, 1)), np.zeros(1), np.zeros(1), np.ones(1))


@pytest.mark.parametrize("ramp", ["linear", "smoothstep"])
def test_fit_anim_part_hits_both_postures(ramp):
    rng = np.random.default_rng(0)
    a = np.cumsum(rng.normal(size=(40, 5)), axis=0)
    p, q = rng.normal(size=5), rng.normal(size=5)
    fitted = fit_anim_part(a, 0, 39, p, q, ramp)
    assert np.allclose(fitted[0], p, atol=1e-12) and np.allclose(fitted[-1], q, atol=1e-12)
    assert np.allclose(a, np.cumsum(np.random.default_rng(0).normal(size=(40, 5)), axis=0))  # input untouched
    off = fitted - a
    if ramp == "linear":
        assert np.allclose(np.diff(off, 2, axis=0), 0, atol=1e-12)  # the offset is linear in time
    else:
        assert np.allclose(off[1] - off[0], 0, atol=0.02 * np.abs(q - a[-1] - p + a[0]).max() + 1e-12)


def test_fit_anim_interpolates_the_key_offsets_as_the_text_says():
    rng = np.random.default_rng(1)
    a = np.cumsum(rng.normal(size=(60, 3)), axis=0)
    keys = [(10, rng.normal(size=3)), (25, rng.normal(size=3)), (50, rng.normal(size=3))]
    got = fit_anim(a, keys)
    frames = [0] + [f for f, _ in keys] + [59]
    offsets = np.stack([np.zeros(3)] + [p - a[f] for f, p in keys] + [np.zeros(3)])
    ref = a + np.stack([np.interp(np.arange(60), frames, offsets[:, d]) for d in range(3)], axis=1)
    assert np.allclose(got, ref)
    for f, p in keys:
        assert np.allclose(got[f], p)
    assert np.allclose(got[0], a[0]) and np.allclose(got[-1], a[-1])
    # the first segment is exactly fitAnim_part with the animation's own frame 0 as target
    assert np.allclose(got[:11], fit_anim_part(a, 0, 10, a[0], keys[0][1])[:11])


def test_fitting_rejects_bad_frames():
    a = np.zeros((10, 2))
    with pytest.raises(ValueError, match="increase strictly"):
        fit_anim(a, [(5, np.zeros(2)), (5, np.ones(2))])
    with pytest.raises(ValueError, match="fi < fj"):
        fit_anim_part(a, 4, 2, np.zeros(2), np.zeros(2))
    with pytest.raises(ValueError, match="ramp"):
        fit_anim_part(a, 0, 9, np.zeros(2), np.zeros(2), ramp="cubic")


def test_static_segments_finds_the_slow_stretches():
    speed = np.array([0, 0, 0, 5, 5, 0, 0, 0, 0, 5, 0], dtype=float)
    assert static_segments(speed, fps=1.0, threshold=1.0, min_duration_s=3).tolist() == [[0, 3], [5, 9]]


def test_categories_are_found_and_match_the_truth(toy):
    recs, _, _, db = toy
    assert db.categories.names == ("left", "both", "right")
    for i, (_, truth) in enumerate(recs):
        segs, cats = db.segments[f"r{i}"]
        acc, ari = segment_agreement(segs, [db.categories.names[c] for c in cats], frame_labels(truth, 2000))
        assert acc == 1.0 and ari == 1.0


def test_category_graph_counts_transitions_and_times():
    g = CategoryGraph.from_sequences(("a", "b", "c"), [[0, 1, 0, 2], [1, 0]], [[1.0, 2.0, np.nan, 5.0], [3.0, 4.0]])
    assert g.counts.tolist() == [[0, 1, 1], [2, 0, 0], [0, 0, 0]]
    assert np.allclose(g.probabilities[0], [0, 0.5, 0.5]) and np.allclose(g.probabilities[2], 0)
    assert g.t_min.tolist() == [1.0, 2.0, 5.0] and g.t_max.tolist() == [4.0, 3.0, 5.0]
    rng = np.random.default_rng(0)
    assert g.shortest_route(1, 2, rng) == [1, 0, 2]
    assert g.shortest_route(0, 0, rng) == [0, 1, 0]  # the shortest cycle
    with pytest.raises(ValueError, match="no outgoing"):
        g.shortest_route(2, 0, rng)
    assert g.routable_pairs().tolist() == [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2]]
    for start, end in g.routable_pairs():
        assert g.shortest_route(start, end, rng)[-1] == end
    with pytest.raises(ValueError, match="one stay duration"):
        CategoryGraph.from_sequences(("a",), [[0, 0]], [[1.0]])


def test_shortest_route_breaks_ties_at_random():
    p = np.array([[0, 0.5, 0.5, 0], [0, 0, 0, 1], [0, 0, 0, 1], [1, 0, 0, 0]], dtype=float)
    g = CategoryGraph(("a", "b", "c", "d"), (p > 0).astype(int), p, np.ones(4), np.ones(4))
    routes = {tuple(g.shortest_route(0, 3, np.random.default_rng(s))) for s in range(20)}
    assert routes == {(0, 1, 3), (0, 2, 3)}


def test_database_removes_the_translation_offset(toy):
    _, pca, _, db = toy
    for a in db.animations:
        ends = pca.root_translation(a[[0, -1]])
        assert np.allclose(ends[:, [0, 2]].mean(axis=0), 0, atol=1e-9)
    assert len(db.animations) == 12 and db.graph.counts.sum() == 12
    assert np.allclose(db.graph.probabilities.sum(axis=1), 1)


def test_parse_postures_checks_items():
    assert parse_postures("left:0:480;both:480:900") == [("left", 0, 480), ("both", 480, 900)]
    with pytest.raises(ValueError, match="clip7"):
        parse_postures("left:0", "clip7")


def test_database_without_rests_is_an_error(toy):
    _, pca, analysed, _ = toy
    with pytest.raises(ValueError, match="no resting segment"):
        build_database(analysed, pca, AnalysisSettings(rest_speed=1e-12), "s9", 0)
