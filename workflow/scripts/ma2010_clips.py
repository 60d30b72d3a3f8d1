"""Rule ma2010_clips: the walking clips of a dataset cut into gait cycles at their key
frames (Ma 2010 Eq. 1-4), space- and time-warped onto the mean skeleton (Sec. 4.2), with
their style parameters (motionvar.ma2010.examples.walk_cycles); the clips are saved as a
model file (npz + json), the cycles as a table."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from _ma2010 import settings, walks_source
    from _rule import joint_map

    from motionvar.io import load_dataset
    from motionvar.io.model_file import save_model
    from motionvar.ma2010.examples import CLIPSET_KIND, walk_cycles

    s = settings(snakemake)
    clips, table = walk_cycles(
        load_dataset(Path(snakemake.input.clips).parent),
        joint_map(snakemake),
        s,
        what=walks_source(snakemake),
    )
    save_model(snakemake.output.clips, clips.to_arrays(), {"kind": CLIPSET_KIND, **s.clips.to_dict()})
    table.to_csv(snakemake.output.table, index=False)
    logging.info("%d cycles of %d subjects", clips.n_clips, table["subject"].nunique())


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
