"""benchmarks/scaling.py: cost growth of each method (fit and query at several sizes, the
exponent of a log-log least-squares fit, a table and a figure), in its --quick mode."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[2]


def _scaling():
    spec = importlib.util.spec_from_file_location("scaling", ROOT / "benchmarks" / "scaling.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["scaling"] = module  # its dataclass looks its module up there
    spec.loader.exec_module(module)
    return module


def test_exponent_of_known_growth():
    sc = _scaling()
    n = np.array([100, 200, 400, 800])
    assert sc.exponent(n, 3e-6 * n**2) == pytest.approx(2.0)
    assert sc.exponent(n, 0.5 * n) == pytest.approx(1.0)
    assert sc.exponent(n, np.full(4, 0.01)) == pytest.approx(0.0, abs=1e-12)
    assert np.isnan(sc.exponent([10], [1.0]))


def test_quick_run_writes_the_table_and_the_figure(tmp_path, capsys):
    sc = _scaling()
    assert sc.main(["--quick", "--out", str(tmp_path), "--only", "fpca,gmm,kriging,kmeans_tree"]) == 0
    timings = pd.read_csv(tmp_path / "scaling.csv")
    exponents = pd.read_csv(tmp_path / "scaling_exponents.csv")
    assert set(timings["method"]) == {"fpca", "gmm", "kriging", "kmeans_tree"}
    assert (timings["cpu_s"] >= 0).all() and timings.groupby(["method", "stage"]).size().eq(3).all()
    assert list(exponents.columns) == ["method", "stage", "unit", "sizes", "k", "k_last", "cpu_s_largest", "required"]
    assert len(exponents) == 8 and exponents["k"].notna().all() and exponents["required"].str.len().gt(0).all()
    assert (tmp_path / "scaling.png").stat().st_size > 10_000
    assert "kriging" in capsys.readouterr().out
    assert sc.main(["--quick", "--out", str(tmp_path), "--only", "nonsense"]) == 1
