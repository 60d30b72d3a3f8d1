"""Rule style_cvae (Du 2022 Sec. 5.3.3, 5.4.1): the CVAE of one primitive and style: the
neutral clips as content plus one style example, loss Eq. 5.11 with the Gram style term
Eq. 5.10 (weight alpha); starts from the neutral VAE when cvae.init_from_neutral."""


def main(snakemake) -> None:
    import logging

    from motionvar.du2022.style import TrainConfig, load_vae, save_vae, train_vae
    from motionvar.du2022.style.data import example_features, primitive_features, select_style_example
    from _style import load_inputs

    cfg, dataset, layout, space = load_inputs(snakemake)
    ccfg = cfg["cvae"]

    primitive, style = snakemake.wildcards.primitive, snakemake.wildcards.style
    neutral, shape, _ = load_vae(snakemake.input.vae)
    rows, feats = primitive_features(dataset, layout, primitive, "neutral", cfg["canonical_frames"])
    example_id = select_style_example(dataset.metadata, primitive, style)
    example = space.encode(example_features(dataset, layout, example_id, cfg["canonical_frames"])[None])[0]
    maps = space.encode(feats)
    logging.info("%s/%s: %d neutral clips, style example %s", primitive, style, len(rows), example_id)
    train_cfg = TrainConfig(ccfg["epochs"], ccfg["lr"], ccfg["batch_size"], cfg["seed"])
    cvae, history = train_vae(
        maps, train_cfg, n_samples=cfg["vae"]["samples_per_input"], style_maps=example, alpha=ccfg["alpha"],
        style_norm=ccfg["style_norm"],
        init=neutral if ccfg["init_from_neutral"] else None, latent=cfg["vae"]["latent"],
    )
    logging.info("trained in %.1f s; final loss %.4g (style %.4g)", history["seconds"].iloc[-1],
                 history["loss"].iloc[-1], history["style"].iloc[-1])
    save_vae(snakemake.output.model, cvae, shape,
             {"primitive": primitive, "style": style, "example": example_id, "n_clips": len(rows)})
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
