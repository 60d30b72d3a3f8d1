# Du 2022 ch. 3, functional data analysis of motion primitives: cubic B-spline functions
# (Fig. 3.9), FPCA, normalized FPCA, SFPCA and a Bayesian GPLVM (Fig. 3.10, 3.11), latent
# dimensions per primitive (Table 3.1). Options: config.fda (config/schema.yaml). Inputs:
# the aligned primitives of results/{dataset}/prep/, warped to a canonical timeline here.
# Library: motionvar.du2022.fda (evaluations/, figures.py).

include: "du2022_fda_helpers.smk"


rule du2022_fda_canonical:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
    output:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
    params:
        options=config_params("fda", ["behaviours", "min_clips", "time_warping"]),
    log:
        ev_log("du2022_fda_canonical"),
    benchmark:
        ev_benchmark("du2022_fda_canonical")
    priority: PRIORITY["du2022_fda_canonical"]
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_canonical.py"


# a checkpoint: the primitives it lists (n_basis.csv) decide which SFPCA models Table 3.1 reads
checkpoint du2022_fda_basis:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
    output:
        rmse=f"{FDA}/basis_rmse.csv",
        n_basis=f"{FDA}/n_basis.csv",
    params:
        options=config_params("fda", ["basis.n_basis", "basis.min_relative_drop"]),
    log:
        ev_log("du2022_fda_basis"),
    benchmark:
        ev_benchmark("du2022_fda_basis")
    priority: PRIORITY["du2022_fda_basis"]
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_basis.py"


# SFPCA of one Fig. 3.10 primitive at Table 3.1's reference dimension, fitted once: read by
# the primitive's curves (which fit SFPCA at that dimension too) and by Table 3.1.
rule du2022_fda_sfpca:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
        n_basis=f"{FDA}/n_basis.csv",
    output:
        model=f"{FDA_SFPCA}/{{primitive}}.npz",
        settings=f"{FDA_SFPCA}/{{primitive}}.json",
    params:
        options=config_params("fda", ["sfpca", "table.reference_components", "table.max_components"]),
    log:
        ev_log("du2022_fda_sfpca", "{primitive}"),
    benchmark:
        ev_benchmark("du2022_fda_sfpca", "{primitive}")
    priority: PRIORITY["du2022_fda_sfpca"]
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_sfpca.py"


rule du2022_fda_curves:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
        n_basis=f"{FDA}/n_basis.csv",
        sfpca=lambda wc: fda_sfpca_files(wc.primitive) if "sfpca" in FDA_PARTS[wc.part] else [],
    output:
        curves=f"{FDA}/curves/{{primitive}}_{{part}}.npz",
    wildcard_constraints:
        part="|".join(FDA_PARTS),
    params:
        options=config_params("fda", ["seed", "reconstruction.dims", "latent.n_components", "sfpca", "gplvm"]),
        methods=lambda wc: FDA_PARTS[wc.part],
    log:
        ev_log("du2022_fda_curves", "{primitive}_{part}"),
    benchmark:
        ev_benchmark("du2022_fda_curves", "{primitive}_{part}")
    priority: PRIORITY["du2022_fda_curves"]
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_curves.py"


# The evaluations (tables, figures, claims): one rule each, same body; evaluation ->
# (published figure or table, inputs, params, mem_mb). Script: ../scripts/<evaluation>.py,
# named through params (a script: line is evaluated when the job runs, after the loop).
FDA_CANONICAL = {"clips": f"{FDA}/canonical/clips.npz", "metadata": f"{FDA}/canonical/metadata.csv"}
FDA_EVALUATIONS = {
    "du2022_fig3_9": (
        "Fig. 3.9",
        {"rmse": f"{FDA}/basis_rmse.csv"},
        {"options": config_params("fda", ["basis.min_relative_drop"])},
        1000,
    ),
    "du2022_fig3_10": (
        "Fig. 3.10",
        {"curves": fda_curve_files()},
        {
            "options": config_params("fda", ["reconstruction.primitives", "reconstruction.pick_primitive"]),
            "methods": FDA_METHODS,
        },
        2000,
    ),
    "du2022_fig3_11": (
        "Fig. 3.11",
        {"curves": fda_curve_files()},
        {
            "options": config_params(
                "fda",
                ["seed", "reconstruction.primitives", "reconstruction.pick_primitive", "latent.knn",
                 "latent.tsne_perplexity"],
            ),
            "methods": FDA_METHODS,
        },
        2000,
    ),
    "du2022_table3_1": (
        "Table 3.1",
        {**FDA_CANONICAL, "n_basis": f"{FDA}/n_basis.csv", "sfpca": fda_sfpca_models},
        {
            "options": config_params(
                "fda",
                ["sfpca", "table.reference_components", "table.max_components", "table.observation_error_cm"],
            ),
        },
        4000,
    ),
}

for _fda_ev, (_figure, _input, _params, _mem_mb) in FDA_EVALUATIONS.items():
    register_evaluation(_fda_ev, paper="du2022")

    rule:
        name:
            _fda_ev
        input:
            **_input,
        output:
            table=in_report(ev_table(_fda_ev), "du2022", f"../report/{_fda_ev}.rst", figure=_figure, kind="table"),
            figure=in_report(ev_figure(_fda_ev), "du2022", f"../report/{_fda_ev}.rst", figure=_figure, kind="figure"),
            claims=ev_claims(_fda_ev),
        params:
            evaluation=_fda_ev,
            **_params,
        log:
            ev_log(_fda_ev),
        benchmark:
            ev_benchmark(_fda_ev)
        priority: PRIORITY.get(_fda_ev, 0)
        threads: 1
        resources:
            mem_mb=_mem_mb,
        conda:
            ENV
        script:
            "../scripts/{params.evaluation}.py"
