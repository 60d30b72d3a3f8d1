"""Du 2022 ch. 3 computed once (issue #16): the reference SFPCA of a primitive is fitted once
(rule du2022_fda_sfpca, a model file), and Table 3.1 and the Fig. 3.10 curves read it
instead of fitting it again, with the same numbers; SFPCA's objective runs forward
kinematics in a joint-major layout with bit-identical results."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import rule_scripts
import torch
from fda_toy import StandInDataset, make_clips
from rule_scripts import FakeSnakemake, Named

from motionvar.core import cmu_skeleton
from motionvar.core.kinematics import fk_torch
from motionvar.du2022.fda import SFPCA, canonical_primitives, choose_basis_sizes, functional_primitive
from motionvar.du2022.fda.evaluations import evaluate_table3_1, reconstruction_curves
from motionvar.du2022.fda.models import fit_reference_sfpca, fitted_sfpca, reference_dims
from motionvar.du2022.fda.settings import BasisSettings, FdaSettings, SfpcaSettings, TableSettings
from motionvar.du2022.fda.sfpca import fk_joint_major
from motionvar.io import save_dataset

SFPCA_OPTIONS = {"max_iter": 3, "eval_frames_per_basis": 2}
TABLE_OPTIONS = {"reference_components": 4, "max_components": 50, "observation_error_cm": 1.0}
SETTINGS = FdaSettings.from_dict({"sfpca": SFPCA_OPTIONS, "table": TABLE_OPTIONS})


@pytest.fixture(scope="module")
def canonical():
    clips, labels = make_clips(30, seed=3, lengths=(28, 36))
    primitive = np.array(["walk_leftStance"] * 18 + ["pick_reach"] * 12)
    meta = pd.DataFrame(
        {
            "clip_id": [f"c{i:02d}" for i in range(30)],
            "behaviour": [p.split("_")[0] for p in primitive],
            "primitive": primitive,
            "variant": np.array(["forward", "left", "right"])[labels],
            "n_frames": [c.n_frames for c in clips],
            "fps": 120.0,
        }
    )
    motions, cmeta = canonical_primitives(StandInDataset(clips, meta), ["walk", "pick"], 3, "linear")
    return StandInDataset(motions, cmeta)


@pytest.fixture(scope="module")
def chosen(canonical):
    return choose_basis_sizes(canonical, BasisSettings(n_basis=(4, 6)))[1]


@pytest.fixture(scope="module")
def saved_models(canonical, chosen, tmp_path_factory):
    """The reference SFPCA of each primitive, fitted and written as rule du2022_fda_sfpca does."""
    folder = tmp_path_factory.mktemp("sfpca")
    for _, c in chosen.iterrows():
        fd, _ = functional_primitive(canonical, c["primitive"], int(c["n_basis"]))
        fit_reference_sfpca(fd, SETTINGS).save(folder / f"{c['primitive']}.npz")
    return folder


def test_reference_dims():
    assert reference_dims(1366, TableSettings()) == (60, 20)
    assert reference_dims(12, TableSettings()) == (11, 11)  # both capped at clips - 1
    assert reference_dims(100, TableSettings(max_components=10)) == (10, 10)


def test_saved_sfpca_keeps_its_options_and_fit_facts(canonical, tmp_path):
    fd, _ = functional_primitive(canonical, "walk_leftStance", 6)
    model = SFPCA(3, weight_groups="joint", max_iter=2, tol=1e-5, n_eval_frames=10).fit(fd)
    model.save(tmp_path / "m")
    back = SFPCA.load(tmp_path / "m.npz")
    for name in SFPCA._SAVED_PARAMS:
        assert getattr(back, name) == getattr(model, name), name
    assert back.bounds == (1e-3, 1e3) and isinstance(back.bounds, tuple)
    for name in ("n_evals_", "converged_", "fit_time_s_", "loss_", "n_iter_", "init_"):
        assert getattr(back, name) == getattr(model, name), name
    for name in ("components_", "function_weights_", "mean_"):
        assert np.array_equal(getattr(back, name), getattr(model, name)), name
    assert np.array_equal(back.reconstruct(fd), model.reconstruct(fd))
    back.check_fitted_on(fd, "m.npz")
    with pytest.raises(ValueError, match="m.npz: fitted on other clips"):
        back.check_fitted_on(fd.subset(np.arange(10)), "m.npz")
    # a file written before the options and fit facts were kept still loads (defaults)
    settings = json.loads((tmp_path / "m.json").read_text())
    for name in ("params", "n_evals_", "converged_", "fit_time_s_"):
        settings.pop(name)
    (tmp_path / "m.json").write_text(json.dumps(settings))
    old = SFPCA.load(tmp_path / "m.npz")
    assert old.max_iter == SfpcaSettings.max_iter and not hasattr(old, "fit_time_s_")
    assert np.array_equal(old.components_, model.components_)


def test_table3_1_from_saved_models_equals_fitting_there(canonical, chosen, saved_models):
    fitted_here = evaluate_table3_1(canonical, chosen, SETTINGS)
    models = {p.stem: SFPCA.load(p) for p in saved_models.glob("*.npz")}
    from_files = evaluate_table3_1(canonical, chosen, SETTINGS, sfpca_models=models)
    pd.testing.assert_frame_equal(from_files.table, fitted_here.table, check_exact=True)
    assert from_files.figure["curves"] == fitted_here.figure["curves"]
    # a primitive without a given model is fitted there
    one = evaluate_table3_1(canonical, chosen, SETTINGS, sfpca_models={"walk_leftStance": models["walk_leftStance"]})
    pd.testing.assert_frame_equal(one.table, fitted_here.table, check_exact=True)
    with pytest.raises(ValueError, match="fitted at d = 4, Table 3.1's reference dimension is 3"):
        at_3 = SETTINGS.replace(table=SETTINGS.table.replace(reference_components=3))
        evaluate_table3_1(canonical, chosen, at_3, sfpca_models=models)


def test_curves_reuse_the_reference_fit(canonical, chosen, saved_models):
    n_basis = int(chosen.set_index("primitive").loc["walk_leftStance", "n_basis"])
    fd, meta = functional_primitive(canonical, "walk_leftStance", n_basis)
    settings = FdaSettings.from_dict(
        {"reconstruction": {"dims": [1, 2, 4]}, "latent": {"n_components": 4}, "sfpca": SFPCA_OPTIONS}
    )
    args = (fd, meta["variant"], "walk_leftStance", ["sfpca"], settings)
    fitted_here = reconstruction_curves(*args)
    model = SFPCA.load(saved_models / "walk_leftStance.npz")
    reused = reconstruction_curves(*args, sfpca_models=[model])
    for key, value in fitted_here.items():
        if key == "sfpca/fit_seconds":
            assert reused[key][-1] == model.fit_time_s_  # the time of the fit made elsewhere
        else:
            assert np.array_equal(reused[key], value), key
    with pytest.raises(ValueError, match="fitted with other options: max_iter 3 \\(wanted 5\\)"):
        fitted_sfpca(model, fd, settings.sfpca.replace(max_iter=5))
    with pytest.raises(ValueError, match="fitted on other clips"):
        fitted_sfpca(model, fd.subset(np.arange(12)), settings.sfpca)


def test_joint_major_fk_is_bit_identical_to_fk_torch():
    sk = cmu_skeleton()  # a branching tree of 31 joints
    rng = np.random.default_rng(0)
    N, T, J = 5, 9, sk.n_joints
    q = torch.as_tensor(rng.normal(size=(N, T, J, 4)), dtype=torch.float32)
    q = (q / q.norm(dim=-1, keepdim=True)).requires_grad_(True)
    root = torch.as_tensor(rng.normal(size=(N, T, 3)), dtype=torch.float32)
    offsets = torch.as_tensor(sk.offsets[None, None] * rng.uniform(0.9, 1.1, size=(N, 1, 1, 1)), dtype=torch.float32)
    target = torch.as_tensor(rng.normal(size=(N, T, J, 3)), dtype=torch.float32)
    out = []
    for fk in ("core", "joint_major"):
        qq, rr = q.detach().clone().requires_grad_(True), root.detach().clone().requires_grad_(True)
        if fk == "core":
            pos = fk_torch(qq, rr, offsets, sk.parents)
        else:
            jm = offsets.expand(N, T, J, 3).permute(2, 3, 0, 1).reshape(J, 3, N * T).contiguous()
            pos = fk_joint_major(qq, rr, jm, sk.parents)
        ((pos - target) ** 2).sum(-1).mean().backward()
        out.append((pos.detach(), qq.grad, rr.grad))
    for a, b in zip(*out):
        assert torch.equal(a, b)


def test_rule_scripts_fit_once_and_read_the_file(canonical, chosen, tmp_path):
    """du2022_fda_sfpca writes the model; du2022_table3_1 and du2022_fda_curves read it."""
    rule_scripts.helper_module("_du2022_fda")
    data = tmp_path / "canonical"
    save_dataset(data, canonical.motions, canonical.metadata)
    chosen.to_csv(tmp_path / "n_basis.csv", index=False)
    inputs = dict(
        clips=str(data / "clips.npz"), metadata=str(data / "metadata.csv"), n_basis=str(tmp_path / "n_basis.csv")
    )
    models = []
    for primitive in chosen["primitive"]:
        out = Named(model=str(tmp_path / f"{primitive}.npz"), settings=str(tmp_path / f"{primitive}.json"))
        sm = FakeSnakemake(
            tmp_path,
            "du2022_fda_sfpca",
            input=Named(**inputs),
            output=out,
            params=Named(settings=SETTINGS.to_dict()),
            wildcards=Named(dataset="test", primitive=primitive),
        )
        rule_scripts.run(sm, rule_scripts.script("du2022_fda_sfpca").main)
        assert Path(out.model).is_file() and Path(out.settings).is_file()
        models += [out.model, out.settings]
    out = Named(table=str(tmp_path / "t.csv"), figure=str(tmp_path / "t.png"), claims=str(tmp_path / "t.json"))
    sm = FakeSnakemake(
        tmp_path,
        "du2022_table3_1",
        input=Named(**inputs, sfpca=models),
        output=out,
        params=Named(settings=SETTINGS.to_dict()),
    )
    expected = evaluate_table3_1(canonical, chosen, SETTINGS).table
    rule_scripts.run(sm, rule_scripts.script("du2022_table3_1").main)
    pd.testing.assert_frame_equal(
        pd.read_csv(out.table), pd.read_csv(pd.io.common.StringIO(expected.to_csv(index=False, float_format="%.6g")))
    )
    curves = tmp_path / "walk_leftStance_pca.npz"
    sm = FakeSnakemake(
        tmp_path,
        "du2022_fda_curves",
        input=Named(**inputs, sfpca=models[2:4]),
        output=Named(curves=str(curves)),
        params=Named(
            settings={
                "seed": 0,
                "reconstruction": {"dims": [2, 4]},
                "latent": {"n_components": 4},
                "sfpca": SFPCA_OPTIONS,
                "table": TABLE_OPTIONS,
            },
            methods=["sfpca"],
        ),
        wildcards=Named(dataset="test", primitive="walk_leftStance", part="pca"),
    )
    assert Path(models[2]).stem == "walk_leftStance"
    rule_scripts.run(sm, rule_scripts.script("du2022_fda_curves").main)
    with np.load(curves) as z:
        model = SFPCA.load(models[2])
        assert z["sfpca/fit_seconds"][-1] == model.fit_time_s_  # d = 4 read, not fitted
        assert "init" in str(z["sfpca/info"][-1])
