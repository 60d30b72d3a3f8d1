"""Rules gif_page_*: a GIF inlined in an HTML page, so that the report can play it."""


def main(snakemake) -> None:
    from pathlib import Path

    from motionvar.plots import gif_page

    Path(snakemake.output[0]).write_text(gif_page(snakemake.input[0], title=snakemake.params.title), encoding="utf-8")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
