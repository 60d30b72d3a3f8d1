# One rule per published evaluation the library declares (motionvar.<paper>.catalog), made
# from the EvaluationSpec each paper's rule file registered for it (EVALUATIONS, common.smk).
# Every such rule runs workflow/scripts/<name>.py with the whole config section of its
# declaration as params.settings and writes its table, figure and claims (and the spec's
# further outputs). The script path comes from params.evaluation: Snakemake resolves a script:
# line again when the job runs, when a loop variable holds the last name the loop gave it.
from motionvar.claim_catalog import EVALUATIONS as _DECLARED

_unregistered = [e.name for e in _DECLARED if e.name not in EVALUATIONS]
if _unregistered:
    raise WorkflowError(f"the library declares {_unregistered}, but no rule file registers them")

for _ev_spec in EVALUATIONS.values():
    _ev_caption = f"../report/{_ev_spec.name}.rst"
    _ev = declared(_ev_spec.name)

    rule:
        name:
            _ev_spec.name
        input:
            **_ev_spec.inputs,
        output:
            table=in_report(ev_table(_ev_spec.name), _ev.paper, _ev_caption, figure=_ev.shown, kind="table"),
            figure=in_report(ev_figure(_ev_spec.name), _ev.paper, _ev_caption, figure=_ev.shown, kind="figure"),
            claims=ev_claims(_ev_spec.name),
            **_ev_spec.outputs,
        params:
            evaluation=_ev_spec.name,
            settings=config[_ev.section],
            **_ev_spec.params,
        log:
            ev_log(_ev_spec.name),
        benchmark:
            ev_benchmark(_ev_spec.name)
        priority: _ev_spec.priority
        threads: _ev_spec.threads
        resources:
            mem_mb=_ev_spec.mem_mb,
        conda:
            ENV
        script:
            "../scripts/{params.evaluation}.py"
