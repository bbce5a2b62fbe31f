"""depth_of_field's report section: the equal-time comparison and the lens-order comparison
(nearest-neighbour path through the Poisson disk against random order)."""
import importlib.util
import pathlib

_spec = importlib.util.spec_from_file_location("accumulation_report", pathlib.Path(__file__).with_name("accumulation_report.py"))
_shared = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_shared)


def extra(rows, out_dir):
    lines = _shared.equal_time(rows) + _shared.equal_time(rows, key="ms_min")
    nearest = {r["samples"]: r for r in rows if r["variant"] == "cached"}
    random = {r["samples"]: r for r in rows if r["variant"] == "cached-random-order"}
    common = sorted(set(nearest) & set(random))
    if common:
        lines += ["### Lens order: nearest-neighbour path against random order", "",
                  "| N | path length NN / random (lens radii) | hit rate NN / random | ms NN / random | RMSE NN / random |",
                  "|---|---|---|---|---|"]
        for n in common:
            a, b = nearest[n], random[n]
            lines.append(f"| {n} | {a.get('lens_path_length', 0):.2f} / {b.get('lens_path_length', 0):.2f} | "
                         f"{a['hit_rate']:.3f} / {b['hit_rate']:.3f} | {a['ms_median']:.0f} / {b['ms_median']:.0f} | "
                         f"{a['rmse']:.4f} / {b['rmse']:.4f} |")
        lines.append("")
    return lines
