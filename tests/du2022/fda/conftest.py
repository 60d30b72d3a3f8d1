"""Fixtures shared by the functional data analysis tests (Du 2022 ch. 3): 60 toy clips of three
classes on a five-joint chain (one instance per test process)."""

import pytest
from fda_toy import make_clips

from motionvar.du2022.fda import FunctionalMotions


@pytest.fixture(scope="session")
def data():
    clips, labels = make_clips()
    return FunctionalMotions.from_motions(clips, n_basis=8), labels, clips
