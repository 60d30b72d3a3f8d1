"""Rule du2022_graph_dense_picks (Du 2022 Fig. 4.11): pick_reach clips at the nodes of the
generator's dense target grid, aligned like the prep stage does (start at the origin,
heading +x), for the synthetic picking primitive of Fig. 4.12."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from _rule import config_settings, joint_map

    from motionvar.io import save_dataset
    from motionvar.prep import align_motions
    from motionvar.synth.dense_picks import dense_pick_segments

    entry, settings = snakemake.params.entry, config_settings(snakemake, "du2022_graph")
    if entry["source"] != "synthetic":
        raise ValueError(f"dataset {snakemake.wildcards.dataset}: dense picks need the synthetic generator")
    pieces, meta = dense_pick_segments(
        entry["subjects"],
        entry["seed"],
        settings.dense_picks_per_subject,
        grid_spacing_cm=settings.dense_grid_spacing_cm,
    )
    motions = align_motions(pieces, joint_map(snakemake), config_settings(snakemake, "prep"))
    save_dataset(Path(snakemake.output.clips).parent, motions, meta)
    logging.info("%d dense-grid pick_reach clips", len(motions))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
