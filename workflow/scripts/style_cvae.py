"""Rule style_cvae (Du 2022 Sec. 5.3.3, 5.4.1): the CVAE of one primitive and style: the
neutral clips as content plus one style example, loss Eq. 5.11 with the Gram style term
Eq. 5.10 (weight alpha, Gram matrices of Eq. 5.9 summed or averaged: cvae.gram); starts from
the neutral VAE when cvae.init_from_neutral."""


def main(snakemake) -> None:
    from _style import load_inputs

    from motionvar.du2022.style import TrainConfig, fit_style_cvae, load_vae, save_vae

    dataset, layout, space = load_inputs(snakemake)
    p, c, wc = snakemake.params.options, snakemake.params.options["cvae"], snakemake.wildcards
    cvae, shape, info, history = fit_style_cvae(
        dataset,
        layout,
        space,
        load_vae(snakemake.input.vae)[0],
        wc.primitive,
        wc.style,
        TrainConfig(c["epochs"], c["lr"], c["batch_size"], p["seed"], c["optimizer"]),
        n_frames=p["canonical_frames"],
        n_samples=p["samples_per_input"],
        alpha=c["alpha"],
        style_norm=c["style_norm"],
        gram_reduce=c["gram"],
        init_from_neutral=c["init_from_neutral"],
        latent=p["latent"],
    )
    save_vae(snakemake.output.model, cvae, shape, info)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
