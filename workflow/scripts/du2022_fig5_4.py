"""Rule du2022_fig5_4 (Du 2022 Sec. 5.4.2-5.4.3, Fig. 5.4-5.5): random samples of the
neutral VAEs and of the stylistic CVAEs as stick figures (the last frame of each sample,
characters started side by side in a line) and as GIF animations."""


def main(snakemake) -> None:
    from _evaluation import evaluate

    from motionvar.du2022.style.figures import animate_fig5_4
    from motionvar.plots import write_gif

    result, settings, _ = evaluate(snakemake)
    for group, out in (("neutral", snakemake.output.gif_neutral), ("styles", snakemake.output.gif_styles)):
        write_gif(out, animate_fig5_4(result, group, panel_px=settings.gif_panel_px), fps=20.0)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
