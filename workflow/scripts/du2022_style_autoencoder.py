"""Rule du2022_style_autoencoder (Du 2022 Sec. 5.3.1, 5.4.1): the convolutional motion
autoencoder (Eq. 5.1-5.2) trained on sliding windows of all clips of the dataset
(config du2022_style.autoencoder)."""


def main(snakemake) -> None:
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import fit_feature_space

    dataset, layout, _ = load_inputs(snakemake)
    space, history = fit_feature_space(dataset, layout, load_settings(snakemake))
    space.save(snakemake.output.model)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
