"""Rule scripts run outside Snakemake with a stand-in for its ``snakemake`` object:
bad input gives one clear error line naming the file or config key, exit status 1, and
no output file."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from rule_scripts import FakeSnakemake, Named, run, script

from motionvar.claims import CLAIM_COLUMNS, Claim, write_claims
from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import qidentity
from motionvar.io.bvh import write_bvh


def claim(i, verdict="reproduced", paper="du2022"):
    return Claim(
        f"{paper}.c{i}", paper, f"Fig. {i}", "replication", f"statement {i}", "< 1 cm", f"{i / 10:.1f} cm", verdict
    )


def test_claims_merge_and_summary(tmp_path):
    write_claims(tmp_path / "a.json", [claim(1), claim(2, "partial")])
    write_claims(tmp_path / "b.json", [claim(3, "not reproduced", paper="ma2010")])
    write_claims(tmp_path / "empty.json", [])
    out = tmp_path / "claims.csv"
    inputs = [str(tmp_path / n) for n in ("b.json", "a.json", "empty.json")]
    run(FakeSnakemake(tmp_path, "claims", input=Named(claims=inputs), output=Named([str(out)])), script("claims").main)
    table = pd.read_csv(out)
    assert list(table.columns) == list(CLAIM_COLUMNS)
    assert table["claim_id"].tolist() == ["du2022.c1", "du2022.c2", "ma2010.c3"]

    html_out = tmp_path / "summary.html"
    fake = FakeSnakemake(
        tmp_path,
        "claims_summary",
        input=Named(claims=str(out)),
        output=Named([str(html_out)]),
        params=Named(categories={"ma2010": "Ma et al. 2010", "du2022": "Du 2022"}, stability=""),
    )
    run(fake, script("claims_summary").main)
    html = html_out.read_text()
    assert html.index("Ma et al. 2010") < html.index("Du 2022")  # paper order of the categories
    for colour in ("#c9ecd0", "#ffe8a8", "#f6c6c6"):
        assert colour in html
    assert "statement 3" in html and "&lt; 1 cm" in html and "across seeds" not in html
    # with a stability run's table (this dataset among its seeds), each verdict says how many seeds give it
    stab = tmp_path / "claims_stability.csv"
    seeds = {f"verdict_{s}": ["reproduced", "not reproduced"] for s in ("test", "b", "c")}
    seeds |= {"verdict_d": ["reproduced", "partial"], "verdict_e": ["partial", "partial"]}
    pd.DataFrame({"claim_id": ["du2022.c1", "ma2010.c3"], **seeds}).to_csv(stab, index=False)
    fake.params = Named(categories={}, stability=str(stab))
    run(fake, script("claims_summary").main)
    html = html_out.read_text()
    assert "4 of 5 seeds give it" in html and "UNSTABLE: 3 of 5 seeds give it" in html
    assert "not in the stability run" in html  # du2022.c2
    # the table of config key stability.marks without this dataset among its seeds marks nothing
    other = tmp_path / "other_stability.csv"
    pd.DataFrame({"claim_id": ["du2022.c1"], "verdict_x": ["reproduced"], "verdict_y": ["partial"]}).to_csv(other)
    fake.params = Named(categories={}, stability=str(other))
    run(fake, script("claims_summary").main)
    assert "across seeds" not in html_out.read_text()


def test_claims_merge_of_no_evaluations_is_an_empty_table(tmp_path):
    out = tmp_path / "claims.csv"
    run(FakeSnakemake(tmp_path, "claims", input=Named(claims=[]), output=Named([str(out)])), script("claims").main)
    assert out.read_text().strip() == ",".join(CLAIM_COLUMNS)
    html_out = tmp_path / "summary.html"
    fake = FakeSnakemake(
        tmp_path,
        "claims_summary",
        input=Named(claims=str(out)),
        output=Named([str(html_out)]),
        params=Named(categories={}, stability=""),
    )
    run(fake, script("claims_summary").main)
    assert "No claims yet" in html_out.read_text()


@pytest.mark.parametrize(
    "content, expected",
    [
        ("{not json", "not a valid claims file"),
        (json.dumps([{"claim_id": "du2022.x", "paper": "du2022"}]), "not a valid claims file"),
        (
            json.dumps([{**dict(zip(CLAIM_COLUMNS, ["du2022.x"] + ["du2022"] + ["s"] * 6)), "verdict": "great"}]),
            "verdict 'great'",
        ),
    ],
)
def test_claims_merge_rejects_a_malformed_claims_file(tmp_path, capsys, content, expected):
    write_claims(tmp_path / "good.json", [claim(1)])
    bad = tmp_path / "du2022_fig9.json"
    bad.write_text(content)
    out = tmp_path / "claims.csv"
    fake = FakeSnakemake(
        tmp_path, "claims", input=Named(claims=[str(tmp_path / "good.json"), str(bad)]), output=Named([str(out)])
    )
    with pytest.raises(SystemExit) as exit_info:
        run(fake, script("claims").main)
    assert exit_info.value.code == 1
    err = capsys.readouterr().err.strip()
    assert err.startswith("ERROR rule claims: ") and str(bad) in err and expected in err
    assert len(err.splitlines()) == 1  # one line on the console, the traceback is in the log
    assert str(bad) in Path(fake.log[0]).read_text()
    assert not out.exists()


def test_claims_merge_rejects_duplicate_claim_ids(tmp_path, capsys):
    write_claims(tmp_path / "a.json", [claim(1)])
    write_claims(tmp_path / "b.json", [claim(1)])
    out = tmp_path / "claims.csv"
    fake = FakeSnakemake(
        tmp_path,
        "claims",
        input=Named(claims=[str(tmp_path / "a.json"), str(tmp_path / "b.json")]),
        output=Named([str(out)]),
    )
    with pytest.raises(SystemExit):
        run(fake, script("claims").main)
    assert "du2022.c1" in capsys.readouterr().err and not out.exists()


def test_claims_summary_rejects_a_table_with_unknown_verdicts(tmp_path, capsys):
    table = tmp_path / "claims.csv"
    pd.DataFrame(
        [{**dict.fromkeys(CLAIM_COLUMNS, "s"), "claim_id": "du2022.x", "paper": "du2022", "verdict": "maybe"}]
    ).to_csv(table, index=False)
    out = tmp_path / "summary.html"
    fake = FakeSnakemake(
        tmp_path,
        "claims_summary",
        input=Named(claims=str(table)),
        output=Named([str(out)]),
        params=Named(categories={}, stability=""),
    )
    with pytest.raises(SystemExit):
        run(fake, script("claims_summary").main)
    err = capsys.readouterr().err
    assert str(table) in err and "unknown verdicts ['maybe']" in err and not out.exists()


def bvh_folder(tmp_path, labels):
    folder = tmp_path / "bvh"
    folder.mkdir()
    sk = cmu_skeleton()
    root = np.column_stack([np.zeros(10), np.full(10, 95.0), np.linspace(0.0, 30.0, 10)])  # 1 m/s forward
    motion = Motion(sk, root, qidentity((10, sk.n_joints)), 30.0)  # a stiff walk, but the gates pass it
    write_bvh(folder / "walk_01.bvh", motion)
    (folder / "labels.csv").write_text(labels)
    return folder


def data_fake(tmp_path, entry):
    out = tmp_path / "results" / "data"
    return out, FakeSnakemake(
        tmp_path,
        "data",
        output=Named(clips=str(out / "clips.npz"), metadata=str(out / "metadata.csv")),
        params=Named(entry=entry),
        wildcards=Named(dataset="mine"),
    )


def bvh_entry(folder, **kw):
    return {
        "source": "bvh",
        "path": str(folder),
        "labels": "labels.csv",
        "unit_cm": 1.0,
        "drop_first_frame": False,
        "joint_map": None,
        **kw,
    }


def test_data_script_imports_a_bvh_folder(tmp_path):
    folder = bvh_folder(tmp_path, "file,subject,behaviour,style\nwalk_01.bvh,s1,walk,neutral\n")
    out, fake = data_fake(tmp_path, bvh_entry(folder))
    run(fake, script("data").main)
    meta = pd.read_csv(out / "metadata.csv")
    assert meta["clip_id"].tolist() == ["walk_01"] and meta["n_frames"].tolist() == [10]


@pytest.mark.parametrize(
    "labels, entry_kw, expected",
    [
        (
            "file,subject,behaviour,style\nmissing.bvh,s1,walk,neutral\n",
            {},
            "labels.csv:2: labelled file 'missing.bvh'",
        ),
        ("file,subject,style\nwalk_01.bvh,s1,neutral\n", {}, "missing required column 'behaviour'"),
        ("file,subject,behaviour,style\nwalk_01.bvh,s1,walk,neutral\n", {"joint_map": "nope.yaml"}, "nope.yaml"),
    ],
)
def test_data_script_names_the_dataset_and_the_file(tmp_path, capsys, labels, entry_kw, expected):
    folder = bvh_folder(tmp_path, labels)
    out, fake = data_fake(tmp_path, bvh_entry(folder, **entry_kw))
    with pytest.raises(SystemExit):
        run(fake, script("data").main)
    err = capsys.readouterr().err
    assert err.startswith("ERROR rule data: datasets.mine: ") and expected in err
    assert not out.exists() or not any(out.iterdir())


def test_data_script_reads_a_deeply_nested_rig(tmp_path, capsys):
    """A hierarchy nested 1,000 deep once stopped the data rule with a bare RecursionError."""
    from bvh_files import chain_bvh

    folder = tmp_path / "bvh"
    folder.mkdir()
    (folder / "deep.bvh").write_text(chain_bvh(1_000))
    (folder / "labels.csv").write_text("file,subject,behaviour,style\ndeep.bvh,s1,walk,neutral\n")
    out, fake = data_fake(tmp_path, bvh_entry(folder))
    with pytest.raises(SystemExit):  # it reads; the CMU joint map then does not fit this rig
        run(fake, script("data").main)
    assert "joints not in the skeleton" in capsys.readouterr().err
    assert not out.exists() or not any(out.iterdir())


def floor_rooted_folder(tmp_path, hips):
    """The CMU rig under an extra ROOT ``Ground`` at floor level (as Bandai's joint_Root),
    walking at 1 m/s, and a joint map whose ``hips`` is ``hips``."""
    from motionvar.core import Skeleton

    cmu = cmu_skeleton()
    names = ("Ground",) + cmu.names
    parents = np.concatenate([[-1], cmu.parents + 1])
    parents[1] = 0
    offsets = np.vstack([[0.0, 0.0, 0.0], cmu.offsets])
    offsets[1] = [0.0, 95.0, 0.0]
    sk = Skeleton(names, parents, offsets, {j + 1: o for j, o in cmu.end_sites.items()})
    root = np.column_stack([np.zeros(30), np.zeros(30), np.linspace(0.0, 100.0, 30)])
    folder = tmp_path / "bvh"
    folder.mkdir()
    write_bvh(folder / "walk_01.bvh", Motion(sk, root, qidentity((30, len(names))), 30.0))
    (folder / "labels.csv").write_text("file,subject,behaviour,style\nwalk_01.bvh,s1,walk,neutral\n")
    jm = (Path(__file__).resolve().parents[2] / "config/joint_maps/cmu.yaml").read_text()
    (folder / "rig.yaml").write_text(jm.replace("  hips: Hips\n", f"  hips: {hips}\n"))
    return folder


def test_data_script_stops_when_the_hips_is_a_floor_point(tmp_path, capsys):
    folder = floor_rooted_folder(tmp_path, hips="Ground")
    out, fake = data_fake(tmp_path, bvh_entry(folder, joint_map=str(folder / "rig.yaml")))
    with pytest.raises(SystemExit):
        run(fake, script("data").main)
    err = capsys.readouterr().err.strip()
    assert (
        err.startswith("ERROR rule data: datasets.mine: pelvis (joint map hips = Ground) is ")
        and len(err.splitlines()) == 1
    )
    assert "1/1 clips outside 60-130 cm" in err and f"check the joint map's 'hips' ({folder / 'rig.yaml'})" in err
    assert not out.exists() or not any(out.iterdir())
    fake.params.entry["plausibility_check"] = False  # expert switch: the same data goes through
    run(fake, script("data").main)
    assert (out / "metadata.csv").is_file()


def test_data_script_reroots_at_the_hips_and_passes(tmp_path):
    from motionvar.io import load_dataset

    folder = floor_rooted_folder(tmp_path, hips="Hips")
    out, fake = data_fake(tmp_path, bvh_entry(folder, joint_map=str(folder / "rig.yaml")))
    run(fake, script("data").main)
    clip = load_dataset(out).motion(0)
    assert clip.skeleton.names == cmu_skeleton().names  # Ground is gone, Hips is joint 0
    assert np.allclose(clip.root_pos[:, 1], 95.0) and np.isclose(clip.root_pos[-1, 2], 100.0)
    assert "plausibility over 1 clips" in Path(fake.log[0]).read_text()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc's mallopt")
def test_keep_freed_memory_reuses_large_blocks_without_new_page_faults():
    """After ``_rule.keep_freed_memory`` a freed 200 MB array's pages serve the next one (no
    new page faults); without it each is a fresh mmap, faulted in page by page (pages of 4 KiB,
    or 2 MiB where transparent huge pages serve it)."""
    code = """
import resource, sys
import numpy as np
sys.path.insert(0, {scripts!r})
if {keep}:
    from _rule import keep_freed_memory
    assert keep_freed_memory()
def faults():
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt
np.ones(25_000_000)
before = faults()
np.ones(25_000_000)
print(faults() - before)
"""
    scripts = str(Path(__file__).resolve().parents[2] / "workflow" / "scripts")
    new_faults = {
        keep: int(
            subprocess.run(
                [sys.executable, "-c", code.format(scripts=scripts, keep=keep)],
                check=True,
                capture_output=True,
                text=True,
            ).stdout
        )
        for keep in (False, True)
    }
    assert new_faults[True] < 50 < new_faults[False], new_faults  # 4 KiB or 2 MiB (huge) pages
