"""The claims of Du 2022, chapter by chapter: what the thesis states, where, the kind of evidence
our check is, the bound, and the function that judges each from its evaluation's measurements
(``motionvar.claims.ClaimSpec``). Evaluations return measurements; the verdicts are computed in
:mod:`.fda` (ch. 3, functional data analysis), :mod:`.graph` (ch. 4, Morphable Graphs) and
:mod:`.style` (ch. 5, stylistic motion primitives)."""

from .fda import CLAIMS as FDA
from .graph import CLAIMS as GRAPH
from .graph import FIG4_10_NATURAL_PERCENTILE, FIG4_10_REACH_CLOSE_CM
from .style import CLAIMS as STYLE

#: every claim of the thesis, in the order of its chapters
CLAIMS = FDA + GRAPH + STYLE

__all__ = ["CLAIMS", "FIG4_10_NATURAL_PERCENTILE", "FIG4_10_REACH_CLOSE_CM"]
