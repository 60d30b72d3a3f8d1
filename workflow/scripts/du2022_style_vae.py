"""Rule du2022_style_vae (Du 2022 Sec. 5.3.2, 5.4.1): the VAE of one motion primitive (Fig.
5.3, loss Eq. 5.6) in the autoencoder's feature space, trained on its neutral clips
(config du2022_style.vae)."""


def main(snakemake) -> None:
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import fit_primitive_vae, save_vae

    dataset, layout, space = load_inputs(snakemake)
    settings = load_settings(snakemake)
    vae, shape, info, history = fit_primitive_vae(dataset, layout, space, snakemake.wildcards.primitive, settings)
    save_vae(snakemake.output.model, vae, shape, info)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
