"""Animation fitting (Egges et al. 2004, Sec. 5.4.4, 7.1, Fig. 4-5): a best-fitting
animation fitted with ``fitAnim_part`` starts at p and ends at q exactly, and the pieces
of a generated sequence (rests, fitted shifts, idle motion between two given postures)
join without jumps; the step measures at the junctions are defined here.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pandas as pd

from ...claims import EvaluationResult, judge_claims
from ..balance import fitted_shift, random_posture, synthesize_balance
from ..claims import CLAIMS
from ..fitting import RAMPS, fit_anim_part, posture_distance
from ..integration import idle_between
from ..pipeline import IdleModel
from ..settings import Egges2004Settings, FittingSettings
from .common import subject_rng

# length (s) of the balance sequence drawn in the figure
FIGURE_BALANCE_S = 60.0


def junction_steps(pcs: np.ndarray, boundaries: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Step sizes (sqrt of Eq. 4 between consecutive frames) and second differences at
    the given frames: the step from frame b to b+1 and |x_{b+1} - 2 x_b + x_{b-1}|."""
    pcs = np.asarray(pcs)
    b = np.asarray(boundaries, dtype=np.int64)
    b = b[(b >= 1) & (b < len(pcs) - 1)]
    step = np.sqrt(posture_distance(pcs[b + 1], pcs[b], weights))
    second = pcs[b + 1] - 2 * pcs[b] + pcs[b - 1]
    accel = np.sqrt(posture_distance(second, np.zeros_like(second), weights))
    return step, accel


def all_steps(pcs: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Step sizes and second differences (as :func:`junction_steps`) at every inner frame."""
    return junction_steps(pcs, np.arange(1, len(pcs) - 1), weights)


def _posture_error_cm(model: IdleModel, subject: str, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Largest joint-position distance (cm) between postures a and b (n, D)."""
    sk, fps = model.skeletons[subject], model.databases[subject].fps
    pa = model.pca.reconstruct(a, sk, fps).positions()
    pb = model.pca.reconstruct(b, sk, fps).positions()
    return np.linalg.norm(pa - pb, axis=-1).max(axis=-1)


def fitting(model: IdleModel, settings: Egges2004Settings) -> EvaluationResult:
    """Fit best-fitting animations to random (p, q) of the category graph and check that
    they start at p and end at q; generate balance sequences and idle motion between two
    recorded postures (Sec. 7.1) and compare the steps at the junctions with the steps
    inside the recorded balance shifts (``settings.fitting``, ``settings.seed``). Returns
    the table, the claim, the figure's data (:func:`_figure_data`) and the measurements
    (:func:`fitting_measurements`)."""
    params, seed = settings.fitting, settings.seed
    rows, example = [], {}
    for s, db in model.databases.items():
        rng = subject_rng(seed, s, "fitting")
        rec_step, rec_acc = (np.concatenate(v) for v in zip(*(all_steps(a, db.weights) for a in db.animations)))
        quantiles = np.quantile(rec_step, params.quantile), np.quantile(rec_acc, params.quantile)
        for ramp in RAMPS:
            rows.append(_shift_row(model, s, ramp, rng, params, quantiles, example))
        rows.append(_between_row(model, s, rng, params, quantiles))
    table = pd.DataFrame(rows)
    measurements = fitting_measurements(table, params)
    claims = judge_claims(CLAIMS, "egges2004_fitting", measurements)
    return EvaluationResult(table, claims, _figure_data(model, example, settings), measurements)


def _shift_row(
    model: IdleModel,
    s: str,
    ramp: str,
    rng: np.random.Generator,
    params: FittingSettings,
    quantiles: tuple[float, float],
    example: dict,
) -> dict:
    """One subject and ramp: ``params.pairs`` best-fitting animations fitted to random (p, q)
    of the graph's edges (Sec. 5.4.4), their end errors, and the junction steps of a
    balance sequence of ``params.sequence_s`` against the recorded ``quantiles`` (step,
    second difference). The first linear fit of each subject goes into ``example``."""
    db = model.databases[s]
    edges = np.argwhere(db.graph.probabilities > 0)
    starts, ends, fit_s, fit_e = [], [], [], []
    for c, t in edges[rng.integers(len(edges), size=params.pairs)]:
        p, q = random_posture(db, c, rng), random_posture(db, t, rng)
        a, i = fitted_shift(db, p, q, ramp)
        starts.append(p), ends.append(q), fit_s.append(a[0]), fit_e.append(a[-1])
        if s not in example and ramp == "linear":
            example[s] = {"original": db.animations[i], "p": p, "q": q, "subject": s, "fps": db.fps}
    seq, events = synthesize_balance(db, int(round(params.sequence_s * db.fps)) + 1, rng, ramp=ramp)
    cuts = np.array([e.start for e in events if e.kind == "shift"] + [e.stop for e in events if e.kind == "shift"])
    j_step, j_acc = junction_steps(seq, cuts, db.weights)
    return _row(model, s, ramp, "fitAnim_part (p, q)", (starts, ends, fit_s, fit_e), j_step, j_acc, quantiles)


def _between_row(
    model: IdleModel, s: str, rng: np.random.Generator, params: FittingSettings, quantiles: tuple[float, float]
) -> dict:
    """One subject: idle motion of ``params.between_s`` between two random postures of
    routable categories (Sec. 7.1), a tenth of ``params.pairs`` cases (at least one)."""
    db = model.databases[s]
    starts, ends, fit_s, fit_e, steps, accs = [], [], [], [], [], []
    routes = db.graph.routable_pairs()
    for c0, c1 in routes[rng.integers(len(routes), size=max(1, params.pairs // 10))]:
        p0, p1 = random_posture(db, c0, rng), random_posture(db, c1, rng)
        out, events = idle_between(db, p0, p1, int(round(params.between_s * db.fps)) + 1, rng)
        starts.append(p0), ends.append(p1), fit_s.append(out[0]), fit_e.append(out[-1])
        cuts = np.array([e.start for e in events] + [e.stop for e in events])
        st, ac = junction_steps(out, cuts, db.weights)
        steps.append(st), accs.append(ac)
    steps, accs = np.concatenate(steps), np.concatenate(accs)
    return _row(model, s, "linear", "idle_between (p0, p1)", (starts, ends, fit_s, fit_e), steps, accs, quantiles)


def _row(
    model: IdleModel,
    s: str,
    ramp: str,
    test: str,
    fits: tuple[list, list, list, list],
    steps: np.ndarray,
    accs: np.ndarray,
    quantiles: tuple[float, float],
) -> dict:
    """A table row: the largest start / end errors (cm) of the ``fits`` (target starts, target
    ends, fitted starts, fitted ends) and the largest junction step and second difference
    as multiples of the recorded ``quantiles``; ``velocity_kink``: a junction's second difference
    exceeds the recorded quantile (the velocity jumps where a rest meets a shift)."""
    starts, ends, fit_s, fit_e = fits
    step_q, acc_q = quantiles
    err_s = _posture_error_cm(model, s, np.array(starts), np.array(fit_s))
    err_e = _posture_error_cm(model, s, np.array(ends), np.array(fit_e))
    return {
        "subject": s,
        "ramp": ramp,
        "test": test,
        "cases": len(starts),
        "max_start_error_cm": float(err_s.max()),
        "max_end_error_cm": float(err_e.max()),
        "junctions": len(steps),
        "max_junction_step_ratio": float(steps.max(initial=0) / step_q),
        "max_junction_accel_ratio": float(accs.max(initial=0) / acc_q),
        "velocity_kink": bool(accs.max(initial=0) > acc_q),
    }


def fitting_measurements(table: pd.DataFrame, params: FittingSettings) -> dict[str, Any]:
    """What Sec. 5.4.4's claim is judged on: the largest start / end error (cm) and the number of
    fits with the paper's linear ramp, the largest junction step and second difference per ramp
    (multiples of the recorded steps' quantile), the rows (subject and test) with a velocity kink
    per ramp out of all rows, and that quantile."""
    faithful = table[table.ramp == "linear"]
    by_ramp = {r: table[table.ramp == r] for r in ("linear", "smoothstep")}
    return {
        "max_end_error_cm": float(faithful[["max_start_error_cm", "max_end_error_cm"]].to_numpy().max()),
        "fits": int(faithful["cases"].sum()),
        "max_junction_step_ratio": {r: float(t["max_junction_step_ratio"].max()) for r, t in by_ramp.items()},
        "max_junction_accel_ratio": {r: float(t["max_junction_accel_ratio"].max()) for r, t in by_ramp.items()},
        "velocity_kinks": {r: [int(t["velocity_kink"].sum()), len(t)] for r, t in by_ramp.items()},
        "quantile": params.quantile,
    }


def _figure_data(model: IdleModel, example: dict, settings: Egges2004Settings) -> dict:
    """For the first subject: PC 1 of a database shift (``original``) and of its fits to
    new end postures p, q, one curve per ramp (``fitted``; Fig. 4), and PC 1 of
    ``FIGURE_BALANCE_S`` seconds of balance shifting (``balance``) with its fitted shifts
    (``shifts_s``, start and end in seconds); the quantile the junction steps are
    compared with."""
    s = next(iter(example))
    ex = example[s]
    a = ex["original"]
    db = model.databases[s]
    n = int(round(FIGURE_BALANCE_S * db.fps)) + 1
    seq, events = synthesize_balance(db, n, subject_rng(settings.seed, s, "figure"))
    return {
        "subject": s,
        "fps": db.fps,
        "original": a[:, 0],
        "p": ex["p"][0],
        "q": ex["q"][0],
        "fitted": {r: fit_anim_part(a, 0, len(a) - 1, ex["p"], ex["q"], r)[:, 0] for r in RAMPS},
        "balance": seq[:, 0],
        "balance_s": FIGURE_BALANCE_S,
        "shifts_s": [(e.start / db.fps, e.stop / db.fps) for e in events if e.kind == "shift"],
        "quantile": settings.fitting.quantile,
    }
