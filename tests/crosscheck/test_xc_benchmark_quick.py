"""benchmarks/reference_libraries.py --quick runs and prints one table row per pair (a
reference library that is absent gives a "not installed" row instead of numbers)."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAIRS = [
    "FPCA vs scikit-fda",
    "Bayesian GPLVM bound+grad vs GPy",
    "Kriging of residuals vs PyKrige OK",
    "Universal Kriging (lin. drift) vs PyKrige UK",
    "BVH read vs pybvh",
    "BVH read vs bvhio",
    "DTW path vs dtaidistance",
]


def test_quick_benchmark_prints_the_table():
    out = subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / "reference_libraries.py"), "--quick"],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=ROOT,
    )
    assert out.returncode == 0, out.stderr[-4000:]
    rows = [line for line in out.stdout.splitlines() if line.startswith("| ") and not line.startswith("| pair")]
    for pair in PAIRS:
        assert any(row.startswith(f"| {pair}") for row in rows), (pair, out.stdout)
    dtw = next(row for row in rows if row.startswith("| DTW path"))
    assert "20/20 paths identical" in dtw
    assert all(row.count("|") == 7 for row in rows)
