"""Rule egges2004_animation: a GIF of generated, personalised idle motion for a few
subjects side by side (Egges 2004 Sec. 5.6, Fig. 10)."""


def main(snakemake) -> None:
    import logging

    from _egges2004 import model, settings

    from motionvar.egges2004.evaluations import idle_animation
    from motionvar.plots import animate_motions

    s = settings(snakemake)
    a = s.animation
    motions, labels = idle_animation(model(snakemake), s)
    size = animate_motions(
        snakemake.output[0], motions, labels=labels, out_fps=a.fps, max_seconds=a.seconds, panel_px=a.panel_px
    )
    logging.info("%d subjects, %.2f MB", len(motions), size / 1e6)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
