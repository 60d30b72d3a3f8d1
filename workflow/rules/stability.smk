# Claims stability across synthetic populations (config/seeds.yaml): the merged claims of
# every dataset in config stability.datasets (one per seed), compared claim by claim.


rule claims_stability:
    input:
        claims=[f"results/{d}/claims.csv" for d in stability_datasets()],
    output:
        table=report(STABILITY_CSV, caption="../report/claims_stability.rst", category=SUMMARY_CATEGORY,
                     subcategory="stability", labels={"figure": "claims stability (CSV)"}),
        figure=report(f"{STABILITY}/claims_stability.png", caption="../report/claims_stability.rst",
                      category=SUMMARY_CATEGORY, subcategory="stability",
                      labels={"figure": "claim values per seed against the bound"}),
        page=report(f"{STABILITY}/claims_stability.html", caption="../report/claims_stability.rst",
                    category=SUMMARY_CATEGORY, subcategory="stability",
                    labels={"figure": "verdicts per seed, stable or not"}),
    params:
        datasets=stability_datasets(),
        stable_share=config["stability"]["stable_share"],
    log:
        f"{STABILITY}/logs/claims_stability.log",
    benchmark:
        f"{STABILITY}/benchmarks/claims_stability.tsv"
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/claims_stability.py"
