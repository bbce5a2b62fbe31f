"""rrc-bench report section for the shadows demo (hooked from scripts/make-report.py)."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import amortized_report as ar  # noqa: E402


def extra(rows, out_dir):
    lines = ar.done_when(rows, ("amortized", 4), ("pcf", 16), ("pcf", 4), 1.2,
                         "4-tap amortized RMSE ≤ 16-tap PCF, time ≤ ×1.2 of 4-tap PCF")
    return lines + ar.convergence("shadows", out_dir, "pcf16") + ar.lambda_sweep("shadows", rows, out_dir)
