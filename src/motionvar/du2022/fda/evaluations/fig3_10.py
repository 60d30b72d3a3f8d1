"""Du 2022 Fig. 3.10 (Sec. 3.3.5-3.3.6): average reconstruction error against the number of
latent dimensions, in feature space and in observation (joint position) space, for FPCA,
normalized FPCA, SFPCA and the Bayesian GPLVM."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from ....claims import EvaluationResult, judge_claims
from ...claims import CLAIMS
from ..settings import FdaSettings
from .curves import METHODS, curves_table

#: the columns of the Fig. 3.10 table its claims are judged on
CURVE_COLUMNS = ("primitive", "method", "dims", "feature_error", "observation_error_cm")


def evaluate_fig3_10(curves: Sequence[Mapping[str, np.ndarray]], settings: FdaSettings) -> EvaluationResult:
    """Fig. 3.10 from the measurements of :func:`.curves.reconstruction_curves`, one per
    primitive. The figure's columns are the methods (:data:`.curves.METHODS`), its rows
    ``settings.reconstruction.primitives``; ``reconstruction.pick_primitive``: the two-hand
    pick primitive of the normalized-FPCA claim.

    Table: one row per (primitive, method, dimension), with the fit's seconds. Figure:
    ``table``, ``methods``, ``primitives``. Measurements (:func:`fig3_10_measurements`): the
    error curves and the pick primitive, judged in :mod:`motionvar.du2022.claims` (FPCA lowest
    in feature space; SFPCA lowest in observation space for most dimensions; normalized FPCA
    below FPCA for picking; monotone curves of the FPCA variants)."""
    table = curves_table(curves)
    figure = {"table": table, "methods": list(METHODS), "primitives": list(settings.reconstruction.primitives)}
    measurements = fig3_10_measurements(table, settings.reconstruction.pick_primitive)
    return EvaluationResult(table, judge_claims(CLAIMS, "du2022_fig3_10", measurements), figure, measurements)


def fig3_10_measurements(table: pd.DataFrame, pick_primitive: str) -> dict[str, Any]:
    """What the Fig. 3.10 claims are judged on: the rows of :func:`.curves.curves_table`
    (``curves``: primitive, method, dims, feature_error, observation_error_cm) and the
    two-hand pick primitive."""
    rows = table[list(CURVE_COLUMNS)].to_dict("records")
    curves = [
        {
            "primitive": str(r["primitive"]),
            "method": str(r["method"]),
            "dims": int(r["dims"]),
            "feature_error": float(r["feature_error"]),
            "observation_error_cm": float(r["observation_error_cm"]),
        }
        for r in rows
    ]
    return {"curves": curves, "pick_primitive": str(pick_primitive)}
