"""Du 2022 ch. 5 training of the autoencoder, VAEs and CVAEs, model files, diversity (Eq. 5.13-5.15) and the data selection (Sec. 5.4.1, 5.4.3)."""

import json

import numpy as np
import pandas as pd
import pytest
import torch
from style_toy import TINY_HIDDEN, toy_walk

from motionvar.core import cmu_joint_map, cmu_skeleton
from motionvar.du2022.style import (
    AutoencoderSettings,
    CvaeSettings,
    FeatureScaler,
    FeatureSpace,
    MotionVAE,
    TrainConfig,
    VaeSettings,
    diagonal_minima,
    diversity,
    kl_loss,
    load_vae,
    motion_features,
    motions_features,
    sample_features,
    sample_maps,
    save_vae,
    sliding_windows,
    style_distance,
    style_distance_matrix,
    style_joints,
    train_autoencoder,
    train_cvae,
    train_vae,
)

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


@pytest.fixture(scope="module")
def tiny(layout):
    """A trained tiny feature space and a clip set (a few seconds)."""
    clips = [toy_walk(n_frames=120, seed=s, turn=0.2 * s) for s in range(6)]
    windows = sliding_windows([motion_features(m, layout) for m in clips], 60, 30)
    scaler = FeatureScaler(21).fit(windows)
    ae, hist = train_autoencoder(
        scaler.transform(windows), AutoencoderSettings(kernels=16, epochs=30, lr=3e-3, batch_size=8), seed=0
    )
    prims = motions_features([toy_walk(seed=10 + s, swing=0.4 + 0.02 * s) for s in range(12)], layout)
    return FeatureSpace(ae, scaler), hist, prims


def test_autoencoder_learns_and_is_deterministic(tiny, layout):
    space, hist, prims = tiny
    assert list(hist.columns) == ["epoch", "loss", "end_loss", "seconds", "kept"] and len(hist) == 30
    assert hist["loss"].iloc[-1] < 0.5 * hist["loss"].iloc[0]
    clips = [toy_walk(n_frames=120, seed=s, turn=0.2 * s) for s in range(6)]
    windows = space.scaler.transform(sliding_windows([motion_features(m, layout) for m in clips], 60, 30))
    ae_settings = AutoencoderSettings(kernels=8, epochs=2, lr=1e-3, batch_size=4)
    a, _ = train_autoencoder(windows, ae_settings, seed=5)
    b, _ = train_autoencoder(windows, ae_settings, seed=5)
    assert all(torch.equal(p, q) for p, q in zip(a.state_dict().values(), b.state_dict().values()))


def test_autoencoder_keeps_the_best_epoch(tiny, layout):
    """keep="best" returns the weights of the epoch with the lowest end-of-epoch loss (a
    learning rate high enough to make the loss jump about), "last" the last epoch's."""
    space, _, _ = tiny
    clips = [toy_walk(n_frames=120, seed=s, turn=0.2 * s) for s in range(6)]
    windows = space.scaler.transform(sliding_windows([motion_features(m, layout) for m in clips], 60, 30))
    ae_settings = AutoencoderSettings(kernels=8, epochs=8, lr=3e-2, batch_size=4)
    x = torch.as_tensor(windows, dtype=torch.float32).permute(0, 2, 1)
    for keep in ("best", "last"):
        model, hist = train_autoencoder(windows, ae_settings.replace(keep=keep), seed=1)
        with torch.no_grad():
            loss = float(torch.mean((model(x) - x) ** 2))
        kept = hist.loc[hist["kept"]]
        assert len(kept) == 1 and loss == pytest.approx(float(kept["end_loss"].iloc[0]), rel=1e-4)
        if keep == "best":
            assert kept["end_loss"].iloc[0] == hist["end_loss"].min() and hist["end_loss"].notna().all()
        else:  # the loss over all windows is computed for the last epoch only
            assert kept["epoch"].iloc[0] == ae_settings.epochs
            assert hist["end_loss"].iloc[:-1].isna().all() and np.isfinite(hist["end_loss"].iloc[-1])
    with pytest.raises(ValueError, match="keep must be one of"):
        train_autoencoder(windows, ae_settings.replace(keep="first"), seed=1)


def test_sliced_adam_is_torch_adam_bit_for_bit():
    """SlicedAdam (slices of 7 elements here: across rows and with ragged tails) gives the
    weights of torch.optim.Adam exactly, over steps where a parameter has no gradient."""
    from motionvar.du2022.style.training import SlicedAdam

    def run(make):
        torch.manual_seed(0)
        vae = MotionVAE(40, hidden=(12, 6), latent=3)
        opt = make(vae.parameters())
        gen = torch.Generator().manual_seed(1)
        for step in range(6):
            mu, logvar = vae.encode(torch.randn(5, 40, generator=gen))
            recon = vae.decode(vae.reparameterize(mu, logvar, torch.randn(2, 5, 3, generator=gen)))
            loss = recon.pow(2).mean() + kl_loss(mu, logvar) * (step != 2)  # step 2: logvar gets no gradient
            opt.zero_grad()
            loss.backward()
            if step == 2:
                vae.logvar.weight.grad = vae.logvar.bias.grad = None
            opt.step()
        return [p.detach().clone() for p in vae.parameters()]

    reference = run(lambda params: torch.optim.Adam(params, lr=1e-2))
    for size in (7, 1 << 18):
        sliced = run(lambda params: SlicedAdam(params, 1e-2, slice_size=size))
        assert all(torch.equal(a, b) for a, b in zip(reference, sliced))
    assert isinstance(
        TrainConfig(1, 1e-3, 4, 0, "adam").make_optimizer(MotionVAE(8, hidden=(4,), latent=2).parameters()), SlicedAdam
    )
    with pytest.raises(ValueError, match="slice_size"):
        SlicedAdam([torch.nn.Parameter(torch.zeros(3))], 1e-3, slice_size=0)


def test_average_pool_is_avg_pool1d_bit_for_bit():
    from torch.nn import functional as F

    from motionvar.du2022.style.networks import average_pool

    for pool in (2, 3):
        h = torch.randn(4, 16, 30, requires_grad=True)
        a, b = average_pool(h, pool), F.avg_pool1d(h, pool)
        g = torch.randn_like(a)
        assert torch.equal(a, b)
        assert torch.equal(*(torch.autograd.grad(out, h, g)[0] for out in (a, b)))


def test_vae_and_cvae_training(tiny):
    space, _, prims = tiny
    maps = space.encode(prims)
    assert maps.shape == (12, 16, 30)
    vae_settings = VaeSettings(latent=4, samples_per_input=3, epochs=40, lr=1e-3, batch_size=6, optimizer="adam")
    cvae_settings = CvaeSettings(alpha=200.0, epochs=40, lr=1e-3, batch_size=6, optimizer="adam")
    hidden = (64, 32, 16)
    vae, hist = train_vae(maps, vae_settings, 0, hidden)
    assert list(hist.columns) == ["epoch", "loss", "content", "kl", "style", "seconds", "active"]
    assert hist["loss"].iloc[-1] < hist["loss"].iloc[0] and (hist["style"] == 0).all()
    # a style example far from the content: the CVAE's samples move toward its Gram matrix
    example = space.encode(motions_features([toy_walk(seed=99, swing=1.2, arm=1.0, speed=4.0)], space_layout()))[0]
    cvae, chist = train_cvae(maps, example, vae_settings, cvae_settings, 0, vae, hidden)
    assert chist["style"].iloc[-1] < chist["style"].iloc[0]
    from motionvar.du2022.style import active_units

    assert 0 <= active_units(vae, maps) <= 4
    d_vae = float(
        style_distance(space.reencode(vae.sample(200, torch.Generator().manual_seed(1)).reshape(200, 16, 30)), example)
    )
    d_cvae = float(
        style_distance(space.reencode(cvae.sample(200, torch.Generator().manual_seed(1)).reshape(200, 16, 30)), example)
    )
    assert d_cvae < d_vae
    with pytest.raises(ValueError, match="style_maps must be"):
        train_cvae(maps, example[:3], vae_settings, cvae_settings, 0, None, hidden)
    with pytest.raises(ValueError, match="init VAE has"):
        train_cvae(maps, example, vae_settings, cvae_settings, 0, MotionVAE(10, hidden, 4), hidden)
    with pytest.raises(ValueError, match="TrainConfig"):
        TrainConfig(epochs=0, lr=1e-3, batch_size=4, seed=0, optimizer="adam")


def test_cvae_keeps_active_latent_units_on_a_toy_set():
    """A CVAE trained a few epochs from a VAE that uses its latent space (toy feature maps
    from 4 latent factors) still uses it at the default regime (Adam lr 1e-4, Eq. 5.9's
    summed Gram, Frobenius norm, alpha 200) and with the thesis' SGD at lr 1e-5; the
    history counts the dimensions in use per epoch."""
    from motionvar.du2022.style import active_units

    gen = torch.Generator().manual_seed(0)
    base = torch.rand(16, 30, generator=gen)
    factors = 0.5 * torch.randn(4, 16, 30, generator=gen)
    maps = torch.relu(base + torch.einsum("nk,kct->nct", torch.randn(64, 4, generator=gen), factors))
    example = torch.relu(1.5 * base + 0.3 * torch.randn(16, 30, generator=gen))
    hidden = (64, 32, 16)
    vae_settings = VaeSettings(latent=4, samples_per_input=3, epochs=30, lr=1e-3, batch_size=16, optimizer="adam")
    vae, hist = train_vae(maps, vae_settings, 0, hidden)
    assert hist["active"].iloc[-1] == active_units(vae, maps) > 0
    for cfg in (
        CvaeSettings(epochs=5, lr=1e-4, batch_size=16, optimizer="adam"),
        CvaeSettings(epochs=5, lr=1e-5, batch_size=16, optimizer="sgd"),
    ):
        cvae, chist = train_cvae(maps, example, vae_settings, cfg, 0, vae, hidden)
        assert list(chist.columns) == ["epoch", "loss", "content", "kl", "style", "seconds", "active"]
        assert (chist["active"] > 0).all() and active_units(cvae, maps) > 0, (cfg, chist["active"].tolist())
        assert chist["style"].iloc[-1] < chist["style"].iloc[0]
    with pytest.raises(ValueError, match="optimizer must be one of"):
        TrainConfig(5, 1e-4, 16, 0, optimizer="rmsprop")
    with pytest.raises(ValueError, match="gram must be one of"):
        train_cvae(maps, example, vae_settings, CvaeSettings(epochs=1, gram="max"), 0, vae, hidden)


def space_layout():
    return style_joints(cmu_skeleton(), cmu_joint_map())


def test_save_load_sample_and_distance_matrix(tiny, tmp_path, layout):
    space, _, prims = tiny
    maps = space.encode(prims)
    vae_settings = VaeSettings(latent=4, samples_per_input=2, epochs=3, lr=1e-3, batch_size=6, optimizer="adam")
    vae, _ = train_vae(maps, vae_settings, 0, TINY_HIDDEN)
    space.save(tmp_path / "ae.pt")
    save_vae(tmp_path / "vae.pt", vae, tuple(maps.shape[1:]), {"primitive": "walk_leftStance", "style": "neutral"})
    # weights: a plain state dict (weights_only); settings: JSON beside it
    assert set(torch.load(tmp_path / "vae.pt", weights_only=True)) == set(vae.state_dict())
    settings = json.loads((tmp_path / "ae.json").read_text())
    assert settings["kind"] == "du2022_conv_autoencoder" and settings["hparams"]["n_kernels"] == 16
    assert json.loads((tmp_path / "vae.json").read_text())["map_shape"] == [16, 30]
    space2 = FeatureSpace.load(tmp_path / "ae.pt")
    vae2, shape, info = load_vae(tmp_path / "vae.pt")
    assert shape == (16, 30) and info["style"] == "neutral"
    # exact round trip: weights and the float32 scaler
    assert all(torch.equal(a, b) for a, b in zip(space.ae.state_dict().values(), space2.ae.state_dict().values()))
    assert space2.scaler.mean_.dtype == space.scaler.mean_.dtype == np.float32
    assert np.array_equal(space2.scaler.mean_, space.scaler.mean_) and np.array_equal(
        space2.scaler.std_, space.scaler.std_
    )
    a = sample_features(vae, shape, space, 5, seed=3)
    b = sample_features(vae2, shape, space2, 5, seed=3)
    assert a.shape == (5, 60, 66) and np.array_equal(a, b)
    maps5 = sample_maps(vae, shape, 5, seed=3)  # decoded in chunks into one array: as concatenating the chunks
    chunks = np.concatenate([space.decode(maps5[i : i + 2]) for i in range(0, 5, 2)])
    assert sample_features(vae, shape, space, 5, seed=3, chunk=2).tobytes() == chunks.tobytes()
    assert space2.reconstruction_rmse(prims) == pytest.approx(space.reconstruction_rmse(prims))
    table = style_distance_matrix(
        {"neutral": (vae, shape), "other": (vae2, shape)},
        {"neutral": prims.mean(axis=0), "other": prims[0]},
        space,
        10,
        seed=0,
    )
    assert table.shape == (2, 2) and np.isfinite(table.to_numpy()).all()
    assert set(diagonal_minima(table)) <= {"neutral", "other"}
    with pytest.raises(FileNotFoundError, match="missing"):
        load_vae(tmp_path / "nope.pt")
    with pytest.raises(ValueError, match="not a saved du2022_vae"):
        load_vae(tmp_path / "ae.pt")
    (tmp_path / "vae.json").unlink()
    with pytest.raises(FileNotFoundError, match="vae.json: model file missing"):
        load_vae(tmp_path / "vae.pt")


def test_diagonal_minima():
    t = pd.DataFrame([[0.1, 0.2], [0.05, 0.3]], index=["a", "b"], columns=["a", "b"])
    assert diagonal_minima(t) == ["a"]


def test_diversity_by_hand():
    rng = np.random.default_rng(0)
    J = 21
    f = np.zeros((3, 4, 3 * J + 3))
    f[..., : 3 * J] = rng.normal(size=(3, 4, 3 * J))
    f[..., 3 * J] = np.array([1.0, 2.0, 3.0])[:, None]  # per-clip constant speed along x
    d = diversity(f, J)
    poses = f[..., : 3 * J].reshape(12, -1)
    assert d["pose_sd"] == pytest.approx(np.sqrt(((poses - poses.mean(0)) ** 2).sum() / 11))
    speeds = np.repeat([1.0, 2.0, 3.0], 4)
    assert d["v_sd"] == pytest.approx(np.sqrt(((speeds - 2.0) ** 2).sum() / 11))
    assert d["step_sd"] == pytest.approx(np.std([3.0, 6.0, 9.0], ddof=1))  # 3 real steps a clip
    with pytest.raises(ValueError, match="features must be"):
        diversity(np.zeros((3, 4, 10)), J)


@pytest.fixture(scope="module")
def prim_dataset(tmp_path_factory):
    from motionvar.io import load_dataset, save_dataset

    motions = [toy_walk(n_frames=50 + 5 * k, seed=k) for k in range(6)]
    meta = pd.DataFrame(
        {
            "clip_id": [f"c{k}" for k in range(6)],
            "primitive": ["walk_leftStance"] * 5 + ["run_rightStance"],
            "style": ["neutral", "neutral", "proud", "proud", "proud", "neutral"],
            "variant": ["forward", "left", "left", "forward", "forward", "forward"],
            "turn_deg": [0.0, 30.0, 2.0, -8.0, 4.0, 0.0],
        }
    )
    path = tmp_path_factory.mktemp("prims")
    save_dataset(path, motions, meta)
    return load_dataset(path)


def test_primitive_features_and_style_example(prim_dataset, layout):
    from motionvar.du2022.style.data import dataset_layout, primitive_features, select_style_example, training_windows

    assert dataset_layout(prim_dataset, cmu_joint_map()).names == layout.names
    rows, feats = primitive_features(prim_dataset, layout, "walk_leftStance", "neutral", 60)
    assert list(rows["clip_id"]) == ["c0", "c1"] and feats.shape == (2, 60, 66)
    # the straightest forward clip of the style (not the straighter left-turning one)
    assert select_style_example(prim_dataset.metadata, "walk_leftStance", "proud") == "c4"
    assert training_windows(prim_dataset, layout, 60, 30).shape == (4, 60, 66)  # 4 clips of 60..75 frames


def test_training_windows_subset_is_the_windows_bit_for_bit(prim_dataset, layout):
    """A subset of the windows is computed from its own frames (and the next one) only:
    the same bytes as the subset of all windows, windows inside clips and at their ends."""
    from motionvar.du2022.style.data import training_windows, window_counts

    for size, stride in ((60, 5), (55, 7), (50, 50)):
        every = training_windows(prim_dataset, layout, size, stride)
        assert window_counts(prim_dataset, size, stride).sum() == len(every)
        for subset in (np.arange(len(every)), np.array([0, 2, 3, len(every) - 1]), np.array([len(every) - 2])):
            part = training_windows(prim_dataset, layout, size, stride, subset)
            assert part.dtype == np.float32 and part.tobytes() == every[subset].tobytes()
    with pytest.raises(ValueError, match="increasing indices below the"):
        training_windows(prim_dataset, layout, 60, 30, np.array([2, 1]))
    with pytest.raises(ValueError, match="increasing indices below the 4 windows"):
        training_windows(prim_dataset, layout, 60, 30, np.array([4]))


def test_primitive_selection_errors_name_what_is_missing(prim_dataset):
    from motionvar.du2022.style.data import primitive_mask, select_style_example

    with pytest.raises(ValueError, match="no clips of primitive 'walk_leftStance' with style 'old'.*primitives"):
        primitive_mask(prim_dataset.metadata, "walk_leftStance", "old")
    with pytest.raises(ValueError, match="no column 'style'"):
        primitive_mask(prim_dataset.metadata.drop(columns="style"), "walk_leftStance", "neutral")
    with pytest.raises(ValueError, match="no clips of primitive 'pick_reach'"):
        select_style_example(prim_dataset.metadata, "pick_reach", "proud")
