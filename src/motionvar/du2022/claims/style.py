"""The claims of Du 2022 chapter 5 (stylistic motion primitives): Table 5.1 (style distance) and
Tables 5.2-5.3 (diversity), with the functions that judge them from their evaluations'
measurements; ``CLAIMS`` at the end lists them."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from ...claims import ClaimSpec, Judgement, verdict_from_fraction
from .common import Measurements, _first_min, _share

#: the fewest latent dimensions in use (active units, Burda et al. 2016: variance over the training clips
#: of the encoder mean above 0.01, ``motionvar.du2022.style.active_units``) of a model whose samples the
#: chapter 5 claims compare: below it the posterior has collapsed toward the prior and the samples vary
#: along at most one direction, so their spread or style distance measures the collapse, not the model
MIN_ACTIVE_LATENTS = 2


def _collapsed(active: Mapping[str, float]) -> list[str]:
    """``"<model> <n>"`` for each model of ``active`` (model -> latent dimensions in use) below
    :data:`MIN_ACTIVE_LATENTS` (unknown counts, None or NaN, are not judged)."""
    return [
        f"{name} {int(n)}"
        for name, n in active.items()
        if n is not None and not math.isnan(n) and n < MIN_ACTIVE_LATENTS
    ]


def _collapse_reason(collapsed: Sequence[str], latent_dims: int | None) -> str:
    of = f", of {latent_dims}" if latent_dims else ""
    return (
        f"Collapsed posteriors (latent dimensions in use{of}: {', '.join(collapsed)}; fewer than "
        f"{MIN_ACTIVE_LATENTS} active units, Burda et al. 2016): the samples hardly vary, so the comparison would "
        "measure the collapse, not the model."
    )


def _diagonal_dominant(m: Measurements) -> Judgement:
    """Sec. 5.4.3, Table 5.1: the samples of each model are closer in style distance D (Eq.
    5.12) to their own style example than to any other (every row's minimum on the diagonal).
    Not testable when a model uses fewer than :data:`MIN_ACTIVE_LATENTS` latent dimensions."""
    distances = m["distances"]
    row_min = {r: _first_min(row) for r, row in distances.items()}
    on_diag = [r for r, row in distances.items() if r in row and row_min[r] == r]
    rows = len(distances)
    off = [f"{r}->{row_min[r]}" for r in distances if r not in on_diag]
    regimes, active = m["cvae_regimes"], m["active_units"]
    training = (
        f"CVAEs: {'; '.join(regimes)} (the thesis: lr 1e-5, 1000 epochs)."
        if regimes
        else "Training budgets are a fraction of the thesis' (see the caption)."
    )
    measured = (
        f"{len(on_diag)} of {rows} rows have their minimum on the diagonal"
        + (f" (off: {', '.join(off)})" if off else "")
        + (f"; latent dimensions in use: {', '.join(f'{s} {n}' for s, n in active.items())}" if active else "")
    )
    collapsed = _collapsed({r: active.get(r) for r in distances})
    if collapsed:
        return Judgement("not testable", measured, note=f"{_collapse_reason(collapsed, m['latent_dims'])} {training}")
    causes = _table5_1_causes(m, [r for r in distances if r not in on_diag])
    return Judgement(
        verdict=verdict_from_fraction(len(on_diag), rows),
        measured=measured + "".join(f"; {cause}: {', '.join(why)}" for cause, why in causes.items()),
        note=f"{m['primitive']}, {m['samples']} samples a model, synthetic styles, CMU 21-joint subset; D averages "
        "the Gram matrices over frames (the thesis' scale, its neutral-to-neutral 0.0149; Eq. 5.9's sum multiplies "
        f"every entry by 900). {training}"
        + (" Off the diagonal by " + ", ".join(f"{c} ({len(w)})" for c, w in causes.items()) + "." if causes else ""),
        value=_share(len(on_diag), rows),
        bound=1.0,
        unit="share",
        direction=">=",
    )


def _table5_1_causes(m: Measurements, off: Sequence[str]) -> dict[str, list[str]]:
    """Cause class -> the rows ``off`` the diagonal it explains (each with its diagnostic), the
    first match per row: the data (the style's own
    clips, through the autoencoder, are themselves nearer another example), our departure (the
    CVAE's style term still fell by more than :data:`CVAE_CONVERGED_DROP` in its last epoch:
    our budget stopped it short of convergence), else the method as we run it."""
    own, drop = m.get("own_clips_minimum", {}), m.get("style_last_drop", {})
    classes: dict[str, list[str]] = {"the data": [], "our training budget": [], "the method": []}
    for r in off:
        if own.get(r, r) != r:
            classes["the data"].append(f"{r} (its own clips nearest {own[r]})")
        elif drop.get(r, 0.0) > CVAE_CONVERGED_DROP:
            classes["our training budget"].append(f"{r} (style term still -{drop[r]:.1%} in the last epoch)")
        else:
            classes["the method"].append(r)
    return {cause: rows for cause, rows in classes.items() if rows}


def _pct(a: float, b: float) -> str:
    return f"{100 * (a / b - 1):+.1f}%"


def _setup(m: Measurements) -> str:
    """The sentence every Table 5.2 claim ends with: samples, data, training regimes and the
    range of latent dimensions the models use (each model's in the table, column active_latents)."""
    active = [int(r["models"][s]["active_latents"]) for r in m["rows"].values() for s in ["neutral", *m["styles"]]]
    used = f"{min(active)}" if min(active) == max(active) else f"{min(active)}-{max(active)}"
    return (
        f"{m['samples']} samples a model; synthetic data, CMU 21-joint subset, reduced training budgets "
        f"({'; '.join(m['regimes']) or 'see the caption'}); latent dimensions in use {used} of {m['latent_dims']}."
    )


def _collapsed_models(m: Measurements, models: Sequence[str]) -> Judgement | None:
    """A ``not testable`` judgement when one of ``models`` (of every primitive) uses fewer than
    :data:`MIN_ACTIVE_LATENTS` latent dimensions, else None."""
    collapsed = _collapsed(
        {f"{p} {s}": m["rows"][p]["models"][s]["active_latents"] for p in m["primitives"] for s in models}
    )
    if not collapsed:
        return None
    return Judgement("not testable", "-", note=f"{_collapse_reason(collapsed, m['latent_dims'])} {_setup(m)}")


def _neutral_pose_sd_close_to_training(m: Measurements) -> Judgement:
    """Sec. 5.4.5, Tables 5.2-5.3: the neutral VAE's pose_SD (Eq. 5.13) is close to the training
    data's: full credit within ``pose_sd_tolerance`` of it, half credit only within it of the
    training data passed through the autoencoder. Not testable when a neutral VAE collapsed."""
    tol, prims = m["pose_sd_tolerance"], m["primitives"]
    credit, parts, misses = 0.0, [], []
    for p in prims:
        r = m["rows"][p]
        vae, train, ae = r["models"]["neutral"]["pose_sd"], r["training"]["pose_sd"], r["round_trip"]["pose_sd"]
        credit += 1.0 if abs(vae / train - 1) <= tol else 0.5 if abs(vae / ae - 1) <= tol else 0.0
        post = r["models"]["neutral"]["posterior_mean_pose_sd"]
        if abs(vae / train - 1) > tol:  # the first step of the chain that is already off names the cause
            if abs(ae / train - 1) > tol:
                misses.append(f"{p} by our autoencoder (its round trip {_pct(ae, train)})")
            elif abs(post / train - 1) > tol:
                misses.append(
                    f"{p} by the VAE's fit at our budget (its decoder at the posterior means {_pct(post, train)})"
                )
            else:
                misses.append(f"{p} by sampling the prior, the method (at the posterior means {_pct(post, train)})")
        parts.append(
            f"{p}: {vae:.2f} vs {train:.2f} ({_pct(vae, train)}); vs the training data through the "
            f"autoencoder {ae:.2f} ({_pct(vae, ae)}; the round trip alone {_pct(ae, train)}; the VAE's "
            f"decoder at the posterior means {post:.2f}, {_pct(post, train)})"
        )
    if (collapsed := _collapsed_models(m, ["neutral"])) is not None:
        return Judgement(collapsed.verdict, "; ".join(parts), note=collapsed.note)
    return Judgement(
        verdict=verdict_from_fraction(credit, len(prims)),
        measured="; ".join(parts),
        note=f"pose_SD of the neutral VAE's prior samples against the training clips (within {tol:.0%}), half credit "
        "against them through the autoencoder (what a perfect VAE gives). "
        + (f"Missed: {'; '.join(misses)}. " if misses else "")
        + _setup(m),
        value=_share(credit, len(prims)),
        bound=1.0,
        unit="share",
        direction=">=",
    )


def _neutral_step_sd_lower_than_training(m: Measurements) -> Judgement:
    """Sec. 5.4.5, Tables 5.2-5.3: the neutral VAE's step_SD (Eq. 5.15) is below the training
    data's, in every primitive. Not testable when a neutral VAE collapsed (its samples' step_SD
    is then low whatever the model)."""
    prims, rows = m["primitives"], m["rows"]
    step = {p: (rows[p]["models"]["neutral"]["step_sd"], rows[p]["training"]["step_sd"]) for p in prims}
    n_ok = sum(a < b for a, b in step.values())

    def mean(values):
        return sum(values) / len(values)

    chain = [
        mean([rows[p]["training"]["step_sd"] for p in prims]),
        mean([rows[p]["round_trip"]["step_sd"] for p in prims]),
        mean([rows[p]["models"]["neutral"]["posterior_mean_step_sd"] for p in prims]),
        mean([rows[p]["models"]["neutral"]["step_sd"] for p in prims]),
    ]
    measured = "; ".join(
        f"{p}: {a:.2f} vs {b:.2f} (through the autoencoder {rows[p]['round_trip']['step_sd']:.2f}; the "
        f"VAE's decoder at the posterior means {rows[p]['models']['neutral']['posterior_mean_step_sd']:.2f})"
        for p, (a, b) in step.items()
    )
    if (collapsed := _collapsed_models(m, ["neutral"])) is not None:
        return Judgement(collapsed.verdict, measured, note=collapsed.note)
    return Judgement(
        verdict=verdict_from_fraction(n_ok, len(prims)),
        measured=measured,
        note=f"Step_SD (cm; mean over primitives) from the neutral clips {chain[0]:.2f}: through the autoencoder "
        f"{chain[1]:.2f} ({chain[1] - chain[0]:+.2f}), the neutral VAE's decoder at the posterior means "
        f"{chain[2]:.2f} ({chain[2] - chain[1]:+.2f}), its prior samples {chain[3]:.2f}. " + _setup(m),
        value=_share(n_ok, len(prims)),
        bound=1.0,
        unit="share",
        direction=">=",
    )


def _style_pose_sd_lower_than_neutral(m: Measurements) -> Judgement:
    """Sec. 5.4.5, Tables 5.2-5.3: every stylistic model's pose_SD is lower than the neutral
    VAE's, compared raw as the thesis prints them (each CVAE trains on the neutral clips of the
    primitive plus one style example, Sec. 5.4.1); each model's pose_SD relative to its style's
    own clips is reported beside it as a diagnostic. Not testable when a model collapsed."""
    prims, styles, rows = m["primitives"], m["styles"], m["rows"]

    def model(p, s):
        return rows[p]["models"][s]

    ratio = {
        (p, s): model(p, s)["pose_sd"] / model(p, s)["training_pose_sd"] for p in prims for s in ["neutral", *styles]
    }
    lower_raw = [(p, s) for p in prims for s in styles if model(p, s)["pose_sd"] < model(p, "neutral")["pose_sd"]]
    lower_own = [(p, s) for p in prims for s in styles if ratio[(p, s)] < ratio[(p, "neutral")]]
    n_style = len(prims) * len(styles)
    measured = (
        f"{len(lower_raw)} of {n_style} CVAEs below the neutral VAE's pose_SD; diagnostic, relative to each "
        f"style's own clips: {len(lower_own)} of {n_style} (per model: the table's pose_sd, pose_sd_own_ratio)"
    )
    if (collapsed := _collapsed_models(m, ["neutral", *styles])) is not None:
        return Judgement(collapsed.verdict, measured, note=collapsed.note)
    causes = _style_pose_sd_causes(m, [(p, s) for p in prims for s in styles if (p, s) not in lower_raw], ratio)
    return Judgement(
        verdict=verdict_from_fraction(len(lower_raw), n_style),
        measured=measured + "".join(f"; {cause}: {', '.join(why)}" for cause, why in causes.items()),
        note="pose_SD (Eq. 5.13) of each CVAE's prior samples against the neutral VAE's, raw as in Tables 5.2-5.3; "
        "each CVAE trains on the primitive's neutral clips plus one style example (Sec. 5.4.1). "
        + ("Not below by " + ", ".join(f"{c} ({len(w)})" for c, w in causes.items()) + ". " if causes else "")
        + _setup(m),
        value=_share(len(lower_raw), n_style),
        bound=1.0,
        unit="share",
        direction=">=",
    )


def _style_pose_sd_causes(
    m: Measurements, missed: Sequence[tuple[str, str]], ratio: Mapping[tuple[str, str], float]
) -> dict[str, list[str]]:
    """Cause class -> the CVAEs ``missed`` (not below the neutral VAE's pose_SD) it explains, the
    first match per CVAE: the data (the style's own clips vary more than the neutral clips, and
    relative to its own clips, ``ratio``, the CVAE varies less than the neutral VAE does: the raw
    comparison measures the styles' spread), our training budget (its style term still fell by
    more than :data:`CVAE_CONVERGED_DROP` in its last epoch), else the method as we run it."""
    rows, drop = m["rows"], m.get("style_last_drop", {})
    classes: dict[str, list[str]] = {"the data": [], "our training budget": [], "the method": []}
    for p, s in missed:
        own, neutral_own = rows[p]["models"][s]["training_pose_sd"], rows[p]["models"]["neutral"]["training_pose_sd"]
        if own > neutral_own and ratio[(p, s)] < ratio[(p, "neutral")]:
            classes["the data"].append(f"{p} {s} (own clips {own:.2f} vs neutral {neutral_own:.2f})")
        elif drop.get(f"{p} {s}", 0.0) > CVAE_CONVERGED_DROP:
            classes["our training budget"].append(f"{p} {s} (style term -{drop[f'{p} {s}']:.1%} in the last epoch)")
        else:
            classes["the method"].append(f"{p} {s}")
    return {cause: found for cause, found in classes.items() if found}


_TABLE5_2 = "du2022_table5_2"


# Tables 5.1-5.2, the cause class "our training budget": a CVAE whose style term still fell by more than this share in
# its last epoch had not converged (a round bound: the thesis trains 1,000 epochs, 100 times ours)
CVAE_CONVERGED_DROP = 0.01


CLAIMS: tuple[ClaimSpec, ...] = (
    ClaimSpec(
        claim_id="du2022.table5_1.diagonal_dominant",
        evaluation="du2022_table5_1",
        source="Table 5.1",
        kind="replication",
        statement="Samples of each stylistic model (and the neutral VAE) are closer, in Gram-matrix style "
        "distance (Eq. 5.12), to their own style example than to any other style's example.",
        published="7 of 7 rows have their minimum on the diagonal",
        bound="every row's minimum on the diagonal (partial: at least half; not testable when a model uses fewer "
        "than 2 latent dimensions)",
        judge=_diagonal_dominant,
    ),
    ClaimSpec(
        claim_id="du2022.table5_2.neutral_pose_sd_close_to_training",
        evaluation=_TABLE5_2,
        source="Tables 5.2-5.3",
        kind="replication",
        statement="The neutral VAE's pose_SD is close to the training data's.",
        published="52.68 vs 52.86 (left), 52.88 vs 53.04 (right): within 0.4%",
        bound="within pose_sd_tolerance of the training data's (half credit: of its autoencoder round trip's; not "
        "testable when a neutral VAE uses fewer than 2 latent dimensions)",
        judge=_neutral_pose_sd_close_to_training,
    ),
    ClaimSpec(
        claim_id="du2022.table5_2.neutral_step_sd_lower_than_training",
        evaluation=_TABLE5_2,
        source="Tables 5.2-5.3",
        kind="replication",
        statement="The neutral VAE's step-length SD is lower than the training data's.",
        published="7.66 < 10.12 (left), 7.51 < 9.98 (right)",
        bound="lower in every primitive (partial: at least half; not testable when a neutral VAE uses fewer than 2 "
        "latent dimensions)",
        judge=_neutral_step_sd_lower_than_training,
    ),
    ClaimSpec(
        claim_id="du2022.table5_2.style_pose_sd_lower_than_neutral",
        evaluation=_TABLE5_2,
        source="Tables 5.2-5.3",
        kind="replication",
        statement="Every stylistic model's pose_SD is lower than the neutral VAE's; each CVAE is trained on the "
        "neutral VAE's clips plus one style example.",
        published="12 of 12 (6 styles x 2 primitives), raw values",
        bound="each CVAE's pose_SD below the neutral VAE's, every style and primitive (partial: at least half; not "
        "testable when a model uses fewer than 2 latent dimensions)",
        judge=_style_pose_sd_lower_than_neutral,
    ),
)
