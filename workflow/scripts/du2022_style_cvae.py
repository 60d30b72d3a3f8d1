"""Rule du2022_style_cvae (Du 2022 Sec. 5.3.3, 5.4.1): the CVAE of one primitive and style:
the neutral clips as content plus one style example, loss Eq. 5.11 with the Gram style term
Eq. 5.10 (weight alpha, Gram matrices of Eq. 5.9 summed or averaged: config style.cvae);
starts from the neutral VAE when cvae.init_from_neutral."""


def main(snakemake) -> None:
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import fit_style_cvae, load_vae, save_vae

    dataset, layout, space = load_inputs(snakemake)
    wc = snakemake.wildcards
    neutral = load_vae(snakemake.input.vae)[0]
    settings = load_settings(snakemake)
    cvae, shape, info, history = fit_style_cvae(dataset, layout, space, neutral, wc.primitive, wc.style, settings)
    save_vae(snakemake.output.model, cvae, shape, info)
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
