"""Rule ma2010_model (Ma 2010 Sec. 5-6): the style-and-variation model fitted once on all
the walking cycles (config ma2010.model: structure, variogram_model, root_group) and saved as
.npz + .json (motionvar.ma2010.storage), for the `motionvar ma2010` command."""


def main(snakemake) -> None:
    import logging

    from _ma2010 import load_walks, settings

    from motionvar.ma2010.storage import save_style_variation_model

    s = settings(snakemake)
    walks = load_walks(snakemake, s)
    model = walks.fit_model(s)
    save_style_variation_model(
        snakemake.output.model,
        model,
        walks.joint_map,
        walks.clips.clip_ids,
        walks.subjects,
        settings={k: getattr(s.model, k) for k in ("structure", "variogram_model", "root_group")},
    )
    logging.info(
        "%d cycles of %d subjects; structure %s; style range %s - %s",
        walks.clips.n_clips,
        len(set(walks.subjects)),
        model.network_.structure,
        model.style_.min(axis=0),
        model.style_.max(axis=0),
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
