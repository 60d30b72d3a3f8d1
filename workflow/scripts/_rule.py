"""Shared by the rule scripts: log to the rule's ``log:`` file, and report bad input as
one clear line instead of a traceback.

Usage at the end of a rule script (``main`` takes the ``snakemake`` object)::

    if "snakemake" in globals():
        from _rule import run
        run(snakemake, main)

Errors that mean bad input (ValueError and its subclasses such as DatasetError,
OSError, KeyError) print ``ERROR rule <name>: <message>`` on the console and in the
log (with the traceback in the log only) and exit with status 1; Snakemake then removes
the rule's outputs. :class:`motionvar.claims.NotApplicable` from an evaluation (the data
lacks what it needs) writes the evaluation's not-applicable outputs instead. Any other
exception is a bug and propagates with its traceback.
It also selects matplotlib's file backend (Agg) for the script, and has glibc keep freed
memory for reuse (:func:`keep_freed_memory`).

Profiling: with the environment variable ``MOTIONVAR_PROFILE=DIR`` set, ``run`` wraps the
rule's ``main`` in cProfile and writes ``DIR/<rule>.prof`` (``pstats``/snakeviz format)
and ``DIR/<rule>.txt`` (the top 30 functions by cumulative time, and whether torch was
imported). A rule with wildcards besides ``dataset`` gets their values in the name
(``du2022_fda_curves.walk_leftStance_pca.prof``), so its jobs do not overwrite each
other. Without the variable nothing changes. Example::

    MOTIONVAR_PROFILE=/tmp/prof snakemake --cores 1 --forcerun du2022_table3_1 \
        -- results/synthetic/tables/du2022_table3_1.csv
"""

from __future__ import annotations

import logging
import os
import sys
import traceback
import warnings

from motionvar.claims import NotApplicable

BAD_INPUT = (ValueError, OSError, KeyError)


def run(snakemake, main) -> None:
    _file_backend()
    keep_freed_memory()
    with open(snakemake.log[0], "w") as log:
        logging.basicConfig(
            level=logging.INFO,
            format="%(asctime)s %(levelname)s %(message)s",
            handlers=[logging.StreamHandler(log)],
            force=True,
        )
        logging.captureWarnings(True)
        warnings.simplefilter("default")
        logging.info("rule %s, wildcards %s", snakemake.rule, dict(snakemake.wildcards.items()))
        try:
            _profiled(snakemake, main)
        except NotApplicable as exc:
            if not all(hasattr(snakemake.output, k) for k in ("table", "figure", "claims")):
                _fail(snakemake, log, f"not applicable to this dataset: {exc.reason}")
            logging.info("not applicable: %s", exc.reason)
            write_not_applicable(snakemake, exc.reason)
        except BAD_INPUT as exc:
            _fail(snakemake, log, str(exc))
        log_job_cpu()
        logging.info("done")


JOB_CPU = "job cpu"


def log_job_cpu() -> None:
    """Log the job's CPU time so far (user + system of this process, all its threads, and of
    its waited-for children) and its peak resident memory: ``job cpu <s> s (user <s>, system
    <s>), peak rss <MB> MB``. Snakemake's benchmark files sample the CPU time every 0.5 s for
    the first 15 s and then every 30 s, so a job's ``cpu_time`` there misses what it used
    after its last sample (up to 30 s); ``benchmarks/profile_rules.py`` reads this line
    instead where a job wrote it."""
    import resource

    own, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    user, system = own.ru_utime + kids.ru_utime, own.ru_stime + kids.ru_stime
    logging.info(
        "%s %.3f s (user %.3f, system %.3f), peak rss %.0f MB",
        JOB_CPU,
        user + system,
        user,
        system,
        max(own.ru_maxrss, kids.ru_maxrss) / 1024,
    )


MALLOC_KEEP_BYTES = 1 << 30
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3  # mallopt parameters, <malloc.h>


def keep_freed_memory(threshold: int = MALLOC_KEEP_BYTES) -> bool:
    """Have glibc serve blocks up to ``threshold`` bytes from its heap and keep freed memory
    for reuse (``mallopt`` M_MMAP_THRESHOLD and M_TRIM_THRESHOLD; either alone does not do
    it). By default every block over 128 KiB-32 MiB is a fresh ``mmap`` that the kernel
    zero-fills page by page and ``munmap`` returns at once: the fits' large temporaries
    (forward kinematics over all clips, autograd buffers, eigendecompositions) cost system
    time on every objective evaluation (docs/speed.md). The numbers computed do not change.
    False where the C library is not glibc (nothing is changed there)."""
    import ctypes
    import ctypes.util

    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    return bool(mallopt(_M_MMAP_THRESHOLD, threshold)) and bool(mallopt(_M_TRIM_THRESHOLD, threshold))


def _file_backend() -> None:
    """Figures are files; the library never chooses a backend. Agg through the environment
    when matplotlib is not imported yet, so that a job without figures does not import it."""
    if "matplotlib" in sys.modules:
        sys.modules["matplotlib"].use("Agg")
    else:
        os.environ["MPLBACKEND"] = "Agg"


PROFILE_ENV = "MOTIONVAR_PROFILE"


def profile_stem(snakemake) -> str:
    """File name stem of a job's profile: the rule's name, then the values of its
    wildcards other than ``dataset`` (``/`` and spaces made ``_``), joined by ``.``."""
    values = [str(v) for k, v in snakemake.wildcards.items() if k != "dataset"]
    stem = ".".join([str(snakemake.rule), "_".join(values)] if values else [str(snakemake.rule)])
    return stem.replace("/", "_").replace(" ", "_")


def _profiled(snakemake, main) -> None:
    """``main(snakemake)``, under cProfile when ``MOTIONVAR_PROFILE`` names a folder
    (module docstring); the profile is written even when ``main`` raises."""
    folder = os.environ.get(PROFILE_ENV)
    if not folder:
        main(snakemake)
        return
    import cProfile
    import io
    import pstats
    import time
    from pathlib import Path

    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    stem = profile_stem(snakemake)
    profiler = cProfile.Profile()
    start = time.perf_counter()
    try:
        profiler.runcall(main, snakemake)
    finally:
        wall = time.perf_counter() - start
        profiler.dump_stats(str(out / f"{stem}.prof"))
        text = io.StringIO()
        pstats.Stats(profiler, stream=text).sort_stats("cumulative").print_stats(30)
        header = (
            f"rule {snakemake.rule} ({stem}): main {wall:.2f} s wall; "
            f"torch imported: {'yes' if 'torch' in sys.modules else 'no'}\n"
        )
        (out / f"{stem}.txt").write_text(header + text.getvalue())
        logging.info("profile written to %s", out / f"{stem}.prof")


def _fail(snakemake, log, message: str) -> None:
    message = f"ERROR rule {snakemake.rule}: {message}"
    log.write(traceback.format_exc() + message + "\n")
    print(message, file=sys.stderr)
    sys.exit(1)


def config_settings(snakemake, section: str):
    """The settings object of config ``section`` (motionvar.config_sections: the one place its
    defaults are written) from the section's merged config the rule passes whole: as
    ``params.<section>`` where the rule reads a section beside its own, else ``params.settings``."""
    from motionvar.config_sections import section_settings

    params = snakemake.params
    return section_settings(section, getattr(params, section) if hasattr(params, section) else params.settings)


def dataset(path):
    """The packed dataset (motionvar.io) whose ``clips.npz`` (or ``metadata.csv``) is ``path``."""
    from pathlib import Path

    from motionvar.io import load_dataset

    return load_dataset(Path(path).parent)


def joint_map(snakemake):
    """The dataset's joint map: the YAML file its config names (``params.joint_map``), or the
    CMU rig's."""
    from motionvar.io.joint_map_file import rig_joint_map

    return rig_joint_map(snakemake.params.joint_map)


def write_not_applicable(snakemake, reason: str) -> None:
    """The evaluation's outputs when its input turns out insufficient (NotApplicable):
    each of its claims not applicable with ``reason``, a table and a figure saying so; further
    outputs of the rule (figures, GIFs, tables) say the same."""
    import matplotlib.pyplot as plt
    import numpy as np

    from motionvar.claim_catalog import specs_of
    from motionvar.claims import evaluation_source, not_applicable_result
    from motionvar.plots import write_gif
    from motionvar.plots.notice import draw_notice

    ev = snakemake.rule
    result = not_applicable_result(
        ev, f"Not applicable to dataset {snakemake.wildcards.dataset}: {reason}", specs_of(ev)
    )
    title = f"{evaluation_source(ev)} ({ev}): not applicable"
    write_evaluation(snakemake, result, lambda r: draw_notice(title, reason))
    written = {str(snakemake.output.table), str(snakemake.output.figure), str(snakemake.output.claims)}
    for path in (str(p) for p in snakemake.output if str(p) not in written):
        if path.endswith(".csv"):
            result.table.to_csv(path, index=False)
            continue
        fig = draw_notice(title, reason)
        if path.endswith(".gif"):
            fig.canvas.draw()
            write_gif(path, np.asarray(fig.canvas.buffer_rgba())[None, ..., :3], fps=1.0)
        else:
            fig.savefig(path)
        plt.close(fig)


def write_evaluation(snakemake, result, draw, dpi: int = 110, **to_csv) -> None:
    """Write an evaluation's outputs: ``result.table`` to ``output.table`` (CSV, no index,
    ``to_csv`` keyword arguments passed on), ``draw(result)`` (a matplotlib Figure) to
    ``output.figure`` (a notice with the reason for a not-applicable result), ``result.claims``
    to ``output.claims``."""
    import matplotlib.pyplot as plt

    from motionvar.claims import write_claims

    result.table.to_csv(snakemake.output.table, index=False, **to_csv)
    if result.figure.get("not_applicable"):  # an evaluation that found its input insufficient
        from motionvar.plots.notice import draw_notice

        fig = draw_notice(result.figure["title"], result.figure["reason"])
    else:
        fig = draw(result)
    fig.savefig(snakemake.output.figure, dpi=dpi)
    plt.close(fig)
    write_claims(snakemake.output.claims, result.claims)
