"""Rule du2022_style_cvae (Du 2022 Sec. 5.3.3, 5.4.1): the CVAEs of one primitive, one per
configured style (``params.styles``, in the order of the outputs): the neutral clips as content
plus one style example, loss Eq. 5.11 with the Gram style term Eq. 5.10 (weight alpha, Gram
matrices of Eq. 5.9 summed or averaged: config du2022_style.cvae); starts from the neutral VAE when
cvae.init_from_neutral. The content is encoded once for every style; each CVAE is seeded by
itself: the same weights as one job per style."""


def main(snakemake) -> None:
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import fit_style_cvae, load_vae, neutral_content, save_vae

    dataset, layout, space = load_inputs(snakemake)
    primitive, out = snakemake.wildcards.primitive, snakemake.output
    neutral = load_vae(snakemake.input.vae)[0]
    settings = load_settings(snakemake)
    content = neutral_content(dataset, layout, space, primitive, settings.canonical_frames)
    for style, model, history_csv in zip(snakemake.params.styles, out.model, out.history, strict=True):
        cvae, shape, info, history = fit_style_cvae(
            dataset, layout, space, neutral, primitive, style, settings, content=content
        )
        save_vae(model, cvae, shape, info)
        history.to_csv(history_csv, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
