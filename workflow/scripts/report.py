"""Rules dataset_report and stability_report: Snakemake's HTML report of the rule's inputs
only (`snakemake --report <output> <inputs>`, run on the same Snakefile and config), so each
report holds one dataset's results."""


def main(snakemake) -> None:
    import logging
    import os
    import subprocess
    import sys
    import tempfile

    import yaml

    with tempfile.TemporaryDirectory() as tmp:
        config = os.path.join(tmp, "config.yaml")
        with open(config, "w", encoding="utf-8") as f:
            yaml.safe_dump(dict(snakemake.config), f)
        command = [sys.executable, "-m", "snakemake", "--snakefile", snakemake.params.snakefile]
        command += ["--configfile", config, "--workflow-profile", "none", "--nolock"]
        command += ["--report", snakemake.output[0], *snakemake.input]
        env = {k: v for k, v in os.environ.items() if k != "SNAKEMAKE_PROFILE"}
        done = subprocess.run(command, capture_output=True, text=True, env=env)
    logging.info("%s\n%s%s", " ".join(command), done.stdout, done.stderr)
    if done.returncode or not os.path.isfile(snakemake.output[0]):
        raise RuntimeError(f"snakemake --report ended with status {done.returncode} (see the log)")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
