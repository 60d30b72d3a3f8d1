"""Rule graph_primitive (Du 2022 Sec. 4.4.1): fit one motion primitive (DTW + SFPCA +
GMM chosen by BIC) to its aligned clips and save it (npz + json)."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from _graph import primitive_clips, primitive_options
    from motionvar.du2022.graph import MotionPrimitive

    name = snakemake.wildcards.primitive
    # the dense-grid picks (graph_dense_picks) are pick_reach clips modelled as pick_reach_dense
    motions, _ = primitive_clips(snakemake.input.clips, name.removesuffix("_dense"))
    model = MotionPrimitive.fit(motions, name, primitive_options(snakemake.params.options))
    model.save(Path(snakemake.output.model).with_suffix(""))
    logging.info("%s: %d clips, %d latent dimensions, %d Gaussians (scores %s), canonical %d frames",
                 name, len(motions), model.n_latent, model.gmm_.n_components, model.gmm_scores_, model.n_frames)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
