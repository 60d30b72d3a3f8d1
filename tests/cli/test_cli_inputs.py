"""What the `motionvar` command reads and takes: a damaged file of the run (truncated or
garbled .npz, .pt, .json, .csv; torch weights under other names or of other shapes) ends,
in every command including `motionvar models`, in one line naming the file and the
Snakemake target that rebuilds it, exit status 2; numbers are checked for what they mean
(the BVH unit within motionvar.io.units' range, seeds >= 0, a walk of at least one gait
cycle, each --xi group once)."""

from __future__ import annotations

import shutil

import pytest
from cli_toy import DS, run, toy_results, toy_stride

from motionvar.cli.common import MAX_SEED
from motionvar.io.bvh import read_bvh
from motionvar.io.units import UNIT_CM_MAX, UNIT_CM_MIN

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py

COMMANDS = {  # a small request of each command (its --out is added)
    "ma2010": ["ma2010", "--style", "135", "--seconds", "2"],  # refused before the style is checked
    "egges2004": ["egges2004", "--subject", "01", "--seconds", "1"],
    "walk": ["du2022", "walk", "--path", "0,0 100,0"],
    "style": ["du2022", "style", "--style", "old"],
}


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """results/toy of tests/cli_toy.py (built once per session)."""
    return toy_results(tmp_path_factory)


def command(name: str, tmp_path) -> list[str]:
    """The request ``name`` of COMMANDS writing to a path in ``tmp_path``."""
    out = tmp_path / ("out.bvh" if name in ("egges2004", "walk") else "out")
    return [*COMMANDS[name], "--out", str(out)]


def damaged_copy(results, tmp_path, relative: str, how: str):
    """A copy of the run with ``results/toy/<relative>`` truncated (its first half) or
    garbled (its first 100 bytes overwritten)."""
    copy = tmp_path / "results"
    shutil.copytree(results, copy)
    path = copy / DS / relative
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 2] if how == "truncated" else b"\xff" * 100 + data[100:])
    return copy


def one_error_line(capsys, name: str) -> str:
    err = capsys.readouterr().err
    prefix = f"motionvar {COMMANDS[name][0] if name in COMMANDS else name}: error: "
    assert err.count("\n") == 1 and err.startswith(prefix) and "Traceback" not in err, err
    return err


def no_output(tmp_path) -> bool:
    return not (tmp_path / "out.bvh").exists() and not (tmp_path / "out").exists()


# (damaged file, the file its target names: the model's data file, command reading it)
DAMAGED = [
    ("models/ma2010/style_variation.npz", "models/ma2010/style_variation.npz", "ma2010"),
    ("models/ma2010/style_variation.json", "models/ma2010/style_variation.npz", "ma2010"),
    ("models/egges2004/idle_model.npz", "models/egges2004/idle_model.npz", "egges2004"),
    ("data/clips.npz", "data/clips.npz", "egges2004"),
    ("models/du2022/graph/graph/edges.npz", "models/du2022/graph/graph/edges.npz", "walk"),
    ("models/du2022/graph/walk_leftStance.json", "models/du2022/graph/walk_leftStance.npz", "walk"),
    ("models/du2022_style/autoencoder.pt", "models/du2022_style/autoencoder.pt", "style"),
    ("models/du2022_style/cvae/walk_leftStance/old.pt", "models/du2022_style/cvae/walk_leftStance/old.pt", "style"),
    ("models/du2022_style/rig.json", "models/du2022_style/rig.npz", "style"),
]


@pytest.mark.parametrize("how", ["truncated", "garbled"])
@pytest.mark.parametrize("damaged,rebuilt,name", DAMAGED, ids=[d[0].split("/", 1)[1] for d in DAMAGED])
def test_a_damaged_file_names_itself_and_the_target_that_rebuilds_it(
    results, tmp_path, capsys, damaged, rebuilt, name, how
):
    copy = damaged_copy(results, tmp_path, damaged, how)
    assert run(copy, *command(name, tmp_path)) == 2
    err = one_error_line(capsys, name)
    assert "cannot be read: " in err and str((copy / DS / damaged).with_suffix("")) in err, err
    assert f"rebuild it with `snakemake --cores 2 --force results/{DS}/{rebuilt}`" in err, err
    assert no_output(tmp_path)


@pytest.mark.parametrize("how", ["truncated", "garbled"])
def test_models_lists_a_damaged_model_as_unreadable_and_exits_2(results, tmp_path, capsys, how):
    copy = damaged_copy(results, tmp_path, "models/ma2010/style_variation.npz", how)
    assert run(copy, "models") == 2
    out, err = capsys.readouterr()
    target = f"results/{DS}/models/ma2010/style_variation.npz"
    assert (
        f"UNREADABLE {copy / DS / 'models/ma2010/style_variation.npz'}   <- snakemake --cores 2 --force {target}" in out
    )
    assert "subjects: 01, 02, 03" in out and "style old: primitives walk_leftStance" in out  # the rest is listed
    assert err.count("\n") == 1 and err.startswith("motionvar models: error: the Ma 2010") and target in err


def test_a_garbled_applicability_table_is_named(results, tmp_path, capsys):
    """Read where a model is missing (to say why): a table that is not text is one line."""
    copy = tmp_path / "results"
    (copy / DS / "models").mkdir(parents=True)
    (copy / DS / "applicability.csv").write_bytes(b"evaluation,applicable,reason\n\xff\xfe\x00garbage\n")
    for name in ("egges2004", "models"):
        assert run(copy, *(command(name, tmp_path) if name != "models" else ["models"])) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and f"{copy / DS / 'applicability.csv'}: " in err, err
        assert f"`snakemake --cores 2 --force results/{DS}/applicability.csv`" in err
    assert no_output(tmp_path)


def _reweighted(results, tmp_path, relative: str, change):
    """A copy of the run whose torch weights ``relative`` are ``change(state_dict)``."""
    import torch

    copy = tmp_path / "results"
    shutil.copytree(results, copy)
    path = copy / DS / relative
    torch.save(change(torch.load(path, weights_only=True)), path)
    return copy


@pytest.mark.parametrize(
    "relative,change,message",
    [
        (
            "models/du2022_style/cvae/walk_leftStance/old.pt",
            lambda s: {f"renamed.{k}": v for k, v in s.items()},
            "Missing key(s) in state_dict",
        ),
        (
            "models/du2022_style/autoencoder.pt",
            lambda s: {k: v[..., :-1] if v.ndim > 1 else v for k, v in s.items()},
            "size mismatch for",
        ),
    ],
    ids=["wrong-keys", "wrong-shape"],
)
def test_weights_under_other_names_or_shapes_are_unreadable(results, tmp_path, capsys, relative, change, message):
    copy = _reweighted(results, tmp_path, relative, change)
    assert run(copy, *command("style", tmp_path)) == 2
    err = one_error_line(capsys, "style")
    assert f"{copy / DS / relative}: RuntimeError: " in err and message in err
    assert f"--force results/{DS}/{relative}`" in err and no_output(tmp_path)


@pytest.mark.parametrize("unit", ["inf", "1e300", "1e-300", "nan", "0", "-1", "2000", "0.0001"])
@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_the_bvh_unit_must_be_a_length_unit(results, tmp_path, capsys, name, unit):
    assert run(results, *command(name, tmp_path), "--unit-cm", unit) == 2
    err = one_error_line(capsys, name)
    assert f"--unit-cm {float(unit):g}: not within {UNIT_CM_MIN:g}-{UNIT_CM_MAX:g} cm per unit" in err
    assert no_output(tmp_path)


def test_the_bounds_of_the_unit_are_accepted(results, tmp_path):
    """The unit's range is inclusive; at its top a 1 m hips height is 0.1 units, still
    written with its digits (not 0.000000 as at an infinite unit)."""
    for unit in (UNIT_CM_MIN, UNIT_CM_MAX):
        out = tmp_path / f"{unit:g}.bvh"
        assert run(results, *COMMANDS["egges2004"], "--unit-cm", f"{unit:g}", "--out", str(out)) == 0
        cm = read_bvh(out, scale=unit)
        assert 50.0 < cm.root_pos[:, 1].mean() < 150.0


@pytest.mark.parametrize("seed", ["-5", "-1", str(MAX_SEED + 1)])
@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_a_seed_is_from_0(results, tmp_path, capsys, name, seed):
    assert run(results, *command(name, tmp_path), "--seed", seed) == 2
    assert f"--seed {seed}: a seed is 0 to {MAX_SEED}" in one_error_line(capsys, name)
    assert no_output(tmp_path)


def test_a_walk_is_at_least_one_gait_cycle_and_idle_motion_one_frame(results, tmp_path, capsys):
    from motionvar.cli.ma2010 import min_seconds
    from motionvar.ma2010.storage import load_style_variation_model

    shortest = min_seconds(load_style_variation_model(results / DS / "models/ma2010/style_variation.npz").model)
    assert 0.5 < shortest < 2.0
    out, style = tmp_path / "out", toy_stride(results)
    assert run(results, "ma2010", "--style", style, "--seconds", "0.001", "--out", str(out)) == 2
    err = one_error_line(capsys, "ma2010")
    assert f"--seconds 0.001: a walk is at least one gait cycle, {shortest:.2f} s" in err
    assert run(results, "ma2010", "--style", style, "--seconds", f"{shortest:.2f}", "--out", str(out)) == 0
    walk = read_bvh(next(out.glob("*.bvh")))
    assert walk.n_frames == round(shortest * walk.fps) + 1
    capsys.readouterr()  # its strides may be too few to measure: a warning says so
    assert run(results, "egges2004", "--subject", "01", "--seconds", "0.01", "--out", str(tmp_path / "i.bvh")) == 2
    assert "--seconds 0.01: shorter than one frame of subject 01's idle motion (30 fps" in one_error_line(
        capsys, "egges2004"
    )
    assert not (tmp_path / "i.bvh").exists()


@pytest.mark.parametrize(
    "xi,message",
    [
        ("A=1,A=1.1", "--xi: A is given twice in 'A=1,A=1.1'"),
        ("A=1,a=1.1", "--xi: a is given twice"),
        ("A=1,legs=1.1", "--xi: A and legs both set joint group legs"),
    ],
)
def test_an_xi_group_is_given_once(results, tmp_path, capsys, xi, message):
    assert run(results, *command("ma2010", tmp_path), "--xi", xi) == 2
    assert message in one_error_line(capsys, "ma2010") and no_output(tmp_path)
