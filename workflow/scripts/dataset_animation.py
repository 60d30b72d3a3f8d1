"""Rule dataset_animation: a GIF of one clip per behaviour, side by side."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from _rule import config_settings

    from motionvar.io import load_dataset
    from motionvar.plots import animate_motions, overview_clips

    report = config_settings(snakemake, "report")
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    behaviours, _ = overview_clips(dataset.metadata)
    chosen = behaviours[: report.animation_clips]
    size = animate_motions(
        snakemake.output[0],
        [dataset.motion(i) for _, i in chosen],
        labels=[label for label, _ in chosen],
        out_fps=report.animation_fps,
        max_seconds=report.animation_seconds,
        panel_px=report.animation_panel_px,
    )
    logging.info("%d clips, %.2f MB", len(chosen), size / 1e6)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
