# Figures of the data, the merged claims of all registered evaluations, and the claims
# summary that opens the report. Included last (after every paper's rule file), so that
# claim_files() sees all registered evaluations.


rule dataset_overview:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
    output:
        in_report(
            "results/{dataset}/figures/dataset_overview.png",
            "data",
            "../report/dataset_overview.rst",
            figure="key frames per behaviour and walking style",
        ),
    params:
        settings=config["report"],
    log:
        ev_log("dataset_overview"),
    benchmark:
        ev_benchmark("dataset_overview")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/dataset_overview.py"


rule dataset_realism:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        table="results/{dataset}/tables/dataset_realism.csv",
        joints="results/{dataset}/tables/dataset_realism_joints.csv",
        figure=in_report(
            "results/{dataset}/figures/dataset_realism.png",
            "data",
            "../report/dataset_realism.rst",
            figure="realism statistics against captured data",
        ),
    params:
        prep=config["prep"],
        settings=config["realism"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("dataset_realism"),
    benchmark:
        ev_benchmark("dataset_realism")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/dataset_realism.py"


rule dataset_animation:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
    output:
        in_report(
            "results/{dataset}/figures/dataset_animation.gif",
            "data",
            "../report/dataset_animation.rst",
            page="gif_page_dataset_animation",
            figure="animation, one clip per behaviour",
        ),
    params:
        settings=config["report"],
    log:
        ev_log("dataset_animation"),
    benchmark:
        ev_benchmark("dataset_animation")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/dataset_animation.py"


rule claims:
    input:
        claims=lambda wc: claim_files(wc.dataset),
    output:
        in_report(
            "results/{dataset}/claims.csv",
            "summary",
            "../report/claims.rst",
            figure="claims table (CSV)",
        ),
    log:
        ev_log("claims"),
    benchmark:
        ev_benchmark("claims")
    threads: 1
    resources:
        mem_mb=500,
    conda:
        ENV
    script:
        "../scripts/claims.py"


rule claims_summary:
    input:
        claims="results/{dataset}/claims.csv",
        # this config's stability table where its seeds include the dataset: the summary waits for it
        stability=lambda wc: [STABILITY_CSV] if wc.dataset in stability_datasets() else [],
    output:
        in_report(
            "results/{dataset}/claims_summary.html",
            "summary",
            "../report/claims_summary.rst",
            figure="claims per paper, with verdicts",
        ),
    params:
        categories=PAPER_CATEGORY,
        # the table of a stability run that has this dataset among its seeds (rule claims_stability): this
        # config's, else the earlier run's of config key stability.marks; each verdict marked stable or not
        stability=lambda wc: stability_table_of(wc.dataset),
    log:
        ev_log("claims_summary"),
    benchmark:
        ev_benchmark("claims_summary")
    threads: 1
    resources:
        mem_mb=500,
    conda:
        ENV
    script:
        "../scripts/claims_summary.py"


# The report of one dataset, reports/{dataset}.html: Snakemake's report (`snakemake --report`)
# of the dataset's default outputs only, so a run on another dataset or a single target
# leaves it as it is. In the default target (report_files, common.smk); a local job, since
# it reads the run's metadata in .snakemake/.
rule dataset_report:
    input:
        lambda wc: default_outputs(wc.dataset),
    output:
        "reports/{dataset}.html",
    params:
        snakefile=workflow.main_snakefile,
    log:
        ev_log("dataset_report"),
    benchmark:
        ev_benchmark("dataset_report")
    localrule: True
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/report.py"


# The report of a claims-stability run (config/seeds.yaml): rule claims_stability's outputs.
rule stability_report:
    input:
        STABILITY_OUTPUTS,
    output:
        STABILITY_REPORT,
    params:
        snakefile=workflow.main_snakefile,
    log:
        f"{STABILITY}/logs/stability_report.log",
    benchmark:
        f"{STABILITY}/benchmarks/stability_report.tsv"
    localrule: True
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/report.py"


# One page per GIF given to in_report (common.smk): the GIF inlined in a small HTML page,
# which the report shows (it cannot show a GIF file itself); each rule is named where its GIF
# is given to in_report (page="gif_page_<what>"). Defined last, after every rule file has
# registered its GIFs.
for _gif, (_name, _category, _caption, _labels) in GIF_PAGES.items():

    rule:
        name:
            _name
        input:
            _gif,
        output:
            report(
                f"{_gif}.html",
                caption=_caption,
                category=_category,
                subcategory="{dataset}",
                labels={"dataset": "{dataset}", **_labels} if _labels else None,
            ),
        params:
            title=_labels.get("figure", os.path.basename(_gif)),
        log:
            ev_log(_name),
        benchmark:
            ev_benchmark(_name)
        threads: 1
        resources:
            mem_mb=500,
        conda:
            ENV
        script:
            "../scripts/gif_page.py"
