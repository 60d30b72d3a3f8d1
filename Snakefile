# motionvar: replication of Ma et al. 2010, Du 2022 and Egges et al. 2004.
# `snakemake --cores 2` builds every registered evaluation and the report
# (reports/replication.html, through the default profile). See README.md and
# workflow/README.md for the conventions every rule file follows.

import os

from snakemake.utils import min_version

min_version("9.0")


configfile: os.path.join(workflow.basedir, "config/config.yaml")


include: "workflow/rules/common.smk"


validate_config(os.path.join(workflow.basedir, "config/schema.yaml"))


wildcard_constraints:
    dataset=dataset_pattern(),



report: "workflow/report/workflow.rst"


include: "workflow/rules/data.smk"
include: "workflow/rules/prep.smk"


# One rule file per paper stage; each is included when it exists, so a stage can be
# added without editing this file.
for _stage in PAPER_RULE_FILES:
    if os.path.exists(os.path.join(workflow.basedir, "workflow/rules", _stage)):

        include: f"workflow/rules/{_stage}"


include: "workflow/rules/report.smk"


rule all:
    default_target: True
    input:
        [path for dataset in run_datasets() for path in default_outputs(dataset)],
