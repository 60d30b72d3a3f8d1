"""Rules du2022_graph_primitives and du2022_graph_primitive (Du 2022 Sec. 4.4.1): fit the
motion primitives ``params.primitives`` (DTW + SFPCA + GMM chosen by BIC) to their aligned
clips and save each (npz + json, the outputs in the same order); settings: config graph.model
and graph.seed (params.settings). Each fit is seeded by itself: the same model as in a job of
its own."""


def _files(named) -> list[str]:
    """A named output as a list of paths (one path or several)."""
    return [named] if isinstance(named, str) else list(named)


def main(snakemake) -> None:
    import logging

    from _graph import dataset

    from motionvar.du2022.graph import MotionPrimitive, PrimitiveOptions, primitive_clips
    from motionvar.du2022.graph.settings import GraphSettings

    settings = GraphSettings.from_dict(snakemake.params.settings)
    options = PrimitiveOptions.from_settings(settings.model, settings.seed)
    clips = snakemake.input.clips
    data = dataset(clips)
    out = snakemake.output
    for name, path in zip(snakemake.params.primitives, _files(out.model), strict=True):
        # the dense-grid picks (du2022_graph_dense_picks) are pick_reach clips modelled as pick_reach_dense
        motions, _ = primitive_clips(data, name.removesuffix("_dense"), source=clips)
        model = MotionPrimitive.fit(motions, name, options)
        model.save(path)
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
