"""Ma et al. 2010 Sec. 6.1-6.2 (after Mukai & Kuriyama 2005): the variogram of universal
Kriging, per joint group (Eq. 11: one interpolator per group over [c, xi_I]) and for
Kriging on the style alone (MK05). A diagnostic: does the binned empirical semivariogram
of the residuals have spatial structure (gamma rising with the lag) for a variogram to
fit, or is it flat (pure nugget: Kriging then reduces to its linear trend)?

For each interpolator fitted to all cycles the table gives the binned semivariogram the
variogram is fitted to (``all pairs``), the same over pairs of cycles from different walks
only (``between walks``: sibling cycles of one walk are nearly copies, which a
leave-one-out that keeps them in training can exploit), and the earlier single fitted
model (``old``: raw units, linear, pair-count weights, every lag, 20 bins), each with the fitted
curve at its lags and the fitted parameters; ``fitted_<model>`` are the four candidates of
``auto`` on the all-pairs semivariogram. No claim: the paper states none about the
variogram ("directly inherited from the universal Kriging model", Sec. 6.2)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...claims import EvaluationResult
from ..examples import WalkCycles
from ..kriging import (
    AUTO_MODELS,
    UniversalKriging,
    VariogramFit,
    empirical_semivariogram,
    fit_semivariogram,
    pair_semivariances,
)
from ..representation import ClipCodec
from ..settings import Ma2010Settings
from ..svi import GROUP_ORDER

STYLE_ONLY = "style only (MK05)"
MAX_CLOUD = 20000  # pairs drawn per panel at most (a seeded subset beyond)


def _rows(
    name: str,
    series: str,
    fit: VariogramFit,
    lag: np.ndarray,
    gamma: np.ndarray,
    pairs: np.ndarray,
    candidates: VariogramFit | None,
) -> list[dict]:
    d = fit.variogram.describe()
    rows = []
    for k in range(len(lag)):  # loop over the bins (at most 100)
        row = {
            "group": name,
            "series": series,
            "lag": lag[k],
            "gamma": gamma[k],
            "pairs": int(pairs[k]),
            "fitted": float(fit.variogram.curve(lag[k])),
            **d,
            "scale": fit.scale,
            "weights": fit.weights,
        }
        for m in AUTO_MODELS:  # a candidate that could not be fitted (too few bins) is left blank
            model = candidates.candidates.get(m) if candidates is not None else None
            row[f"fitted_{m}"] = float(model.curve(lag[k])) if model is not None else np.nan
        rows.append(row)
    return rows


def variogram_fits(walks: WalkCycles, settings: Ma2010Settings) -> EvaluationResult:
    """The semivariograms and fitted variograms of the model fitted to all walking cycles
    (one per joint group; ``settings`` structure, variogram_model, variogram_scale) and of
    MK05 Kriging on style alone (module docstring); the cloud's subset is seeded by
    ``settings.seed``. Figure:
    per interpolator the variogram cloud (pair distance, semivariance; same-walk pairs
    marked) for :func:`motionvar.ma2010.figures.draw_variogram`."""
    clips = walks.clips
    variogram_model, variogram_scale = settings.model.variogram_model, settings.model.variogram_scale
    model = walks.fit_model(settings)
    krigs: dict[str, UniversalKriging] = {g: model.interpolators_[g][1] for g in GROUP_ORDER}
    # MK05's clip vectors (:mod:`..baselines.mukai_kuriyama`: every joint and the key times) over style alone
    codec = ClipCodec(np.arange(clips.skeleton.n_joints), timing=True, key_timing=settings.model.key_timing).fit(clips)
    style_only = UniversalKriging(variogram_model, variogram_scale=variogram_scale)
    krigs[STYLE_ONLY] = style_only.fit(clips.style, codec.encode(clips))
    source = getattr(walks, "source_clips", None)  # each cycle's walk (capture)
    iu = np.triu_indices(clips.n_clips, k=1)
    same_walk = None if source is None else (np.asarray(source)[:, None] == np.asarray(source)[None, :])[iu]
    rng = np.random.default_rng(settings.seed)
    rows, clouds, fits = [], {}, {}
    for name, k in krigs.items():  # loop over the five interpolators
        fit = k.variogram_fit_
        every = fit_semivariogram(k.x_, k.residuals_, "auto", k.n_bins, fit.scale, fit.weights, k.max_lag)
        rows += _rows(name, "all pairs", fit, fit.lag, fit.gamma, fit.pairs, every)
        if same_walk is not None and (~same_walk).any():
            b = empirical_semivariogram(k.x_, k.residuals_, k.n_bins, fit.scale, k.max_lag, pair_mask=~same_walk)
            rows += _rows(name, "between walks", fit, *b, None)
        old = fit_semivariogram(k.x_, k.residuals_, "linear", 20, "none", "pairs", 1.0)
        rows += _rows(name, "old", old, old.lag, old.gamma, old.pairs, None)
        h, g = pair_semivariances(k.x_, k.residuals_, fit.scale)
        sw = np.zeros(len(h), dtype=bool) if same_walk is None else same_walk
        pick = np.sort(rng.choice(len(h), MAX_CLOUD, replace=False)) if len(h) > MAX_CLOUD else np.arange(len(h))
        clouds[name] = {
            "lag": h[pick],
            "gamma": g[pick],
            "same_walk": sw[pick],
            "max_lag": float(k.max_lag * h.max()) if len(h) else 0.0,
        }
        fits[name] = {"chosen": fit.variogram, "candidates": every.candidates}
    table = pd.DataFrame(rows)
    return EvaluationResult(
        table=table,
        claims=[],
        figure={
            "clouds": clouds,
            "fits": fits,
            "scale": variogram_scale,
            "model": variogram_model,
            "n_clips": clips.n_clips,
            "has_walks": same_walk is not None,
        },
    )
