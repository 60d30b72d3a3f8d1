# One rule per published evaluation the library declares (motionvar.<paper>.catalog; EVALUATIONS,
# common.smk), made from the declaration alone: its input set's files (INPUT_SETS), its config
# section as params.settings, its table, figure and claims, and the RuleAdditions of the few
# that write more (EVALUATION_ADDITIONS). The rule runs workflow/scripts/evaluation.py, which
# loads the inputs, measures and draws as the declaration says; an evaluation with further
# outputs runs its own script, workflow/scripts/<name>.py. The script path comes from
# params.script: Snakemake resolves a script: line again when the job runs, when a loop variable
# holds the last name the loop gave it. Included after every paper's rule file.

_unused = sorted(set(INPUT_SETS) - {e.inputs for e in EVALUATIONS.values()})
if _unused:
    raise WorkflowError(f"input sets {_unused} are added but no evaluation declares them")

for _ev in EVALUATIONS.values():
    if _ev.paper not in PAPER_CATEGORY or _ev.section not in config:
        raise WorkflowError(f"evaluation {_ev.name}: unknown paper {_ev.paper} or config section {_ev.section}")
    _ev_add = EVALUATION_ADDITIONS.get(_ev.name, RuleAdditions())
    _ev_inputs = evaluation_input(_ev.name)
    _ev_caption = f"../report/{_ev.name}.rst"

    rule:
        name:
            _ev.name
        input:
            **_ev_inputs,
        output:
            table=in_report(ev_table(_ev.name), _ev.paper, _ev_caption, figure=_ev.shown, kind="table"),
            figure=in_report(ev_figure(_ev.name), _ev.paper, _ev_caption, figure=_ev.shown, kind="figure"),
            claims=ev_claims(_ev.name),
            **_ev_add.outputs,
        params:
            script=_ev.name if _ev_add.outputs else "evaluation",
            settings=section_for(_ev.section, _ev.name),
            **({"joint_map": lambda wc: joint_map_path(wc.dataset)} if "joint_map" in _ev_inputs else {}),
            **_ev_add.params,
        log:
            ev_log(_ev.name),
        benchmark:
            ev_benchmark(_ev.name)
        priority: PRIORITY.get(_ev.name, 0)
        threads: 1
        resources:
            mem_mb=_ev.mem_mb,
        conda:
            ENV
        script:
            "../scripts/{params.script}.py"
