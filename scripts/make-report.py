#!/usr/bin/python3
"""Turns rrc-bench's out/results.json into out/results.csv, one time-against-error plot per demo
(out/plot_<demo>.png, matplotlib) and out/report.md, which embeds the plots and the sample frames
rrc-bench wrote (brute and cached side by side, hit/miss visualisation, amplified difference).

Usage: make-report.py OUT_DIR"""
import csv
import json
import math
import pathlib
import sys

COLUMNS = ["demo", "variant", "samples", "lambda", "width", "height", "frames", "ms_median", "ms_min",
           "rmse", "psnr", "hit_rate", "speedup", "best_speedup", "fraction_of_best"]


def fmt(value, digits=2):
    if value is None:
        return "–"
    if isinstance(value, float):
        if math.isinf(value):
            return "∞"
        return f"{value:.{digits}f}"
    return str(value)


def plot(demo, rows, out_dir):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    for variant in sorted({r["variant"] for r in rows}):
        pts = sorted((r["ms_median"], r["rmse"], r.get("samples")) for r in rows
                     if r["variant"] == variant and r.get("rmse") is not None)
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=variant)
        for ms, rmse, samples in pts:
            if samples and len(pts) > 1:
                ax.annotate(str(samples), (ms, rmse), textcoords="offset points", xytext=(3, 3), fontsize=7)
    ax.set_xlabel("frame time, median (ms)")
    ax.set_ylabel("RMSE against the reference")
    ax.set_title(f"{demo}: run time against error")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    path = out_dir / f"plot_{demo}.png"
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path.name


def demo_extras(demo, rows, out_dir):
    """A demo's own report section: scripts/report/<demo>.py, when it exists, defines
    extra(rows, out_dir) -> list of markdown lines (extra plots, equal-time tables ...)."""
    path = pathlib.Path(__file__).resolve().parent / "report" / f"{demo}.py"
    if not path.exists():
        return []
    import importlib.util
    spec = importlib.util.spec_from_file_location(f"report_{demo}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return list(module.extra(rows, out_dir))


def main():
    out_dir = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out")
    data = json.loads((out_dir / "results.json").read_text())
    meta = {}
    meta_path = out_dir / "run.json"
    if meta_path.exists():
        meta = json.loads(meta_path.read_text())
    with open(out_dir / "results.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for row in data:
            writer.writerow(row)

    lines = ["# rrc-bench report", ""]
    if meta:
        lines += [f"Run on {meta.get('date', '?')}: `{meta.get('command', '')}` — {meta.get('renderer', '')} "
                  f"({meta.get('backend', '')}), {meta.get('width')}x{meta.get('height')}, "
                  f"{meta.get('frames')} measured frames after {meta.get('warmup')} warm-up frames, "
                  f"wall clock around glFinish.", ""]
    for demo in dict.fromkeys(r["demo"] for r in data):
        rows = [r for r in data if r["demo"] == demo]
        lines += [f"## {demo}", ""]
        lines += ["| variant | samples | λ | ms median | ms min | RMSE | PSNR dB | hit rate | speedup | best possible | achieved |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in rows:
            lines.append("| " + " | ".join([r["variant"], fmt(r.get("samples")), fmt(r.get("lambda")),
                                             fmt(r.get("ms_median")), fmt(r.get("ms_min")), fmt(r.get("rmse"), 4),
                                             fmt(r.get("psnr"), 1), fmt(r.get("hit_rate"), 3), fmt(r.get("speedup")),
                                             fmt(r.get("best_speedup")), fmt(r.get("fraction_of_best")),
                                             ]) + " |")
        lines.append("")
        notes = [r["note"] for r in rows if r.get("note")]
        lines += [f"- {n}" for n in dict.fromkeys(notes)]
        if notes:
            lines.append("")
        name = plot(demo, rows, out_dir)
        if name:
            lines += [f"![{demo}: time against error]({name})", ""]
        lines += demo_extras(demo, rows, out_dir)
        for r in rows:
            images = r.get("images") or {}
            if images:
                lines.append(f"**{r['variant']}**: " + " ".join(f"![{k}]({v})" for k, v in images.items()))
                lines.append("")
    lines += ["## Columns", "",
              "- *speedup*: brute-force time / this variant's time, same demo and sample count.",
              "- *best possible*: the speedup this run could reach given its own measured lookup cost and miss "
              "fraction (brute / (lookup + miss fraction × full shading)); *achieved* = speedup / best possible.",
              ""]
    (out_dir / "report.md").write_text("\n".join(lines))
    print(f"wrote {out_dir / 'report.md'}, {out_dir / 'results.csv'}")


if __name__ == "__main__":
    main()
