# Shared helpers, included first by the Snakefile (see workflow/README.md): config
# validation, datasets and their inputs, path conventions, report categories and the
# evaluation registry. Functions live here (or in a paper's own helper .smk without
# rules): `snakemake --lint` flags a file that mixes rules and functions.

import os
import re
from dataclasses import dataclass, field

import jsonschema
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

ENV = "../envs/motionvar.yaml"


PAPER_CATEGORY = {
    "data": "Data",
    "ma2010": "Ma et al. 2010",
    "du2022": "Du 2022",
    "egges2004": "Egges et al. 2004",
}
SUMMARY_CATEGORY = "Summary"

# outputs of rule claims_stability (stability.smk), in the default target when config
# stability.datasets names the datasets of a seeds run (config/seeds.yaml)
STABILITY = config.get("stability", {}).get("folder", "results/stability")
STABILITY_CSV = f"{STABILITY}/claims_stability.csv"
STABILITY_OUTPUTS = [STABILITY_CSV, f"{STABILITY}/claims_stability.png", f"{STABILITY}/claims_stability.html"]
STABILITY_REPORT = f"reports/{os.path.basename(STABILITY)}.html"

# Scheduling (`priority:` of the rules on the run's long chains; every other rule has 0). On a
# few cores the wall time is set by when the long chains start: left to input sizes, the
# scheduler started the style chain 1,675 s into a 2,106 s full run, and the CI run ended
# with 56 s of one job at a time. Among the jobs that are ready, Snakemake starts the highest
# priority first. Order: the length of the chain of jobs that follows, in the CPU seconds of
# a full run's benchmark files (Du ch. 3: canonical primitives -> basis -> reference SFPCA ->
# SFPCA curve, ~400 s; Du ch. 5: autoencoder -> VAE -> CVAE -> Table 5.2, ~240 s), except the
# autoencoder, which comes first: it takes both cores (it trains on two threads, pinned:
# style.training.AUTOENCODER_THREADS), and a two-core job starts only while no one-core job
# holds a core: right after the applicability checkpoint, when nothing runs, rather than
# last. The default profile's greedy scheduler starts jobs in this order; the ILP scheduler
# would weigh two lower priorities together against one higher (measured: it started two
# one-core jobs before the autoencoder).
PRIORITY = {
    "du2022_style_autoencoder": 100,
    "du2022_fda_canonical": 90,
    "du2022_fda_basis": 80,
    "du2022_fda_sfpca": 70,
    "du2022_fda_curves": 60,
    "du2022_style_vae": 50,
    "du2022_table3_1": 40,
    "du2022_style_cvae": 30,
    "du2022_graph_primitive": 20,
}

# Every published evaluation is one declaration in its paper's package (motionvar.<paper>.catalog:
# its name, source, config section, input set, measuring and drawing functions; read here through
# motionvar.claim_catalog.EVALUATIONS, in the claims table's order); evaluations.smk makes one
# rule of each. The paper rule files add the files of each input set (INPUT_SETS) and, for the
# few evaluations that write or bring more than their table, figure and claims, those outputs
# (EVALUATION_ADDITIONS).
from motionvar.claim_catalog import EVALUATIONS as _DECLARED
from motionvar.ma2010.settings import Ma2010Settings

# name -> the library's declaration (motionvar.claims.Evaluation)
EVALUATIONS = {e.name: e for e in _DECLARED}
# input set (Evaluation.inputs) -> {input name: path pattern or input function}; loaded for the
# rule's measuring function by workflow/scripts/_evaluation.py (LOADERS)
INPUT_SETS = {}
# evaluation name -> RuleAdditions
EVALUATION_ADDITIONS = {}

# Config keys that were renamed: old dotted key -> new one (a config that still uses the old
# key stops with a message naming the new one).
RENAMED_CONFIG_KEYS = {
    "idle": "egges2004",
    "fda": "du2022_fda",
    "graph": "du2022_graph",
    "style": "du2022_style",
    # Ma 2010's former keys: its flat section's and older names (Ma2010Settings.RENAMED, nested)
    **Ma2010Settings.renamed_keys(),
}


def _config_error(err):
    """One line naming the config key and what is wrong with it."""
    key = ".".join(str(p) for p in err.absolute_path) or "(top level)"
    if err.validator == "additionalProperties" and isinstance(err.instance, dict):
        known = set(err.schema.get("properties", {}))
        unknown = sorted(set(err.instance) - known)
        where = f"{key}." if err.absolute_path else ""
        return (
            f"unknown config key(s) {', '.join(where + k for k in unknown)} "
            f"(allowed here: {', '.join(sorted(known)) or 'none'})"
        )
    return f"config key {key}: {err.message}"


def validate_config(schema_path):
    """Validate ``config`` against the schema (filling defaults); stop with a message
    naming the offending key. Also checks what a schema cannot: run_datasets names
    configured datasets, and no key is one that was renamed (RENAMED_CONFIG_KEYS)."""
    for old, new in RENAMED_CONFIG_KEYS.items():
        node, parts = config, old.split(".")
        for part in parts[:-1]:
            node = node.get(part) if isinstance(node, dict) else None
        if isinstance(node, dict) and parts[-1] in node:
            raise WorkflowError(f"Invalid configuration: config key {old} is now {new}")
    try:
        validate(config, schema_path)
    except WorkflowError as exc:
        cause = exc.__context__
        if isinstance(cause, jsonschema.ValidationError):
            raise WorkflowError(f"Invalid configuration: {_config_error(cause)}") from None
        raise
    for key, names in (("run_datasets", config["run_datasets"]), ("stability.datasets", stability_datasets())):
        missing = [d for d in names if d not in config["datasets"]]
        if missing:
            raise WorkflowError(
                f"Invalid configuration: {key} names {missing}, not in datasets "
                f"({', '.join(config['datasets'])})"
            )
    if len(stability_datasets()) == 1:
        raise WorkflowError("Invalid configuration: stability.datasets needs at least 2 datasets (one per seed)")


def stability_table_of(dataset):
    """The claims-stability table that marks ``dataset``'s verdicts in its summary: this config's
    (rule claims_stability) where its seeds include the dataset, else the earlier run's that
    config key stability.marks names, where that file exists; "" for none."""
    if dataset in stability_datasets():
        return STABILITY_CSV
    marks = config.get("stability", {}).get("marks", "")
    return marks if marks and os.path.isfile(marks) else ""


def stability_datasets():
    """The datasets of a claims-stability run (config key stability.datasets; [] for none)."""
    return list(config.get("stability", {}).get("datasets", []))


def run_datasets():
    """The datasets the default target builds (config key run_datasets)."""
    return list(config["run_datasets"])


def dataset_config(dataset):
    """The config entry of one dataset (defaults filled by the schema)."""
    return config["datasets"][dataset]


def joint_map_path(dataset):
    """The dataset's joint map YAML, or None for the CMU rig (motionvar.core.cmu_joint_map)."""
    return dataset_config(dataset).get("joint_map")


def joint_map_input(wildcards):
    """Input function: the dataset's joint map file, if it has one (so edits rerun)."""
    path = joint_map_path(wildcards.dataset)
    return [path] if path else []


def dataset_pattern():
    """Regex of the configured dataset names (the {dataset} wildcard constraint)."""
    return "|".join(re.escape(d) for d in config["datasets"])


def data_input(wildcards):
    """Input function of the data rule: a BVH dataset's files (labels, BVH files, joint map),
    so that edits rerun the import; nothing for the synthetic generator (its config
    entry is a param). The BVH files are those the import may read: every file in the
    folder and its subfolders whose name ends in .bvh in any case, linked subfolders not
    followed: the files of motionvar.io.bvh_dataset.bvh_files, whose import refuses labels
    naming any other file (written again here: the Snakemake process does not import the
    package, which conda deployment puts in the jobs' environment only; a test holds the two
    equal)."""
    entry = dataset_config(wildcards.dataset)
    if entry["source"] != "bvh":
        return []
    folder = entry["path"]
    if not os.path.isdir(folder):
        raise WorkflowError(f"datasets.{wildcards.dataset}.path: BVH folder {folder} not found")
    labels = entry["labels"] if os.path.isabs(entry["labels"]) else os.path.join(folder, entry["labels"])
    bvh = sorted(
        os.path.join(root, f) for root, _, files in os.walk(folder) for f in files if f.lower().endswith(".bvh")
    )
    return [labels, *bvh, *joint_map_input(wildcards)]


# Paths (workflow/README.md). Data and preprocessed clips of a dataset:
DATA = "results/{dataset}/data"
PREP = "results/{dataset}/prep"


def ev_table(ev):
    return f"results/{{dataset}}/tables/{ev}.csv"


def ev_figure(ev):
    return f"results/{{dataset}}/figures/{ev}.png"


def ev_claims(ev):
    return f"results/{{dataset}}/claims/{ev}.json"


def ev_log(rule_name, extra=""):
    """Log of a rule; ``extra`` names further wildcards, e.g. "{k}" -> logs/rule/{k}.log."""
    if extra:
        return f"results/{{dataset}}/logs/{rule_name}/{extra}.log"
    return f"results/{{dataset}}/logs/{rule_name}.log"


def ev_benchmark(rule_name, extra=""):
    """Benchmark of a rule: benchmarks/{rule}.tsv, or benchmarks/{rule}/{extra}.tsv for a
    rule with wildcards beyond {dataset} (the end-to-end test checks one per rule)."""
    if extra:
        return f"results/{{dataset}}/benchmarks/{rule_name}/{extra}.tsv"
    return f"results/{{dataset}}/benchmarks/{rule_name}.tsv"


# GIF path pattern -> (page rule, category, caption, labels): the report shows HTML pages of them
# (rules gif_page_* in report.smk), since Snakemake's report cannot display a GIF itself.
GIF_PAGES = {}


def in_report(path, paper, caption, page="", **labels):
    """``path`` as a report output of ``paper`` (a key of PAPER_CATEGORY, or "summary"),
    subcategory the dataset, with ``labels`` shown as columns of the report's table.

    A ``.gif`` stays a plain output; the report gets ``<path>.html``, a page that plays
    it (same caption, category and labels), built by rule ``page`` (``gif_page_<what>``, made
    in report.smk) and added to the default target."""
    category = SUMMARY_CATEGORY if paper == "summary" else PAPER_CATEGORY[paper]
    if path.endswith(".gif"):
        if path in GIF_PAGES:
            raise ValueError(f"{path} given to in_report twice")
        if not page.startswith("gif_page_"):
            raise ValueError(f"{path}: a GIF needs the name of its page's rule, page='gif_page_<what>'")
        GIF_PAGES[path] = (page, category, caption, labels)
        return path
    return report(
        path, caption=caption, category=category, subcategory="{dataset}",
        labels={"dataset": "{dataset}", **labels} if labels else None,
    )


def gif_pages(dataset):
    """The report pages of the GIFs whose paths vary only with the dataset and that no
    evaluation owns (those come with their evaluation: evaluation_outputs)."""
    owned = {p for ev in EVALUATIONS for p in evaluation_extra(ev)}
    return [
        f"{p}.html".format(dataset=dataset) for p in GIF_PAGES
        if p not in owned and re.fullmatch(r"[^{}]*(\{dataset\}[^{}]*)*", p)
    ]


def section_for(section, rule="", only=()):
    """Config section ``section`` as it is given to the rule named ``rule`` (``params.settings``),
    without the keys that other evaluations own (``Evaluation.own_keys``), so that an edit of such
    a key reruns its evaluation alone; with ``only``, just those keys (a stage that reads one
    subsection). The rule's settings class fills what is left out with its defaults, which the
    rule never reads."""
    if only:
        return {k: v for k, v in config[section].items() if k in only}
    owned = {k for e in EVALUATIONS.values() if e.section == section and e.name != rule for k in e.own_keys}
    return {k: v for k, v in config[section].items() if k not in owned}


def add_input_set(name, files):
    """The files of input set ``name`` (a declaration's ``inputs``): {input name: path pattern or
    input function}. An input named ``joint_map`` brings the map's path as a param too."""
    if name in INPUT_SETS:
        raise ValueError(f"input set {name} added twice")
    INPUT_SETS[name] = files


@dataclass(frozen=True)
class RuleAdditions:
    """What the rule of a declared evaluation writes or brings besides its table, figure and
    claims: ``outputs`` (name -> path, already given to ``in_report`` where the report shows
    them; the evaluation's own script, workflow/scripts/<name>.py, writes them), ``params``,
    and ``extra``: files of other rules that join the default target with the evaluation."""

    outputs: dict = field(default_factory=dict)
    params: dict = field(default_factory=dict)
    extra: tuple = ()


def add_to_evaluation(name, **additions):
    """RuleAdditions (outputs, params, extra) for the rule of declared evaluation ``name``."""
    if name not in EVALUATIONS:
        raise ValueError(f"{name}: no such evaluation is declared (motionvar.<paper>.catalog)")
    if name in EVALUATION_ADDITIONS:
        raise ValueError(f"evaluation {name} given additions twice")
    EVALUATION_ADDITIONS[name] = RuleAdditions(**additions)


def evaluation_input(ev):
    """The files of a declared evaluation's input set (WorkflowError naming it when no rule
    file adds that set)."""
    d = EVALUATIONS[ev]
    if d.inputs not in INPUT_SETS:
        raise WorkflowError(f"evaluation {ev}: no rule file adds its input set {d.inputs!r} (add_input_set)")
    return INPUT_SETS[d.inputs]


def evaluation_extra(name):
    """The further outputs that join the default target with evaluation ``name``."""
    add = EVALUATION_ADDITIONS.get(name, RuleAdditions())
    return [str(p) for p in [*add.extra, *(p for p in add.outputs.values() if str(p).endswith(".gif"))]]


# Applicability (rules/applicability.smk): checkpoint applicability decides from a
# dataset's metadata which evaluations it supports; the others give "not applicable"
# outputs under results/{dataset}/not_applicable/.
APPLICABILITY = "results/{dataset}/applicability.csv"
NOT_APPLICABLE = "results/{dataset}/not_applicable"


def not_applicable_outputs(ev):
    """Table, figure and claims of an evaluation the dataset cannot support."""
    return {k: f"{NOT_APPLICABLE}/{ev}.{ext}" for k, ext in (("table", "csv"), ("figure", "png"), ("claims", "json"))}


def applicable(dataset):
    """Evaluation -> whether the dataset supports it (checkpoint applicability)."""
    import pandas as pd

    path = checkpoints.applicability.get(dataset=dataset).output[0]
    table = pd.read_csv(path, dtype={"evaluation": str}, keep_default_na=False)
    status = dict(zip(table["evaluation"], table["applicable"].astype(str) == "True"))
    missing = sorted(set(EVALUATIONS) - set(status))
    if missing:
        raise WorkflowError(f"{path}: no applicability decided for {missing} (rerun rule applicability)")
    return status


def _evaluation_files(dataset, ev, ok):
    if not ok:
        return [p.format(dataset=dataset) for p in not_applicable_outputs(ev).values()]
    extra = [p.format(dataset=dataset) for p in evaluation_extra(ev)]
    pages = [f"{p}.html".format(dataset=dataset) for p in evaluation_extra(ev) if p in GIF_PAGES]
    return [ev_table(ev).format(dataset=dataset), ev_figure(ev).format(dataset=dataset),
            ev_claims(ev).format(dataset=dataset), *extra, *pages]


def evaluation_outputs(dataset):
    """Every registered evaluation's outputs for one dataset: its own where the dataset
    supports it, else its not-applicable table, figure and claims."""
    return [p for ev, ok in applicable(dataset).items() if ev in EVALUATIONS for p in _evaluation_files(dataset, ev, ok)]


def claim_files(dataset):
    """The claims files of all registered evaluations (not-applicable ones included)."""
    status = applicable(dataset)
    return [
        (ev_claims(ev) if status[ev] else not_applicable_outputs(ev)["claims"]).format(dataset=dataset)
        for ev in EVALUATIONS
    ]


# Model files built for every dataset whatever it supports (patterns with {dataset}; the
# `motionvar` command reads them): a paper's rule file adds those that need only the
# prep stage, each as (pattern, the hands or toes it needs from the rig). Models that need
# more join the default target as an evaluation's `extra`.
DATASET_MODELS = []


def rig_lacks(dataset):
    """The hands and toes the dataset's joint map leaves out (none for the CMU rig, or for a
    map that cannot be read: the data rule names its problem)."""
    path = joint_map_path(dataset)
    if not path:
        return set()
    from motionvar.io.joint_map_file import JointMapError, load_joint_map

    try:
        return set(load_joint_map(path).lacking)
    except JointMapError:
        return set()


def dataset_models(dataset):
    """The DATASET_MODELS of one dataset: those whose hands or toes its rig has."""
    lacks = rig_lacks(dataset)
    return [p.format(dataset=dataset) for p, joints in DATASET_MODELS if not lacks & set(joints)]


def default_outputs(dataset):
    """What `snakemake` builds for one dataset: the data figures, the preprocessed
    clips, the DATASET_MODELS, every registered evaluation (or its not-applicable
    outputs), the merged claims and their summary."""
    return [
        f"results/{dataset}/prep/metadata.csv",
        f"results/{dataset}/figures/dataset_overview.png",
        f"results/{dataset}/figures/dataset_realism.png",
        f"results/{dataset}/figures/dataset_animation.gif",
        *dataset_models(dataset),
        *evaluation_outputs(dataset),
        *gif_pages(dataset),
        f"results/{dataset}/claims.csv",
        f"results/{dataset}/claims_summary.html",
    ]


def report_files():
    """The reports of a run (rules dataset_report and stability_report, report.smk): one per
    dataset of run_datasets, reports/<dataset>.html, each showing that dataset's outputs
    only, and reports/stability.html when stability.datasets names some."""
    stability = [STABILITY_REPORT] if stability_datasets() else []
    return [f"reports/{dataset}.html" for dataset in run_datasets()] + stability


def all_outputs(wildcards):
    """Input function of the default target: the default outputs of every dataset in
    run_datasets, the claims-stability outputs when stability.datasets names some, and
    the reports (report_files)."""
    stability = STABILITY_OUTPUTS if stability_datasets() else []
    return [path for dataset in run_datasets() for path in default_outputs(dataset)] + stability + report_files()
