"""Rule du2022_sec4_6_1 (Du 2022 Sec. 4.6.1, "Compactness"): bytes of the motion
primitive models against the bytes of the clips they were fitted to, and the models'
bytes when each is refitted with its own settings to a seeded random half of its clips
(written to a temporary folder, measured, and deleted). Settings: config graph.seed
(params.settings)."""


def main(snakemake) -> None:
    import tempfile
    from pathlib import Path

    import pandas as pd
    from _graph import model_bytes, models, primitive_clips_of
    from _rule import config_settings, write_evaluation

    from motionvar.du2022.graph.evaluations.sec4_6_1 import evaluate_sec4_6_1, fit_half
    from motionvar.du2022.graph.figures import draw_sec4_6_1

    settings = config_settings(snakemake, "graph")
    paths, dense = snakemake.input.models, snakemake.input.dense
    loaded = models(paths)
    half = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, (idx, model) in fit_half(loaded, primitive_clips_of(loaded, snakemake), settings.seed).items():
            files = model.save(Path(tmp) / name)
            half[name] = (idx, model, sum(f.stat().st_size for f in files))
    result = evaluate_sec4_6_1(
        loaded,
        model_bytes(paths),
        pd.read_csv(snakemake.input.metadata),
        pd.read_csv(dense[0]) if dense else None,
        half,
    )
    write_evaluation(snakemake, result, draw_sec4_6_1, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
