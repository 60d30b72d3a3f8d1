# Du 2022 ch. 3, functional data analysis of motion primitives: cubic B-spline functions
# (Fig. 3.9), FPCA, normalized FPCA, SFPCA and a Bayesian GPLVM (Fig. 3.10, 3.11), latent
# dimensions per primitive (Table 3.1). Options: config.fda (config/schema.yaml). Inputs:
# the aligned primitives of results/{dataset}/prep/, warped to a canonical timeline here.

include: "du2022_fda_helpers.smk"


rule du2022_fda_canonical:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
    output:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
    params:
        options=config["fda"],
    log:
        ev_log("du2022_fda_canonical"),
    benchmark:
        ev_benchmark("du2022_fda_canonical")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_canonical.py"


rule du2022_fda_basis:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
    output:
        rmse=f"{FDA}/basis_rmse.csv",
        n_basis=f"{FDA}/n_basis.csv",
    params:
        options=config["fda"],
    log:
        ev_log("du2022_fda_basis"),
    benchmark:
        ev_benchmark("du2022_fda_basis")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_basis.py"


rule du2022_fig3_9:
    input:
        rmse=f"{FDA}/basis_rmse.csv",
    output:
        table=in_report(ev_table("du2022_fig3_9"), "du2022", "../report/du2022_fig3_9.rst", figure="Fig. 3.9", kind="table"),
        figure=in_report(ev_figure("du2022_fig3_9"), "du2022", "../report/du2022_fig3_9.rst", figure="Fig. 3.9", kind="figure"),
        claims=ev_claims("du2022_fig3_9"),
    params:
        options=config["fda"],
    log:
        ev_log("du2022_fig3_9"),
    benchmark:
        ev_benchmark("du2022_fig3_9")
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig3_9.py"


rule du2022_fda_curves:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
        n_basis=f"{FDA}/n_basis.csv",
    output:
        curves=f"{FDA}/curves/{{primitive}}_{{part}}.npz",
    wildcard_constraints:
        part="|".join(FDA_PARTS),
    params:
        options=config["fda"],
        methods=lambda wc: FDA_PARTS[wc.part],
    log:
        ev_log("du2022_fda_curves", "{primitive}_{part}"),
    benchmark:
        ev_benchmark("du2022_fda_curves", "{primitive}_{part}")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_curves.py"


rule du2022_fig3_10:
    input:
        curves=fda_curve_files(),
    output:
        table=in_report(ev_table("du2022_fig3_10"), "du2022", "../report/du2022_fig3_10.rst", figure="Fig. 3.10", kind="table"),
        figure=in_report(ev_figure("du2022_fig3_10"), "du2022", "../report/du2022_fig3_10.rst", figure="Fig. 3.10", kind="figure"),
        claims=ev_claims("du2022_fig3_10"),
    params:
        options=config["fda"],
        methods=FDA_METHODS,
    log:
        ev_log("du2022_fig3_10"),
    benchmark:
        ev_benchmark("du2022_fig3_10")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig3_10.py"


rule du2022_fig3_11:
    input:
        curves=fda_curve_files(),
    output:
        table=in_report(ev_table("du2022_fig3_11"), "du2022", "../report/du2022_fig3_11.rst", figure="Fig. 3.11", kind="table"),
        figure=in_report(ev_figure("du2022_fig3_11"), "du2022", "../report/du2022_fig3_11.rst", figure="Fig. 3.11", kind="figure"),
        claims=ev_claims("du2022_fig3_11"),
    params:
        options=config["fda"],
        methods=FDA_METHODS,
    log:
        ev_log("du2022_fig3_11"),
    benchmark:
        ev_benchmark("du2022_fig3_11")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig3_11.py"


rule du2022_table3_1:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
        n_basis=f"{FDA}/n_basis.csv",
    output:
        table=in_report(ev_table("du2022_table3_1"), "du2022", "../report/du2022_table3_1.rst", figure="Table 3.1", kind="table"),
        figure=in_report(ev_figure("du2022_table3_1"), "du2022", "../report/du2022_table3_1.rst", figure="Table 3.1", kind="figure"),
        claims=ev_claims("du2022_table3_1"),
    params:
        options=config["fda"],
    log:
        ev_log("du2022_table3_1"),
    benchmark:
        ev_benchmark("du2022_table3_1")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_table3_1.py"
