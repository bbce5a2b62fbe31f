"""rrc-bench report section for the shadows demo (hooked from scripts/make-report.py)."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import amortized_report as ar  # noqa: E402

FLOWS = [("ms_pcf4_no_prepass", "PCF 4, no prepass"), ("ms_pcf4_prepass", "PCF 4, depth prepass"),
         ("ms_flow_single_pass", "amortized, single pass (lookup pass shades all)"),
         ("ms_flow_one_pass", "amortized, ControlFlow::OnePass (prepass + shade)"),
         ("ms_flow_two_pass", "amortized, ControlFlow::TwoPass (prepass, lookup, probe, miss)")]


def flows(rows):
    row = next((r for r in rows if r["variant"] == "amortized"), None)
    if not row or "ms_flow_single_pass" not in row:
        return []
    lines = ["### shadows: control flows (interleaved, 4 taps)", "", "| flow | ms median |", "|---|---|"]
    lines += [f"| {label} | {row[key]:.2f} |" for key, label in FLOWS if key in row]
    static = [(k, row.get(k)) for k in ("rmse_pcf4_static", "rmse_pcf16_static", "rmse_converged_static", "rmse_blurred_static")]
    if all(v is not None for _, v in static):
        lines += ["", "Static camera at the convergence view (RMSE): " +
                  ", ".join(f"{k.replace('rmse_', '').replace('_static', '')} {v:.4f}" for k, v in static), ""]
    return lines + [""]


def extra(rows, out_dir):
    lines = ar.done_when(rows, ("amortized", 4), ("pcf", 16), ("pcf", 4), 1.2,
                         "4-tap amortized RMSE ≤ 16-tap PCF, time ≤ ×1.2 of 4-tap PCF")
    return lines + flows(rows) + ar.convergence("shadows", out_dir, "pcf16") + ar.lambda_sweep("shadows", rows, out_dir)
