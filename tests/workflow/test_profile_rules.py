"""benchmarks/profile_rules.py (per-rule cost from Snakemake's benchmark TSVs) and the
cProfile hook of workflow/scripts/_rule.run (MOTIONVAR_PROFILE)."""

from __future__ import annotations

import importlib.util
import pstats
from pathlib import Path

import pandas as pd
import pytest
from rule_scripts import FakeSnakemake, Named, rule_module

ROOT = Path(__file__).resolve().parents[2]
HEADER = "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"


def _profile_rules():
    spec = importlib.util.spec_from_file_location("profile_rules", ROOT / "benchmarks" / "profile_rules.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _write(path: Path, *rows: tuple[float, float, float]) -> None:
    """A benchmark TSV in Snakemake's format; rows of (wall s, max_rss MB, cpu s)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    lines = [f"{s}\t0:00:00\t{rss}\t0\t0\t0\t0\t0\t50.0\t{cpu}\n" for s, rss, cpu in rows]
    path.write_text(HEADER + "".join(lines))


@pytest.fixture
def two_runs(tmp_path):
    after, before = tmp_path / "after" / "synthetic", tmp_path / "before" / "synthetic"
    _write(after / "benchmarks" / "data.tsv", (10.0, 500.0, 8.0))
    _write(after / "benchmarks" / "fit" / "a.tsv", (30.0, 900.0, 20.0))
    _write(after / "benchmarks" / "fit" / "b.tsv", (20.0, 700.0, 12.0), (22.0, 800.0, 14.0))  # two repeats
    _write(after / "benchmarks" / "plot.tsv", (2.0, 100.0, 1.0))
    _write(before / "benchmarks" / "data.tsv", (10.0, 400.0, 16.0))
    _write(before / "benchmarks" / "old_fit" / "a.tsv", (60.0, 900.0, 50.0))
    (before / "benchmarks" / "gone.tsv").write_text(HEADER + "1.0\t0:00:01\tNA\tNA\tNA\tNA\tNA\tNA\tNA\tNA\n")
    return after, before


def test_per_rule_sums_jobs_and_sorts_by_cpu(two_runs):
    pr = _profile_rules()
    after, _ = two_runs
    jobs = pr.read_jobs(after)
    assert len(jobs) == 4
    b = jobs[(jobs["rule"] == "fit") & (jobs["job"] == "b")].iloc[0]
    assert b["cpu_s"] == pytest.approx(13.0) and b["wall_s"] == pytest.approx(21.0)  # mean of the repeats
    table = pr.with_total(pr.per_rule(jobs))
    assert list(table["rule"]) == ["fit", "data", "plot", "TOTAL"]
    fit = table.iloc[0]
    assert fit["jobs"] == 2 and fit["cpu_s"] == pytest.approx(33.0) and fit["wall_s"] == pytest.approx(51.0)
    assert fit["max_rss_mb"] == pytest.approx(900.0)
    total = table.iloc[-1]
    assert total["jobs"] == 4 and total["cpu_s"] == pytest.approx(42.0) and total["max_rss_mb"] == 900.0
    # the same from a results/ folder, a benchmarks folder, and the dataset folder
    assert pr.read_jobs(after.parent)["cpu_s"].sum() == pytest.approx(42.0)
    assert pr.read_jobs(after / "benchmarks")["cpu_s"].sum() == pytest.approx(42.0)


def test_compare_gives_before_after_and_ratios(two_runs, tmp_path, capsys):
    pr = _profile_rules()
    after, before = two_runs
    out = tmp_path / "cmp.csv"
    assert pr.main([str(after), "--compare", str(before), "--rename", "old_fit=fit", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "cpu_s_ratio" in printed and "TOTAL" in printed
    table = pd.read_csv(out).set_index("rule")
    assert table.loc["fit", "cpu_s_before"] == pytest.approx(50.0)
    assert table.loc["fit", "cpu_s_after"] == pytest.approx(33.0)
    assert table.loc["fit", "cpu_s_ratio"] == pytest.approx(0.66)
    assert table.loc["data", "cpu_s_ratio"] == pytest.approx(0.5)
    assert table.loc["data", "max_rss_mb_ratio"] == pytest.approx(1.25)
    assert pd.isna(table.loc["plot", "cpu_s_before"]) and pd.isna(table.loc["gone", "cpu_s_after"])
    assert pd.isna(table.loc["gone", "cpu_s_before"])  # NA in the file: missing, not zero
    assert table.loc["TOTAL", "cpu_s_before"] == pytest.approx(66.0)
    assert table.loc["TOTAL", "cpu_s_after"] == pytest.approx(42.0)
    assert table.loc["TOTAL", "cpu_s_ratio"] == pytest.approx(42.0 / 66.0)
    assert list(table.index[:3]) == ["fit", "data", "plot"]  # by CPU time after


def test_job_cpu_comes_from_the_jobs_log_line(two_runs, tmp_path):
    """Snakemake's cpu_time is its last 0.5 s / 30 s sample; the job's own end-of-job line
    (``job cpu ...``, written by _rule.run) is read as job_cpu_s, beside it."""
    pr = _profile_rules()
    after, before = two_runs
    (after / "logs" / "fit").mkdir(parents=True)
    (after / "logs" / "data.log").write_text(
        "x INFO rule data\nx INFO job cpu 9.500 s (user 9, system 0.5), peak rss 500 MB\nx INFO done\n"
    )
    (after / "logs" / "fit" / "a.log").write_text("x INFO job cpu 1.0 s\nx INFO job cpu 31.250 s (user 30)\n")
    (after / "logs" / "fit" / "b.log").write_text("x INFO an older run: no line\n")
    jobs = pr.read_jobs(after).set_index(["rule", "job"])
    assert jobs.loc[("data", ""), "job_cpu_s"] == pytest.approx(9.5)
    assert jobs.loc[("fit", "a"), "job_cpu_s"] == pytest.approx(31.25)  # the last line
    assert pd.isna(jobs.loc[("fit", "b"), "job_cpu_s"]) and pd.isna(jobs.loc[("plot", ""), "job_cpu_s"])
    table = pr.with_total(pr.per_rule(jobs.reset_index())).set_index("rule")
    assert table.loc["fit", "job_cpu_s"] == pytest.approx(31.25) and pd.isna(table.loc["plot", "job_cpu_s"])
    assert table.loc["TOTAL", "job_cpu_s"] == pytest.approx(40.75)
    assert list(table.index[:2]) == ["fit", "data"]  # sorted by the jobs' own CPU time
    cmp = pr.with_total(pr.compare(pr.per_rule(jobs.reset_index()), pr.per_rule(pr.read_jobs(before))))
    assert cmp.set_index("rule").loc["data", "job_cpu_s_after"] == pytest.approx(9.5)
    assert pd.isna(cmp.set_index("rule").loc["data", "job_cpu_s_before"])


def test_rule_run_logs_the_jobs_cpu_time(tmp_path, monkeypatch):
    import resource

    def cpu() -> float:  # this process and its waited-for children, as the rule logs it
        own, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
        return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime

    monkeypatch.delenv("MOTIONVAR_PROFILE", raising=False)
    before = cpu()
    rule_module().run(_job(tmp_path), _main)
    after = cpu()
    logged = _profile_rules().read_job_cpu(tmp_path / "some_rule.log")
    assert 0 < before - 0.01 <= logged <= after + 0.01  # this test process's CPU time so far


def test_bad_input_is_one_line(tmp_path, capsys):
    pr = _profile_rules()
    assert pr.main([str(tmp_path / "nowhere")]) == 1
    assert "no such folder" in capsys.readouterr().err
    (tmp_path / "benchmarks").mkdir()
    (tmp_path / "benchmarks" / "x.tsv").write_text("a\tb\n1\t2\n")
    assert pr.main([str(tmp_path)]) == 1
    assert "not a Snakemake benchmark file" in capsys.readouterr().err


def _job(tmp_path, **wildcards):
    return FakeSnakemake(tmp_path, "some_rule", wildcards=Named(dataset="synthetic", **wildcards))


def _main(snakemake):
    sum(i * i for i in range(20000))


def test_profile_hook_writes_a_profile_per_job(tmp_path, monkeypatch):
    run = rule_module().run
    folder = tmp_path / "prof"
    monkeypatch.setenv("MOTIONVAR_PROFILE", str(folder))
    run(_job(tmp_path), _main)
    run(_job(tmp_path, primitive="walk", part="pca"), _main)
    assert sorted(p.name for p in folder.iterdir()) == [
        "some_rule.prof",
        "some_rule.txt",
        "some_rule.walk_pca.prof",
        "some_rule.walk_pca.txt",
    ]
    stats = pstats.Stats(str(folder / "some_rule.prof"))
    assert any(func[2] == "_main" for func in stats.stats)
    text = (folder / "some_rule.txt").read_text()
    assert text.startswith("rule some_rule") and "torch imported:" in text and "cumulative" in text


def test_profile_hook_off_without_the_variable(tmp_path, monkeypatch):
    monkeypatch.delenv("MOTIONVAR_PROFILE", raising=False)
    rule_module().run(_job(tmp_path), _main)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["some_rule.log"]


def test_profile_written_when_main_fails(tmp_path, monkeypatch):
    folder = tmp_path / "prof"
    monkeypatch.setenv("MOTIONVAR_PROFILE", str(folder))

    def bad(snakemake):
        raise ValueError("bad input file x.csv")

    with pytest.raises(SystemExit):
        rule_module().run(_job(tmp_path), bad)
    assert (folder / "some_rule.prof").is_file()
