"""Person identification (Egges et al. 2004, Sec. 5.6, 8): does idle motion generated
from a person's database identify that person? A classifier trained on windows of each
subject's recorded idle clips names the subject of windows of held-out recordings, of
generated idle motion and of the Perlin baseline; the window features and the classifier
are defined here.
"""

from __future__ import annotations

import logging
from typing import Any

import numpy as np
import pandas as pd
from scipy.signal import welch
from scipy.stats import binomtest
from sklearn.linear_model import LogisticRegression
from sklearn.metrics import confusion_matrix
from sklearn.pipeline import Pipeline, make_pipeline
from sklearn.preprocessing import StandardScaler

from ...claims import EvaluationResult, judge_claims
from ...core.joint_map import JointMap
from ..categories import support_ratio
from ..claims import CLAIMS
from ..database import Recording
from ..engine import generate_idle_pcs
from ..pipeline import IdleModel
from ..settings import Egges2004Settings, IdentificationSettings
from .common import perlin_sds, perlin_sequence, subject_rng

log = logging.getLogger(__name__)

FEATURE_SETS = ("all", "posture", "dynamics")
SWAY_BANDS_HZ = ((0.05, 0.3), (0.3, 1.0), (1.0, 3.0))


def window_frames(window_s: float, fps: float) -> int:
    """Frames of a window of ``window_s`` seconds at ``fps``."""
    return int(round(window_s * fps))


def _windows(x: np.ndarray, length: int) -> np.ndarray:
    """(n, length, ...) non-overlapping windows of ``x`` (T, ...); the tail is dropped."""
    n = len(x) // length
    return np.asarray(x)[: n * length].reshape(n, length, *np.shape(x)[1:])


def window_features(
    pcs: np.ndarray,
    support: np.ndarray,
    fps: float,
    window_s: float,
    n_pcs: int,
    margin: float,
    feature_set: str = "all",
    n_spectral_pcs: int = 3,
) -> np.ndarray:
    """(n_windows, F) features of non-overlapping windows of an idle sequence.

    ``all``: per window the mean and standard deviation of the first ``n_pcs`` PCs
    (posture and its variation), posture-category statistics from the support ratio
    (mean, SD, share of frames on the left foot / right foot / both, with ``margin`` as
    in :func:`~motionvar.egges2004.categories.name_by_support`), and sway spectra: the log
    Welch power of the first ``n_spectral_pcs`` PCs in the bands of ``SWAY_BANDS_HZ``.
    ``posture``: only the posture held (the PC means, the support-ratio mean and shares).
    ``dynamics``: only what describes movement, the posture means removed (Sec. 5.6: "the
    way a person changes posture"): the PC SDs, the support-ratio SD and the sway spectra.
    """
    if feature_set not in FEATURE_SETS:
        raise ValueError(f"feature_set must be one of {FEATURE_SETS}, got {feature_set!r}")
    length = window_frames(window_s, fps)
    if length < 2 or len(pcs) < length:
        raise ValueError(
            f"window_features: a window of {window_s} s needs {length} frames; the sequence has {len(pcs)}"
        )
    w = _windows(np.asarray(pcs)[:, :n_pcs], length)
    lam = _windows(np.asarray(support), length)
    shares = np.stack([lam > 0.5 + margin, lam < 0.5 - margin, np.abs(lam - 0.5) <= margin], axis=2).mean(axis=1)
    posture = np.concatenate([w.mean(axis=1), lam.mean(axis=1, keepdims=True), shares], axis=1)
    if feature_set == "posture":
        return posture
    freqs, power = welch(
        w[:, :, :n_spectral_pcs], fs=fps, nperseg=min(length, int(round(8 * fps))), axis=1, detrend="linear"
    )
    bands = np.stack([power[:, (freqs >= lo) & (freqs < hi)].mean(axis=1) for lo, hi in SWAY_BANDS_HZ], axis=2)
    spectra = np.log10(np.maximum(bands, 1e-20)).reshape(len(w), -1)
    dynamics = np.concatenate([w.std(axis=1), lam.std(axis=1, keepdims=True), spectra], axis=1)
    return dynamics if feature_set == "dynamics" else np.concatenate([posture, dynamics], axis=1)


def feature_subset(features: np.ndarray, feature_set: str, n_pcs: int) -> np.ndarray:
    """The columns of ``feature_set`` among the ``all`` features of :func:`window_features`
    (which puts the posture columns, ``n_pcs`` + 4 of them, first)."""
    if feature_set not in FEATURE_SETS:
        raise ValueError(f"feature_set must be one of {FEATURE_SETS}, got {feature_set!r}")
    cut = n_pcs + 4
    return {"all": features, "posture": features[:, :cut], "dynamics": features[:, cut:]}[feature_set]


def make_identifier(seed: int) -> Pipeline:
    """Standardised multinomial logistic regression naming the subject of a window."""
    return make_pipeline(StandardScaler(), LogisticRegression(max_iter=5000, random_state=seed))


REC, GEN, PERLIN = "recorded (held out)", "generated (Egges 2004)", "Perlin noise on PCs"
IDENTIFICATION_SOURCES = (REC, GEN, PERLIN)
#: a sequence to train on or to identify: (subject, PC values (T, D), support ratio (T,))
Sequence = tuple[str, np.ndarray, np.ndarray]


def identification(
    model: IdleModel,
    recordings: dict[str, list[Recording]],
    held_out: dict[str, list[Recording]],
    joint_map: JointMap,
    settings: Egges2004Settings,
) -> EvaluationResult:
    """Train a classifier on windows of each subject's training recordings; name the
    subject of windows of held-out recordings, of generated idle motion and of the
    Perlin baseline (``settings.identification``, ``settings.perlin_frequency_hz``,
    ``settings.analysis.support_margin``, ``settings.seed``). Returns the accuracy table,
    the claim, the measurements (:func:`identification_measurements`) and, for the figure,
    ``labels`` and ``confusion`` (the confusion matrix of the generated windows, all
    features) and ``window_s``."""
    params = settings.identification
    subjects = list(model.databases)
    fps = model.databases[subjects[0]].fps
    sequences = _test_sequences(model, recordings, held_out, joint_map, settings)
    train = [(s, r.pcs, r.support) for s in subjects for r in recordings[s]]
    table, confusion = identification_table(train, sequences, subjects, fps, settings)
    measurements = identification_measurements(table, params)
    claims = judge_claims(CLAIMS, "egges2004_identification", measurements)
    return EvaluationResult(table, claims, {**confusion, "window_s": params.window_s}, measurements)


def identification_table(
    train: list[Sequence],
    sequences: dict[str, list[Sequence]],
    subjects: list[str],
    fps: float,
    settings: Egges2004Settings,
) -> tuple[pd.DataFrame, dict[str, Any]]:
    """Per feature set, a classifier trained on the windows of ``train`` names the subject of the
    windows of each source's ``sequences``: the accuracy table (accuracy, chance and the binomial
    p-value against it per source and feature set; on the generated rows, the paired comparison
    with the Perlin windows, :func:`mcnemar_greater`) and, for the generated windows with all
    features, ``labels`` and ``confusion`` (empty without a generated source)."""
    params = settings.identification

    length = window_frames(params.window_s, fps)

    def features(items):
        short = [s for s, p, _ in items if len(p) < length]
        if short:  # a held-out end of a short recording (held_out_by: time) holds no whole window
            log.info(
                "%d sequence(s) shorter than one %g s window left out (subjects %s)",
                len(short),
                params.window_s,
                ", ".join(sorted(set(short))),
            )
        blocks = [
            (window_features(p, lam, fps, params.window_s, params.feature_pcs, settings.analysis.support_margin), s)
            for s, p, lam in items
            if len(p) >= length
        ]
        return np.concatenate([b for b, _ in blocks]), np.concatenate([[s] * len(b) for b, s in blocks])

    n_pcs = min(params.feature_pcs, train[0][1].shape[1])
    X_all, y = features(train)
    tests = {source: features(items) for source, items in sequences.items()}
    rows, confusion = [], {}
    chance = 1.0 / len(subjects)
    for fs in FEATURE_SETS:
        clf = make_identifier(settings.seed).fit(feature_subset(X_all, fs, n_pcs), y)
        correct = {}
        for source, (Xs_all, ys) in tests.items():
            Xs = feature_subset(Xs_all, fs, n_pcs)
            pred = clf.predict(Xs)
            correct[source] = pred == ys
            n_ok = int(np.sum(correct[source]))
            rows.append(
                {
                    "source": source,
                    "features": fs,
                    "subjects": len(subjects),
                    "windows": len(ys),
                    "accuracy": n_ok / len(ys),
                    "chance": chance,
                    "p_value": binomtest(n_ok, len(ys), chance, alternative="greater").pvalue,
                }
            )
            if source == GEN:
                generated_row = rows[-1]
                if fs == "all":
                    confusion = {"labels": subjects, "confusion": confusion_matrix(ys, pred, labels=subjects)}
        if GEN in correct and PERLIN in correct:
            better, worse, p = mcnemar_greater(correct[GEN], correct[PERLIN])
            generated_row.update(better_than_perlin=better, worse_than_perlin=worse, p_vs_perlin=p)
    return pd.DataFrame(rows), confusion


def mcnemar_greater(a_ok: np.ndarray, b_ok: np.ndarray) -> tuple[int, int, float]:
    """Exact one-sided McNemar test that method A names windows correctly more often than B, on
    paired windows (``a_ok``, ``b_ok``: correct or not, one entry per pair): the pairs where only A
    is right, those where only B is, and the binomial p-value of the first among the discordant
    pairs against 1/2 (1 without discordant pairs)."""
    a_ok, b_ok = np.asarray(a_ok, dtype=bool), np.asarray(b_ok, dtype=bool)
    if a_ok.shape != b_ok.shape:
        raise ValueError(f"mcnemar_greater: paired windows must match; got {a_ok.shape} and {b_ok.shape}")
    better, worse = int(np.sum(a_ok & ~b_ok)), int(np.sum(~a_ok & b_ok))
    p = binomtest(better, better + worse, 0.5, alternative="greater").pvalue if better + worse else 1.0
    return better, worse, float(p)


def binomial_power(n: int, chance: float, accuracy: float, alpha: float) -> float:
    """Power of the one-sided binomial test against ``chance`` at level ``alpha`` with ``n``
    windows, when the classifier's true accuracy is ``accuracy``: the probability of at least the
    fewest correct windows that reach p < alpha (0 when even n of n do not)."""
    from scipy.stats import binom

    k = np.arange(n + 1)
    reach = k[binom.sf(k - 1, n, chance) < alpha]  # P(X >= k) under chance
    return float(binom.sf(reach[0] - 1, n, accuracy)) if len(reach) else 0.0


def _test_sequences(
    model: IdleModel,
    recordings: dict[str, list[Recording]],
    held_out: dict[str, list[Recording]],
    joint_map: JointMap,
    settings: Egges2004Settings,
) -> dict[str, list[Sequence]]:
    """Per source (IDENTIFICATION_SOURCES), the (subject, PC values, support ratio) of every
    sequence to identify: the held-out recordings, ``generated_s`` of generated idle motion
    and of the Perlin baseline per subject."""
    subjects = list(model.databases)
    fps = model.databases[subjects[0]].fps
    n_gen = int(round(settings.identification.generated_s * fps)) + 1
    sds = perlin_sds(model, recordings)
    sequences: dict[str, list[Sequence]] = {k: [] for k in IDENTIFICATION_SOURCES}
    for s in subjects:
        db, pca, sk = model.databases[s], model.pca, model.skeletons[s]
        sequences[REC] += [(s, r.pcs, r.support) for r in held_out[s]]
        gen, _ = generate_idle_pcs(db, n_gen, subject_rng(settings.seed, s, "identification"))
        per = perlin_sequence(
            model,
            recordings[s],
            sds,
            settings.perlin_frequency_hz,
            n_gen,
            int(subject_rng(settings.seed, s, "perlin").integers(2**31)),
        )
        for name, pcs in ((GEN, gen), (PERLIN, per)):
            sequences[name].append((s, pcs, support_ratio(pca.reconstruct(pcs, sk, fps), joint_map)))
    return sequences


#: measurement key of each source's accuracies (motionvar.egges2004.claims)
SOURCE_KEYS = {REC: "recorded", GEN: "generated", PERLIN: "perlin"}


def identification_measurements(table: pd.DataFrame, params: IdentificationSettings) -> dict[str, Any]:
    """What Sec. 5.6 and 8's claim is judged on, from the accuracy table: the accuracy and binomial
    p-value (against chance) per source and feature set; per feature set the paired comparison of the
    generated with the Perlin windows (windows only the generated / only the Perlin one names right,
    McNemar p-value); the number of subjects, and the significance level and window length used."""

    def get(source: str, fs: str, col: str) -> float:
        return float(table.loc[(table.source == source) & (table.features == fs), col].iloc[0])

    def per_source(col: str) -> dict[str, dict[str, float]]:
        return {key: {fs: get(source, fs, col) for fs in FEATURE_SETS} for source, key in SOURCE_KEYS.items()}

    subjects = int(table["subjects"].iloc[0])
    n_generated = {fs: int(get(GEN, fs, "windows")) for fs in FEATURE_SETS}
    return {
        "accuracy": per_source("accuracy"),
        "p_value": per_source("p_value"),
        # each test against chance, as many windows as generated, at the held-out recordings' accuracy
        "power": {
            fs: binomial_power(n_generated[fs], 1.0 / subjects, get(REC, fs, "accuracy"), params.alpha)
            for fs in FEATURE_SETS
        },
        "generated_windows": n_generated["all"],
        "min_power": params.min_power,
        "vs_perlin": {
            fs: {
                "better": int(get(GEN, fs, "better_than_perlin")),
                "worse": int(get(GEN, fs, "worse_than_perlin")),
                "p_value": get(GEN, fs, "p_vs_perlin"),
            }
            for fs in FEATURE_SETS
        },
        "subjects": subjects,
        "alpha": params.alpha,
        "window_s": params.window_s,
    }
