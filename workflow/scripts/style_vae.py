"""Rule style_vae (Du 2022 Sec. 5.3.2, 5.4.1): the VAE of one motion primitive (Fig. 5.3,
loss Eq. 5.6) in the autoencoder's feature space, trained on its neutral clips."""


def main(snakemake) -> None:
    from _style import load_inputs

    from motionvar.du2022.style import TrainConfig, fit_primitive_vae, save_vae

    dataset, layout, space = load_inputs(snakemake)
    p, v = snakemake.params.options, snakemake.params.options["vae"]
    vae, shape, info, history = fit_primitive_vae(
        dataset,
        layout,
        space,
        snakemake.wildcards.primitive,
        TrainConfig(v["epochs"], v["lr"], v["batch_size"], p["seed"], v["optimizer"]),
        n_frames=p["canonical_frames"],
        n_samples=v["samples_per_input"],
        latent=v["latent"],
    )
    save_vae(snakemake.output.model, vae, shape, info)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
