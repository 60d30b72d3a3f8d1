"""Rule ma2010_sec7_4 (Ma 2010 Sec. 7.4): long sequences by ours and every rival method
from the same few example cycles, their naturalness and variation
(motionvar.ma2010.evaluations.sec7_4); the GIF shows each method's first sequence (of a
swept method, at the middle setting of its sweep)."""


def main(snakemake) -> None:
    from _evaluation import evaluate
    from _rule import config_settings

    from motionvar.ma2010.comparison import METHODS, family
    from motionvar.plots import animate_motions

    result, s, _ = evaluate(snakemake)
    report = config_settings(snakemake, "report")
    labels = result.figure["labels"]
    shown = [[v for v in labels if family(v) == m] for m in METHODS]
    shown = [variants[len(variants) // 2] for variants in shown]
    animate_motions(
        snakemake.output.animation,
        [result.figure["sequences"][v][0] for v in shown],
        labels=[labels[v] for v in shown],
        out_fps=report.animation_fps,
        max_seconds=s.sec7_4.animation_seconds,
        panel_px=report.animation_panel_px,
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
