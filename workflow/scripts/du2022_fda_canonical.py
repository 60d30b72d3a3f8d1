"""Rule du2022_fda_canonical (Du 2022 Sec. 3.3.3 / 4.4.1): the primitives of the chosen
behaviours on a canonical timeline, by DTW to the median-length clip of each primitive
(or by linear resampling to the median length), written as a packed dataset."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    import numpy as np

    from motionvar.io import load_dataset, save_dataset
    from motionvar.prep import apply_warp, median_length_index, resample_motion, warp_to_median

    o = snakemake.params.options
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    meta = dataset.metadata
    known = set(meta["behaviour"].unique())
    unknown = [b for b in o["behaviours"] if b not in known]
    if unknown:
        raise ValueError(f"config fda.behaviours: {unknown} not in the prep data (behaviours: {sorted(known)})")
    out_motions, out_rows = [], []
    primitives = sorted(meta.loc[meta["behaviour"].isin(o["behaviours"]), "primitive"].unique())
    for primitive in primitives:
        idx = np.flatnonzero(meta["primitive"].to_numpy() == primitive)
        if len(idx) < o["min_clips"]:
            logging.warning("primitive %s: %d clips < fda.min_clips=%d, left out", primitive, len(idx), o["min_clips"])
            continue
        motions = [dataset.motion(int(i)) for i in idx]
        if o["time_warping"] == "dtw":
            ref, warps = warp_to_median(motions)
            warped = [apply_warp(m, w) for m, w in zip(motions, warps)]
        else:
            ref = median_length_index(motions)
            warped = [resample_motion(m, motions[ref].n_frames, keep_duration=False) for m in motions]
        rows = meta.iloc[idx].copy()
        rows["source_frames"] = rows["n_frames"]
        rows["canonical_reference"] = meta["clip_id"].iloc[idx[ref]]
        out_motions += warped
        out_rows.append(rows.drop(columns=["n_frames", "fps"]))
        logging.info("%s: %d clips -> %d canonical frames (%s)", primitive, len(idx), warped[0].n_frames,
                     o["time_warping"])
    if not out_motions:
        raise ValueError("config fda.behaviours: no primitive has fda.min_clips clips")
    import pandas as pd

    save_dataset(Path(snakemake.output.clips).parent, out_motions, pd.concat(out_rows, ignore_index=True))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
