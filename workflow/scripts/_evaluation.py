"""The rule of a declared evaluation (``motionvar.<paper>.catalog``; rules made by
workflow/rules/evaluations.smk): load its input set, measure, write its table, figure and claims.

An input set's loader reads the rule's input files (the paths: the paper's rule file,
``add_input_set``) and returns the measuring function's keyword arguments; the rule's settings
come with it (``settings=``) where that function takes them."""

from __future__ import annotations

from pathlib import Path
from typing import Any, NamedTuple


class Evaluated(NamedTuple):
    """What :func:`evaluate` measured from (``inputs``: the loader's keyword arguments;
    ``settings``: the section's settings) and its result, for a script that writes more."""

    result: Any
    settings: Any
    inputs: dict


def evaluate(snakemake) -> Evaluated:
    """Measure and write the declared evaluation the rule is named after."""
    import inspect

    from _rule import config_settings, write_evaluation

    from motionvar.claim_catalog import evaluation
    from motionvar.claims import resolve

    declared = evaluation(str(snakemake.rule))
    settings = config_settings(snakemake, declared.section)
    if declared.inputs not in LOADERS:
        raise KeyError(f"evaluation {declared.name}: no loader of its input set {declared.inputs!r} (_evaluation.py)")
    inputs = LOADERS[declared.inputs](snakemake, settings)
    measure = resolve(declared.measure)
    takes_settings = "settings" in inspect.signature(measure).parameters
    result = measure(**inputs, **({"settings": settings} if takes_settings else {}))
    to_csv = {"float_format": declared.table_format} if declared.table_format else {}
    write_evaluation(snakemake, result, resolve(declared.draw), dpi=declared.dpi, **to_csv)
    return Evaluated(result, settings, inputs)


def ma2010_data(snakemake, settings) -> dict:
    from _ma2010 import walks_source
    from _rule import dataset, joint_map

    return {
        "dataset": dataset(snakemake.input.clips),
        "joint_map": joint_map(snakemake),
        "what": walks_source(snakemake),
    }


def ma2010_walks(snakemake, settings) -> dict:
    from _ma2010 import load_walks

    return {"walks": load_walks(snakemake, settings)}


def ma2010_walks_model(snakemake, settings) -> dict:
    """The walking cycles and the model of Sec. 5-6 fitted to them."""
    walks = ma2010_walks(snakemake, settings)["walks"]
    return {"walks": walks, "model": walks.fit_model(settings)}


def egges2004_model(snakemake, settings) -> dict:
    from _egges2004 import model

    return {"model": model(snakemake)}


def egges2004_training(snakemake, settings) -> dict:
    """The model and the training recordings it was fitted to, per subject."""
    from _egges2004 import model, recordings

    m = model(snakemake)
    return {"model": m, "recordings": recordings(snakemake, m)[0]}


def egges2004_recordings(snakemake, settings) -> dict:
    """The model, its training and held-out recordings per subject, the joint map."""
    from _egges2004 import model, recordings
    from _rule import joint_map

    m = model(snakemake)
    train, held_out = recordings(snakemake, m)
    return {"model": m, "recordings": train, "held_out": held_out, "joint_map": joint_map(snakemake)}


def du2022_fda_rmse(snakemake, settings) -> dict:
    import pandas as pd

    return {"rmse": pd.read_csv(snakemake.input.rmse)}


def du2022_fda_curves(snakemake, settings) -> dict:
    from _du2022_fda import load_curves

    return {"curves": load_curves(snakemake.input.curves)}


def du2022_fda_sfpca(snakemake, settings) -> dict:
    """The canonical primitives, the chosen basis sizes, the saved SFPCA models."""
    import pandas as pd
    from _du2022_fda import canonical, load_sfpca

    return {
        "dataset": canonical(snakemake),
        "chosen": pd.read_csv(snakemake.input.n_basis),
        "sfpca_models": load_sfpca(snakemake.input.sfpca),
    }


def du2022_graph_queries(snakemake, settings) -> dict:
    import pandas as pd

    return {"queries": pd.concat([pd.read_csv(p) for p in snakemake.input.queries], ignore_index=True)}


def du2022_graph_models(snakemake, settings) -> dict:
    """The motion primitives, the prep dataset (named ``source`` in errors), the joint map."""
    from _graph import models
    from _rule import dataset, joint_map

    clips = snakemake.input.clips
    return {
        "models": models(snakemake.input.models),
        "dataset": dataset(clips),
        "joint_map": joint_map(snakemake),
        "source": clips,
    }


def du2022_graph_sizes(snakemake, settings) -> dict:
    """Every primitive, its bytes on disk, the clips' metadata (and the dense picks'), and each
    primitive refitted to half of its clips with the bytes of its saved files (Sec. 4.6.1)."""
    import tempfile

    import pandas as pd
    from _graph import model_bytes, models, primitive_clips_of

    from motionvar.du2022.graph.evaluations.sec4_6_1 import fit_half

    paths, dense = snakemake.input.models, snakemake.input.dense
    loaded = models(paths)
    half = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, (idx, model) in fit_half(loaded, primitive_clips_of(loaded, snakemake), settings.seed).items():
            files = model.save(Path(tmp) / name)
            half[name] = (idx, model, sum(f.stat().st_size for f in files))
    return {
        "models": loaded,
        "model_bytes": model_bytes(paths),
        "metadata": pd.read_csv(snakemake.input.metadata),
        "dense_metadata": pd.read_csv(dense[0]) if dense else None,
        "half": half,
    }


def _style(snakemake) -> dict:
    from _style import load_inputs

    dataset, layout, space = load_inputs(snakemake)
    return {"dataset": dataset, "layout": layout, "space": space}


def _vaes(paths) -> list:
    from motionvar.du2022.style import load_vae

    return [load_vae(f) for f in paths]


def _histories(snakemake) -> list:
    import pandas as pd

    return [pd.read_csv(f) for f in snakemake.input.cvae_histories]


def du2022_style_distance(snakemake, settings) -> dict:
    """The feature space, the first neutral VAE, the CVAEs and their training histories."""
    return {
        **_style(snakemake),
        "neutral": _vaes(snakemake.input.vaes[:1])[0],
        "cvaes": _vaes(snakemake.input.cvaes),
        "histories": _histories(snakemake),
    }


def du2022_style_diversity(snakemake, settings) -> dict:
    """The feature space, the neutral VAEs then the CVAEs, the CVAEs' training histories."""
    return {
        **_style(snakemake),
        "models": _vaes([*snakemake.input.vaes, *snakemake.input.cvaes]),
        "histories": _histories(snakemake),
    }


def du2022_style_samples(snakemake, settings) -> dict:
    return {**_style(snakemake), "models": _vaes([*snakemake.input.vaes, *snakemake.input.cvaes])}


#: input set (``Evaluation.inputs``) -> its loader
LOADERS = {
    "ma2010_data": ma2010_data,
    "ma2010_walks": ma2010_walks,
    "ma2010_walks_model": ma2010_walks_model,
    "egges2004_model": egges2004_model,
    "egges2004_training": egges2004_training,
    "egges2004_recordings": egges2004_recordings,
    "du2022_fda_rmse": du2022_fda_rmse,
    "du2022_fda_curves": du2022_fda_curves,
    "du2022_fda_sfpca": du2022_fda_sfpca,
    "du2022_graph_queries": du2022_graph_queries,
    "du2022_graph_diversity": du2022_graph_models,
    "du2022_graph_synthesis": du2022_graph_models,
    "du2022_graph_sizes": du2022_graph_sizes,
    "du2022_style_distance": du2022_style_distance,
    "du2022_style_diversity": du2022_style_diversity,
    "du2022_style_samples": du2022_style_samples,
}
