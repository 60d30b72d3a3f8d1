"""Rule ma2010_clips: the walking clips of a dataset cut into gait cycles at their key
frames (Ma 2010 Eq. 1-4), space- and time-warped onto the mean skeleton (Sec. 4.2), with
their style parameters (stride of the left and right support phases, Sec. 7.2)."""


def main(snakemake) -> None:
    import logging

    import numpy as np
    from pathlib import Path

    from _ma2010 import joint_map
    from motionvar.io import load_dataset
    from motionvar.ma2010 import build_clipset
    from motionvar.ma2010.correspondence import standard_skeleton
    from motionvar.ma2010.examples import collect_cycles, rows_matching

    o = snakemake.params.options
    data = load_dataset(Path(snakemake.input.clips).parent)
    meta = data.metadata
    idx = rows_matching(meta, behaviour="walk", style=o["walk_styles"], variant=o["walk_variants"],
                        what=f"{snakemake.input.metadata} (config ma2010.walk_styles / walk_variants)")
    jm = joint_map(snakemake)
    motions = [data.motion(int(i)) for i in idx]
    cycles, keys, table = collect_cycles(
        motions, meta["clip_id"].iloc[idx].tolist(), jm, o["keyframe_prominence"], o["keyframe_min_separation_s"]
    )
    if len(cycles) < 3:
        raise ValueError(
            f"{snakemake.input.metadata}: {len(idx)} walking clips gave {len(cycles)} complete gait cycles; need at "
            "least 3 (more subjects in config datasets, or other config ma2010.walk_styles)"
        )
    sk = standard_skeleton([c.skeleton for c in cycles])
    clips = build_clipset(cycles, keys, sk, jm, o["n_frames"], clip_ids=table["clip_id"].tolist())
    src = meta.set_index("clip_id").loc[table["source_clip"]]
    table["subject"] = src["subject"].astype(str).to_numpy()
    for col in ("style", "stride_length_cm", "speed_cm_s"):
        if col in src:
            table[f"source_{col}"] = src[col].to_numpy()
    table["left_support_stride_cm"], table["right_support_stride_cm"] = clips.style[:, 0], clips.style[:, 1]
    table["duration_s"] = clips.key_times[:, -1]
    np.savez(snakemake.output.clips, **clips.to_arrays())
    table.to_csv(snakemake.output.table, index=False)
    logging.info("%d walking clips -> %d cycles of %d subjects", len(idx), len(cycles), table["subject"].nunique())


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
