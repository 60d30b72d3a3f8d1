"""Applicability: evaluations declare what they need, a dataset that lacks it gets
`not applicable` claims with the reason (decided from the data), and the summary counts
them apart from the checked claims."""

from __future__ import annotations

import json

import pandas as pd
import pytest
from rule_scripts import FakeSnakemake, Named, run

from motionvar.applicability import Need, applicability_table, unmet
from motionvar.claim_catalog import specs_of
from motionvar.claims import Claim, NotApplicable, evaluation_source, not_applicable_result
from motionvar.du2022.fda.settings import FdaSettings
from motionvar.du2022.graph.settings import GraphSettings
from motionvar.du2022.requirements import fda_requirements, graph_requirements, style_requirements
from motionvar.du2022.style.settings import StyleSettings
from motionvar.egges2004.requirements import requirements as egges2004_requirements
from motionvar.egges2004.settings import Egges2004Settings
from motionvar.ma2010.requirements import requirements as ma2010_requirements
from motionvar.ma2010.settings import Ma2010Settings
from motionvar.report.summary import claims_html


def _meta(rows):
    meta = pd.DataFrame(rows, columns=["clip_id", "subject", "behaviour", "style", "variant", "primitive"]).astype(str)
    return meta.assign(n_frames="360", fps="120")  # 3-s clips


DATA = _meta(
    [
        ("w1", "s1", "walk", "neutral", "forward", ""),
        ("w2", "s2", "walk", "neutral", "forward", ""),
        ("w3", "s1", "walk", "proud", "forward", ""),
        ("r1", "s1", "run", "neutral", "", ""),
    ]
)
PREP = _meta(
    [
        ("w1_0", "s1", "walk", "neutral", "forward", "walk_leftStance"),
        ("w1_1", "s1", "walk", "neutral", "forward", "walk_rightStance"),
        ("w2_0", "s2", "walk", "neutral", "forward", "walk_leftStance"),
        ("w3_0", "s1", "walk", "proud", "forward", "walk_leftStance"),
    ]
)


def test_unmet_names_what_is_missing_and_why():
    need = Need(what="idle recordings", why="Egges 2004 models standing", where={"behaviour": ("idle",)}, min_count=2)
    assert unmet(need, DATA) == (
        "needs at least 2 idle recordings (clips with behaviour idle), the dataset has none: Egges 2004 models standing"
    )
    walks = Need(what="walks", why="w", where={"behaviour": ("walk",)}, min_count=2, min_subjects=3)
    assert "from at least 3 subjects, the dataset has 2" in unmet(walks, DATA)
    variants = Need(what="walks", why="w", where={"behaviour": ("walk",)}, min_distinct={"variant": 2})
    assert "at least 2 different variant values, the dataset has 1 (forward)" in unmet(variants, DATA)
    assert unmet(Need(what="walks", why="w", where={"behaviour": ("walk",), "variant": ()}), DATA) is None
    long = Need(what="walks", why="w", where={"behaviour": ("walk",)}, min_seconds=4.0)
    assert "(clips with behaviour walk, at least 4 s long), the dataset has none" in unmet(long, DATA)


def test_every_paper_declares_its_evaluations_and_decides_from_the_data():
    reqs = [
        *ma2010_requirements(
            Ma2010Settings().replace(clips__walk_styles=("neutral",), clips__walk_variants=("forward",))
        ),
        *fda_requirements(
            FdaSettings.from_dict(
                {"behaviours": ["walk"], "min_clips": 1, "reconstruction": {"primitives": ["walk_leftStance"]}}
            )
        ),
        *graph_requirements(
            GraphSettings.from_dict({"primitives": ["walk_leftStance"], "search": {"primitives": ["walk_leftStance"]}}),
            1,
        ),
        *style_requirements(
            StyleSettings.from_dict(
                {"styles": ["proud"], "vae_primitives": ["walk_leftStance"], "style_primitives": ["walk_leftStance"]}
            ),
            1,
        ),
        *egges2004_requirements(Egges2004Settings(held_out_clips=1)),
    ]
    table = applicability_table(reqs, {"data": DATA, "prep": PREP}).set_index("evaluation")
    assert table.loc["ma2010_fig6", "applicable"] and table.loc["du2022_fig3_10", "applicable"]
    assert table.loc["du2022_table5_1", "applicable"] and table.loc["du2022_fig4_12", "applicable"]
    assert not table.loc["egges2004_speed", "applicable"]
    assert "idle recordings" in table.loc["egges2004_speed", "reason"]
    assert not table.loc["du2022_fig3_11", "applicable"] and "pick_reach" in table.loc["du2022_fig3_11", "reason"]
    assert not table.loc["du2022_fig4_10", "applicable"]


def test_a_rig_without_hands_or_toes_leaves_out_what_needs_them():
    """Evaluations that need the hands or toes a joint map leaves out are not applicable, with
    the joints and the reason; the others are decided from the data as before."""
    from motionvar.core import REQUIRED_JOINTS, cmu_joint_map
    from motionvar.core.joint_map import JointMap

    cmu = cmu_joint_map()
    handless = JointMap({s: cmu.joints[s] for s in REQUIRED_JOINTS}, cmu.groups, origin="config/joint_maps/x.yaml")
    assert handless.lacking == ("left_hand", "right_hand", "left_toe", "right_toe") and not handless.has("left_toe")
    reqs = [
        *ma2010_requirements(
            Ma2010Settings().replace(clips__walk_styles=("neutral",), clips__walk_variants=("forward",))
        ),
        *style_requirements(
            StyleSettings.from_dict(
                {"styles": ["proud"], "vae_primitives": ["walk_leftStance"], "style_primitives": ["walk_leftStance"]}
            ),
            1,
        ),
        *fda_requirements(
            FdaSettings.from_dict(
                {"behaviours": ["walk"], "min_clips": 1, "reconstruction": {"primitives": ["walk_leftStance"]}}
            )
        ),
    ]
    meta = {"data": DATA, "prep": PREP}
    full = applicability_table(reqs, meta, cmu).set_index("evaluation")
    table = applicability_table(reqs, meta, handless).set_index("evaluation")
    assert full.loc["ma2010_fig6", "applicable"] and not table.loc["ma2010_fig6", "applicable"]
    assert table.loc["ma2010_fig6", "reason"] == (
        "needs the rig's left_toe, right_toe, which the joint map (config/joint_maps/x.yaml) leaves out: Ma 2010's "
        "footskate cleanup stands each foot on its ankle or its toe"
    )
    assert "left_hand, right_hand, left_toe, right_toe" in table.loc["du2022_table5_1", "reason"]
    assert table.loc["du2022_fig3_10", "applicable"]  # functions of every joint the rig has
    from motionvar.core import OPTIONAL_JOINTS
    from motionvar.du2022.requirements import STYLE_JOINTS
    from motionvar.du2022.style.features import FEATURE_JOINTS

    assert STYLE_JOINTS.names == tuple(j for j in FEATURE_JOINTS if j in OPTIONAL_JOINTS)


def test_a_model_per_person_counts_the_people_who_have_enough():
    """Egges 2004 holds out clips per person: a person with one clip does not count towards
    the people identification needs; holding out the end of each recording lets them count."""
    rows = [("a1", "p1", "idle"), ("a2", "p1", "idle"), ("b1", "p2", "idle"), ("c1", "p3", "idle")]
    data = _meta([(c, s, b, "genuine", "", "") for c, s, b in rows]).assign(n_frames="2400", fps="24")
    by_clips = applicability_table(egges2004_requirements(Egges2004Settings()), {"data": data, "prep": data})
    by_clips = by_clips.set_index("evaluation")
    assert by_clips.loc["egges2004_speed", "applicable"]  # p1 has two clips
    assert not by_clips.loc["egges2004_identification", "applicable"]
    assert (
        "(clips with behaviour idle, at least 2 of a subject), the dataset has 2"
        in (by_clips.loc["egges2004_identification", "reason"])
    )
    by_time = applicability_table(
        egges2004_requirements(Egges2004Settings(held_out_by="time")), {"data": data, "prep": data}
    ).set_index("evaluation")
    assert by_time["applicable"].all()  # 100 s recordings: a 20 s window in each held-out 30 %
    short = data.assign(n_frames="1200")  # 50 s: the held-out 15 s hold no 20 s window
    reason = (
        applicability_table(
            egges2004_requirements(Egges2004Settings(held_out_by="time")), {"data": short, "prep": short}
        )
        .set_index("evaluation")
        .loc["egges2004_identification", "reason"]
    )
    assert "at least 66.6667 s long" in reason and "egges2004.identification.window_s" in reason


def test_not_applicable_result_gives_each_claim_the_reason():
    specs = specs_of("egges2004_repetition")
    result = not_applicable_result(
        "egges2004_repetition", "no idle clips", specs, checks="No repeats.", source="Sec. 6"
    )
    assert [c.claim_id for c in result.claims] == [s.claim_id for s in specs] and len(specs) >= 1
    for claim, s in zip(result.claims, specs):
        assert claim.verdict == "not applicable" and claim.note == "no idle clips"
        assert (claim.kind, claim.source, claim.statement) == (s.kind, s.source, s.statement)
    assert result.table["reason"].tolist() == ["no idle clips"] and result.table["checks"].tolist() == ["No repeats."]
    with pytest.raises(ValueError, match="needs its reason"):
        Claim("ma2010.x", "ma2010", "Fig. 6", "replication", "s", "p", "m", "not applicable", note="")


@pytest.mark.parametrize(
    "ev, source",
    [
        ("ma2010_fig6", "Fig. 6"),
        ("du2022_sec4_6_1", "Sec. 4.6.1"),
        ("du2022_table5_1", "Table 5.1"),
        ("egges2004_speed", "egges2004_speed"),
    ],
)
def test_evaluation_source(ev, source):
    assert evaluation_source(ev) == source


def test_summary_counts_undecided_verdicts_apart():
    claims = [
        Claim("ma2010.a", "ma2010", "Fig. 6", "replication", "s", "p", "m", "reproduced"),
        Claim("ma2010.b", "ma2010", "Fig. 8", "replication", "s", "p", "-", "not applicable", note="one subject"),
    ]
    table = pd.DataFrame([c.__dict__ for c in claims])
    html = claims_html(table, {"ma2010": "Ma et al. 2010"})
    assert "not decided:" in html and "1 not applicable" in html and "1 reproduced" in html


def test_an_evaluation_that_raises_not_applicable_writes_its_outputs(tmp_path):
    def main(snakemake):
        raise NotApplicable("only 1 gait cycle; leave-one-out needs 3")

    out = Named(
        table=str(tmp_path / "t.csv"),
        figure=str(tmp_path / "f.png"),
        claims=str(tmp_path / "c.json"),
        gif=str(tmp_path / "a.gif"),
    )
    run(FakeSnakemake(tmp_path, "egges2004_repetition", output=out, wildcards=Named(dataset="xia")), main)
    claims = json.loads((tmp_path / "c.json").read_text())
    assert [c["claim_id"] for c in claims] == [s.claim_id for s in specs_of("egges2004_repetition")]
    for claim in claims:
        assert claim["verdict"] == "not applicable" and "leave-one-out needs 3" in claim["note"]
        assert "xia" in claim["note"]
    assert (tmp_path / "f.png").stat().st_size > 0 and (tmp_path / "a.gif").stat().st_size > 0
    assert pd.read_csv(tmp_path / "t.csv")["verdict"].tolist() == ["not applicable"]


def test_not_applicable_in_a_model_rule_is_an_error_line(tmp_path, capsys):
    def main(snakemake):
        raise NotApplicable("no idle clips")

    with pytest.raises(SystemExit):
        run(FakeSnakemake(tmp_path, "egges2004_model", output=Named(model=str(tmp_path / "m.npz"))), main)
    assert "ERROR rule egges2004_model: not applicable to this dataset: no idle clips" in capsys.readouterr().err


def test_summary_shows_each_claims_value_against_its_bound_in_one_line():
    """The summary's measured cell is one line, the value and its bound; the numbers behind it
    fold beneath it, whole; a claim without a value says so."""
    claims = [
        Claim(
            "ma2010.a",
            "ma2010",
            "Fig. 6",
            "replication",
            "s",
            "p",
            "max 1.83 cm over 80 cycles; a; b; c",
            "partial",
            value=1.83,
            bound=1.2,
            unit="cm",
            direction="<=",
        ),
        Claim("ma2010.b", "ma2010", "Fig. 8", "replication", "s", "p", "-", "not applicable", note="one subject"),
    ]
    html = claims_html(pd.DataFrame([c.__dict__ for c in claims]), {"ma2010": "Ma et al. 2010"})
    assert "<summary>1.83 cm, bound &lt;= 1.2 <span>(the numbers)</span></summary>" in html
    assert "<div>max 1.83 cm over 80 cycles; a; b; c</div>" in html
    assert "<td>no value</td>" in html
