# Included first: a YAML syntax error in the default config file stops the run with the
# file and the line (Snakemake's own message names neither). Config files given with
# --configfile are read by Snakemake before this file; check them with
# `python tools/check_config.py FILE`.


from snakemake.exceptions import WorkflowError


def check_yaml_syntax(path):
    """Stop with ``path:line:column: problem`` when ``path`` is not valid YAML."""
    import yaml

    try:
        with open(path, encoding="utf-8") as fh:
            yaml.safe_load(fh)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark is not None else str(path)
        raise WorkflowError(f"Invalid configuration file {where}: {getattr(exc, 'problem', None) or exc}") from None
