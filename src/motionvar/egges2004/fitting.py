"""Posture distance and animation fitting (Egges et al. 2004, Sec. 5.4.3-5.4.4, Eq. 4,
Fig. 4-5).

Animations are arrays of postures over frames, each posture a vector of PC values
(T, D). Fitting adds to every frame an offset interpolated between the offsets
p_i - a_{f_i} at the key frames, so the animation passes through the key postures
exactly while keeping its own motion in between.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

RAMPS = ("linear", "smoothstep")


def posture_distance(p: np.ndarray, q: np.ndarray, weights: np.ndarray) -> np.ndarray:
    """Weighted distance d_{p,q} = sum_i w_i (p_i - q_i)^2 (Eq. 4), broadcast over leading
    axes. ``weights`` as in footnote 1 (:meth:`PosturePCA.weights`); fewer weights than
    PCs compare only the first PCs."""
    w = np.asarray(weights, dtype=float)
    k = w.shape[0]
    d = np.asarray(p, dtype=float)[..., :k] - np.asarray(q, dtype=float)[..., :k]
    return np.sum(w * d * d, axis=-1)


def best_fitting_animation(
    starts: np.ndarray, ends: np.ndarray, p: np.ndarray, q: np.ndarray, weights: np.ndarray
) -> tuple[int, np.ndarray]:
    """Index of the animation a with minimal M_a = max(d_{a_0,p}, d_{a_e,q}) (Sec. 5.4.3),
    and all M_a. ``starts``/``ends``: (n, D) first and last frames of the n animations."""
    if len(starts) == 0:
        raise ValueError("best_fitting_animation: the animation database is empty")
    m = np.maximum(posture_distance(starts, p, weights), posture_distance(ends, q, weights))
    return int(np.argmin(m)), m


def _ramp(u: np.ndarray, ramp: str) -> np.ndarray:
    if ramp == "linear":
        return u
    if ramp == "smoothstep":
        return u * u * (3.0 - 2.0 * u)
    raise ValueError(f"ramp must be one of {RAMPS}, got {ramp!r}")


def fit_anim_part(a: np.ndarray, fi: int, fj: int, pi: np.ndarray, pj: np.ndarray, ramp: str = "linear") -> np.ndarray:
    """``fitAnim_part`` of Fig. 5: a copy of ``a`` (T, D) whose frames fi..fj are offset so
    that frame fi equals ``pi`` and frame fj equals ``pj``.

    The offset at frame f is o_i (f_j - f)/(f_j - f_i) + o_j (f - f_i)/(f_j - f_i) with
    o_i = p_i - a_i and o_j = p_j - a_j. (Fig. 5 prints o_j = a_j - p_j, a sign slip:
    with it the last frame would land on 2 a_j - p_j, not on p_j as the text requires.)
    ``ramp="smoothstep"`` (an option beyond the paper) eases the interpolation weight
    with 3u^2 - 2u^3, so the offset's velocity is zero at both ends and the fitted clip
    keeps the velocity of the original at the junctions.
    """
    a = np.array(a, dtype=float, copy=True)
    if not 0 <= fi < fj < len(a):
        raise ValueError(f"fit_anim_part: need 0 <= fi < fj < {len(a)}; got fi={fi}, fj={fj}")
    oi, oj = np.asarray(pi) - a[fi], np.asarray(pj) - a[fj]
    u = _ramp((np.arange(fi, fj + 1) - fi) / (fj - fi), ramp)[:, None]
    a[fi : fj + 1] += oi * (1.0 - u) + oj * u
    return a


def fit_anim(a: np.ndarray, keys: Sequence[tuple[int, np.ndarray]], ramp: str = "linear") -> np.ndarray:
    """``fitAnim`` of Fig. 5: a copy of ``a`` (T, D) passing through the key postures
    ``keys`` = [(f_i, p_i), ...] (frames strictly increasing, within [0, T-1]).

    As the text says, the offsets p_i - a_{f_i} are computed at the keys and interpolated
    between consecutive keys; before the first and after the last key the offset returns
    to zero at frames 0 and e (the figure's calls with the animation's own frames as
    targets), so frames 0 and e stay unchanged unless keyed. (Read literally as in-place
    calls, Fig. 5's last call would find a zero offset at f_i and leave a jump after the
    last key; we follow the text.) Vectorised over frames.
    """
    a = np.array(a, dtype=float, copy=True)
    e = len(a) - 1
    if len(keys) == 0:
        return a
    frames = np.array([int(f) for f, _ in keys])
    if np.any(np.diff(frames) <= 0) or frames[0] < 0 or frames[-1] > e:
        raise ValueError(f"fit_anim: key frames must increase strictly within [0, {e}]; got {frames.tolist()}")
    offsets = np.stack([np.asarray(p, dtype=float) for _, p in keys]) - a[frames]
    if frames[0] != 0:
        frames, offsets = np.concatenate([[0], frames]), np.concatenate([np.zeros((1, a.shape[1])), offsets])
    if frames[-1] != e:
        frames, offsets = np.concatenate([frames, [e]]), np.concatenate([offsets, np.zeros((1, a.shape[1]))])
    t = np.arange(e + 1)
    seg = np.clip(np.searchsorted(frames, t, side="right") - 1, 0, len(frames) - 2)
    u = _ramp((t - frames[seg]) / (frames[seg + 1] - frames[seg]), ramp)[:, None]
    return a + offsets[seg] * (1.0 - u) + offsets[seg + 1] * u
