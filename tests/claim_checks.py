"""Checks shared by the claim tests: the number a claim's verdict is computed from (``value``
against ``bound`` in ``direction``, motionvar.claims) agrees with its verdict; a note's length."""

from __future__ import annotations

import operator
import re

from motionvar.claims import CHECKED_VERDICTS, Claim

_COMPARE = {"<=": operator.le, ">=": operator.ge, "<": operator.lt, ">": operator.gt}
#: claims whose verdict needs a second condition beside value-against-bound (its code comment says
#: which): reproduced still needs the value to meet the bound, but meeting it is not enough
GATED = {
    "ma2010.fig7b.error_grows_with_distance",  # and p < 0.05
    "egges2004.sec6.variations_show_little_repetition",  # and generated < looped repetition
    "egges2004.sec5_4.fitting_hits_end_postures",  # and exact end postures
    "ma2010.sec7_4.ours_natural_and_varied",  # and its sequences vary
}


def meets(claim: Claim) -> bool:
    """Whether the claim's value meets its bound in its direction (never for NaN)."""
    return bool(_COMPARE[claim.direction](claim.value, claim.bound))


def check_value_bound(claim: Claim) -> None:
    """A checked claim carries its number (a float, with bound, unit and direction) and is
    reproduced exactly when the number meets the bound (only if, for a :data:`GATED` claim);
    an undecided claim carries none."""
    if claim.verdict not in CHECKED_VERDICTS:
        assert claim.value is None and claim.bound is None and claim.direction == "", claim
        return
    assert isinstance(claim.value, float) and isinstance(claim.bound, float), claim
    assert claim.direction in _COMPARE and claim.unit, claim
    if claim.verdict == "reproduced":
        assert meets(claim), claim
    elif claim.claim_id not in GATED:
        assert not meets(claim), claim


#: a note says what was measured and how it differs from the paper's setup: at most three sentences
NOTE_SENTENCES, NOTE_CHARS = 3, 600


def sentences(text: str) -> int:
    """Sentences of a note: ends of sentence are '.', '!' or '?' before a capital letter or the end."""
    return len(re.findall(r"[.!?](?=\s+[A-Z]|\s*$)", text.strip()))
