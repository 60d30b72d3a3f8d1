"""Fixtures shared by the command tests: a results folder with toy models of every paper."""

from __future__ import annotations

import pytest
from cli_toy import toy_results


@pytest.fixture(scope="session")
def results(tmp_path_factory):
    """results/toy of tests/cli_toy.py (built once per session)."""
    return toy_results(tmp_path_factory)
