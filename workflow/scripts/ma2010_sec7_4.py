"""Rule ma2010_sec7_4 (Ma 2010 Sec. 7.4): long sequences by ours and every rival method
from the same few example cycles, their naturalness and variation
(motionvar.ma2010.evaluations.sec7_4); the GIF shows each method's first sequence."""


def main(snakemake) -> None:
    from _ma2010 import load_walks
    from _rule import write_evaluation

    from motionvar.ma2010.comparison import LABELS, METHODS
    from motionvar.ma2010.evaluations.sec7_4 import sec7_4_comparison
    from motionvar.ma2010.figures import draw_sec7_4
    from motionvar.plots import animate_motions

    o, a = snakemake.params.options, snakemake.params.animation
    result = sec7_4_comparison(
        load_walks(snakemake),
        n_examples=o["comparison_examples"],
        seconds=o["comparison_seconds"],
        n_sequences=o["comparison_sequences"],
        seed=o["seed"],
        structure=o["structure"],
        variogram_model=o["variogram_model"],
        perlin_amplitude=o["perlin_amplitude_rad"],
        perlin_frequency_hz=o["perlin_frequency_hz"],
        gplvm_latent_dim=o["gplvm_latent_dim"],
        gplvm_iterations=o["gplvm_iterations"],
        gplvm_frame_step=o["gplvm_frame_step"],
        dbn_max_parents=o["dbn_max_parents"],
        contact_height_cm=o["contact_height_cm"],
        discontinuity_factor=o["discontinuity_factor"],
        xi_per=o["comparison_xi"],
        landing_rule=o["comparison_landing"],
    )
    write_evaluation(snakemake, result, draw_sec7_4)
    first = [result.figure["sequences"][m][0] for m in METHODS]
    animate_motions(
        snakemake.output.animation,
        first,
        labels=[LABELS[m] for m in METHODS],
        out_fps=a["animation_fps"],
        max_seconds=o["animation_seconds"],
        panel_px=a["animation_panel_px"],
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
