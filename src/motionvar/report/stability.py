"""Verdicts across synthetic populations (one dataset per seed): which claims hold when the
subjects are drawn again.

:func:`claims_stability` reads the merged claims table of each seed's run (columns of
:data:`motionvar.claims.CLAIM_COLUMNS`) and gives, per claim, the verdict of every seed, how
many seeds give the most common verdict, whether that is enough to call the claim
``stable`` (at least ``stable_share`` of the seeds; 4 of 5 by default), and the claim's
``value`` across seeds: mean, SD and the 95 % interval of the mean (Student t over the
seeds that measured it). A claim missing from a seed's table counts as a verdict of its
own ("missing"), so it can never look stable by absence.
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping

import numpy as np
import pandas as pd
from scipy import stats

from .counts import STABLE_SHARE, seed_bounds, seed_names

MISSING = "missing"


def _numbers(column: pd.Series) -> pd.Series:
    return pd.to_numeric(column.replace("", np.nan), errors="coerce")


def _mean_interval(values: np.ndarray, level: float = 0.95) -> tuple[float, float, float, float]:
    """Mean, SD and the Student-t interval of the mean of the finite ``values``."""
    v = values[np.isfinite(values)]
    if len(v) == 0:
        return (math.nan,) * 4
    mean = float(v.mean())
    if len(v) == 1:
        return mean, math.nan, math.nan, math.nan
    sd = float(v.std(ddof=1))
    half = float(stats.t.ppf(0.5 + level / 2, len(v) - 1)) * sd / math.sqrt(len(v))
    return mean, sd, mean - half, mean + half


def claims_stability(tables: Mapping[str, pd.DataFrame], stable_share: float = STABLE_SHARE) -> pd.DataFrame:
    """One row per claim seen in any of ``tables`` (seed name -> merged claims table): the
    claim's columns (claim_id, paper, source, kind, statement, unit, direction, bound), its
    verdict, n_agree, n_seeds, stable and the values' mean, SD and 95 % interval
    (value_mean, value_sd, value_ci_low, value_ci_high), then ``verdict_<seed>``, ``value_<seed>`` and
    ``bound_<seed>`` per seed in the order given (``bound`` is the first seed's; a bound measured
    on the data, such as a recorded reference, differs between seeds). ``verdict`` is the most
    common verdict (ties: the first seed's order), ``stable`` whether at least ``stable_share``
    of the seeds give it."""
    if not tables:
        raise ValueError("claims_stability: no claims tables")
    if not 0.0 < stable_share <= 1.0:
        raise ValueError(f"claims_stability: stable_share must be in (0, 1]; got {stable_share}")
    seeds = list(tables)
    indexed = {}
    for seed, t in tables.items():
        if t["claim_id"].duplicated().any():
            raise ValueError(f"claims_stability: seed {seed!r} lists a claim twice")
        t = t.set_index("claim_id")
        for col in ("value", "bound"):
            t[col] = _numbers(t[col]) if col in t else np.nan
        indexed[seed] = t
    ids = list(dict.fromkeys(cid for t in tables.values() for cid in t["claim_id"]))
    rows = []
    for cid in ids:  # loop over claims (tens)
        present = [indexed[s].loc[cid] for s in seeds if cid in indexed[s].index]
        first = present[0]
        verdicts = [indexed[s].loc[cid, "verdict"] if cid in indexed[s].index else MISSING for s in seeds]
        values = np.array(
            [indexed[s].loc[cid, "value"] if cid in indexed[s].index else np.nan for s in seeds], dtype=float
        )
        counts = pd.Series(verdicts).value_counts(sort=False)
        top = max(counts.index, key=lambda v: (counts[v], -verdicts.index(v)))
        mean, sd, low, high = _mean_interval(values)
        per_seed = [indexed[s].loc[cid, "bound"] if cid in indexed[s].index else np.nan for s in seeds]
        bounds = [float(b) for b in per_seed if np.isfinite(b)]
        row = {
            "claim_id": cid,
            "paper": first["paper"],
            "source": first["source"],
            "kind": first.get("kind", ""),
            "statement": first["statement"],
            "unit": first.get("unit", ""),
            "direction": first.get("direction", ""),
            "bound": bounds[0] if bounds else np.nan,
            "verdict": top,
            "n_agree": int(counts[top]),
            "n_seeds": len(seeds),
            "stable": bool(counts[top] >= stable_share * len(seeds) - 1e-9),
            "value_mean": mean,
            "value_sd": sd,
            "value_ci_low": low,
            "value_ci_high": high,
        }
        row.update({f"verdict_{s}": v for s, v in zip(seeds, verdicts)})
        row.update({f"value_{s}": v for s, v in zip(seeds, values)})
        row.update({f"bound_{s}": float(b) for s, b in zip(seeds, per_seed)})
        rows.append(row)
    return pd.DataFrame(rows).sort_values("claim_id", kind="stable").reset_index(drop=True)


def stability_html(table: pd.DataFrame, title: str = "Verdicts across seeds") -> str:
    """A report page of a :func:`claims_stability` table: the claims that are not stable
    first, then the stable ones; per seed its verdict and value."""
    esc = html.escape
    seeds = seed_names(table)
    n_unstable = int((~table["stable"].astype(bool)).sum())
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{esc(title)}</title>",
        "<style>body{font-family:-apple-system,Helvetica,Arial,sans-serif;margin:1.5em;color:#222}"
        "table{border-collapse:collapse;font-size:0.85em}th,td{border:1px solid #ccc;padding:0.3em 0.45em;"
        "vertical-align:top}th{background:#f0f0f0}.no{background:#f6d5cf}.yes{background:#d5ecd4}</style>",
        f"</head><body><h1>{esc(title)}</h1>",
        f"<p>{len(table)} claims over {len(seeds)} synthetic populations ({', '.join(map(esc, seeds))}); a claim is "
        f"stable when at least {math.ceil(STABLE_SHARE * len(seeds))} of {len(seeds)} seeds give the same verdict. "
        f"Not stable: {n_unstable}. Value: the number the verdict is computed from; interval: 95 % of the mean "
        "(Student t over the seeds).</p>",
        "<table><tr><th>claim</th><th>stable</th><th>verdict (agree)</th><th>value mean ± SD [95 %]</th><th>bound</th>"
        + "".join(f"<th>{esc(s)}</th>" for s in seeds)
        + "</tr>",
    ]
    order = table.assign(_s=table["stable"].astype(bool)).sort_values(["_s", "claim_id"], kind="stable")
    for r in order.to_dict("records"):
        unit = esc(r["unit"] if isinstance(r["unit"], str) else "")
        if not np.isfinite(r["value_mean"]):
            value = "-"
        elif not np.isfinite(r["value_sd"]):  # one seed measured it
            value = f"{r['value_mean']:.3g} {unit} (one seed)"
        else:
            value = (
                f"{r['value_mean']:.3g} ± {r['value_sd']:.2g} [{r['value_ci_low']:.3g}, {r['value_ci_high']:.3g}]"
                f" {unit}"
            )
        direction = r["direction"] if isinstance(r["direction"], str) else ""
        per_seed = seed_bounds(r, seeds)
        bound = "-" if not np.isfinite(r["bound"]) else f"{esc(direction)} {r['bound']:.3g}"
        if per_seed is not None:  # measured on each seed's data: given in each seed's cell
            bound = f"{esc(direction)} measured per seed"
        cells = "".join(
            f"<td>{esc(str(r[f'verdict_{s}']))}"
            + (f"<br>{r[f'value_{s}']:.3g}" if np.isfinite(r[f"value_{s}"]) else "")
            + (f" ({esc(direction)} {b:.3g})" if per_seed is not None and np.isfinite(b) else "")
            + "</td>"
            for s, b in zip(seeds, per_seed if per_seed is not None else [np.nan] * len(seeds))
        )
        parts.append(
            f"<tr><td>{esc(r['source'])}<br><small>{esc(r['claim_id'])}</small></td>"
            f'<td class="{"yes" if r["stable"] else "no"}">{"stable" if r["stable"] else "not stable"}</td>'
            f"<td>{esc(r['verdict'])} ({r['n_agree']}/{r['n_seeds']})</td><td>{value}</td><td>{bound}</td>{cells}</tr>"
        )
    parts.append("</table></body></html>")
    return "\n".join(parts) + "\n"
