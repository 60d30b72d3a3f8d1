"""Rule style_autoencoder (Du 2022 Sec. 5.3.1, 5.4.1): the convolutional motion
autoencoder (Eq. 5.1-5.2) trained on sliding windows of all clips of the dataset."""


def main(snakemake) -> None:
    from _style import load_inputs

    from motionvar.du2022.style import TrainConfig, fit_feature_space

    dataset, layout, _ = load_inputs(snakemake)
    p, ae = snakemake.params.options, snakemake.params.options["autoencoder"]
    space, history = fit_feature_space(
        dataset,
        layout,
        TrainConfig(ae["epochs"], ae["lr"], ae["batch_size"], p["seed"]),
        window=p["canonical_frames"],
        stride=ae["window_stride"],
        max_windows=ae["max_windows"],
        decoder_order=ae["decoder_order"],
        n_kernels=ae["kernels"],
        kernel_width=ae["kernel_width"],
        keep=ae["keep"],
    )
    space.save(snakemake.output.model)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
