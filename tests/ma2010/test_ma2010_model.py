"""Ma 2010 the whole model (Sec. 5-6) on toy clips: style, prediction of held-out strides, structure, real-time synthesis."""

import numpy as np
import pytest
from ma2010_toy import DEFAULTS, JM

from motionvar.core.quaternions import qmul, qnormalize
from motionvar.ma2010 import StyleVariationModel, normalized_strides, resolve_structure, root_solver, structure_evidence
from motionvar.ma2010.correspondence import retime
from motionvar.ma2010.keyframes import keyframe_signal
from motionvar.ma2010.network import LOWER_FIRST, UPPER_FIRST
from motionvar.ma2010.variation import joint_variation


def svi_model(groups, structure="auto"):
    """The model with the default variogram (config ma2010.model.variogram_model, variogram_scale)."""
    return StyleVariationModel(
        groups, structure, DEFAULTS.model.variogram_model, variogram_scale=DEFAULTS.model.variogram_scale
    )


def test_clipset_style_is_the_stride_on_the_standard_skeleton(toy_clips):
    assert toy_clips.style.shape == (toy_clips.n_clips, 2)
    assert np.all((toy_clips.style > 60) & (toy_clips.style < 200))
    assert toy_clips.rotations.shape[1] == 48 and np.all(np.diff(toy_clips.key_times, axis=1) > 0)


def test_model_predicts_held_out_strides_and_varies_at_fixed_style(toy_clips):
    groups = JM.group_indices(toy_clips.skeleton)
    solver = root_solver(toy_clips.skeleton, JM)
    rng = np.random.default_rng(6)
    errors = []
    for i in (0, 7, 13):
        model = svi_model(groups).fit(toy_clips.subset(np.arange(toy_clips.n_clips) != i), d_lower=1, d_upper=0)
        pred, _ = model.synthesize_clips(toy_clips.style[i], rng=rng)
        rot, _ = retime(pred.rotations[0], model.reference_keys_, pred.key_times[0], toy_clips.fps)
        kf = np.minimum(np.round((pred.key_times[0] - pred.key_times[0, 0]) * toy_clips.fps).astype(int), len(rot) - 1)
        errors.append(normalized_strides(rot, kf, solver, toy_clips.fps) - toy_clips.style[i])
    assert np.abs(errors).max() < 3.0  # cm
    model = svi_model(groups, "lower_first").fit(toy_clips)
    c = np.tile(toy_clips.style.mean(0), (5, 1))
    pred, xi = model.synthesize_clips(c, rng=rng)
    spread = pred.rotations[:, :, groups["left_arm"]].std(axis=0).mean()
    assert spread > 1e-3 and np.ptp(xi["left_arm"]) > 0
    again, _ = model.synthesize_clips(c, fixed={g: v for g, v in xi.items()}, noise=False)
    assert np.allclose(again.rotations, pred.rotations)  # xi set by hand reproduces the clips
    assert np.allclose(np.linalg.norm(pred.rotations, axis=-1), 1.0)


def test_model_rejects_bad_groups_and_structure(toy_clips):
    groups = JM.group_indices(toy_clips.skeleton)
    with pytest.raises(ValueError, match="missing"):
        svi_model({k: v for k, v in groups.items() if k != "legs"}).fit(toy_clips, 1, 0)
    with pytest.raises(ValueError, match="unknown structure"):
        svi_model(groups, "sideways").fit(toy_clips)


def test_auto_structure_measures_d_l_and_d_u_of_the_examples(toy_clips):
    """Fig. 5 "auto": with D_l and D_u not given, the model measures them on its examples
    (Eq. 3 over every clip's frames); walking moves the legs most, so lower-first."""
    from motionvar.core.kinematics import fk

    groups = JM.group_indices(toy_clips.skeleton)
    d_l, d_u = structure_evidence(toy_clips, groups)
    sk = toy_clips.skeleton
    upper = np.setdiff1d(np.arange(sk.n_joints), groups["legs"])
    per_clip = [
        keyframe_signal(fk(r, np.zeros((len(r), 3)), sk.offsets, sk.parents), groups["legs"], upper)
        for r in toy_clips.rotations
    ]
    assert d_l == pytest.approx(np.sqrt(sum(s.d_lower**2 for s in per_clip)))
    assert d_u == pytest.approx(np.sqrt(sum(s.d_upper**2 for s in per_clip))) and d_l > d_u
    assert resolve_structure("auto", toy_clips, groups) == "lower_first"
    assert resolve_structure("upper_first", toy_clips, groups) == "upper_first"
    model = svi_model(groups).fit(toy_clips)
    assert model.network_.structure == LOWER_FIRST and model.timing_group_ == "legs"
    assert svi_model(groups).fit(toy_clips, d_lower=0, d_upper=1).network_.structure == UPPER_FIRST


def test_realtime_clips_match_one_by_one_retiming(toy_clips):
    from motionvar.ma2010.synthesis import realtime_clips

    sub = toy_clips.subset(np.arange(3))
    together = realtime_clips(sub.rotations, sub.key_times, sub.reference_keys, sub.fps, sub.root_height)
    for m, (rot, height) in enumerate(together):
        one, h = retime(sub.rotations[m], sub.reference_keys, sub.key_times[m], sub.fps, sub.root_height[m])
        assert np.allclose(np.abs(np.sum(rot * one, axis=-1)), 1.0) and np.allclose(height, h)


def test_a_constant_posture_offset_cancels_out_of_xi_exactly():
    """Eq. 7 sums the distances between consecutive rotations of a joint, so a constant
    rotation offset of the joint (a torso lean, an elbow held more flexed), on either side,
    leaves delta and hence xi unchanged: between-subject posture offsets cannot enter xi
    (the ceiling of Fig. 8's variation)."""
    rng = np.random.default_rng(3)
    rot = qnormalize(rng.normal(size=(2, 30, 5, 4)))
    offset = qnormalize(rng.normal(size=(1, 1, 5, 4)))
    delta = joint_variation(rot)
    assert np.allclose(joint_variation(qmul(offset, rot)), delta, atol=1e-9)
    assert np.allclose(joint_variation(qmul(rot, offset)), delta, atol=1e-9)
    assert np.ptp(delta) > 0  # but the motion itself does vary
