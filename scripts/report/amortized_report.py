"""Report sections shared by the amortized-supersampling demos (shadows, bump_env): the
convergence after a camera move (from <demo>_convergence.json, written by rrc-bench) and the
trailing/ghosting trade-off against lambda (the moving sequence's rows)."""
import json
import pathlib


def _plt():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError:
        return None


def convergence(demo, out_dir, baseline_label):
    out_dir = pathlib.Path(out_dir)
    path = out_dir / f"{demo}_convergence.json"
    if not path.exists():
        return []
    series = json.loads(path.read_text())
    lines = [f"### {demo}: error after a camera move", "",
             "The camera holds still, jumps (most pixels miss) and holds still again; RMSE against the "
             "reference per frame after the jump. Brute-force / PCF variants are flat lines.", ""]
    plt = _plt()
    if plt:
        fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
        for name, values in sorted(series.items()):
            style = "-" if name.startswith("amortized") else "--"
            ax.plot(range(len(values)), values, style, label=name.replace("amortized_l", "amortized λ="))
        ax.set_xlabel("frames after the camera move")
        ax.set_ylabel("RMSE against the reference")
        ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out_dir / f"plot_{demo}_convergence.png")
        plt.close(fig)
        lines += [f"![{demo}: convergence](plot_{demo}_convergence.png)", ""]
    amortized = {k: v for k, v in series.items() if k.startswith("amortized")}
    baseline = series.get(baseline_label, [None])[0]
    lines += ["| series | frame 0 | frame 1 | frame 3 | frame 7 | last | first frame ≤ " + baseline_label + " |",
              "|---|---|---|---|---|---|---|"]
    for name, v in sorted(amortized.items()):
        below = next((i for i, e in enumerate(v) if baseline is not None and e <= baseline), None)
        cells = [f"{v[i]:.4f}" if i < len(v) else "–" for i in (0, 1, 3, 7)]
        lines.append(f"| {name} | " + " | ".join(cells) + f" | {v[-1]:.4f} | {below if below is not None else 'never'} |")
    lines.append("")
    return lines


def lambda_sweep(demo, rows, out_dir):
    sweep = sorted((r["lambda"], r["rmse"], r["ms_median"]) for r in rows
                   if r["variant"] in ("amortized", "amortized (lambda sweep)") and r.get("rmse") is not None)
    if len(sweep) < 2:
        return []
    out_dir = pathlib.Path(out_dir)
    lines = [f"### {demo}: λ sweep on the moving sequence", "",
             "Higher λ averages more frames (less noise) but trails further behind changes (moving shadows, "
             "disocclusions, resampling blur): the moving-sequence RMSE shows where the trade-off turns.", "",
             "| λ | RMSE | ms median |", "|---|---|---|"]
    lines += [f"| {l:.2f} | {e:.4f} | {ms:.2f} |" for l, e, ms in sweep]
    lines.append("")
    plt = _plt()
    if plt:
        fig, ax = plt.subplots(figsize=(5, 3.5), dpi=100)
        ax.plot([s[0] for s in sweep], [s[1] for s in sweep], "o-")
        ax.set_xlabel("λ")
        ax.set_ylabel("RMSE (moving sequence)")
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(out_dir / f"plot_{demo}_lambda.png")
        plt.close(fig)
        lines += [f"![{demo}: λ sweep](plot_{demo}_lambda.png)", ""]
    return lines


def done_when(rows, cheap, rival, timing_base, time_ratio, label):
    """cheap, rival, timing_base: (variant, samples) keys. Checks cheap.rmse <= rival.rmse and
    cheap.ms <= time_ratio * timing_base.ms."""
    def find(key):
        return next((r for r in rows if r["variant"] == key[0] and r.get("samples") == key[1]), None)
    c, r, b = find(cheap), find(rival), find(timing_base)
    if not (c and r and b):
        return []
    ok_error = c["rmse"] <= r["rmse"]
    ratio = c["ms_median"] / b["ms_median"]
    ok_time = ratio <= time_ratio
    return [f"**Done-when ({label})**: RMSE {c['rmse']:.4f} vs {r['rmse']:.4f} → {'holds' if ok_error else 'MISSED'}; "
            f"time {c['ms_median']:.2f} ms = ×{ratio:.2f} of {b['ms_median']:.2f} ms (target ≤ ×{time_ratio}) → "
            f"{'holds' if ok_time else 'MISSED'}.", ""]
