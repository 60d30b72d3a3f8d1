"""The generator against the bands from captured data, over five seeds (motionvar.realism):
with captured variation (the default) every gating statistic lies in its band; the clean data
(``captured_variation=False``) lies outside every gating band and inside every descriptive one
(which is why it does not gate)."""

from __future__ import annotations

import tempfile

import numpy as np
import pandas as pd
import pytest
from realism_known import IDLE_OUTSIDE

from motionvar.core import cmu_joint_map
from motionvar.io import load_dataset, save_dataset
from motionvar.realism import BANDS, dataset_realism, judge
from motionvar.synth import (
    ReachParams,
    SynthSpec,
    generate_dataset,
    generate_pick,
    generate_walk,
    make_subjects,
    sample_walk_params,
)
from motionvar.synth.dataset import REACH_REGIONS

SEEDS = range(5)
CI_SUBJECTS = 4  # config/ci.yaml
# the statistics that need more subjects or reaches than the CI size has (realism.min_subjects,
# realism.min_reaches), judged on the full size's 25 subjects: their neutral walks and picks.
# Their sampling spread there reaches a band's edge (the share of 75 reaches with two speed
# peaks: 0.09-0.15 over five seeds), so they are held to the project's stability rule: the
# same verdict in at least 4 of the 5 seeds (README, Results).
SPREAD = ("stride_within_between", "reach_multi_peak_share")
STABLE = 4


def _judged(motions, meta) -> pd.DataFrame:
    with tempfile.TemporaryDirectory() as tmp:
        save_dataset(tmp, motions, meta)
        table = judge(dataset_realism(load_dataset(tmp), cmu_joint_map())[0])
    return table.set_index(["statistic", "behaviour"])


def _ci_table(seed: int, captured: bool) -> pd.DataFrame:
    """The realism table of the CI size's walks and picks (the statistics read no other behaviour)."""
    spec = SynthSpec(
        subjects=CI_SUBJECTS, seed=seed, runs=0, sidesteps=0, places=0, idle_clips=0, captured_variation=captured
    )
    return _judged(*generate_dataset(spec))


def _spread_table(seed: int, captured: bool, subjects: int = 25) -> pd.DataFrame:
    """Six neutral walks and three picks of each of ``subjects`` subjects (SynthSpec's neutral
    walks: two straight and four turning ones), drawn as SynthSpec draws them."""
    motions, rows = [], []
    for i, subject in enumerate(make_subjects(subjects, seed)):
        rng = np.random.default_rng([seed, i])
        walks = [
            generate_walk(subject, sample_walk_params(subject, rng, "neutral", captured=captured)) for _ in range(6)
        ]
        reach = [ReachParams(region=REACH_REGIONS[k], correction=None if captured else False) for k in range(3)]
        picks = [generate_pick(subject, params, rng) for params in reach]
        for k, (behaviour, (motion, _)) in enumerate([("walk", w) for w in walks] + [("pick", p) for p in picks]):
            motions.append(motion)
            rows.append({"clip_id": f"s{i}_{k}", "subject": f"s{i}", "behaviour": behaviour, "style": "neutral"})
    return _judged(motions, pd.DataFrame(rows))


def _idle_table(seed: int, captured: bool, subjects: int = CI_SUBJECTS) -> pd.DataFrame:
    """The realism table of the CI size's idle clips (config/ci.yaml: 3 clips of 40 s a subject)."""
    spec = SynthSpec(
        subjects=subjects,
        seed=seed,
        runs=0,
        sidesteps=0,
        places=0,
        idle_clips=3,
        idle_duration_s=40.0,
        captured_variation=captured,
    )
    motions, meta = generate_dataset(spec)
    keep = (meta["behaviour"] == "idle").to_numpy()
    return _judged([m for m, k in zip(motions, keep) if k], meta[keep].reset_index(drop=True))


def _idle_gating(table: pd.DataFrame) -> pd.Series:
    return table.loc[[k for k, band in BANDS.items() if band.gates and k[1] == "idle"], "in_band"]


def _gating(table: pd.DataFrame, names=None) -> pd.Series:
    keys = [k for k, band in BANDS.items() if band.gates and k[1] != "idle" and (names is None or k[0] in names)]
    return table.loc[keys, "in_band"]


class TestCapturedVariation:
    @pytest.fixture(scope="class")
    def tables(self):
        return {seed: (_ci_table(seed, True), _spread_table(seed, True)) for seed in SEEDS}

    def test_every_gating_statistic_in_its_band_at_ci_size(self, tables):
        for seed, (ci, _) in tables.items():
            inside = _gating(ci).dropna()
            assert len(inside) >= 9 and inside.astype(bool).all(), (seed, inside)

    def test_idle_gating_statistics_in_their_bands_but_the_known_one(self):
        """Standing idle against ReActIdle's bands, in every seed: the channel shares inside, the
        weight-shift rate outside (IDLE_OUTSIDE: the generator shifts a third as often)."""
        for seed in SEEDS:
            inside = _idle_gating(_idle_table(seed, True))
            assert len(inside) == 3 and inside.notna().all(), (seed, inside)
            assert inside.drop(list(IDLE_OUTSIDE)).astype(bool).all(), (seed, inside)
            assert not inside[list(IDLE_OUTSIDE)].astype(bool).any(), (seed, inside)

    def test_spread_and_reach_in_their_bands(self, tables):
        inside = pd.DataFrame({seed: _gating(spread, SPREAD) for seed, (_, spread) in tables.items()})
        assert inside.notna().all().all() and (inside.astype(bool).sum(axis=1) >= STABLE).all(), inside


class TestCleanData:
    @pytest.fixture(scope="class")
    def tables(self):
        return {seed: (_ci_table(seed, False), _spread_table(seed, False)) for seed in SEEDS}

    def test_outside_every_gating_band(self, tables):
        """Negative control of every gating band: the clean data (strides repeated, left = right,
        still channels, single-peaked reaches) lies outside it in every seed."""
        for seed, (ci, _) in tables.items():
            outside = ~_gating(ci).drop(list(_gating(ci, SPREAD).index))
            assert outside.notna().all() and outside.astype(bool).all(), (seed, outside)
        outside = pd.DataFrame({seed: ~_gating(spread, SPREAD) for seed, (_, spread) in tables.items()})
        assert outside.notna().all().all() and (outside.astype(bool).sum(axis=1) >= STABLE).all(), outside

    def test_idle_outside_every_gating_band_inside_every_descriptive_one(self):
        """The idle bands' negative control (clean idle data holds half its channels still) and
        why the others are descriptive (the switch leaves the sway and the shifts alone)."""
        descriptive = [k for k, band in BANDS.items() if not band.gates and k[1] == "idle"]
        for seed in SEEDS:
            clean = _idle_table(seed, False, subjects=8 if seed == 0 else CI_SUBJECTS)
            outside = ~_idle_gating(clean)
            assert outside.notna().all() and outside.astype(bool).all(), (seed, outside)
            inside = clean.loc[descriptive, "in_band"]
            if seed:  # the within/between spread needs realism.min_idle_subjects people: seed 0 has 8
                inside = inside.drop(("idle_posture_within_between", "idle"))
            assert inside.notna().all() and inside.astype(bool).all(), (seed, inside)

    def test_inside_every_descriptive_band(self, tables):
        """Why a band is descriptive: the clean data lies in it too (in every seed)."""
        descriptive = [k for k, band in BANDS.items() if not band.gates and k[1] != "idle"]
        posture = [("posture_within_between", "walk")]  # needs realism.min_subjects
        for seed, (ci, spread) in tables.items():
            inside = pd.concat(
                [ci.loc[[k for k in descriptive if k not in posture], "in_band"], spread.loc[posture, "in_band"]]
            )
            assert inside.notna().all() and inside.astype(bool).all(), (seed, inside)


def test_too_few_subjects_or_reaches_give_no_value_and_say_why():
    table = _spread_table(0, True, subjects=4)
    for key in (
        ("stride_within_between", "walk"),
        ("posture_within_between", "walk"),
        ("reach_multi_peak_share", "pick"),
    ):
        row = table.loc[key]
        assert np.isnan(row["value"]) and row["n"] == 0 and "fewer than realism.min_" in row["note"], row
