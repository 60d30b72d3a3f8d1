"""Du 2022 ch. 5 features (Sec. 5.2: the 21 joints, heading-relative positions) and the networks (Eq. 5.1-5.2, Fig. 5.3)."""

import numpy as np
import pytest
import torch
from style_toy import toy_walk

from motionvar.core import JointMap, cmu_joint_map, cmu_skeleton
from motionvar.du2022.style import (
    AutoencoderSettings,
    ConvAutoencoder,
    FeatureScaler,
    MotionVAE,
    VaeSettings,
    features_to_positions,
    heading_angles,
    motion_features,
    motions_features,
    positions_to_features,
    sliding_windows,
    step_lengths,
    style_joints,
)

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


CMU_21 = (
    "Hips",
    "Spine",
    "Spine1",
    "Neck1",
    "Head",
    "LeftShoulder",
    "LeftArm",
    "LeftForeArm",
    "LeftHand",
    "RightShoulder",
    "RightArm",
    "RightForeArm",
    "RightHand",
    "LeftUpLeg",
    "LeftLeg",
    "LeftFoot",
    "LeftToeBase",
    "RightUpLeg",
    "RightLeg",
    "RightFoot",
    "RightToeBase",
)


def test_style_joints_are_the_21_of_the_thesis(layout):
    assert layout.names == CMU_21
    assert layout.n_channels == 66  # "each frame is represented as a vector of length 66"
    assert layout.parents[0] == -1
    assert all(layout.parents[k] < k for k in range(1, 21))
    # clavicle parent of the shoulder, neck parent of the head
    assert layout.names[layout.parents[layout.names.index("LeftArm")]] == "LeftShoulder"
    assert layout.names[layout.parents[layout.names.index("Head")]] == "Neck1"


def test_style_joints_missing_semantic_joint_is_named():
    jm = cmu_joint_map()
    joints = dict(jm.joints)
    del joints["left_toe"]
    with pytest.raises(ValueError, match="left_toe"):
        style_joints(cmu_skeleton(), JointMap(joints=joints, groups=jm.groups))


def test_features_round_trip_to_positions(layout):
    m = toy_walk()
    pos = m.positions()[:, layout.joints]
    f = positions_to_features(pos, layout)
    assert f.shape == (60, 66)
    theta0 = heading_angles(pos, layout)[0]
    back = features_to_positions(f, layout, start_heading=theta0)
    ground0 = pos[0, 0] * np.array([1, 0, 1])
    # the last frame's velocity repeats the one before, so all but the last frame's root
    # are exact, and poses are exact everywhere
    assert np.allclose(back[:-1] + ground0, pos[:-1], atol=1e-9)
    assert np.allclose(back - back[:, :1], pos - pos[:, :1], atol=1e-9)


def test_features_are_invariant_to_place_and_heading(layout):
    m = toy_walk(seed=3)
    pos = m.positions()[:, layout.joints]
    a = 1.1
    c, s = np.cos(a), np.sin(a)
    turned = pos @ np.array([[c, 0, -s], [0, 1, 0], [s, 0, c]]).T + np.array([40.0, 0.0, -7.0])
    assert np.allclose(positions_to_features(turned, layout), positions_to_features(pos, layout), atol=1e-9)


def test_features_face_plus_x_and_measure_speed(layout):
    # a body walking straight along +z (its facing on the CMU rig) at 2 cm a frame
    m = toy_walk(turn=0.0, speed=2.0, swing=0.0, arm=0.0)
    m.rotations[:, 0] = [1, 0, 0, 0]
    m.root_pos[:] = np.array([0, 95.0, 0]) + np.arange(60)[:, None] * np.array([0, 0, 2.0])
    f = motion_features(m, layout)
    local = f[:, :63].reshape(60, 21, 3)
    left = layout.names.index("LeftUpLeg")
    assert np.all(local[:, left, 2] < 0)  # facing +x: the left side is at -z
    assert np.allclose(np.hypot(f[:, 63], f[:, 64]), 2.0) and np.allclose(f[:, 63], 2.0, atol=1e-2)
    assert np.allclose(f[:, 65], 0.0)
    assert np.allclose(step_lengths(f[None], 21), 2.0 * 59)


def test_features_bad_input(layout):
    with pytest.raises(ValueError, match="positions must be"):
        positions_to_features(np.zeros((10, 20, 3)), layout)
    with pytest.raises(ValueError, match="at least 2 frames"):
        positions_to_features(np.zeros((1, 21, 3)), layout)
    with pytest.raises(ValueError, match="clip 1 has 50 frames"):
        motions_features([toy_walk(), toy_walk(n_frames=50)], layout)
    with pytest.raises(ValueError, match="facing direction undefined"):
        positions_to_features(np.zeros((5, 21, 3)), layout)
    with pytest.raises(ValueError, match="expected 66 channels"):
        features_to_positions(np.zeros((5, 60)), layout)


def test_sliding_windows_of_60_overlapping_by_half():
    clips = [np.arange(150 * 2).reshape(150, 2), np.zeros((40, 2)), np.ones((60, 2))]
    w = sliding_windows(clips, 60, 30)
    assert w.shape == (4 + 0 + 1, 60, 2)
    assert np.array_equal(w[1], clips[0][30:90])
    with pytest.raises(ValueError, match="no clip has"):
        sliding_windows([np.zeros((10, 2))], 60, 30)


def test_scaler_pools_positions_and_inverts(layout):
    f = motions_features([toy_walk(seed=s) for s in range(4)], layout)
    sc = FeatureScaler(21).fit(f)
    assert len(np.unique(sc.std_[:63])) == 1 and sc.std_[63] == sc.std_[64]
    assert np.allclose(sc.inverse(sc.transform(f)), f, atol=1e-4)
    # float64 scaled * std + mean, into a given array too (strided input as a decoder's transpose)
    scaled = sc.transform(f).transpose(1, 0, 2).copy().transpose(1, 0, 2)
    expected = np.asarray(scaled, dtype=float) * sc.std_ + sc.mean_
    out = np.empty(f.shape)
    assert sc.inverse(scaled).tobytes() == expected.tobytes()
    assert sc.inverse(scaled, out=out) is out and out.tobytes() == expected.tobytes()


def test_conv_autoencoder_shapes_and_eq_5_2_depooling():
    torch.manual_seed(0)
    thesis = AutoencoderSettings()  # the defaults: Sec. 5.3.1's 256 kernels of 15 frames
    ae = ConvAutoencoder(66, thesis.kernels, thesis.kernel_width, thesis.decoder_order)
    assert ae.conv.weight.shape == ae.deconv.weight.shape == (256, 66, 15)  # W' has W's shape
    x = torch.randn(3, 66, 60)
    y = ae.encode(x)
    assert y.shape == (3, 256, 30) and torch.all(y >= 0)  # ReLU then average pooling
    out = ae.decode(y)
    assert out.shape == x.shape
    assert torch.equal(out[..., 0::2], out[..., 1::2])  # Eq. 5.2 depools after the convolution
    smooth = ConvAutoencoder(66, 256, 15, decoder_order="depool_conv")
    assert not torch.equal(smooth(x)[..., 0::2], smooth(x)[..., 1::2])
    with pytest.raises(ValueError, match="multiple of the pooling"):
        ae.encode(torch.randn(1, 66, 59))
    with pytest.raises(ValueError, match="decoder_order"):
        ConvAutoencoder(66, 256, 15, decoder_order="max")


def test_vae_architecture_of_fig_5_3():
    from motionvar.du2022.style.networks import VAE_HIDDEN

    vae = MotionVAE(7680, VAE_HIDDEN, VaeSettings().latent)  # the default latent size: the thesis' 32
    lin = [m for m in vae.encoder if isinstance(m, torch.nn.Linear)]
    assert [m.out_features for m in lin] == [512, 256, 128]
    assert vae.mu.out_features == vae.logvar.out_features == 32
    dec = [m.out_features for m in vae.decoder if isinstance(m, torch.nn.Linear)]
    assert dec == [128, 256, 512, 7680]
    assert isinstance(vae.decoder[-1], torch.nn.Linear)  # no tanh on the output
    assert vae.sample(5, torch.Generator().manual_seed(0)).shape == (5, 7680)
