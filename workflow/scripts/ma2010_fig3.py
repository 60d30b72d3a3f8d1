"""Rule ma2010_fig3 (Ma 2010 Fig. 3, Sec. 4.1): S_M(t) and its key frames for a walk and
a run; the claim checks over every walk and run of the dataset that the maxima of S_M(t)
(the legs farthest apart) fall at one phase of the step (between a foot strike and the
next), so that the key frames cut every cycle at the same gait phase."""


def step_phases(maxima, strikes):
    """Phase in [0, 1) of each maximum within its step (previous strike -> next strike);
    maxima outside the first and last strike are left out."""
    import numpy as np

    k = np.searchsorted(strikes, maxima, side="right") - 1
    ok = (k >= 0) & (k + 1 < len(strikes))
    k = k[ok]
    return (maxima[ok] - strikes[k]) / (strikes[k + 1] - strikes[k])


def circular_sd(phases):
    """Circular standard deviation of phases in [0, 1), in units of one step."""
    import numpy as np

    r = np.abs(np.mean(np.exp(2j * np.pi * np.asarray(phases))))
    return float(np.sqrt(-2.0 * np.log(max(r, 1e-12))) / (2 * np.pi))


def onsets(row, motion, joint_map):
    """Foot-strike frames of a clip: the generator's ground truth when the metadata has
    contact intervals, else detected (motionvar.prep)."""
    import numpy as np

    from motionvar.prep.contacts import detect_foot_contacts
    from motionvar.prep.intervals import parse_intervals

    if "left_contacts" in row and isinstance(row["left_contacts"], str):
        starts = [parse_intervals(row[f"{s}_contacts"], f"{s}_contacts")[:, 0] for s in ("left", "right")]
    else:
        c = detect_foot_contacts(motion, joint_map)
        starts = [c.intervals(s)[:, 0] for s in ("left", "right")]
    all_starts = np.sort(np.concatenate(starts))
    return all_starts[all_starts > 0]


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from _ma2010 import PAPER, PROTOCOL, joint_map
    from motionvar.claims import Claim, verdict_threshold, write_claims
    from motionvar.io import load_dataset
    from motionvar.ma2010 import extract_cycles
    from motionvar.ma2010.examples import rows_matching
    from motionvar.plots import plot_key_frames

    o = snakemake.params.options
    data = load_dataset(Path(snakemake.input.clips).parent)
    meta = data.metadata
    jm = joint_map(snakemake)
    walks = rows_matching(meta, behaviour="walk", style=o["walk_styles"], variant=o["walk_variants"],
                          what=f"{snakemake.input.metadata} (config ma2010.walk_styles / walk_variants)")
    runs = np.flatnonzero(meta["behaviour"].astype(str).to_numpy() == "run")
    limit = o["fig3_max_clips"] or None
    rows, counts, shown = [], {}, {}
    for behaviour, idx in (("walk", walks), ("run", runs)):
        phases, offsets = [], []
        for k, i in enumerate(idx[:limit]):  # loop over clips
            m = data.motion(int(i))
            ex = extract_cycles(m, jm, o["keyframe_prominence"], o["keyframe_min_separation_s"])
            strikes = onsets(meta.iloc[int(i)], m, jm)
            maxima = ex.frames[ex.kinds == 1]
            if len(strikes) and len(maxima):
                diff = maxima[:, None] - strikes[None, :]
                offsets.extend((diff[np.arange(len(maxima)), np.abs(diff).argmin(axis=1)] / m.fps).tolist())
                phases.extend(step_phases(maxima, strikes).tolist())
            if k == 0:
                shown[behaviour] = (meta["clip_id"].iloc[int(i)], m, ex, strikes)
                for f, kind in zip(ex.frames, ex.kinds):
                    near = np.abs(strikes - f).min() / m.fps if len(strikes) else np.nan
                    rows.append({"clip_id": meta["clip_id"].iloc[int(i)], "behaviour": behaviour, "frame": int(f),
                                 "time_s": f / m.fps, "extremum": "max" if kind == 1 else "min",
                                 "S_M": float(ex.signal.signal[f]), "to_foot_strike_s": near,
                                 "D_l": ex.signal.d_lower, "D_u": ex.signal.d_upper, "part": ex.signal.part})
        if phases:
            counts[behaviour] = (circular_sd(phases), len(phases), float(np.median(offsets)))
    pd.DataFrame(rows).to_csv(snakemake.output.table, index=False)

    fig, axes = plt.subplots(4, 1, figsize=(13, 11), gridspec_kw={"height_ratios": [1, 1.3, 1, 1.3]})
    for r, behaviour in enumerate(("walk", "run")):
        ax_s, ax_k = axes[2 * r], axes[2 * r + 1]
        if behaviour not in shown:
            ax_s.text(0.5, 0.5, f"no {behaviour} clips in this dataset", ha="center", transform=ax_s.transAxes)
            ax_s.axis("off")
            ax_k.axis("off")
            continue
        cid, m, ex, strikes = shown[behaviour]
        t = np.arange(m.n_frames) / m.fps
        s = ex.signal.signal
        ax_s.plot(t, s, color="k", lw=1.2, label=r"$S_\mathcal{M}(t)$" + f" ({ex.signal.part} body)")
        mx, mn = ex.frames[ex.kinds == 1], ex.frames[ex.kinds == -1]
        ax_s.plot(t[mx], s[mx], "v", color="tab:red", label="key frame (maximum)")
        ax_s.plot(t[mn], s[mn], "^", color="tab:blue", label="key frame (minimum)")
        for f in strikes:
            ax_s.axvline(f / m.fps, color="tab:green", lw=0.8, alpha=0.6)
        ax_s.plot([], [], color="tab:green", lw=0.8, label="foot strike (ground truth)")
        ax_s.set_xlabel("time (s)")
        ax_s.set_ylabel("S_M (cm)")
        ax_s.set_title(f"{behaviour} {cid}: D_l = {ex.signal.d_lower:.0f}, D_u = {ex.signal.d_upper:.0f}", fontsize=10)
        ax_s.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
        keys = ex.frames[: min(len(ex.frames), 7)]
        plot_key_frames(ax_k, m.positions(), m.skeleton.parents, keys, names=m.skeleton.names, fps=m.fps,
                        title=f"first {len(keys)} key frames of the {behaviour}")
    fig.suptitle("Ma 2010 Fig. 3: key frames at the local extrema of S_M(t)", fontsize=12)
    fig.tight_layout()
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)

    claims = []
    bound = o["fig3_phase_sd"]
    for behaviour, (sd, n, offset) in counts.items():
        claims.append(Claim(
            claim_id=f"{PAPER}.fig3.{behaviour}_keyframes_at_one_gait_phase", paper=PAPER, source="Fig. 3, Sec. 4.1-4.2",
            statement=f"The key frames (extrema of S_M(t)) of {behaviour}ing fall at the same gait phase in every "
                      "step, so they can segment and time-warp the motion.",
            published="each local extremum of S_M(t) is a key frame, used to cut and time-warp clips (no number given)",
            measured=f"circular SD of the maxima's phase within the step: {sd:.3f} of a step over {n} maxima; median "
                     f"offset from the nearest foot strike {offset * 1000:+.0f} ms",
            verdict=verdict_threshold(sd, bound, "<=", tolerance=1.0),
            note=f"Reproduced when the SD is at most {bound:g} of a step (partial: twice that; our bound, the paper gives "
                 f"none). Steps run from one foot strike (generator ground truth) to the next. {PROTOCOL}",
        ))
    write_claims(snakemake.output.claims, claims)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
