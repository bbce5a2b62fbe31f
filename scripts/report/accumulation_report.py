"""Shared by scripts/report/motion_blur.py and depth_of_field.py: the equal-time comparison of the
accumulation demos (issue 5). Brute force's time at N = 8 is the budget; each cached arm's largest
measured N within it is compared with brute force at N = 8 (sample ratio and RMSE)."""


def equal_time(rows, budget_samples=8, key="ms_median"):
    brute = {r["samples"]: r for r in rows if r["variant"] == "brute"}
    if budget_samples not in brute:
        return ["(no brute-force row at N = 8: no equal-time comparison)", ""]
    b = brute[budget_samples]
    budget = b[key]
    what = "median" if key == "ms_median" else "minimum (the least disturbed frame)"
    lines = [f"### Equal time by the {what} frame time: brute force's budget at N = {budget_samples} is {budget:.0f} ms", "",
             "| variant | largest N within the budget | its ms | samples vs brute force | RMSE | brute force RMSE at N = 8 | lower error | done-when (≥ ×2 samples and lower RMSE) |",
             "|---|---|---|---|---|---|---|---|"]
    for variant in dict.fromkeys(r["variant"] for r in rows):
        if variant in ("brute", "reference"):
            continue
        fits = [r for r in rows if r["variant"] == variant and r[key] <= budget]
        if not fits:
            lines.append(f"| {variant} | none | – | – | – | {b['rmse']:.4f} | – | no |")
            continue
        best = max(fits, key=lambda r: r["samples"])
        ratio = best["samples"] / budget_samples
        lower = best["rmse"] < b["rmse"]
        ok = ratio >= 2 and lower
        lines.append(f"| {variant} | {best['samples']} | {best[key]:.0f} | ×{ratio:.2f} | {best['rmse']:.4f} | "
                     f"{b['rmse']:.4f} | {'yes' if lower else 'no'} | {'yes' if ok else 'no'} |")
    lines += ["", "Only measured N count (the sweep is 2, 4, 8, 12, 16, 20, 24, 32 for the cached variant); "
              "times are medians over the measured frames, all arms interleaved frame by frame.", ""]
    return lines
