"""Rule style_autoencoder (Du 2022 Sec. 5.3.1, 5.4.1): the convolutional motion
autoencoder (Eq. 5.1-5.2) trained on sliding windows of all clips of the dataset."""


def main(snakemake) -> None:
    import logging

    import numpy as np

    from motionvar.du2022.style import FeatureScaler, FeatureSpace, TrainConfig, train_autoencoder
    from motionvar.du2022.style.data import training_windows
    from _style import load_inputs

    cfg, dataset, layout, space = load_inputs(snakemake)
    ae_cfg = cfg["autoencoder"]

    windows = training_windows(dataset, layout, cfg["canonical_frames"], ae_cfg["window_stride"])
    n_all = len(windows)
    if 0 < ae_cfg["max_windows"] < n_all:
        keep = np.sort(np.random.default_rng(cfg["seed"]).choice(n_all, ae_cfg["max_windows"], replace=False))
        windows = windows[keep]
    logging.info("%d windows of %d frames (%d in all) from %d clips; joints %s", len(windows),
                 windows.shape[1], n_all, len(dataset), ", ".join(layout.names))
    scaler = FeatureScaler.fit(windows, layout.n_joints)
    train_cfg = TrainConfig(ae_cfg["epochs"], ae_cfg["lr"], ae_cfg["batch_size"], cfg["seed"])
    ae, history = train_autoencoder(
        scaler.transform(windows), train_cfg, decoder_order=ae_cfg["decoder_order"],
        n_kernels=ae_cfg["kernels"], kernel_width=ae_cfg["kernel_width"],
    )
    space = FeatureSpace(ae, scaler)
    history["windows"] = len(windows)
    logging.info("trained in %.1f s; final loss %.4g; reconstruction RMSE %.3f", history["seconds"].iloc[-1],
                 history["loss"].iloc[-1], space.reconstruction_rmse(windows[:512]))
    space.save(snakemake.output.model)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
