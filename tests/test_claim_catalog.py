"""The claims catalog (motionvar.claim_catalog): every claim declared once with its kind, every
replication and stand-in claim with a negative control, and notes without run history."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from claim_checks import NOTE_CHARS, NOTE_SENTENCES, sentences
from negative_controls import all_controls

from motionvar.claim_catalog import CLAIMS, catalog_markdown, spec, specs_of
from motionvar.claims import EVIDENCE_KINDS, KINDS, not_applicable_result, specs_table

SRC = Path(__file__).resolve().parents[1] / "src" / "motionvar"
#: words that tell a run's history rather than what is (history belongs in CHANGELOG.md)
HISTORY = re.compile(r"previous run|changed from|changed since|no longer|earlier run|\(issue \d+\)", re.I)


def test_every_claim_is_declared_once_with_a_kind():
    ids = [s.claim_id for s in CLAIMS]
    assert len(ids) == len(set(ids))
    assert all(s.kind in KINDS for s in CLAIMS)
    assert {s.paper for s in CLAIMS} == {"ma2010", "du2022", "egges2004"}


def test_every_evaluation_is_declared_once_and_everything_else_is_read_off_it():
    """Each paper declares its evaluations once (``<paper>/catalog.py``): a unique name
    ``<paper>_<what>``, a config section with a settings class, a report caption of that name,
    an input set, a measuring and a drawing function, the requirements the applicability table gives it (the same source and
    checks), and every claim's evaluation among them."""
    from motionvar.claim_catalog import EVALUATIONS, evaluation
    from motionvar.config_sections import SECTIONS, section_settings
    from motionvar.du2022.requirements import fda_requirements, graph_requirements, style_requirements
    from motionvar.egges2004.requirements import requirements as egges2004
    from motionvar.ma2010.requirements import requirements as ma2010

    names = [e.name for e in EVALUATIONS]
    assert len(names) == len(set(names)) and {e.paper for e in EVALUATIONS} == {"ma2010", "du2022", "egges2004"}
    workflow = SRC.parents[1] / "workflow"
    for e in EVALUATIONS:
        assert e.section in SECTIONS and e.source and e.checks, e
        assert (workflow / "report" / f"{e.name}.rst").is_file() and e.inputs and e.measure and e.draw, e.name
    papers = {
        "ma2010": ma2010,
        "du2022_fda": fda_requirements,
        "du2022_graph": graph_requirements,
        "du2022_style": style_requirements,
    }
    reqs = [r for sec, of in {**papers, "egges2004": egges2004}.items() for r in of(section_settings(sec, {}))]
    assert sorted(r.evaluation for r in reqs) == sorted(names)
    for r in reqs:
        e = evaluation(r.evaluation)
        assert (r.paper, r.source, r.checks) == (e.paper, e.source, e.checks), r.evaluation
    assert {s.evaluation for s in CLAIMS} <= set(names)
    with pytest.raises(KeyError, match="no evaluation 'du2022_fig9' is declared"):
        evaluation("du2022_fig9")


def test_every_replication_and_stand_in_claim_has_a_negative_control():
    controls = all_controls()
    needed = {s.claim_id for s in CLAIMS if s.kind in EVIDENCE_KINDS}
    assert sorted(needed - set(controls)) == [], "claims without a negative control"
    unknown = sorted(set(controls) - {s.claim_id for s in CLAIMS})
    assert unknown == [], "controls of claims that are not declared"
    consistency = sorted(c for c in controls if spec(c).kind == "consistency")
    assert consistency == [], "a consistency claim needs no control: it cannot fail by construction"
    assert all(len(m) == 1 for m in controls.values()), {c: m for c, m in controls.items() if len(m) > 1}


def test_a_declaration_table_shows_every_claim_and_its_bound():
    table = specs_table(CLAIMS)
    assert len(table) == len(CLAIMS) and table["bound"].str.len().min() > 0


def test_a_not_applicable_evaluation_lists_each_of_its_claims():
    result = not_applicable_result("egges2004_repetition", "no idle clips", specs_of("egges2004_repetition"))
    assert [c.claim_id for c in result.claims] == [s.claim_id for s in specs_of("egges2004_repetition")]
    assert all(c.verdict == "not applicable" and c.note == "no idle clips" for c in result.claims)


@pytest.mark.parametrize("path", sorted(SRC.rglob("*.py")), ids=lambda p: str(p.relative_to(SRC)))
def test_library_code_tells_no_run_history(path):
    hits = [line.strip() for line in path.read_text().splitlines() if HISTORY.search(line)]
    assert hits == [], f"{path}: history belongs in CHANGELOG.md"


def test_docs_claims_md_lists_the_declarations_as_they_are():
    doc = Path(__file__).resolve().parents[1] / "docs" / "claims.md"
    assert doc.read_text(encoding="utf-8") == catalog_markdown(), "run python tools/claims_doc.py"


@pytest.mark.parametrize("claim_id", sorted(all_controls()))
def test_a_note_is_at_most_three_sentences(claim_id):
    from negative_controls import control_claim

    note = control_claim(claim_id).note
    assert sentences(note) <= NOTE_SENTENCES and len(note) <= NOTE_CHARS, (claim_id, len(note), note)
