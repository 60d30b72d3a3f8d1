"""The rule of every declared evaluation without further outputs (``motionvar.<paper>.catalog``;
rules made by workflow/rules/evaluations.smk): its input set loaded, measured, its table,
figure and claims written (:func:`_evaluation.evaluate`)."""


def main(snakemake) -> None:
    from _evaluation import evaluate

    evaluate(snakemake)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
