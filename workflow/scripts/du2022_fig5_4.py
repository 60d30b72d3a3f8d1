"""Rule du2022_fig5_4 (Du 2022 Sec. 5.4.2-5.4.3, Fig. 5.4-5.5): random samples of the
neutral VAEs and of the stylistic CVAEs as stick figures (the last frame of each sample,
characters started side by side in a line) and as GIF animations."""


def main(snakemake) -> None:
    from _rule import write_evaluation
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import evaluate_fig5_4, load_vae
    from motionvar.du2022.style.figures import animate_fig5_4, draw_fig5_4
    from motionvar.plots import write_gif

    dataset, layout, space = load_inputs(snakemake)
    settings = load_settings(snakemake)
    models = [load_vae(f) for f in [*snakemake.input.vaes, *snakemake.input.cvaes]]
    result = evaluate_fig5_4(dataset, layout, space, models, settings)
    write_evaluation(snakemake, result, draw_fig5_4)
    for group, out in (("neutral", snakemake.output.gif_neutral), ("styles", snakemake.output.gif_styles)):
        write_gif(out, animate_fig5_4(result, group, panel_px=settings.gif_panel_px), fps=20.0)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
