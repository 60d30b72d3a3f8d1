# Shared helpers of all rule files: dataset list, paths, and the evaluation registry.
# Included first by the Snakefile (see workflow/README.md).

ENV = "../envs/motionvar.yaml"

PAPER_CATEGORY = {
    "data": "Data",
    "ma2010": "Ma et al. 2010",
    "du2022": "Du 2022",
    "egges2004": "Egges et al. 2004",
}

# name -> {"paper": ..., "extra": [path patterns with {dataset}]}
EVALUATIONS = {}


def run_datasets():
    """The datasets the default target builds (config key run_datasets)."""
    return list(config["run_datasets"])


def ev_table(ev):
    return f"results/{{dataset}}/tables/{ev}.csv"


def ev_figure(ev):
    return f"results/{{dataset}}/figures/{ev}.png"


def ev_claims(ev):
    return f"results/{{dataset}}/claims/{ev}.json"


def ev_log(rule_name):
    return f"results/{{dataset}}/logs/{rule_name}.log"


def ev_benchmark(rule_name):
    return f"results/{{dataset}}/benchmarks/{rule_name}.tsv"


def register_evaluation(ev, paper, extra=()):
    """Add evaluation ``ev`` (table, figure, claims, plus ``extra`` outputs) to the
    default target, the claims merge and the report."""
    if ev in EVALUATIONS:
        raise ValueError(f"evaluation {ev} registered twice")
    if paper not in PAPER_CATEGORY:
        raise ValueError(f"evaluation {ev}: unknown paper {paper}")
    EVALUATIONS[ev] = {"paper": paper, "extra": list(extra)}


def evaluation_outputs(dataset):
    """Every registered evaluation's outputs for one dataset."""
    out = []
    for ev, spec in EVALUATIONS.items():
        for pattern in [ev_table(ev), ev_figure(ev), ev_claims(ev), *spec["extra"]]:
            out.append(pattern.format(dataset=dataset))
    return out


def claim_files(dataset):
    return [ev_claims(ev).format(dataset=dataset) for ev in EVALUATIONS]
