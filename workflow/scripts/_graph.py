"""Loaders shared by the Morphable Graph rule scripts (Du 2022 ch. 4)."""

from __future__ import annotations

from pathlib import Path


def models(paths) -> dict:
    """The motion primitives saved at the ``.npz`` files among ``paths``, by name, in order."""
    from motionvar.du2022.graph import MotionPrimitive

    loaded = [MotionPrimitive.load(p) for p in paths if str(p).endswith(".npz")]
    return {m.name: m for m in loaded}


def model_bytes(paths) -> dict:
    """Bytes on disk (npz + json) of the models at the ``.npz`` files among ``paths``, by name."""
    return {
        Path(p).stem: sum(Path(p).with_suffix(s).stat().st_size for s in (".npz", ".json"))
        for p in paths
        if str(p).endswith(".npz")
    }


def primitive_clips_of(loaded, snakemake) -> dict:
    """The clips of each loaded primitive (prep stage's, or the dense picks' for ``*_dense``)."""
    from _rule import dataset

    from motionvar.du2022.graph.evaluations.sec4_6_1 import clips_by_primitive

    prep, dense = snakemake.input.clips, list(snakemake.input.dense_clips)
    dense_data = dataset(dense[0]) if dense else None
    return clips_by_primitive(list(loaded), dataset(prep), dense_data, prep, dense[0] if dense else "")
