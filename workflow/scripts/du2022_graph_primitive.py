"""Rule du2022_graph_primitive (Du 2022 Sec. 4.4.1): fit one motion primitive (DTW +
SFPCA + GMM chosen by BIC) to its aligned clips and save it (npz + json); settings: config
du2022_graph.model and du2022_graph.seed (params.settings)."""


def main(snakemake) -> None:
    import logging

    from _rule import config_settings, dataset

    from motionvar.du2022.graph import MotionPrimitive, PrimitiveOptions, primitive_clips

    name, settings = snakemake.wildcards.primitive, config_settings(snakemake, "du2022_graph")
    options = PrimitiveOptions.from_settings(settings.model, settings.seed)
    # the dense-grid picks (du2022_graph_dense_picks) are pick_reach clips modelled as pick_reach_dense
    clips = snakemake.input.clips
    motions, _ = primitive_clips(dataset(clips), name.removesuffix("_dense"), source=clips)
    model = MotionPrimitive(name, options).fit(motions)
    model.save(snakemake.output.model)
    logging.info(
        "%s: %d clips, %d latent dimensions, %d Gaussians (scores %s), canonical %d frames",
        name,
        len(motions),
        model.n_latent,
        model.gmm_.n_components,
        model.gmm_scores_,
        model.n_frames,
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
