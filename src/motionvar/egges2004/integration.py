"""Integration into an animation system (Egges et al. 2004, Sec. 7, Fig. 9).

Sec. 7.1: idle motion between two animations, from the end posture p_0 of the one to
the start posture p_1 of the next, through the shortest path (or cycle) of the category
graph, the last shift fitted to end at p_1; when time is short the rests are shortened
and the shifts time-scaled.
Sec. 7.2: balance shifting blended with another animation by a weight and joint masks,
then the small variations added in PC space.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.quaternions import qslerp
from ..core.skeleton import Skeleton
from .balance import Event, fitted_shift, next_category, random_posture, rest_frames, time_scale
from .database import IdleDatabase
from .fitting import posture_distance
from .pca import PosturePCA


def _route_frames(db: IdleDatabase, c: int, end: int) -> float:
    """Expected frames the final route from c to ``end`` needs: per hop a minimal rest
    and an animation of mean length."""
    hops = db.graph.hops()
    if c != end:
        n_hops = hops[c, end]
    else:
        n_hops = (1 + hops[np.flatnonzero(db.graph.probabilities[c] > 0), end]).min(initial=np.inf)
    t_min = db.graph.t_min
    rest = np.nanmean(t_min) if np.any(np.isfinite(t_min)) else 0.0
    return n_hops * (np.mean([len(a) - 1 for a in db.animations]) + rest * db.fps)


def _split(total: int, shares: np.ndarray) -> np.ndarray:
    """Integers >= 0 proportional to ``shares`` summing to ``total`` (largest remainder)."""
    shares = np.asarray(shares, dtype=float)
    if shares.sum() <= 0:
        shares = np.ones_like(shares)
    exact = total * shares / shares.sum()
    out = np.floor(exact).astype(np.int64)
    out[np.argsort(exact - out)[::-1][: total - out.sum()]] += 1
    return out


def idle_between(
    db: IdleDatabase,
    p0: np.ndarray,
    p1: np.ndarray,
    n_frames: int,
    rng: np.random.Generator,
    ramp: str = "linear",
    close_distance: float | None = None,
) -> tuple[np.ndarray, list[Event]]:
    """(n_frames, D) idle motion in PC space that starts at p_0 and ends at p_1 (Sec. 7.1).

    Balance shifts run as in Sec. 5.4 while the time left exceeds what the final route
    to p_1's category needs; then the shortest path in the category graph (the shortest
    cycle when already in p_1's category) leads there, the last shift fitted to end at
    p_1. Rests on the route share the time left; when it is too short they shrink and
    the shifts are time-scaled. With ``close_distance``, a current posture within that
    distance (Eq. 4) of p_1 in p_1's category is interpolated to p_1 directly.
    """
    if n_frames < 2:
        raise ValueError(f"idle_between: n_frames must be >= 2, got {n_frames}")
    p0, p1 = np.asarray(p0, dtype=float), np.asarray(p1, dtype=float)
    c, p, end = db.classify(p0), p0, db.classify(p1)
    pieces, events, n = [p0[None]], [], 1
    while True:  # free balance shifting (Sec. 5.4) while there is time
        r = rest_frames(db, c, rng)
        s = next_category(db, c, rng)
        if s is None:
            break
        q = random_posture(db, s, rng)
        anim, i = fitted_shift(db, p, q, ramp)
        if n + r + len(anim) - 1 + _route_frames(db, s, end) > n_frames:
            break
        pieces += [np.broadcast_to(p, (r, p.size)), anim[1:]]
        events += [Event("rest", n - 1, n - 1 + r, c), Event("shift", n - 1 + r, n + r + len(anim) - 2, s, c, i)]
        n += r + len(anim) - 1
        c, p = s, q
    left = n_frames - n
    if close_distance is not None and c == end and posture_distance(p, p1, db.weights) <= close_distance:
        route = [c]
    else:
        route = db.graph.shortest_route(c, end, rng)
    anims, ids, rests = [], [], []
    for k, s in enumerate(route[1:]):
        q = p1 if k == len(route) - 2 else random_posture(db, s, rng)
        a, i = fitted_shift(db, anims[-1][-1] if anims else p, q, ramp)
        anims.append(a)
        ids.append(i)
        rests.append(db.graph.t_min[route[k]] * db.fps if np.isfinite(db.graph.t_min[route[k]]) else 0.0)
    moving = np.array([len(a) - 1 for a in anims], dtype=np.int64)
    if not anims or left < len(anims):  # no time (or no need) for shifts: interpolate to p1
        u = np.arange(1, left + 1)[:, None] / max(left, 1)
        pieces.append(p + (p1 - p) * u)
        events.append(Event("interpolate", n - 1, n_frames - 1, end, c))
        return np.concatenate(pieces), events
    if left >= moving.sum():
        rest_n = _split(left - moving.sum(), np.array(rests))
    else:  # too little time: no rests, time-scaled shifts
        rest_n = np.zeros(len(anims), dtype=np.int64)
        moving = _split(left - len(anims), moving) + 1
    for k, (a, i) in enumerate(zip(anims, ids)):
        a = time_scale(a, moving[k] + 1)
        start = a[0]
        pieces += [np.broadcast_to(start, (rest_n[k], start.size)), a[1:]]
        events += [
            Event("rest", n - 1, n - 1 + rest_n[k], route[k]),
            Event("shift", n - 1 + rest_n[k], n - 1 + rest_n[k] + moving[k], route[k + 1], route[k], i),
        ]
        n += rest_n[k] + moving[k]
    return np.concatenate(pieces), events


def joint_mask(skeleton: Skeleton, joint_map: JointMap, groups: Sequence[str], value: float = 1.0) -> np.ndarray:
    """(J,) mask with ``value`` on the joints of the named joint groups (legs, left_arm,
    right_arm, upper_body) and 0 elsewhere (Sec. 7.2's joint masks)."""
    idx = joint_map.group_indices(skeleton)
    unknown = [g for g in groups if g not in idx]
    if unknown:
        raise ValueError(f"joint_mask: unknown joint groups {unknown} (expected {sorted(idx)})")
    mask = np.zeros(skeleton.n_joints)
    for g in groups:
        mask[idx[g]] = value
    return mask


def blend_motions(idle: Motion, other: Motion, weight: float | np.ndarray, mask: np.ndarray) -> Motion:
    """Blend balance shifting into another animation at joint level (Sec. 7.2, Fig. 9).

    Joint j at frame t takes slerp(other, idle, weight_t * mask_j): ``weight`` (scalar or
    (T,)) is the idle motion's weight, ``mask`` (J,) in [0, 1] the joint mask (0: keep the
    other animation's joint, e.g. the arms of a gesture). The root translation blends
    with the root joint's weight.
    """
    if idle.n_frames != other.n_frames or not idle.skeleton.same_topology(other.skeleton):
        raise ValueError(
            f"blend_motions: need the same skeleton and length; got {idle.n_frames} and {other.n_frames} frames"
        )
    mask = np.asarray(mask, dtype=float)
    if mask.shape != (idle.skeleton.n_joints,) or mask.min() < 0 or mask.max() > 1:
        raise ValueError(f"blend_motions: mask must be ({idle.skeleton.n_joints},) in [0, 1]; got {mask.shape}")
    w = np.broadcast_to(np.asarray(weight, dtype=float), (idle.n_frames,))[:, None] * mask
    rot = qslerp(other.rotations, idle.rotations, w)
    root = other.root_pos + w[:, :1] * (idle.root_pos - other.root_pos)
    return Motion(skeleton=other.skeleton, root_pos=root, rotations=rot, fps=other.fps)


def add_variations(motion: Motion, variations: np.ndarray, pcs: np.ndarray, pca: PosturePCA) -> Motion:
    """Add small-variation curves (T, P) to PCs ``pcs`` of every frame (Sec. 7.2, last step)."""
    values = pca.project(motion)
    values[:, np.asarray(pcs)] += variations
    return pca.reconstruct(values, motion.skeleton, motion.fps)
