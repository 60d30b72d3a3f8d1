"""Rule egges2004_animation: a GIF of generated, personalised idle motion for a few
subjects side by side (Egges 2004 Sec. 5.6, Fig. 10)."""


def main(snakemake) -> None:
    import logging

    from _egges2004 import figure_subjects, model
    from motionvar.egges2004 import generate_idle
    from motionvar.egges2004.experiments import subject_rng
    from motionvar.plots import animate_motions

    o = snakemake.params.options
    a = o["animation"]
    m = model(snakemake)
    shown = figure_subjects(m, o)
    motions = [
        generate_idle(m.databases[s], m.pca, m.skeletons[s], a["seconds"], subject_rng(o["seed"], s, "animation"))
        for s in shown
    ]
    size = animate_motions(
        snakemake.output[0], motions, labels=[f"subject {s} (generated)" for s in shown],
        out_fps=a["fps"], max_seconds=a["seconds"], panel_px=a["panel_px"],
    )
    logging.info("%d subjects, %.2f MB", len(shown), size / 1e6)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
