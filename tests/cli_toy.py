"""A tiny pipeline run for the `motionvar` command's tests: models fitted with the library
on toy data and saved in a results/<dataset>/models/ layout (a Ma 2010 model from the
generator's walks, an idle model, a Morphable Graph of two walking primitives, tiny style
models, plus the packed data), built once per test session; and ``run``, which calls the
command on it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
from egges2004_toy import toy_dataset as idle_toy_dataset
from graph_toy import toy_clips

from motionvar.cli.main import main
from motionvar.core import cmu_joint_map
from motionvar.io import load_dataset, save_dataset

DS = "toy"
JM = cmu_joint_map()
_BUILT: list[Path] = []  # the session's results folder, once built


def toy_results(tmp_path_factory) -> Path:
    """The results folder of the toy run (``<results>/toy``), built on the first call of
    the session; tests that change a file copy it first."""
    if not _BUILT:
        root = tmp_path_factory.mktemp("run") / "results"
        models = root / DS / "models"
        _ma2010(root / DS, models)
        _egges2004(tmp_path_factory.mktemp("idle"), models)
        _graph(models)
        _style(tmp_path_factory.mktemp("style"), models)
        _BUILT.append(root)
    return _BUILT[0]


def _ma2010(ds, models):
    from motionvar.ma2010.examples import WalkCycles, walk_cycles
    from motionvar.ma2010.settings import Ma2010Settings
    from motionvar.ma2010.storage import save_style_variation_model
    from motionvar.synth import generate_walk, make_subjects, sample_walk_params

    rng = np.random.default_rng(1)
    motions, rows = [], []
    for i, s in enumerate(make_subjects(5, seed=7)):
        m, _ = generate_walk(s, sample_walk_params(s, rng, "neutral", n_steps=6))
        motions.append(m)
        rows.append(
            {"clip_id": f"w{i}", "subject": s.subject_id, "behaviour": "walk", "style": "neutral", "variant": "forward"}
        )
    save_dataset(ds / "data", motions, pd.DataFrame(rows))
    settings = Ma2010Settings().replace(clips__n_frames=32)
    clips, table = walk_cycles(load_dataset(ds / "data"), JM, settings)
    walks = WalkCycles(clips, table["subject"].tolist(), JM, root_group=settings.model.root_group)
    model = walks.fit_model(settings)
    save_style_variation_model(models / "ma2010" / "style_variation", model, JM, clips.clip_ids, walks.subjects)


def _egges2004(tmp, models):
    from motionvar.egges2004.pipeline import fit_idle_model, idle_clips, split_clips
    from motionvar.egges2004.settings import Egges2004Settings
    from motionvar.egges2004.storage import save_idle_model

    train, test = split_clips(idle_clips(load_dataset(idle_toy_dataset(tmp)), "prep"), 1)
    model, _ = fit_idle_model(train, test, JM, Egges2004Settings.from_dict({"analysis": {"variation_pcs": 4}}))
    save_idle_model(models / "egges2004" / "idle_model", model)


def _graph(models):
    from motionvar.du2022.graph import MorphableGraph, MotionPrimitive, PrimitiveOptions
    from motionvar.du2022.graph.storage import save_graph

    opt = PrimitiveOptions(n_basis=8, n_components=5, gmm_components=(1, 2), sfpca_max_iter=0)
    for k, name in enumerate(("walk_leftStance", "walk_rightStance")):
        MotionPrimitive(name, opt).fit(toy_clips(10, seed=k)).save(models / "du2022" / "graph" / name)
    graph = MorphableGraph(
        {"walk_leftStance": {"walk_rightStance": 3}, "walk_rightStance": {"walk_leftStance": 3}},
        {"walk_leftStance": 2},
        {"walk_rightStance": 2},
    )
    settings = {"tree_samples": 200, "beam": 2, "max_nfev": 10, "look_ahead": 1, "joint_steps": 0, "seed": 0}
    save_graph(models / "du2022" / "graph" / "graph" / "edges", graph, JM, settings)


def _style(tmp, models):
    from style_toy import TINY_HIDDEN, tiny_settings
    from style_toy import toy_walk as style_toy_walk

    from motionvar.du2022.style import fit_feature_space, fit_primitive_vae, fit_style_cvae, save_vae
    from motionvar.du2022.style.data import dataset_layout
    from motionvar.du2022.style.generate import fit_rig, save_rig

    specs = [("neutral", 0.5, 0.3, 2.0)] * 6 + [("old", 0.2, 0.1, 1.2)] * 2
    motions = [
        style_toy_walk(n_frames=70, seed=k, swing=sw, arm=arm, speed=sp) for k, (_, sw, arm, sp) in enumerate(specs)
    ]
    meta = pd.DataFrame(
        {
            "clip_id": [f"c{k}" for k in range(len(specs))],
            "primitive": "walk_leftStance",
            "style": [st for st, *_ in specs],
            "variant": "forward",
            "turn_deg": 0.0,
        }
    )
    save_dataset(tmp / "prep", motions, meta)
    dataset = load_dataset(tmp / "prep")
    layout = dataset_layout(dataset, JM)
    small, hidden = tiny_settings(ae_epochs=2, vae_epochs=2, cvae_epochs=1), TINY_HIDDEN
    space, _ = fit_feature_space(dataset, layout, small)
    base = models / "du2022_style"
    space.save(base / "autoencoder.pt")
    vae, shape, info, _ = fit_primitive_vae(dataset, layout, space, "walk_leftStance", small, hidden)
    save_vae(base / "vae" / "walk_leftStance.pt", vae, shape, info)
    cvae, cshape, cinfo, _ = fit_style_cvae(dataset, layout, space, vae, "walk_leftStance", "old", small, hidden)
    save_vae(base / "cvae" / "walk_leftStance" / "old.pt", cvae, cshape, cinfo)
    save_rig(base / "rig", fit_rig(dataset, JM, 60))


def run(results, *argv):
    return main(
        [
            argv[0],
            *(argv[1:2] if argv[0] == "du2022" else []),
            "--results",
            str(results),
            "--dataset",
            DS,
            *([] if argv[0] == "models" else ["--quiet"]),
            *argv[(2 if argv[0] == "du2022" else 1) :],
        ]
    )


def toy_stride(results: Path) -> str:
    """A --style inside the toy Ma 2010 model's range: the mean of its examples' strides (cm)."""
    from motionvar.ma2010.storage import load_style_variation_model

    model = load_style_variation_model(results / DS / "models" / "ma2010" / "style_variation.npz").model
    return f"{model.style_.mean():.1f}"
