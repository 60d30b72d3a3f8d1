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
from .curves import METHODS, NORMALIZED_METHODS, curves_table

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
    below FPCA for picking; monotone curves of the FPCA variants), normalized FPCA being the
    variant of ``reconstruction.normalized_variant``; the figure draws every variant present."""
    table = curves_table(curves)
    rec = settings.reconstruction
    if rec.normalized_variant not in NORMALIZED_METHODS:
        raise ValueError(
            f"du2022_fda.reconstruction.normalized_variant must be one of {list(NORMALIZED_METHODS)}; "
            f"got {rec.normalized_variant!r}"
        )
    present = list(dict.fromkeys(table["method"]))
    methods = [*METHODS, *(m for m in NORMALIZED_METHODS.values() if m in present and m not in METHODS)]
    figure = {"table": table, "methods": methods, "primitives": list(rec.primitives)}
    measurements = fig3_10_measurements(table, rec.pick_primitive, NORMALIZED_METHODS[rec.normalized_variant])
    return EvaluationResult(table, judge_claims(CLAIMS, "du2022_fig3_10", measurements), figure, measurements)


def fig3_10_measurements(table: pd.DataFrame, pick_primitive: str, normalized: str) -> dict[str, Any]:
    """What the Fig. 3.10 claims are judged on: the rows of :func:`.curves.curves_table`
    (``curves``: primitive, method, dims, feature_error, observation_error_cm) of the four
    methods, the normalized FPCA's from method ``normalized`` (one of
    :data:`.curves.NORMALIZED_METHODS`), the two-hand pick primitive, and per normalized
    variant present, at how many of the pick primitive's dimensions it reconstructs joint
    positions better than FPCA (``normalized_variants``: method -> [below FPCA, dimensions])."""
    variants = {}
    pick = table[table["primitive"] == pick_primitive]
    fpca = pick[pick["method"] == "fpca"].set_index("dims")["observation_error_cm"]
    for method in NORMALIZED_METHODS.values():
        v = pick[pick["method"] == method].set_index("dims")["observation_error_cm"]
        if len(v) and len(fpca):
            variants[method] = [int((v < fpca.reindex(v.index)).sum()), len(v)]
    if normalized not in set(table["method"]):
        raise ValueError(
            f"Fig. 3.10: no curves of {normalized} (du2022_fda.reconstruction.normalized_variant); "
            f"the curves hold {sorted(set(table['method']))}"
        )
    four = table[table["method"].isin([m for m in METHODS if m != "normalized_fpca"]) | (table["method"] == normalized)]
    four = four.assign(method=four["method"].replace({normalized: "normalized_fpca"}))
    rows = four[list(CURVE_COLUMNS)].to_dict("records")
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
    return {
        "curves": curves,
        "pick_primitive": str(pick_primitive),
        "normalized_method": normalized,
        "normalized_variants": variants,
    }
