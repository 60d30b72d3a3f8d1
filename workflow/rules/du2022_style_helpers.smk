# Helpers of style.smk (Du 2022 ch. 5), kept apart from its rules (snakemake --lint).

STYLE_CFG = config["style"]
STYLE_MODELS = "results/{dataset}/models/du2022_style"
STYLE_PRIMITIVE_PATTERN = "[A-Za-z]+(?:_[A-Za-z]+)?"
STYLE_STYLE_PATTERN = "[a-z]+"


def style_params(keys):
    """The part of config.style a rule reads (so that other keys' edits do not rerun it)."""
    return {k: STYLE_CFG[k] for k in keys}


def style_vaes(primitives, kind="model"):
    suffix = ".pt" if kind == "model" else "_history.csv"
    return [f"{STYLE_MODELS}/vae/{p}{suffix}" for p in primitives]


def style_cvaes(primitives, kind="model"):
    suffix = ".pt" if kind == "model" else "_history.csv"
    return [f"{STYLE_MODELS}/cvae/{p}/{s}{suffix}" for p in primitives for s in STYLE_CFG["styles"]]
