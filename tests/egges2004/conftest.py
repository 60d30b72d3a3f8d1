"""Fixtures shared by the Egges 2004 tests: two toy recordings of one subject analysed into an
idle database (one instance per test process)."""

import pytest
from egges2004_toy import RESTS, SEQ, toy_recording

from motionvar.core import cmu_joint_map
from motionvar.egges2004 import AnalysisSettings, PosturePCA, analyse_recording, build_database


@pytest.fixture(scope="session")
def toy():
    recs = [toy_recording(SEQ, RESTS, seed=s) for s in range(2)]
    pca = PosturePCA(0.01).fit([m for m, _ in recs])
    jm = cmu_joint_map()
    analysed = [analyse_recording(m, pca, jm, f"r{i}") for i, (m, _) in enumerate(recs)]
    db = build_database(analysed, pca, AnalysisSettings(), "s1", 0)
    return recs, pca, analysed, db
