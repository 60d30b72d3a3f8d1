"""Rule style_vae (Du 2022 Sec. 5.3.2, 5.4.1): the VAE of one motion primitive (Fig. 5.3,
loss Eq. 5.6) in the autoencoder's feature space, trained on its neutral clips."""


def main(snakemake) -> None:
    import logging

    from motionvar.du2022.style import TrainConfig, save_vae, train_vae
    from motionvar.du2022.style.data import primitive_features
    from _style import load_inputs

    cfg, dataset, layout, space = load_inputs(snakemake)
    vcfg = cfg["vae"]

    primitive = snakemake.wildcards.primitive
    rows, feats = primitive_features(dataset, layout, primitive, "neutral", cfg["canonical_frames"])
    maps = space.encode(feats)
    logging.info("%s: %d neutral clips, feature maps %s", primitive, len(rows), tuple(maps.shape))
    train_cfg = TrainConfig(vcfg["epochs"], vcfg["lr"], vcfg["batch_size"], cfg["seed"])
    vae, history = train_vae(maps, train_cfg, n_samples=vcfg["samples_per_input"], latent=vcfg["latent"])
    logging.info("trained in %.1f s; final loss %.4g", history["seconds"].iloc[-1], history["loss"].iloc[-1])
    save_vae(snakemake.output.model, vae, tuple(maps.shape[1:]),
             {"primitive": primitive, "style": "neutral", "n_clips": len(rows)})
    history.to_csv(snakemake.output.history, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
