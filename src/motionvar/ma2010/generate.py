"""Style-and-variation walks from a fitted model (Ma et al. 2010, Sec. 5-6.3), for the
``motionvar ma2010`` command: given the style parameters c (the strides of the left and
right support phase, Sec. 7.2) and optionally the latent variation xi of some joint groups
("advanced users can manually specify the latent variation parameters", Sec. 1), every
variant draws the remaining xi from the parameter propagation network once (Eq. 10: one
person walks the whole sequence), predicts the gait cycle (Eq. 11-13), repeats it for the
requested duration with transitions (Eq. 14-15) and recovers the root by footskate
cleanup (Sec. 6.3) — the path of "ours" in Sec. 7.4 (:mod:`.comparison`), here with the
user's style and xi instead of the examples' median. The cleanup is the solver's
(:class:`.synthesis.RootSolver` ``cleanup``; the command asks for "root+feet", the
paper's root plus the feet in contact pinned by leg IK [KSG02], unless told "root").

:func:`style_range` is the range of style parameters the model is asked for: the
examples' range widened by :data:`STYLE_MARGIN` of it on each side (universal Kriging
extrapolates by its trend hyperplane outside the examples, Fig. 7b, and the walks
degrade beyond), and within it only near the examples along the directions in which they
hardly vary (:class:`StyleRegion`); :func:`check_style` and :func:`check_xi` reject requests
outside. :func:`walk_measures` measures a generated walk (strides between footfalls, foot
skating), as the evaluations measure theirs; :func:`generate_walks` draws xi again when a
walk misses the requested strides (:data:`STRIDE_TOLERANCE`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np

from ..core.motion import Motion
from ..metrics.foot_skating import foot_skating
from ..metrics.stride import footprints
from .comparison import trim
from .contacts import foot_contacts
from .examples import MIN_FOOTFALL_S
from .svi import GROUP_ORDER, StyleVariationModel
from .synthesis import RootSolver, sequence_motion

#: The requested style may leave the examples' range by this fraction of it on each side.
STYLE_MARGIN = 0.25
#: xi of a group may leave the examples' range by this fraction of it on each side.
XI_MARGIN = 0.5
#: Joint groups by their letters in Ma 2010 Fig. 4 (A legs, B left arm, C right arm, D the rest).
GROUP_LETTERS = dict(zip("ABCD", GROUP_ORDER))


def _widened(values: np.ndarray, margin: float) -> tuple[np.ndarray, np.ndarray]:
    lo, hi = values.min(axis=0), values.max(axis=0)
    pad = margin * (hi - lo)
    return lo - pad, hi + pad


def style_range(model: StyleVariationModel, margin: float = STYLE_MARGIN) -> tuple[np.ndarray, np.ndarray]:
    """(low, high) per style parameter: the examples' range widened by ``margin`` of it."""
    return _widened(np.asarray(model.style_, dtype=float), margin)


def range_text(low: np.ndarray, high: np.ndarray, names: Sequence[str], unit: str = "") -> str:
    """ "name lo-hi unit, ..." with the bounds rounded inwards to 0.1 (every value shown is allowed)."""
    u = f" {unit}" if unit else ""
    return ", ".join(
        f"{n} {np.ceil(a * 10 - 1e-9) / 10:.1f}-{np.floor(b * 10 + 1e-9) / 10:.1f}{u}"
        for n, a, b in zip(names, low, high)
    )


def xi_range(model: StyleVariationModel, margin: float = XI_MARGIN) -> dict[str, tuple[float, float]]:
    """Joint group -> (low, high) of its latent variation xi: the examples' widened."""
    out = {}
    for g, x in model.xi_.items():
        lo, hi = _widened(np.asarray(x, dtype=float)[:, None], margin)
        out[g] = (float(lo[0]), float(hi[0]))
    return out


@dataclass(frozen=True)
class StyleRegion:
    """Where the examples' style parameters lie, along their principal directions: the
    mean (d,), the directions (d, d) (rows, widest first), and along each the examples'
    range widened by ``margin`` of it on each side (``low``, ``high``). Style parameters
    that vary together (the two support strides of steady walkers, nearly equal) span a
    thin direction: a request off it is extrapolation however inside each parameter's
    own range it is, and Kriging's trend extrapolates it badly (a walk asked for strides of
    130 and 136 cm from examples whose strides differ by < 0.5 cm takes 63 and 31 cm)."""

    mean: np.ndarray
    axes: np.ndarray
    low: np.ndarray
    high: np.ndarray
    margin: float

    def coords(self, c: np.ndarray) -> np.ndarray:
        return (np.asarray(c, dtype=float) - self.mean) @ self.axes.T


def style_region(model: StyleVariationModel, margin: float = STYLE_MARGIN) -> StyleRegion:
    """The :class:`StyleRegion` of the model's examples."""
    c = np.asarray(model.style_, dtype=float)
    mean = c.mean(axis=0)
    _, _, axes = np.linalg.svd(c - mean, full_matrices=True)
    axes = axes * np.where(axes[np.arange(len(axes)), np.argmax(np.abs(axes), axis=1)] < 0, -1.0, 1.0)[:, None]
    lo, hi = _widened((c - mean) @ axes.T, margin)
    slack = 1e-9 * max(float(np.abs(c).max()), 1.0)  # rounding, and examples that coincide
    return StyleRegion(mean, axes, lo - slack, hi + slack, margin)


def check_style(
    style: Sequence[float],
    model: StyleVariationModel,
    names: Sequence[str] | None = None,
    unit: str = "",
    margin: float = STYLE_MARGIN,
) -> np.ndarray:
    """``style`` as a (d,) array; ValueError naming the allowed range when it has the wrong
    length, a value outside :func:`style_range`, or lies off the examples along a
    direction in which they do not vary (:class:`StyleRegion`)."""
    c = np.asarray(style, dtype=float).reshape(-1)
    d = model.style_.shape[1]
    names = list(names) if names is not None else [f"c{k + 1}" for k in range(d)]
    u = f" {unit}" if unit else ""
    lo, hi = style_range(model, margin)
    ranges = range_text(lo, hi, names, unit)
    if len(c) != d:
        raise ValueError(f"style: the model takes {d} style parameters ({', '.join(names)}); got {len(c)}")
    if not np.all(np.isfinite(c)):
        raise ValueError(f"style: values must be finite numbers; got {c.tolist()}")
    got = ", ".join(f"{n} {v:g}" for n, v in zip(names, c))
    bad = [k for k in range(d) if not lo[k] <= c[k] <= hi[k]]
    if bad:
        ex_lo, ex_hi = style_range(model, 0.0)
        examples = ", ".join(f"{a:.1f}-{b:.1f}" for a, b in zip(ex_lo, ex_hi))
        raise ValueError(
            f"style {got} is outside the model's range ({ranges}: the examples' {examples} widened by "
            f"{margin:.0%} of it on each side)"
        )
    region = style_region(model, margin)
    x = region.coords(c)
    off = [k for k in range(d) if not region.low[k] <= x[k] <= region.high[k]]
    if off:
        k = off[0]
        expr = " ".join(f"{'-' if w < 0 else '+'} {abs(w):.2f}*{n}" for w, n in zip(region.axes[k], names)).lstrip("+ ")
        ex = region.coords(model.style_)[:, k]
        raise ValueError(
            f"style {got} lies off the examples: their style parameters vary together, {expr} (minus its mean) "
            f"spans {ex.min():.2f} to {ex.max():.2f}{u} over the examples ({region.low[k]:.2f} to {region.high[k]:.2f} "
            f"with the {margin:.0%} margin) and this request gives {x[k]:.2f}; ask for parameters like the examples' "
            f"(for walks: nearly equal strides, one number sets both)"
        )
    return c


def check_xi(xi: Mapping[str, float], model: StyleVariationModel, margin: float = XI_MARGIN) -> dict[str, float]:
    """Fixed xi by joint group (names of :data:`GROUP_ORDER` or the letters of
    :data:`GROUP_LETTERS`); ValueError naming the groups or the allowed range."""
    ranges = xi_range(model, margin)
    out = {}
    for key, value in xi.items():
        g = GROUP_LETTERS.get(str(key).upper(), str(key))
        if g not in ranges:
            valid = ", ".join(f"{k}={v}" for k, v in GROUP_LETTERS.items())
            raise ValueError(f"xi: unknown joint group {key!r} (groups: {valid})")
        lo, hi = ranges[g]
        if not (np.isfinite(value) and lo <= value <= hi):
            raise ValueError(
                f"xi {key}={value:g} is outside the model's range for {g} ({lo:.3g}-{hi:.3g}: the "
                f"examples' xi widened by {margin:.0%} of it on each side)"
            )
        out[g] = float(value)
    return out


#: A drawn xi whose walk misses the requested strides by more than this fraction is drawn
#: again (:func:`generate_walks`): at some draws the predicted swing foot dips below the
#: stance foot for longer than the cleanup's minimum contact (0.1 s), the cleanup then
#: stands on the swinging foot and the walk steps back every cycle (strides of 60 and 110
#: cm for 137 asked).
STRIDE_TOLERANCE = 0.05
MAX_DRAWS = 10


@dataclass
class GeneratedWalk:
    """One variant: the motion (on the model's standard skeleton, root from footskate
    cleanup), the style parameters and the xi of every joint group it was made with, how
    many draws of xi it took and its measures (:func:`walk_measures`); ``accepted`` is
    False when no draw met the stride tolerance (the best draw is kept)."""

    motion: Motion
    style: np.ndarray
    xi: dict[str, float]
    draws: int = 1
    measures: dict[str, float] | None = None
    accepted: bool = True


def _cycle_seconds(model: StyleVariationModel, c: np.ndarray, xi: Mapping[str, np.ndarray]) -> float:
    one = model.predict(c, xi)
    return float(one.key_times[0, -1] - one.key_times[0, 0])


def _walk(
    model: StyleVariationModel,
    solver: RootSolver,
    c: np.ndarray,
    drawn: Mapping[str, np.ndarray],
    seconds: float,
    landing_rule: str,
) -> Motion:
    """``seconds`` of the cycle predicted at (c, xi), repeated with transitions and root-solved."""
    fps = model.fps_
    span = _cycle_seconds(model, c, drawn)
    if not span > 0:
        raise ValueError(f"style {c[0].tolist()}: the predicted gait cycle has no duration ({span:.3g} s)")
    n_clips = int(np.ceil(seconds / span)) + 2  # one more for trimming, one for the transitions' frames
    while True:
        pred = model.predict(np.repeat(c, n_clips, axis=0), {g: np.repeat(x, n_clips) for g, x in drawn.items()})
        motion = sequence_motion(
            pred.rotations, pred.key_times, model.reference_keys_, solver, fps, pred.root_height, landing_rule
        )
        if motion.duration >= seconds - 0.5 / fps:
            return trim(motion, seconds)
        n_clips += 1


def _stride_error(measures: Mapping[str, float], c: np.ndarray) -> float:
    """Largest relative miss of the two support strides (inf when unmeasurable)."""
    got = np.array([measures["left_support_stride_cm"], measures["right_support_stride_cm"]])
    err = np.abs(got - c[:2]) / np.abs(c[:2])
    return float(err.max()) if np.all(np.isfinite(err)) else float("inf")


def generate_walks(
    model: StyleVariationModel,
    solver: RootSolver,
    style: Sequence[float],
    seconds: float,
    n_variants: int = 1,
    seed: int = 0,
    xi: Mapping[str, float] | None = None,
    landing_rule: str = "significant_maximum",
    progress: Callable[[int, int], None] | None = None,
    tolerance: float = STRIDE_TOLERANCE,
    max_draws: int = MAX_DRAWS,
    cleanup: str | None = None,
) -> list[GeneratedWalk]:
    """``n_variants`` walks of ``seconds`` s (``round(seconds * fps) + 1`` frames) at style
    ``style`` (module docstring). Variant ``v`` draws from
    ``numpy.random.default_rng([seed, v])``; groups in ``xi`` keep the given value and
    their children in the network propagate from it. The style parameters are the two
    support strides (Sec. 7.2, as every walk model here: :func:`.examples.build_clipset`): a
    draw whose walk misses them by more than ``tolerance`` (relative) is drawn again, at
    most ``max_draws`` times (:data:`STRIDE_TOLERANCE`); with every groups' xi given there
    is nothing to draw again. ``progress(done, total)`` is called after every variant.
    ``cleanup`` overrides the solver's footskate cleanup (:data:`.postprocess.CLEANUPS`:
    "root" the paper's, "root+feet" with the feet in contact pinned by leg IK); None keeps
    the solver's."""
    if cleanup is not None:
        solver = replace(solver, cleanup=cleanup)
    if not seconds > 0:
        raise ValueError(f"generate_walks: seconds must be positive; got {seconds}")
    if n_variants < 1:
        raise ValueError(f"generate_walks: need at least 1 variant; got {n_variants}")
    c = np.atleast_2d(np.asarray(style, dtype=float))
    fixed = dict(xi or {})
    draws = max_draws if set(model.xi_) - set(fixed) else 1
    out = []
    for v in range(n_variants):  # loop over variants
        rng = np.random.default_rng([seed, v])
        best = None
        for k in range(draws):  # redraw xi while the walk misses the strides
            drawn = model.sample_variation(c, rng=rng, fixed=fixed)
            motion = _walk(model, solver, c, drawn, seconds, landing_rule)
            meas = walk_measures(motion, solver)
            err = _stride_error(meas, c[0]) if c.shape[1] >= 2 else 0.0
            if best is None or err < best[0]:
                best = (
                    err,
                    GeneratedWalk(
                        motion, c[0].copy(), {g: float(x[0]) for g, x in drawn.items()}, k + 1, meas, err <= tolerance
                    ),
                )
            if err <= tolerance:
                break
        best[1].draws = k + 1
        out.append(best[1])
        if progress is not None:
            progress(v + 1, n_variants)
    return out


def walk_measures(motion: Motion, solver: RootSolver, skip_s: float = 1.0) -> dict[str, float]:
    """Strides and foot skating of a generated walk, measured as the evaluations do:
    footfalls (contacts of at least :data:`.examples.MIN_FOOTFALL_S`) from the project's
    contact detection (:func:`.contacts.foot_contacts`); the
    left-support stride is the right foot's travel between consecutive footfalls, the
    right-support stride the left foot's (median over the footfalls after the first
    ``skip_s`` s, the start from standing still); foot skating (cm/s) is the speed of each
    foot's contact point while it is in contact (:func:`..metrics.foot_skating.foot_skating`,
    Sec. 7.4's measure). NaN strides when a foot has fewer than two footfalls."""
    pos = motion.positions()
    contacts = foot_contacts(motion, solver.feet, pos)
    ankles = pos[:, [solver.left_foot, solver.right_foot]]
    strides, n_footfalls = [], 0
    for runs, prints in footprints(ankles, contacts):  # left foot, then right foot
        keep = (runs[:, 1] - runs[:, 0]) >= int(round(MIN_FOOTFALL_S * motion.fps))  # no grazing swing foot
        runs, prints = runs[keep], prints[keep]
        n_footfalls += len(runs)
        later = runs[:, 0] >= int(round(skip_s * motion.fps))
        prints = prints[later] if later.sum() >= 2 else prints
        d = np.linalg.norm(np.diff(prints, axis=0), axis=-1)
        strides.append(float(np.median(d)) if len(d) else float("nan"))
    left_foot, right_foot = strides
    skating = foot_skating(pos[:, solver.feet], contacts, motion.fps, solver.planted)
    return {
        "left_support_stride_cm": right_foot,
        "right_support_stride_cm": left_foot,
        "foot_skating_cm_s": skating,
        "footfalls": n_footfalls,
    }
