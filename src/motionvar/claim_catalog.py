"""Every evaluation and every claim of the three papers as they declare them
(``motionvar.<paper>.catalog``, ``motionvar.<paper>.claims``): the catalog the rules, the report
and the tests look them up in."""

from __future__ import annotations

from .claims import ClaimSpec, Evaluation
from .du2022.catalog import EVALUATIONS as DU2022_EVALUATIONS
from .du2022.claims import CLAIMS as DU2022
from .egges2004.catalog import EVALUATIONS as EGGES2004_EVALUATIONS
from .egges2004.claims import CLAIMS as EGGES2004
from .ma2010.catalog import EVALUATIONS as MA2010_EVALUATIONS
from .ma2010.claims import CLAIMS as MA2010

CLAIMS: tuple[ClaimSpec, ...] = MA2010 + DU2022 + EGGES2004
#: every published evaluation, as each paper's ``catalog.py`` declares it, in the order of a run's
#: claims table (``results/<dataset>/claims.csv``)
EVALUATIONS: tuple[Evaluation, ...] = DU2022_EVALUATIONS + MA2010_EVALUATIONS + EGGES2004_EVALUATIONS


def evaluation(name: str) -> Evaluation:
    """The declaration of one evaluation; KeyError naming it when no paper declares it."""
    for e in EVALUATIONS:
        if e.name == name:
            return e
    raise KeyError(f"no evaluation {name!r} is declared (motionvar.<paper>.catalog)")


def specs_of(evaluation: str) -> tuple[ClaimSpec, ...]:
    """The claims of one evaluation (e.g. ``egges2004_repetition``), in declaration order."""
    return tuple(s for s in CLAIMS if s.evaluation == evaluation)


def spec(claim_id: str) -> ClaimSpec:
    """The declaration of one claim; KeyError naming the id when none has it."""
    for s in CLAIMS:
        if s.claim_id == claim_id:
            return s
    raise KeyError(f"no claim {claim_id!r} is declared (motionvar.<paper>.claims)")


PAPER_TITLES = {"ma2010": "Ma et al. 2010", "du2022": "Du 2022", "egges2004": "Egges et al. 2004"}


def catalog_markdown() -> str:
    """docs/claims.md: per paper, every claim with its source, kind, statement, published value and
    bound, in declaration order (``python tools/claims_doc.py`` writes it; a test keeps it current)."""

    def cell(text: str) -> str:
        return str(text).replace("|", "\\|").replace("\n", " ")

    parts = [
        "# Every claim and its bound",
        "",
        "Written from the declarations (`motionvar/<paper>/claims.py`) by `python tools/claims_doc.py`.",
        "Kinds: `replication`, the paper's own experiment, an outcome that could have gone either way;",
        "`stand-in`, a stated measure for what the paper judged by eye, informally, or cited; `consistency`,",
        "true by construction or a sanity check (listed, never counted as reproduction). Every replication",
        "and stand-in claim has a negative control in `tests/test_controls_*.py`.",
        "",
    ]
    for paper, title in PAPER_TITLES.items():
        specs = [s for s in CLAIMS if s.paper == paper]
        parts += [
            f"## {title}",
            "",
            "| claim | source | kind | statement | published | bound |",
            "|---|---|---|---|---|---|",
        ]
        parts += [
            f"| `{s.claim_id}` | {cell(s.source)} | {s.kind} | {cell(s.statement)} | {cell(s.published)} | "
            f"{cell(s.bound)} |"
            for s in specs
        ]
        parts.append("")
    return "\n".join(parts)
