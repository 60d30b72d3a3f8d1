"""Per-rule cost of a finished pipeline run, from Snakemake's benchmark files.

Every rule writes ``results/<dataset>/benchmarks/<rule>.tsv`` (or
``benchmarks/<rule>/<wildcards>.tsv`` for a rule with further wildcards), one file per job,
in Snakemake's benchmark format: a header and one row per repeat with the columns

    s  h:m:s  max_rss  max_vms  max_uss  max_pss  io_in  io_out  mean_load  cpu_time

(``s``: wall seconds; ``max_*``: peak memory in MB of the job's process tree; ``io_*``: MB
read/written; ``mean_load``: mean CPU use in percent of one core; ``cpu_time``: user +
system CPU seconds of the process tree). A value Snakemake could not measure (a job that
ended before the first sample) is ``NA``; it counts as missing, not as zero.

Snakemake samples a job's CPU time every 0.5 s for its first 15 s and then every 30 s, and
``cpu_time`` is the last sample: a job of 30 s shows about 15 CPU-s. So every rule script
also logs its own total at its end (``workflow/scripts/_rule.log_job_cpu``: a line
``job cpu <s> s ...`` in ``results/<dataset>/logs/<rule>[/<wildcards>].log``), read here as
``job_cpu_s`` (missing for a run older than that line, or a job without the line); use it,
not ``cpu_s``, to compare runs that have it.

This script sums them per rule (jobs, CPU seconds, wall seconds, the largest peak
resident memory), sorted by CPU time, with a total row; with ``--compare`` it puts a
second run beside it (columns ``*_before`` from the other run, ``*_after`` from this one,
and their ratios after/before)::

    python benchmarks/profile_rules.py results/synthetic
    python benchmarks/profile_rules.py results/synthetic --compare old/results/synthetic --out cmp.csv
    python benchmarks/profile_rules.py results/synthetic --jobs      # one row per job instead of per rule

A rule renamed between the two runs is matched with ``--rename OLD=NEW`` (repeatable;
applied to the ``--compare`` run), e.g. ``--rename graph_primitive=du2022_graph_primitive``.

RESULTS_DIR is a dataset's results folder (``results/<dataset>``), its ``benchmarks``
folder, or ``results/`` itself (all datasets, rules named ``<dataset>:<rule>`` when there
are several).
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import numpy as np
import pandas as pd

COLUMNS = {"s": "wall_s", "cpu_time": "cpu_s", "max_rss": "max_rss_mb", "mean_load": "mean_load_pct"}


def benchmark_folders(results_dir: str | Path) -> dict[str, Path]:
    """{dataset (or "") -> benchmarks folder} below ``results_dir`` (module docstring)."""
    d = Path(results_dir)
    if not d.is_dir():
        raise FileNotFoundError(f"{d}: no such folder")
    if d.name == "benchmarks":
        return {"": d}
    if (d / "benchmarks").is_dir():
        return {"": d / "benchmarks"}
    found = {p.parent.name: p for p in sorted(d.glob("*/benchmarks")) if p.is_dir()}
    if not found:
        raise FileNotFoundError(f"{d}: no benchmarks folder (expected {d}/benchmarks or {d}/<dataset>/benchmarks)")
    return found


def read_benchmark(path: Path) -> dict[str, float]:
    """Wall s, CPU s, peak RSS MB, mean load % of one benchmark TSV (the mean over its
    repeats; NaN where Snakemake wrote NA or the file has no row)."""
    table = pd.read_csv(path, sep="\t", na_values=["NA", "-"])
    missing = [c for c in COLUMNS if c not in table.columns]
    if missing:
        raise ValueError(f"{path}: not a Snakemake benchmark file (no column {', '.join(missing)})")
    return {
        name: float(pd.to_numeric(table[col], errors="coerce").mean()) if len(table) else np.nan
        for col, name in COLUMNS.items()
    }


JOB_CPU_LINE = re.compile(r"job cpu ([0-9.]+) s")


def read_job_cpu(log: Path) -> float:
    """The CPU seconds a job logged at its end (module docstring); NaN without the line."""
    try:
        found = JOB_CPU_LINE.findall(log.read_text(errors="replace"))
    except OSError:
        return np.nan
    return float(found[-1]) if found else np.nan


def read_jobs(results_dir: str | Path) -> pd.DataFrame:
    """One row per job: ``rule``, ``job`` (the wildcards part of the path, "" for none), the
    measures of :func:`read_benchmark` and ``job_cpu_s`` (:func:`read_job_cpu` of the job's
    log, ``logs/`` beside ``benchmarks/`` with the same relative path)."""
    folders = benchmark_folders(results_dir)
    rows = []
    for dataset, folder in folders.items():
        prefix = f"{dataset}:" if len(folders) > 1 else ""
        for path in sorted(folder.rglob("*.tsv")):
            rel = path.relative_to(folder).with_suffix("")
            rule = prefix + rel.parts[0]
            job_cpu = read_job_cpu(folder.parent / "logs" / rel.with_suffix(".log"))
            rows.append({"rule": rule, "job": "/".join(rel.parts[1:]), **read_benchmark(path), "job_cpu_s": job_cpu})
    if not rows:
        raise FileNotFoundError(f"{results_dir}: no benchmark files (*.tsv)")
    return pd.DataFrame(rows)


def per_rule(jobs: pd.DataFrame) -> pd.DataFrame:
    """Sum per rule (jobs, CPU s, wall s; largest peak RSS), sorted by CPU time (largest
    first), without the total row."""
    table = jobs.groupby("rule").agg(
        jobs=("job", "size"),
        cpu_s=("cpu_s", lambda x: x.sum(min_count=1)),
        job_cpu_s=("job_cpu_s", lambda x: x.sum(min_count=1)),
        wall_s=("wall_s", lambda x: x.sum(min_count=1)),
        max_rss_mb=("max_rss_mb", "max"),
    )
    first = "job_cpu_s" if table["job_cpu_s"].notna().any() else "cpu_s"
    return table.sort_values([first, "wall_s"], ascending=False, na_position="last").reset_index()


def with_total(table: pd.DataFrame) -> pd.DataFrame:
    """``table`` plus a row ``TOTAL``: sums of jobs, CPU and wall seconds, largest peak RSS
    (and ratios of the totals for a comparison)."""
    total = {"rule": "TOTAL"}
    for col in table.columns:
        if col == "rule":
            continue
        if col.startswith("max_rss_mb"):
            total[col] = table[col].max()
        elif col.startswith(("jobs", "cpu_s", "job_cpu_s", "wall_s")):
            total[col] = table[col].sum(min_count=1)
    for measure in MEASURES:
        if f"{measure}_ratio" in table.columns:
            total[f"{measure}_ratio"] = _ratio(total[f"{measure}_after"], total[f"{measure}_before"])
    return pd.concat([table, pd.DataFrame([total])], ignore_index=True)


MEASURES = ("cpu_s", "job_cpu_s", "wall_s", "max_rss_mb")


def _ratio(after, before):
    """after / before as floats (NaN where before is missing or not positive)."""
    a, b = np.asarray(after, dtype=float), np.asarray(before, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(b > 0, a / b, np.nan)
    return float(out) if out.ndim == 0 else out


def renamed(jobs: pd.DataFrame, renames: list[str]) -> pd.DataFrame:
    """``jobs`` with rules renamed by ``OLD=NEW`` items."""
    mapping = {}
    for item in renames:
        old, sep, new = item.partition("=")
        if not sep or not old or not new:
            raise ValueError(f"--rename {item!r}: expected OLD=NEW")
        mapping[old] = new
    return jobs.assign(rule=jobs["rule"].replace(mapping))


def compare(after: pd.DataFrame, before: pd.DataFrame) -> pd.DataFrame:
    """Per-rule tables of two runs side by side (outer join on the rule: a rule only one run
    has gets blanks in the other), ratios after/before, sorted by CPU time after (then
    before)."""
    merged = before.merge(after, on="rule", how="outer", suffixes=("_before", "_after"))
    for col in ("jobs_before", "jobs_after"):
        merged[col] = merged[col].astype("Int64")
    for measure in MEASURES:
        merged[f"{measure}_ratio"] = _ratio(merged[f"{measure}_after"], merged[f"{measure}_before"])
    order = ["rule", "jobs_before", "jobs_after"] + [
        f"{measure}_{part}" for measure in MEASURES for part in ("before", "after", "ratio")
    ]
    first = "job_cpu_s" if merged["job_cpu_s_after"].notna().any() else "cpu_s"
    merged = merged[order].sort_values([f"{first}_after", f"{first}_before"], ascending=False, na_position="last")
    return merged.reset_index(drop=True)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results_dir", help="results/<dataset> (or its benchmarks folder, or results/)")
    parser.add_argument("--compare", metavar="OTHER_RESULTS_DIR", help="the run to compare with (the 'before')")
    parser.add_argument("--out", metavar="CSV", help="also write the table to this CSV file")
    parser.add_argument("--jobs", action="store_true", help="one row per job instead of per rule")
    parser.add_argument(
        "--rename",
        action="append",
        default=[],
        metavar="OLD=NEW",
        help="a rule of the --compare run named NEW in this run (repeatable)",
    )
    args = parser.parse_args(argv)
    try:
        jobs = read_jobs(args.results_dir)
        if args.jobs:
            first = "job_cpu_s" if jobs["job_cpu_s"].notna().any() else "cpu_s"
            table = jobs.sort_values(first, ascending=False, na_position="last").reset_index(drop=True)
            table = pd.concat(
                [
                    table,
                    pd.DataFrame(
                        [
                            {
                                "rule": "TOTAL",
                                "job": f"{len(jobs)} jobs",
                                "cpu_s": jobs["cpu_s"].sum(),
                                "job_cpu_s": jobs["job_cpu_s"].sum(min_count=1),
                                "wall_s": jobs["wall_s"].sum(),
                                "max_rss_mb": jobs["max_rss_mb"].max(),
                            }
                        ]
                    ),
                ],
                ignore_index=True,
            )
        elif args.compare:
            before = renamed(read_jobs(args.compare), args.rename)
            table = with_total(compare(per_rule(jobs), per_rule(before)))
        else:
            table = with_total(per_rule(jobs))
    except (OSError, ValueError) as exc:
        print(f"profile_rules: {exc}", file=sys.stderr)
        return 1
    with pd.option_context("display.max_rows", None, "display.width", 200, "display.max_columns", None):
        print(table.to_string(index=False, float_format=lambda v: f"{v:.2f}", na_rep="-"))
    if args.out:
        table.to_csv(args.out, index=False, float_format="%.6g")
    return 0


if __name__ == "__main__":
    sys.exit(main())
