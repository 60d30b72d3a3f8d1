"""Benchmark of Du 2022 ch. 5 (motionvar.du2022.style) on 2 CPU threads, printed as times and as
ratios against baselines measured in the same run:

1. Training seconds per epoch of each model at the full config's sizes: the conv
   autoencoder (W windows of 60 frames x 66 channels), a neutral VAE (N clips, L = 10
   draws of z, Eq. 5.7) and a CVAE (the same plus the Gram style term, Eq. 5.10); and
   the seconds a model takes at the configured epochs.
2. The Gram style loss (forward + backward) computed with explicit 256 x 256 Gram matrices
   (Eq. 5.9-5.10 as written) vs the factored form (T x T products, the same value):
   time ratio and the largest relative difference of the values.
3. The cost of the thesis' L = 10 draws per input: a VAE epoch with L = 10 vs L = 1.
4. The decoder order: Eq. 5.2 (convolve, then depool) vs Holden et al. (depool, then
   convolve): autoencoder epoch time ratio.
5. Sampling throughput (clips per second): z -> VAE decoder -> conv decoder -> features,
   and on to joint positions (integration of the root, Sec. 5.2).
6. The CVAE regime: an epoch with Eq. 5.9's summed Gram matrix (the default) vs the
   frame-averaged one, and with SGD (the thesis' optimiser) vs Adam (the same work, so
   ratios near 1: the regime changes what the training does, not what it costs).

Inputs are random tensors of the right shapes (cost depends only on the sizes).

    python benchmarks/style_training.py [--windows 4000] [--clips 450] [--repeats 2]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import torch

from motionvar.core import cmu_joint_map, cmu_skeleton
from motionvar.du2022.style import (
    AutoencoderSettings,
    CvaeSettings,
    FeatureScaler,
    FeatureSpace,
    VaeSettings,
    features_to_positions,
    gram,
    gram_distance,
    gram_distance_maps,
    sample_features,
    style_joints,
    train_autoencoder,
    train_cvae,
    train_vae,
)


def timed(fn, repeats: int) -> float:
    """Best of ``repeats`` timings after one untimed warm-up call."""
    fn()
    best = float("inf")
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--windows", type=int, default=4000, help="autoencoder windows (config du2022_style.autoencoder.max_windows)"
    )
    ap.add_argument(
        "--clips", type=int, default=450, help="clips of a primitive (neutral walk_leftStance, 25 subjects)"
    )
    ap.add_argument("--ae-epochs", type=int, default=15)
    ap.add_argument("--vae-epochs", type=int, default=40)
    ap.add_argument("--cvae-epochs", type=int, default=20)
    ap.add_argument("--samples", type=int, default=2000, help="clips drawn for the sampling throughput")
    ap.add_argument("--repeats", type=int, default=2)
    args = ap.parse_args()
    torch.set_num_threads(2)
    gen = torch.Generator().manual_seed(0)
    layout = style_joints(cmu_skeleton(), cmu_joint_map())
    C, T = layout.n_channels, 60
    print(f"torch {torch.__version__}, {torch.get_num_threads()} threads; {C} channels x {T} frames")

    windows = np.random.default_rng(0).normal(size=(args.windows, T, C)).astype(np.float32)
    one = AutoencoderSettings(epochs=1, lr=1e-3, batch_size=64)
    ae_faithful = timed(lambda: train_autoencoder(windows, one, 0), args.repeats)
    ae_holden = timed(lambda: train_autoencoder(windows, one.replace(decoder_order="depool_conv"), 0), args.repeats)
    print(
        f"\n1. autoencoder: {ae_faithful:.2f} s per epoch over {args.windows} windows "
        f"-> {args.ae_epochs} epochs ~ {ae_faithful * args.ae_epochs:.0f} s"
    )

    ae, _ = train_autoencoder(windows[:64], one, 0)
    space = FeatureSpace(ae, FeatureScaler(layout.n_joints).fit(windows[:256].astype(float)))
    maps = torch.rand(args.clips, 256, T // 2, generator=gen)
    vae_cfg = VaeSettings(samples_per_input=10, epochs=1, lr=1e-3, batch_size=32, optimizer="adam")
    cvae_cfg = CvaeSettings(alpha=200.0, epochs=1, lr=1e-3, batch_size=32, optimizer="adam")
    vae_l10 = timed(lambda: train_vae(maps, vae_cfg, 0), args.repeats)
    vae_l1 = timed(lambda: train_vae(maps, vae_cfg.replace(samples_per_input=1), 0), args.repeats)
    cvae = timed(lambda: train_cvae(maps, maps[0], vae_cfg, cvae_cfg, 0, None), args.repeats)
    cvae_mean = timed(lambda: train_cvae(maps, maps[0], vae_cfg, cvae_cfg.replace(gram="mean"), 0, None), args.repeats)
    sgd = cvae_cfg.replace(lr=1e-5, optimizer="sgd")
    cvae_sgd = timed(lambda: train_cvae(maps, maps[0], vae_cfg, sgd, 0, None), args.repeats)
    print(
        f"   VAE (L = 10): {vae_l10:.2f} s per epoch over {args.clips} clips -> {args.vae_epochs} epochs "
        f"~ {vae_l10 * args.vae_epochs:.0f} s"
    )
    print(
        f"   CVAE (L = 10, alpha = 200): {cvae:.2f} s per epoch -> {args.cvae_epochs} epochs "
        f"~ {cvae * args.cvae_epochs:.0f} s; CVAE / VAE epoch = {cvae / vae_l10:.2f}"
    )

    recon = torch.rand(10, 32, 256, T // 2, generator=gen, requires_grad=True)
    style = torch.rand(256, T // 2, generator=gen)

    def explicit():
        gram_distance(gram(recon), gram(style)).mean().backward()

    def factored():
        gram_distance_maps(recon, style).mean().backward()

    t_exp, t_fac = timed(explicit, 3 * args.repeats), timed(factored, 3 * args.repeats)
    with torch.no_grad():
        a = gram_distance(gram(recon.double()), gram(style.double()))
        b = gram_distance_maps(recon, style).double()
    print(
        f"\n2. Gram style loss, 320 decoded maps: explicit {1e3 * t_exp:.1f} ms, factored {1e3 * t_fac:.1f} ms "
        f"(explicit / factored = {t_exp / t_fac:.1f}x); largest relative difference {float(((a - b).abs() / a).max()):.1e}"
    )
    print(f"\n3. VAE epoch L = 10 / L = 1: {vae_l10 / vae_l1:.1f}x ({vae_l10:.2f} s vs {vae_l1:.2f} s)")
    print(
        f"\n4. autoencoder epoch, depool-then-conv (Holden) / conv-then-depool (Eq. 5.2): "
        f"{ae_holden / ae_faithful:.2f}x ({ae_holden:.2f} s vs {ae_faithful:.2f} s)"
    )

    from motionvar.du2022.style import MotionVAE
    from motionvar.du2022.style.networks import VAE_HIDDEN

    vae = MotionVAE(256 * (T // 2), VAE_HIDDEN, VaeSettings().latent).eval()
    n = args.samples
    t_feat = timed(lambda: sample_features(vae, (256, T // 2), space, n, seed=0), args.repeats)
    feats = sample_features(vae, (256, T // 2), space, n, seed=0)
    t_pos = timed(lambda: features_to_positions(feats, layout), args.repeats)
    print(
        f"\n5. sampling: {n / t_feat:,.0f} clips/s to features, {n / (t_feat + t_pos):,.0f} clips/s to joint "
        f"positions ({n} clips of {T} frames; 10,000 samples of Table 5.2 ~ {10000 * t_feat / n:.1f} s a model)"
    )
    print(
        f"\n6. CVAE epoch, summed / averaged Gram: {cvae / cvae_mean:.2f}x; SGD / Adam: {cvae_sgd / cvae:.2f}x "
        f"({cvae:.2f} s, {cvae_mean:.2f} s, {cvae_sgd:.2f} s)"
    )


if __name__ == "__main__":
    main()
