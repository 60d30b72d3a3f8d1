"""DTW (motionvar.prep.dtw_path, the time warping of Du 2022 Sec. 4.4.1) against dtaidistance's
public entry points and against a plain dynamic program written out here.

Ours calls dtaidistance's C ``warping_path_fast`` on (T, D) pose features, so this checks what
we add around it: multivariate input kept as (T, D) (not flattened), 1-D input, the (L, 2)
(source, reference) path layout, and the Sakoe-Chiba window. The cost is dtaidistance's:
squared Euclidean distance between frames summed along the path, distance = its square root.

Tolerances: paths identical; distances 1e-12 relative (measured ~2e-16)."""

import numpy as np
import pytest

from motionvar.prep import dtw_path, dtw_warp

pytest.importorskip("dtaidistance", reason="dtaidistance is not installed")
from dtaidistance import dtw, dtw_ndim  # noqa: E402


def dynamic_program(a, b, window=None):
    """sqrt of the least sum of squared frame distances over monotone paths (steps (1,0), (0,1),
    (1,1)), within dtaidistance's band: row i allows columns
    [i - max(0, r - c) - window + 1, i + max(0, c - r) + window)."""
    r, c = len(a), len(b)
    window = max(r, c) if window is None else window
    cost = ((a[:, None, :] - b[None, :, :]) ** 2).sum(-1)
    acc = np.full((r + 1, c + 1), np.inf)
    acc[0, 0] = 0.0
    for i in range(r):
        lo, hi = max(0, i - max(0, r - c) - window + 1), min(c, i + max(0, c - r) + window)
        for j in range(lo, hi):
            acc[i + 1, j + 1] = cost[i, j] + min(acc[i, j], acc[i, j + 1], acc[i + 1, j])
    return float(np.sqrt(acc[r, c]))


def path_cost(a, b, path):
    return float(np.sqrt(((a[path[:, 0]] - b[path[:, 1]]) ** 2).sum()))


CASES = [(40, 47, 6, None), (47, 40, 6, 12), (30, 30, 60, None), (25, 33, 60, 9), (35, 28, 1, None), (50, 50, 3, 4)]


@pytest.mark.parametrize("n, m, d, window", CASES, ids=[f"{n}x{m}x{d}-w{w}" for n, m, d, w in CASES])
def test_dtw_path_and_distance_match_dtaidistance(n, m, d, window):
    rng = np.random.default_rng(n * 1000 + m + d)
    a, b = np.cumsum(rng.normal(size=(n, d)), 0), np.cumsum(rng.normal(size=(m, d)), 0)
    ours = dtw_path(a, b, window=window)
    kw = {} if window is None else {"window": window}
    if d == 1:
        theirs = np.array(dtw.warping_path(a[:, 0], b[:, 0], use_c=True, **kw))
        dist = [dtw.distance(a[:, 0], b[:, 0], use_c=c, **kw) for c in (True, False)]
    else:
        theirs = np.array(dtw_ndim.warping_path(a, b, use_c=True, **kw))
        dist = [dtw_ndim.distance(a, b, use_c=c, **kw) for c in (True, False)]
    assert ours.shape[1] == 2 and np.array_equal(ours, theirs)
    assert tuple(ours[0]) == (0, 0) and tuple(ours[-1]) == (n - 1, m - 1)
    steps = {tuple(s) for s in np.diff(ours, axis=0)}
    assert steps <= {(0, 1), (1, 0), (1, 1)}
    reference = dynamic_program(a, b, window)
    for value in (path_cost(a, b, ours), *dist):
        assert abs(value - reference) <= 1e-12 * reference


def test_dtw_warp_averages_the_path():
    rng = np.random.default_rng(7)
    a, b = np.cumsum(rng.normal(size=(45, 4)), 0), np.cumsum(rng.normal(size=(38, 4)), 0)
    path = np.array(dtw_ndim.warping_path(a, b, use_c=True))
    warp = dtw_warp(a, b)
    expected = np.array([path[path[:, 1] == j, 0].mean() for j in range(len(b))])
    expected[0], expected[-1] = 0.0, len(a) - 1
    assert np.allclose(warp, expected, rtol=0, atol=1e-12)
