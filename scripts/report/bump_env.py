"""rrc-bench report section for the bump_env demo (hooked from scripts/make-report.py)."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import amortized_report as ar  # noqa: E402


def extra(rows, out_dir):
    lines = ar.done_when(rows, ("amortized", 4), ("brute", 9), ("brute", 9), 0.6,
                         "4× amortized RMSE ≤ 9×, time ≤ 0.6 × that of 9×")
    return lines + ar.convergence("bump_env", out_dir, "brute9") + ar.lambda_sweep("bump_env", rows, out_dir)
