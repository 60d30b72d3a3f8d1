"""Rule du2022_sec4_6_1 (Du 2022 Sec. 4.6.1, "Compactness"): bytes of the motion
primitive models against the bytes of the clips they were fitted to."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from _graph import save
    from motionvar.claims import write_claims
    from motionvar.du2022.graph.evaluation import motion_bytes
    from motionvar.du2022.graph.verdicts import compactness_claim

    models = [p for p in snakemake.input.models if p.endswith(".npz")]
    meta = pd.read_csv(snakemake.input.metadata)
    rows = []
    for path in models:
        from pathlib import Path

        name = Path(path).stem
        size = Path(path).stat().st_size + Path(path).with_suffix(".json").stat().st_size
        with np.load(path, allow_pickle=False) as z:
            n_joints = len(z["parents"])
        if name.endswith("_dense"):
            dense = pd.read_csv(Path(path).parent / "dense_picks" / "metadata.csv")
            frames = (dense["stop_frame"] - dense["start_frame"]).to_numpy()
        else:
            sub = meta[meta["primitive"] == name]
            frames = (sub["stop_frame"] - sub["start_frame"]).to_numpy()
        data = int(sum(motion_bytes(int(t), n_joints) for t in frames))
        rows.append(dict(primitive=name, clips=len(frames), frames=int(frames.sum()), data_bytes=data,
                         model_bytes=int(size), ratio=data / size))
    table = pd.DataFrame(rows)
    total = dict(primitive="all", clips=int(table["clips"].sum()), frames=int(table["frames"].sum()),
                 data_bytes=int(table["data_bytes"].sum()), model_bytes=int(table["model_bytes"].sum()))
    total["ratio"] = total["data_bytes"] / total["model_bytes"]
    table = pd.concat([table, pd.DataFrame([total])], ignore_index=True)
    table.to_csv(snakemake.output.table, index=False, float_format="%.6g")
    write_claims(snakemake.output.claims, [compactness_claim(total["model_bytes"], total["data_bytes"])])

    t = table[table["primitive"] != "all"]
    fig, ax = plt.subplots(figsize=(8, 4))
    x = np.arange(len(t))
    ax.bar(x - 0.2, t["data_bytes"] / 1e6, 0.4, label="clips (float64 arrays)", color="tab:gray")
    ax.bar(x + 0.2, t["model_bytes"] / 1e6, 0.4, label="model (npz + json)", color="tab:blue")
    for i, r in enumerate(t["ratio"]):
        ax.text(i, max(t["data_bytes"].iloc[i], t["model_bytes"].iloc[i]) / 1e6 * 1.15, f"{r:.0f}x",
                ha="center", fontsize=8)
    ax.set_yscale("log")
    ax.set_xticks(x)
    ax.set_xticklabels(t["primitive"], rotation=30, ha="right", fontsize=8)
    ax.set_ylabel("MB (log scale)")
    ax.set_title(f"Model vs data size: {total['model_bytes'] / 1e6:.2f} MB of models for "
                 f"{total['data_bytes'] / 1e6:.1f} MB of clips ({total['ratio']:.0f}x; thesis: 41 MB vs 4.2 GB)",
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, snakemake.output.figure)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
