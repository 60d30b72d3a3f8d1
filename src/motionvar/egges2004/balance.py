"""Synthesis of balance changes (Egges et al. 2004, Sec. 5.4).

A sequence alternates resting postures and fitted balance-shift animations: rest at p
(drawn from Q_c) for t in [T_c,min, T_c,max] (5.4.1), pick the successor category s by
P(c => s) and a posture q in Q_s (5.4.2), take the animation of A whose first and last
frames are closest to p and q (5.4.3, Eq. 4) and fit it to start at p and end at q
(5.4.4, ``fitAnim_part``); then rest at q, and so on. All postures are PC vectors.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import interp1d

from .database import IdleDatabase
from .fitting import best_fitting_animation, fit_anim_part


@dataclass(frozen=True)
class Event:
    """One piece of a synthesised sequence: a rest in ``category`` or a shift from
    ``source`` to ``category`` using animation ``animation``, over frames [start, stop]."""

    kind: str
    start: int
    stop: int
    category: int
    source: int = -1
    animation: int = -1

    def __post_init__(self) -> None:
        for name in ("start", "stop", "category", "source", "animation"):
            object.__setattr__(self, name, int(getattr(self, name)))


def rest_frames(db: IdleDatabase, c: int, rng: np.random.Generator) -> int:
    """Frames of a rest in category c: t ~ U[T_c,min, T_c,max] (Sec. 5.4.1), at least 1.
    A category without measured stays takes the range over all categories."""
    lo, hi = db.graph.t_min[c], db.graph.t_max[c]
    if np.isnan(lo):
        if np.all(np.isnan(db.graph.t_min)):
            raise ValueError(f"subject {db.subject}: no resting time measured for any category")
        lo, hi = np.nanmin(db.graph.t_min), np.nanmax(db.graph.t_max)
    return max(1, int(round(rng.uniform(lo, hi) * db.fps)))


def fitted_shift(db: IdleDatabase, p: np.ndarray, q: np.ndarray, ramp: str = "linear") -> tuple[np.ndarray, int]:
    """The best-fitting animation of A for (p, q), fitted to start at p and end at q."""
    i, _ = best_fitting_animation(db.anim_starts, db.anim_ends, p, q, db.weights)
    a = db.animations[i]
    return fit_anim_part(a, 0, len(a) - 1, p, q, ramp), i


def time_scale(anim: np.ndarray, n_frames: int) -> np.ndarray:
    """Resample an animation (T, D) to ``n_frames`` >= 2 frames, keeping both ends (Sec. 7.1)."""
    if n_frames < 2:
        raise ValueError(f"time_scale: need at least 2 frames, got {n_frames}")
    if len(anim) == n_frames:
        return np.array(anim, copy=True)
    return interp1d(np.linspace(0.0, 1.0, len(anim)), anim, axis=0)(np.linspace(0.0, 1.0, n_frames))


def next_category(db: IdleDatabase, c: int, rng: np.random.Generator) -> int | None:
    """Successor category drawn from P(c => s) (Sec. 5.4.2); None if c has no successor."""
    row = db.graph.probabilities[c]
    if row.sum() <= 0:
        return None
    return int(rng.choice(db.graph.n, p=row / row.sum()))


def random_posture(db: IdleDatabase, c: int, rng: np.random.Generator) -> np.ndarray:
    """A posture drawn uniformly from Q_c."""
    return db.postures[c][rng.integers(len(db.postures[c]))]


def start_state(db: IdleDatabase, rng: np.random.Generator, start: np.ndarray | None) -> tuple[int, np.ndarray]:
    """A random category with postures and a random posture in it (Sec. 5.4.1), or the
    category of a given start posture (Sec. 7.1)."""
    if start is not None:
        return db.classify(start), np.asarray(start, dtype=float)
    cats = [c for c in range(db.graph.n) if len(db.postures[c])]
    c = int(rng.choice(cats))
    return c, random_posture(db, c, rng)


def synthesize_balance(
    db: IdleDatabase,
    n_frames: int,
    rng: np.random.Generator,
    start: np.ndarray | None = None,
    ramp: str = "linear",
) -> tuple[np.ndarray, list[Event]]:
    """(n_frames, D) balance-shifting sequence in PC space, and its events (Sec. 5.4).

    ``start``: a start posture p_0 (Sec. 7.1) instead of a random one. A category with
    no observed successor rests until the end.
    """
    if n_frames < 1:
        raise ValueError(f"synthesize_balance: n_frames must be >= 1, got {n_frames}")
    c, p = start_state(db, rng, start)
    pieces, events, n = [p[None]], [], 1
    while n < n_frames:
        r = rest_frames(db, c, rng)
        pieces.append(np.broadcast_to(p, (r, p.size)))
        events.append(Event("rest", n - 1, n - 1 + r, c))
        n += r
        if n >= n_frames:
            break
        s = next_category(db, c, rng)
        if s is None:  # no way out of c in the data: rest until the end
            pieces.append(np.broadcast_to(p, (n_frames - n, p.size)))
            events[-1] = Event("rest", events[-1].start, n_frames - 1, c)
            break
        q = random_posture(db, s, rng)
        anim, i = fitted_shift(db, p, q, ramp)
        pieces.append(anim[1:])
        events.append(Event("shift", n - 1, n - 1 + len(anim) - 1, s, c, i))
        n += len(anim) - 1
        c, p = s, q
    return np.concatenate(pieces)[:n_frames], events
